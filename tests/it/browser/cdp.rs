//! A tiny Chrome DevTools Protocol client that drives a headless `chromium`, for the
//! integration tests and the benchmark that check the generated HTML in a real browser.
//!
//! Kept to std, `serde_json`, `base64` and `tungstenite` (blocking, no TLS: the browser listens on
//! ws://127.0.0.1) so that a bench can include this file with `#[path]` without the test
//! helpers. One browser process per [`Browser`]; one page (a flattened CDP session) at a
//! time. Every wait has a deadline, and errors say what was being waited for, so a broken
//! page fails a test instead of hanging it.

// Included by several crates (the test binary, benches), each using part of the API.
#![allow(dead_code)]

use serde_json::{Value, json};
use std::io::{BufRead, BufReader, ErrorKind};
use std::net::TcpStream;
use std::path::PathBuf;
use std::process::{Child, Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;
use std::time::{Duration, Instant};
use tungstenite::{Message, WebSocket};

/// How long any single wait (start-up, a command's answer, a page load) may take.
pub const TIMEOUT: Duration = Duration::from_secs(20);
/// The socket's read timeout: how often a blocked read wakes up to check its deadline.
/// Data arriving earlier is returned at once, so this costs no latency.
const READ_SLICE: Duration = Duration::from_millis(50);
/// The polling interval of [`Browser::wait_for`].
const POLL: Duration = Duration::from_millis(20);

/// A running headless chromium with one open page.
pub struct Browser {
    child: Child,
    ws: WebSocket<TcpStream>,
    next_id: u64,
    /// The page's target and its flattened session (empty before the first `open`).
    target: String,
    session: String,
    /// What the current page reported since `open`.
    console: Vec<String>,
    requests: Vec<String>,
    /// The `Page.loadEventFired` of the current navigation has been seen.
    loaded: bool,
    profile: PathBuf,
}

/// The browser executable: `AXCHECK_CHROMIUM` if set, else the first usual name on PATH.
fn find_chromium() -> Result<PathBuf, String> {
    if let Some(exe) = std::env::var_os("AXCHECK_CHROMIUM") {
        let exe = PathBuf::from(exe);
        return match exe.is_file() {
            true => Ok(exe),
            false => Err(format!("AXCHECK_CHROMIUM={} is not a file", exe.display())),
        };
    }
    let names = ["chromium", "chromium-browser", "google-chrome"];
    let path = std::env::var_os("PATH").unwrap_or_default();
    names
        .iter()
        .flat_map(|n| std::env::split_paths(&path).map(move |d| d.join(n)))
        .find(|p| p.is_file())
        .ok_or_else(|| {
            format!(
                "no browser found: AXCHECK_CHROMIUM is not set and none of {} is on PATH",
                names.join(", ")
            )
        })
}

impl Browser {
    /// Starts chromium with a fresh profile and connects to its browser-wide endpoint.
    pub fn launch() -> Result<Browser, String> {
        let exe = find_chromium()?;
        // Unique even for parallel tests in one process.
        static COUNT: AtomicUsize = AtomicUsize::new(0);
        let profile = std::env::temp_dir().join(format!(
            "axcheck-chromium-{}-{}",
            std::process::id(),
            COUNT.fetch_add(1, Ordering::Relaxed)
        ));
        let _ = std::fs::remove_dir_all(&profile);
        std::fs::create_dir_all(&profile).map_err(|e| format!("{}: {e}", profile.display()))?;
        let mut child = Command::new(&exe)
            .args([
                "--headless=new",
                "--no-sandbox", // we run as root in a container
                "--disable-gpu",
                "--no-first-run",
                "--no-default-browser-check",
                "--disable-extensions",
                "--disable-background-networking",
                "--disable-sync",
                "--disable-default-apps",
                "--mute-audio",
                "--remote-debugging-port=0", // the port is read from stderr
            ])
            .arg(format!("--user-data-dir={}", profile.display()))
            .arg("about:blank")
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(|e| format!("cannot start {}: {e}", exe.display()))?;
        // A thread forwards stderr lines until the endpoint shows, then keeps draining
        // them (sends fail once the receiver is gone) so chromium never blocks on a full pipe.
        let stderr = child.stderr.take().expect("stderr is piped");
        let (tx, rx) = mpsc::channel();
        std::thread::spawn(move || {
            for line in BufReader::new(stderr).lines().map_while(Result::ok) {
                let _ = tx.send(line);
            }
        });
        let deadline = Instant::now() + TIMEOUT;
        let mut seen = Vec::new();
        let url = loop {
            let left = deadline.saturating_duration_since(Instant::now());
            match rx.recv_timeout(left) {
                Ok(line) => match line.split_once("DevTools listening on ") {
                    Some((_, url)) => break url.trim().to_string(),
                    None => seen.push(line),
                },
                Err(e) => {
                    let _ = child.kill();
                    let status = child.wait().map(|s| s.to_string()).unwrap_or_default();
                    let _ = std::fs::remove_dir_all(&profile);
                    let why = match e {
                        mpsc::RecvTimeoutError::Timeout => format!("no endpoint after {TIMEOUT:?}"),
                        mpsc::RecvTimeoutError::Disconnected => format!("it exited ({status})"),
                    };
                    return Err(format!(
                        "{} did not open its DevTools endpoint: {why}; stderr:\n{}",
                        exe.display(),
                        seen.join("\n")
                    ));
                }
            }
        };
        let browser = |child, ws| Browser {
            child,
            ws,
            next_id: 0,
            target: String::new(),
            session: String::new(),
            console: Vec::new(),
            requests: Vec::new(),
            loaded: false,
            profile: profile.clone(),
        };
        match connect(&url) {
            Ok(ws) => Ok(browser(child, ws)),
            Err(e) => {
                let _ = child.kill();
                let _ = child.wait();
                let _ = std::fs::remove_dir_all(&profile);
                Err(e)
            }
        }
    }

    /// Opens `url` in a fresh page (the previous one is closed, the event log cleared) and
    /// waits for its load event. A fresh target keeps late events of the old page out.
    pub fn open(&mut self, url: &str) -> Result<(), String> {
        if !self.target.is_empty() {
            let target = std::mem::take(&mut self.target);
            self.browser_call("Target.closeTarget", json!({ "targetId": target }))?;
            self.session.clear();
        }
        let created = self.browser_call("Target.createTarget", json!({ "url": "about:blank" }))?;
        self.target = str_of(&created["targetId"]).to_string();
        let attach = json!({ "targetId": self.target, "flatten": true });
        let attached = self.browser_call("Target.attachToTarget", attach)?;
        self.session = str_of(&attached["sessionId"]).to_string();
        for domain in ["Page", "Runtime", "Log", "Network"] {
            self.call(&format!("{domain}.enable"), json!({}))?;
        }
        self.console.clear();
        self.requests.clear();
        self.loaded = false;
        let nav = self.call("Page.navigate", json!({ "url": url }))?;
        if let Some(err) = nav["errorText"].as_str() {
            return Err(format!("cannot open {url}: {err}"));
        }
        let deadline = Instant::now() + TIMEOUT;
        while !self.loaded {
            self.pump(deadline, &format!("the load event of {url}"))?;
        }
        Ok(())
    }

    /// Evaluates `expression` in the page (promises awaited) and returns its value as JSON
    /// (`undefined` becomes `null`). A thrown exception becomes `Err` with its text.
    pub fn eval(&mut self, expression: &str) -> Result<Value, String> {
        let params =
            json!({ "expression": expression, "returnByValue": true, "awaitPromise": true });
        let mut r = self.call("Runtime.evaluate", params)?;
        if let Some(ex) = r.get("exceptionDetails") {
            return Err(format!("{expression}: {}", exception_text(ex)));
        }
        Ok(r["result"]["value"].take())
    }

    /// Evaluates `expression` every 20 ms until it is truthy (then returns its value) or
    /// `timeout` passes. Polling also collects the page's events meanwhile.
    pub fn wait_for(&mut self, expression: &str, timeout: Duration) -> Result<Value, String> {
        let deadline = Instant::now() + timeout;
        loop {
            let v = self.eval(expression)?;
            if truthy(&v) {
                return Ok(v);
            }
            if Instant::now() >= deadline {
                return Err(format!("`{expression}` still {v} after {timeout:?}"));
            }
            std::thread::sleep(POLL);
        }
    }

    /// Clicks with real mouse events (press and release of the left button) at the centre of
    /// the first element matching `selector`, scrolled into view first, so hit-testing,
    /// focus and overlays behave as for a user.
    pub fn click(&mut self, selector: &str) -> Result<(), String> {
        let sel = Value::from(selector);
        let js = format!(
            "(() => {{ const e = document.querySelector({sel}); if (!e) return null;
               e.scrollIntoView({{block: 'center', inline: 'center'}});
               const r = e.getBoundingClientRect();
               return [r.left + r.width / 2, r.top + r.height / 2, r.width, r.height]; }})()"
        );
        let rect = self.eval(&js)?;
        let n = |i: usize| rect[i].as_f64().unwrap_or(0.0);
        if rect.is_null() {
            return Err(format!("click: no element matches {selector}"));
        }
        if n(2) <= 0.0 || n(3) <= 0.0 {
            return Err(format!("click: {selector} has no size (hidden?)"));
        }
        let (x, y) = (n(0), n(1));
        self.call(
            "Input.dispatchMouseEvent",
            json!({ "type": "mouseMoved", "x": x, "y": y }),
        )?;
        for kind in ["mousePressed", "mouseReleased"] {
            let ev = json!({ "type": kind, "x": x, "y": y, "button": "left", "clickCount": 1 });
            self.call("Input.dispatchMouseEvent", ev)?;
        }
        Ok(())
    }

    /// Types `text` into the focused element as the IME would (input events, no key events).
    pub fn type_text(&mut self, text: &str) -> Result<(), String> {
        self.call("Input.insertText", json!({ "text": text }))
            .map(drop)
    }

    /// Presses and releases one key: "Enter", "Tab", "Escape", "Backspace", "Delete",
    /// "Arrow{Up,Down,Left,Right}", "Home", "End", "PageUp", "PageDown", " ", or a single
    /// ASCII letter or digit. The virtual key code is what makes chromium run the default
    /// action (focus moves on Tab, forms submit on Enter).
    pub fn press_key(&mut self, key: &str) -> Result<(), String> {
        let (code, vk, text) = match key {
            "Enter" => ("Enter", 13, "\r"),
            "Tab" => ("Tab", 9, ""),
            "Escape" => ("Escape", 27, ""),
            "Backspace" => ("Backspace", 8, ""),
            "Delete" => ("Delete", 46, ""),
            "ArrowUp" => ("ArrowUp", 38, ""),
            "ArrowDown" => ("ArrowDown", 40, ""),
            "ArrowLeft" => ("ArrowLeft", 37, ""),
            "ArrowRight" => ("ArrowRight", 39, ""),
            "Home" => ("Home", 36, ""),
            "End" => ("End", 35, ""),
            "PageUp" => ("PageUp", 33, ""),
            "PageDown" => ("PageDown", 34, ""),
            " " => ("Space", 32, " "),
            _ => ("", 0, key),
        };
        let (code, vk) = match (code, key.as_bytes()) {
            ("", [c]) if c.is_ascii_alphabetic() => (
                format!("Key{}", c.to_ascii_uppercase() as char),
                c.to_ascii_uppercase(),
            ),
            ("", [c]) if c.is_ascii_digit() => (format!("Digit{}", *c as char), *c),
            ("", _) => return Err(format!("press_key: unknown key {key:?}")),
            (code, _) => (code.to_string(), vk),
        };
        let mut down = json!({ "type": "rawKeyDown", "key": key, "code": code,
            "windowsVirtualKeyCode": vk, "nativeVirtualKeyCode": vk });
        if !text.is_empty() {
            // A key with text is a "keyDown" so that it also produces keypress / input.
            down["type"] = "keyDown".into();
            down["text"] = text.into();
            down["unmodifiedText"] = text.into();
        }
        self.call("Input.dispatchKeyEvent", down)?;
        let up = json!({ "type": "keyUp", "key": key, "code": code,
            "windowsVirtualKeyCode": vk, "nativeVirtualKeyCode": vk });
        self.call("Input.dispatchKeyEvent", up).map(drop)
    }

    /// A PNG of the viewport, resized to `width` × `height` CSS pixels at scale 1 (the size
    /// stays set for later calls).
    pub fn screenshot_png(&mut self, width: u32, height: u32) -> Result<Vec<u8>, String> {
        let metrics =
            json!({ "width": width, "height": height, "deviceScaleFactor": 1, "mobile": false });
        self.call("Emulation.setDeviceMetricsOverride", metrics)?;
        let shot = self.call("Page.captureScreenshot", json!({ "format": "png" }))?;
        use base64::Engine;
        let png = base64::engine::general_purpose::STANDARD.decode(str_of(&shot["data"]));
        png.map_err(|e| format!("the screenshot's base64: {e}"))
    }

    /// Console errors and warnings, log errors and uncaught exceptions since `open`, in the
    /// order they came. Events are collected while a command waits, so call this after
    /// `open`/`eval`/`wait_for`, not expecting events that happened after the last one.
    pub fn console_errors(&self) -> Vec<String> {
        self.console.clone()
    }

    /// The URL of every request the page made since `open`, its own document and data:
    /// URLs included (the caller filters).
    pub fn requests(&self) -> Vec<String> {
        self.requests.clone()
    }

    /// Sends a command to the page's session and returns its result.
    fn call(&mut self, method: &str, params: Value) -> Result<Value, String> {
        let session = self.session.clone();
        self.send(method, params, Some(&session))
    }

    /// Sends a command to the browser itself (Target domain).
    fn browser_call(&mut self, method: &str, params: Value) -> Result<Value, String> {
        self.send(method, params, None)
    }

    fn send(
        &mut self,
        method: &str,
        params: Value,
        session: Option<&str>,
    ) -> Result<Value, String> {
        self.next_id += 1;
        let id = self.next_id;
        let mut msg = json!({ "id": id, "method": method, "params": params });
        if let Some(s) = session {
            msg["sessionId"] = s.into();
        }
        self.ws
            .send(Message::text(msg.to_string()))
            .map_err(|e| format!("{method}: cannot send: {e}"))?;
        let deadline = Instant::now() + TIMEOUT;
        loop {
            if let Some(mut reply) = self.pump(deadline, &format!("the answer to {method}"))?
                && reply["id"] == id
            {
                if let Some(err) = reply.get("error") {
                    return Err(format!("{method}: {}", err["message"]));
                }
                return Ok(reply["result"].take());
            }
        }
    }

    /// Reads one message (or nothing after a read slice): an event is logged and `None`
    /// returned; a reply is returned. Past `deadline`, fails naming `what`.
    fn pump(&mut self, deadline: Instant, what: &str) -> Result<Option<Value>, String> {
        if Instant::now() >= deadline {
            return Err(format!("timed out after {TIMEOUT:?} waiting for {what}"));
        }
        let text = match self.ws.read() {
            Ok(Message::Text(t)) => t,
            Ok(_) => return Ok(None), // ping/pong (answered by tungstenite), binary
            Err(tungstenite::Error::Io(e))
                if matches!(e.kind(), ErrorKind::WouldBlock | ErrorKind::TimedOut) =>
            {
                return Ok(None);
            }
            Err(e) => return Err(format!("connection lost waiting for {what}: {e}")),
        };
        let msg: Value = serde_json::from_str(&text).map_err(|e| format!("bad message: {e}"))?;
        if msg.get("id").is_some() {
            return Ok(Some(msg));
        }
        if msg["sessionId"] == self.session.as_str() {
            self.record(&msg["method"], &msg["params"]);
        }
        Ok(None)
    }

    /// Logs one event of the current page.
    fn record(&mut self, method: &Value, p: &Value) {
        match method.as_str().unwrap_or("") {
            "Page.loadEventFired" => self.loaded = true,
            "Network.requestWillBeSent" => self.requests.push(str_of(&p["request"]["url"]).into()),
            "Runtime.consoleAPICalled"
                if matches!(p["type"].as_str(), Some("error" | "warning")) =>
            {
                let args: Vec<String> = p["args"]
                    .as_array()
                    .into_iter()
                    .flatten()
                    .map(show)
                    .collect();
                self.console.push(format!(
                    "console.{}: {}",
                    str_of(&p["type"]),
                    args.join(" ")
                ));
            }
            "Log.entryAdded" if p["entry"]["level"] == "error" => {
                let e = &p["entry"];
                self.console.push(format!(
                    "log: {} ({})",
                    str_of(&e["text"]),
                    str_of(&e["url"])
                ));
            }
            "Runtime.exceptionThrown" => {
                let ex = &p["exceptionDetails"];
                self.console
                    .push(format!("uncaught: {}", exception_text(ex)));
            }
            _ => {}
        }
    }
}

