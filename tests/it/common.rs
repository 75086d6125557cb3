//! Helpers shared by the integration tests.

use axcheck::measurement::{self, AxisData};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

pub fn data_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

pub fn load(name: &str) -> AxisData {
    measurement::read_file(&data_path(name), None)
        .map(|t| t.data)
        .unwrap_or_else(|e| panic!("{e}"))
}

pub fn assert_close(what: &str, got: f64, want: f64, tol: f64) {
    assert!(
        (got - want).abs() <= tol,
        "{what}: got {got}, want {want} ± {tol}"
    );
}

/// Runs the `axcheck` binary from the crate folder: (exit code, stdout, stderr).
pub fn axcheck(args: &[&str]) -> (i32, String, String) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_axcheck"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("axcheck runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// A fresh folder for one test, with an empty `data/` inside.
pub fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("axcheck-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("data")).unwrap();
    dir
}

/// The campaign at `path` evaluated as `run` evaluates it (compensation tables and
/// verifications, readings kept), with or without the diagnosis, on two workers.
pub fn run_campaign(path: &std::path::Path, diagnose: bool) -> axcheck::results::CampaignResult {
    let campaign = axcheck::campaign::Campaign::load(path).unwrap();
    let options = axcheck::batch::BatchOptions {
        diagnose,
        drop_data: false,
        compensate: true,
        record_inputs: true,
    };
    axcheck::batch::run(&campaign, options, &|_| {})
}

/// Copies `tests/data/NAME` into `DIR/data/NAME`.
pub fn copy_data(dir: &std::path::Path, name: &str) {
    std::fs::copy(data_path(name), dir.join("data").join(name)).unwrap();
}

/// The text of `pdf` as `pdftotext -layout` gives it (pages end in form feeds).
pub fn pdftotext_layout(pdf: &std::path::Path) -> String {
    let out = std::process::Command::new("pdftotext")
        .arg("-layout")
        .arg(pdf)
        .arg("-")
        .output()
        .expect("pdftotext runs (.ci/test installs poppler-utils)");
    assert!(out.status.success(), "pdftotext {}", pdf.display());
    String::from_utf8(out.stdout).unwrap()
}

/// The text of a PDF's pages, in order.
pub fn pdf_text(path: &std::path::Path) -> String {
    let doc = lopdf::Document::load(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let pages: Vec<u32> = doc.get_pages().keys().copied().collect();
    doc.extract_text(&pages).unwrap()
}

/// Runs `body` while another thread calls `swap` over and over (a race with whoever can
/// write a folder), from the first swap on. The swapping stops when `body` returns, and also
/// when it fails: the scope waits for the thread before it lets the failure through.
#[cfg(unix)]
pub fn while_swapping<T>(mut swap: impl FnMut() + Send, body: impl FnOnce() -> T) -> T {
    use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
    struct StopOnDrop<'a>(&'a AtomicBool);
    impl Drop for StopOnDrop<'_> {
        fn drop(&mut self) {
            self.0.store(true, Ordering::Relaxed);
        }
    }
    let (stop, swaps) = (AtomicBool::new(false), AtomicUsize::new(0));
    std::thread::scope(|scope| {
        scope.spawn(|| {
            while !stop.load(Ordering::Relaxed) {
                swap();
                swaps.fetch_add(1, Ordering::Relaxed);
            }
        });
        let _stop = StopOnDrop(&stop);
        while swaps.load(Ordering::Relaxed) == 0 {
            std::thread::yield_now();
        }
        body()
    })
}

/// Copies the folder `from` with everything in it to `to`.
pub fn copy_tree(from: &std::path::Path, to: &std::path::Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let entry = entry.unwrap();
        let target = to.join(entry.file_name());
        if entry.file_type().unwrap().is_dir() {
            copy_tree(&entry.path(), &target);
        } else {
            std::fs::copy(entry.path(), target).unwrap();
        }
    }
}

/// How long a spawned run may take before a test calls it blocked.
pub const DEADLINE: Duration = Duration::from_secs(120);

/// Starts `axcheck ARGS` in the crate folder, its output piped.
pub fn spawn(args: &[&str]) -> Child {
    Command::new(env!("CARGO_BIN_EXE_axcheck"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("axcheck starts")
}

/// Waits for `child` until `limit`, then kills it and fails: (exit code, stdout, stderr).
pub fn finish(mut child: Child, limit: Duration) -> (i32, String, String) {
    let pipe = |mut r: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut text = String::new();
            let _ = r.read_to_string(&mut text);
            text
        })
    };
    let stdout = pipe(Box::new(child.stdout.take().unwrap()));
    let stderr = pipe(Box::new(child.stderr.take().unwrap()));
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            panic!("axcheck did not finish within {limit:?}: it blocks");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let (stdout, stderr) = (stdout.join().unwrap(), stderr.join().unwrap());
    (status.code().unwrap_or(-1), stdout, stderr)
}

/// A small campaign in `dir` (one good axis) for the lock and race tests.
pub fn small_campaign(dir: &Path) -> PathBuf {
    std::fs::copy(data_path("iso230-2_table2.csv"), dir.join("data/good.csv")).unwrap();
    let yaml = "campaign: {name: L, date: 2026-11-20, unjudged: allowed}\nmachines:\n  - id: M\n    axes:\n      - {name: X, kind: linear, data: data/good.csv}\n";
    let campaign = dir.join("campaign.yaml");
    std::fs::write(&campaign, yaml).unwrap();
    campaign
}

/// `run CAMPAIGN --out OUT --no-pdf --no-diagnose EXTRA…`.
pub fn run_args<'a>(campaign: &'a Path, out: &'a Path, extra: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec![
        "run",
        campaign.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
        "--no-diagnose",
    ];
    args.extend_from_slice(extra);
    args
}
