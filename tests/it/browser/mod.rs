//! Tests of the headless browser driver itself, on small hand-written pages, so that a
//! failure in a test of the generated HTML can be trusted to be about the HTML.

pub mod cdp;

use cdp::Browser;
use std::path::PathBuf;
use std::time::Duration;

/// A temporary folder of HTML pages, removed when dropped.
struct Pages(PathBuf);

impl Pages {
    fn new(name: &str) -> Pages {
        let dir = std::env::temp_dir().join(format!("axcheck-cdp-{}-{name}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        Pages(dir)
    }

    /// Writes `body` into `<file>.html` and returns its file:// URL.
    fn page(&self, file: &str, body: &str) -> String {
        let path = self.0.join(format!("{file}.html"));
        let html = format!(
            "<!doctype html><html><head><title>{file}</title></head><body>{body}</body></html>"
        );
        std::fs::write(&path, html).unwrap();
        format!("file://{}", path.display())
    }
}

impl Drop for Pages {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn launch() -> Browser {
    Browser::launch().unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn a_click_runs_the_pages_handler() {
    let pages = Pages::new("click");
    // Below the fold, so the click only lands if the element is scrolled into view.
    let url = pages.page(
        "click",
        r#"<div style="height: 3000px"></div>
        <button id="b" onclick="document.title = 'clicked ' + event.isTrusted">Go</button>"#,
    );
    let mut b = launch();
    b.open(&url).unwrap();
    assert_eq!(b.eval("document.title").unwrap(), "click");
    b.click("#b").unwrap();
    // isTrusted: a real input event, not a scripted one.
    assert_eq!(b.eval("document.title").unwrap(), "clicked true");
    let missing = b.click("#nothing").unwrap_err();
    assert!(missing.contains("#nothing"), "{missing}");
}

#[test]
fn typing_fills_the_focused_input_and_keys_reach_the_page() {
    let pages = Pages::new("type");
    let url = pages.page(
        "type",
        r#"<input id="i"><input id="j">
        <script>
          const i = document.getElementById('i');
          i.focus();
          i.addEventListener('keydown', e => {
            if (e.key === 'Enter') document.title = 'enter ' + i.value;
          });
        </script>"#,
    );
    let mut b = launch();
    b.open(&url).unwrap();
    b.type_text("M0042").unwrap();
    assert_eq!(
        b.eval("document.getElementById('i').value").unwrap(),
        "M0042"
    );
    b.press_key("Enter").unwrap();
    assert_eq!(b.eval("document.title").unwrap(), "enter M0042");
    // Tab's default action (moving the focus) runs too: the key events are real.
    b.press_key("Tab").unwrap();
    assert_eq!(b.eval("document.activeElement.id").unwrap(), "j");
    assert!(b.press_key("NoSuchKey").is_err());
}

#[test]
fn console_errors_and_uncaught_exceptions_are_reported_per_page() {
    let pages = Pages::new("console");
    let logged = pages.page(
        "logged",
        r#"<script>console.log('fine'); console.error('boom', 42)</script>"#,
    );
    let thrown = pages.page("thrown", "<script>\n\nthrow new Error('kaboom')</script>");
    let clean = pages.page(
        "clean",
        "<p>nothing wrong</p><script>console.log('fine')</script>",
    );
    let mut b = launch();
    b.open(&logged).unwrap();
    assert_eq!(b.console_errors(), ["console.error: boom 42"]);
    b.open(&thrown).unwrap();
    let errors = b.console_errors();
    assert_eq!(errors.len(), 1, "{errors:?}");
    // The line of the throw: the third line of the script, i.e. line 3 of the file.
    assert!(errors[0].contains("Error: kaboom"), "{errors:?}");
    assert!(errors[0].contains("thrown.html:3:"), "{errors:?}");
    b.open(&clean).unwrap();
    assert_eq!(b.console_errors(), Vec::<String>::new());
    // eval reports exceptions as errors too.
    let e = b.eval("null.x").unwrap_err();
    assert!(e.contains("TypeError"), "{e}");
}

#[test]
fn every_request_of_the_page_is_listed() {
    let pages = Pages::new("requests");
    let external = "http://127.0.0.1:9/x.png";
    // A 1×1 transparent GIF.
    let data = "data:image/gif;base64,R0lGODlhAQABAAAAACH5BAEAAAAALAAAAAABAAEAAAI=";
    let with_image = pages.page(
        "image",
        &format!(r#"<img src="{external}" alt=""><img src="{data}" alt="">"#),
    );
    let plain = pages.page("plain", "<p>self-contained</p>");
    let mut b = launch();
    b.open(&with_image).unwrap();
    let requests = b.requests();
    assert_eq!(requests, [with_image.as_str(), external, data]);
    // The failed load is also reported on the console (port 9 is even refused as unsafe).
    let errors = b.console_errors();
    assert!(errors.iter().any(|e| e.contains(external)), "{errors:?}");
    b.open(&plain).unwrap();
    assert_eq!(b.requests(), [plain]);
}

#[test]
fn a_screenshot_is_a_png_of_the_requested_size() {
    let pages = Pages::new("screenshot");
    let url = pages.page(
        "shot",
        r#"<div style="background: teal; height: 100px"></div>"#,
    );
    let mut b = launch();
    b.open(&url).unwrap();
    for (width, height) in [(320, 200), (1024, 768)] {
        let png = b.screenshot_png(width, height).unwrap();
        assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
        assert_eq!(&png[12..16], b"IHDR");
        let be = |r: std::ops::Range<usize>| u32::from_be_bytes(png[r].try_into().unwrap());
        assert_eq!((be(16..20), be(20..24)), (width, height));
    }
}

/// `wait_for` returns once the page reaches the state, and fails naming the expression.
#[test]
fn waiting_ends_when_the_page_gets_there_or_times_out() {
    let pages = Pages::new("wait");
    let url = pages.page(
        "wait",
        "<script>setTimeout(() => document.title = 'late', 200)</script>",
    );
    let mut b = launch();
    b.open(&url).unwrap();
    let title = "document.title === 'late' && document.title";
    assert_eq!(b.wait_for(title, Duration::from_secs(5)).unwrap(), "late");
    let never = b
        .wait_for("window.never", Duration::from_millis(100))
        .unwrap_err();
    assert!(never.contains("window.never"), "{never}");
}