/// Connects to the browser endpoint `ws://host:port/...` over a plain TCP stream whose
/// reads time out, so that no read blocks past a deadline.
fn connect(url: &str) -> Result<WebSocket<TcpStream>, String> {
    let host = url.strip_prefix("ws://").and_then(|r| r.split('/').next());
    let host = host.ok_or_else(|| format!("unexpected DevTools URL {url}"))?;
    let tcp = TcpStream::connect(host).map_err(|e| format!("cannot connect to {url}: {e}"))?;
    let _ = tcp.set_nodelay(true);
    tcp.set_read_timeout(Some(TIMEOUT))
        .map_err(|e| e.to_string())?;
    let (ws, _) =
        tungstenite::client(url, tcp).map_err(|e| format!("handshake with {url}: {e}"))?;
    ws.get_ref()
        .set_read_timeout(Some(READ_SLICE))
        .map_err(|e| e.to_string())?;
    Ok(ws)
}

impl Drop for Browser {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
        // Helper processes may still be closing files in the profile for a moment.
        for _ in 0..50 {
            if std::fs::remove_dir_all(&self.profile).is_ok() || !self.profile.exists() {
                break;
            }
            std::thread::sleep(POLL);
        }
    }
}

fn str_of(v: &Value) -> &str {
    v.as_str().unwrap_or("")
}

