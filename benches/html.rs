//! `cargo bench --bench html`: `summary.html` of a synthetic fleet (10 000 axes unless
//! `AXCHECK_BENCH_AXES` says otherwise) in headless Chromium, driven through its DevTools
//! protocol (the tests' client, `tests/it/browser/cdp.rs`). Measures the page's size, and
//! medians over 5 fresh page loads of:
//! - navigation → first rows in the document and their first frame (the page's own clock,
//!   `performance.now()`, whose origin is the navigation), and → the load event;
//! - typing a machine name in the search box → the filtered rows' next frame;
//! - sorting by E (largest first) → the next frame;
//! - clicking the first row → its detail with its two charts drawn.
//!
//! The fleet is made once by `axcheck simulate --fleet N --seed 1` in
//! `$TMPDIR/axcheck-html-bench-N` and run with `--no-pdf`. Prints a table and writes
//! `bench/html.md`. Needs `chromium` (or `AXCHECK_CHROMIUM`).

#[path = "../tests/it/browser/cdp.rs"]
mod cdp;

use serde_json::Value;
use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

const LOADS: usize = 5;

fn axcheck(args: &[&str]) {
    let out = Command::new(env!("CARGO_BIN_EXE_axcheck"))
        .args(args)
        .output()
        .expect("axcheck runs");
    // A fleet has failing axes: exit 1 is a normal run.
    if !matches!(out.status.code(), Some(0 | 1)) {
        panic!("axcheck {args:?}: {}", String::from_utf8_lossy(&out.stderr));
    }
}

fn median(mut xs: Vec<f64>) -> f64 {
    xs.sort_by(f64::total_cmp);
    xs[xs.len() / 2]
}

fn ms(v: Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a time: {v}"))
}

/// Runs `action` in the page and returns the milliseconds until the frame after it.
const AFTER_FRAME: &str = "new Promise(done => requestAnimationFrame(() => setTimeout(done)))";

fn timed(b: &mut cdp::Browser, action: &str) -> f64 {
    let js = format!(
        "(async () => {{ const t0 = performance.now(); {action}; await {AFTER_FRAME}; return performance.now() - t0; }})()"
    );
    ms(b.eval(&js).expect("timed action"))
}

struct Load {
    rows_ms: f64,
    frame_ms: f64,
    load_ms: f64,
    filter_ms: f64,
    sort_ms: f64,
    detail_ms: f64,
    wall_ms: f64,
}

fn one_load(b: &mut cdp::Browser, url: &str, machine: &str) -> Load {
    let start = Instant::now();
    b.open(url).expect("page opens");
    let wait = Duration::from_secs(20);
    b.wait_for("window.axcheckFirstFrameMs", wait)
        .expect("first rows");
    let wall_ms = start.elapsed().as_secs_f64() * 1e3;
    let rows_ms = ms(b.eval("window.axcheckFirstRowsMs").unwrap());
    let frame_ms = ms(b.eval("window.axcheckFirstFrameMs").unwrap());
    let load = "performance.getEntriesByType('navigation')[0].loadEventEnd";
    let load_ms = ms(b.wait_for(load, wait).unwrap());
    let search = format!(
        "const s = document.getElementById('search'); s.value = {}; s.dispatchEvent(new Event('input'))",
        Value::from(machine)
    );
    let filter_ms = timed(b, &search);
    let shown = b
        .eval("document.getElementById('shown-count').textContent")
        .unwrap();
    assert!(
        !shown.as_str().unwrap_or("").starts_with("0 of"),
        "{machine}: {shown}"
    );
    timed(
        b,
        "const s = document.getElementById('search'); s.value = ''; s.dispatchEvent(new Event('input'))",
    );
    let sort_ms = timed(
        b,
        "document.querySelector('button[data-column=\"E\"]').click()",
    );
    let open = "document.querySelector('#rows tr[data-test-id]').click(); \
        await new Promise(function wait(done) { document.querySelectorAll('#detail svg[role=img]').length >= 2 ? done() : setTimeout(() => wait(done), 5); })";
    let detail_ms = timed(b, open);
    let errors = b.console_errors();
    assert!(errors.is_empty(), "{errors:?}");
    Load {
        rows_ms,
        frame_ms,
        load_ms,
        filter_ms,
        sort_ms,
        detail_ms,
        wall_ms,
    }
}

fn main() {
    let axes: usize = std::env::var("AXCHECK_BENCH_AXES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(10_000);
    let dir = std::env::temp_dir().join(format!("axcheck-html-bench-{axes}"));
    let campaign = dir.join("campaign.yaml");
    if !campaign.is_file() {
        let n = axes.to_string();
        axcheck(&[
            "simulate",
            "--fleet",
            &n,
            "--seed",
            "1",
            "--out",
            dir.to_str().unwrap(),
        ]);
    }
    let out = dir.join("out");
    let started = Instant::now();
    axcheck(&[
        "run",
        campaign.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
    ]);
    let run_s = started.elapsed().as_secs_f64();
    let page = out.join("summary.html");
    let size_mb = std::fs::metadata(&page).expect("summary.html").len() as f64 / 1e6;
    let url = format!("file://{}", page.display());
    let machine = first_machine(&out);

    let mut b = cdp::Browser::launch().expect("chromium");
    // Warm-up load (the browser's own start-up, the file in the page cache).
    one_load(&mut b, &url, &machine);
    let loads: Vec<Load> = (0..LOADS)
        .map(|_| one_load(&mut b, &url, &machine))
        .collect();
    let m = |f: fn(&Load) -> f64| median(loads.iter().map(f).collect());
    let rows = [
        ("navigation → first rows in the document", m(|l| l.rows_ms)),
        ("navigation → first frame with rows", m(|l| l.frame_ms)),
        (
            "navigation → load event (all details parsed)",
            m(|l| l.load_ms),
        ),
        (
            "page opened as the driver sees it (wall time to the load event, CDP included)",
            m(|l| l.wall_ms),
        ),
        (
            &*format!("filter by a machine name ({machine}) → next frame"),
            m(|l| l.filter_ms),
        ),
        ("sort by E → next frame", m(|l| l.sort_ms)),
        (
            "open a row → its detail with both charts",
            m(|l| l.detail_ms),
        ),
    ]
    .map(|(what, t)| format!("| {what} | {t:.0} |"));
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let report = format!(
        "# summary.html benchmark\n\n\
         {axes} axis tests from `axcheck simulate --fleet {axes} --seed 1`, run with `--no-pdf` \
         ({run_s:.1} s); `summary.html` {size_mb:.1} MB. Headless Chromium ({}), {cores} cores, \
         {}; medians of {LOADS} fresh page loads after one warm-up.\n\n\
         | what | median (ms) |\n|---|---:|\n{}\n",
        chromium_version(),
        chrono::Utc::now().format("%Y-%m-%d"),
        rows.join("\n")
    );
    print!("{report}");
    let target = Path::new(env!("CARGO_MANIFEST_DIR")).join("bench/html.md");
    std::fs::write(target, report).expect("bench/html.md");
}

/// The first machine of the fleet's summary.csv (the name typed in the search box).
fn first_machine(out: &Path) -> String {
    let csv = std::fs::read_to_string(out.join("summary.csv")).expect("summary.csv");
    let row = csv.lines().nth(1).expect("a test");
    row.split(',').next().unwrap_or_default().to_string()
}

fn chromium_version() -> String {
    let exe = std::env::var("AXCHECK_CHROMIUM").unwrap_or_else(|_| "chromium".into());
    let out = Command::new(exe).arg("--version").output();
    let text = out.map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string());
    text.unwrap_or_else(|_| "version unknown".into())
}