/// A console argument as the console shows it: a primitive's value, else its description.
fn show(arg: &Value) -> String {
    match &arg["value"] {
        Value::String(s) => s.clone(),
        Value::Null => arg["description"]
            .as_str()
            .unwrap_or(str_of(&arg["type"]))
            .to_string(),
        v => v.to_string(),
    }
}

/// An exception's message with its place, e.g. "Error: boom (file:///p.html:3:9)".
fn exception_text(ex: &Value) -> String {
    // The description is the message followed by the stack; the place is given below.
    let text = ex["exception"]["description"]
        .as_str()
        .unwrap_or(str_of(&ex["text"]));
    let text = text.lines().next().unwrap_or("");
    let line = ex["lineNumber"].as_u64().unwrap_or(0) + 1;
    let col = ex["columnNumber"].as_u64().unwrap_or(0) + 1;
    format!("{text} ({}:{line}:{col})", str_of(&ex["url"]))
}

/// JavaScript truthiness of a JSON value.
fn truthy(v: &Value) -> bool {
    match v {
        Value::Null => false,
        Value::Bool(b) => *b,
        Value::Number(n) => n.as_f64().is_some_and(|f| f != 0.0 && !f.is_nan()),
        Value::String(s) => !s.is_empty(),
        Value::Array(_) | Value::Object(_) => true,
    }
}
