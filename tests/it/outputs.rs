//! Safe outputs (issue 7): a run killed at any moment leaves every output complete (the
//! previous run's or the new one's), stale temporary files of killed runs are removed by
//! the next run, and axcheck never replaces or deletes a file it did not write (the
//! folder's `.axcheck-outputs` manifest lists what it wrote).

use crate::common::{axcheck, copy_data, scratch};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

const MANIFEST: &str = ".axcheck-outputs";

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// Every regular file under `dir` by `/`-separated relative path, temporary files of
/// atomic writes (`.NAME.axcheck-tmp-PID`) apart.
#[derive(Debug, Default, Clone, PartialEq)]
struct Snapshot {
    files: BTreeMap<String, Vec<u8>>,
    temporaries: Vec<String>,
}

fn snapshot(dir: &Path) -> Snapshot {
    fn walk(root: &Path, dir: &Path, out: &mut Snapshot) {
        let Ok(list) = std::fs::read_dir(dir) else {
            return;
        };
        for item in list.flatten() {
            let path = item.path();
            let kind = item.file_type().unwrap();
            let rel = path
                .strip_prefix(root)
                .unwrap()
                .components()
                .map(|c| c.as_os_str().to_string_lossy().into_owned())
                .collect::<Vec<_>>()
                .join("/");
            if kind.is_dir() {
                walk(root, &path, out);
            } else if rel == axcheck::lock::LOCK_FILE {
                // A killed run leaves its lock file (the system released the lock); the
                // next run takes it over and removes it.
                continue;
            } else if rel.contains(".axcheck-tmp-") {
                out.temporaries.push(rel);
            } else if kind.is_file() {
                out.files.insert(rel, std::fs::read(&path).unwrap());
            }
        }
    }
    let mut out = Snapshot::default();
    walk(dir, dir, &mut out);
    out
}

/// Asserts that `bytes` is a complete, valid output of its format; `reference` is a
/// complete version of the same file (for the CSV header and row count).
#[cfg(unix)]
fn assert_complete(name: &str, bytes: &[u8], reference: &[u8]) {
    let text = || String::from_utf8_lossy(bytes);
    match Path::new(name).extension().and_then(|e| e.to_str()) {
        Some("json") => {
            let v: serde_json::Value = serde_json::from_slice(bytes)
                .unwrap_or_else(|e| panic!("{name} is not complete JSON: {e}"));
            assert!(v["axes"].is_array(), "{name}: no axes");
        }
        Some("csv") => {
            let want = String::from_utf8_lossy(reference);
            let got = text();
            assert_eq!(got.lines().next(), want.lines().next(), "{name}: header");
            assert_eq!(got.lines().count(), want.lines().count(), "{name}: rows");
            assert!(got.ends_with('\n'), "{name}: last row cut");
        }
        Some("xml") => {
            let t = text();
            assert!(t.starts_with("<?xml"), "{name}");
            assert!(t.trim_end().ends_with("</testsuites>"), "{name} is cut");
        }
        Some("pdf") => {
            assert!(bytes.starts_with(b"%PDF"), "{name}: no %PDF header");
            assert!(
                bytes.trim_ascii_end().ends_with(b"%%EOF"),
                "{name}: no %%EOF"
            );
            lopdf::Document::load_mem(bytes)
                .unwrap_or_else(|e| panic!("{name} does not load: {e}"));
        }
        Some("parquet") => {
            assert!(
                bytes.starts_with(b"PAR1") && bytes.ends_with(b"PAR1"),
                "{name}: not a whole parquet file"
            );
        }
        Some("md") => assert!(text().ends_with('\n') && bytes.len() > 100, "{name}"),
        Some("html") => {
            let t = text();
            assert!(t.starts_with("<!DOCTYPE html>"), "{name}");
            assert!(t.trim_end().ends_with("</html>"), "{name} is cut");
        }
        Some("xlsx") => {
            let book = zip::ZipArchive::new(std::io::Cursor::new(bytes))
                .unwrap_or_else(|e| panic!("{name} is not a whole archive: {e}"));
            assert!(book.index_for_name("xl/workbook.xml").is_some(), "{name}");
        }
        _ => {
            assert_eq!(name, MANIFEST, "unexpected output {name}");
            assert!(text().starts_with("# axcheck output manifest"), "{name}");
        }
    }
}

/// The manifest's entries (files and folders ending in `/`).
fn manifest_entries(dir: &Path) -> Vec<String> {
    std::fs::read_to_string(dir.join(MANIFEST))
        .unwrap()
        .lines()
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .map(str::to_string)
        .collect()
}

/// Runs a campaign to completion: (exit code, stdout + stderr).
fn run(campaign: &Path, out: &Path, extra: &[&str]) -> (i32, String) {
    let mut args = vec!["run", s(campaign), "--out", s(out)];
    args.extend_from_slice(extra);
    let (code, stdout, stderr) = axcheck(&args);
    (code, format!("{stdout}{stderr}"))
}

/// When to kill a run.
#[cfg(unix)]
#[derive(Debug, Clone, Copy)]
enum Kill {
    /// This long after the start (usually while evaluating or typesetting).
    After(std::time::Duration),
    /// This long after the run started writing (its manifest was replaced).
    AfterWriting(std::time::Duration),
}

/// Starts `axcheck run` and kills it (SIGKILL) at `when`; true when it was killed,
/// false when it had finished first.
#[cfg(unix)]
fn run_and_kill(campaign: &Path, out: &Path, when: Kill) -> bool {
    use std::os::unix::fs::MetadataExt;
    use std::time::{Duration, Instant};
    let inode = || std::fs::metadata(out.join(MANIFEST)).map(|m| m.ino()).ok();
    let before = inode();
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_axcheck"))
        .args(["run", s(campaign), "--out", s(out), "--jobs", "2"])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let start = Instant::now();
    // A safety net against a run that never starts writing, not a timing assertion.
    let deadline = start + Duration::from_secs(120);
    let delay = loop {
        if child.try_wait().unwrap().is_some() {
            return false;
        }
        match when {
            Kill::After(d) if start.elapsed() >= d => break Duration::ZERO,
            Kill::AfterWriting(d) if inode() != before => break d,
            _ if Instant::now() > deadline => break Duration::ZERO,
            _ => std::thread::sleep(Duration::from_micros(200)),
        }
    };
    std::thread::sleep(delay);
    let killed = child.kill().is_ok();
    let status = child.wait().unwrap();
    killed && !status.success() && status.code().is_none()
}

/// A run killed (SIGKILL) at several moments, before and while it writes, alternating
/// between two campaigns whose outputs differ in every file: after each kill every output
/// is complete and valid, and byte-identical either to what the folder held before that
/// run or to the complete outputs of the new one (the manifest may also be the run's own
/// while it writes, which says `complete: false`). Stale temporary files are removed by
/// the next run.
#[cfg(unix)]
#[test]
fn a_run_killed_at_any_moment_leaves_complete_outputs() {
    use std::time::Duration;
    let dir = scratch("outputs-kill");
    let fleet = dir.join("fleet");
    let (code, _, stderr) = axcheck(&[
        "simulate",
        "--fleet",
        "8",
        "--seed",
        "7",
        "--out",
        s(&fleet),
    ]);
    assert_eq!(code, 0, "{stderr}");
    let a = fleet.join("campaign.yaml");
    let b = fleet.join("second.yaml");
    let yaml = std::fs::read_to_string(&a).unwrap();
    let second = yaml
        .replace("date: 2026-11-20", "date: 2026-11-21, inspector: B. Second")
        .replace("spec: general}", "spec: precision}");
    assert!(
        second.contains("B. Second") && second.contains("precision"),
        "{yaml}"
    );
    std::fs::write(&b, second).unwrap();

    // The complete outputs of each campaign: A's in the folder under test, B's beside it.
    let complete = |campaign: &Path, out: &Path| {
        let (code, log) = run(campaign, out, &["--jobs", "2"]);
        assert!(code == 0 || code == 1, "{log}");
        snapshot(out)
    };
    let out = dir.join("out");
    let ref_a = complete(&a, &out);
    let ref_b = complete(&b, &dir.join("ref-b"));
    assert_eq!(
        ref_a.files.keys().collect::<Vec<_>>(),
        ref_b.files.keys().collect::<Vec<_>>()
    );
    assert!(ref_a.files.keys().any(|k| k.starts_with("reports/")));
    for (name, bytes) in &ref_a.files {
        if name != MANIFEST {
            assert_ne!(
                bytes, &ref_b.files[name],
                "{name} must differ between A and B"
            );
        }
    }

    let kills = [
        Kill::After(Duration::from_millis(150)),
        Kill::AfterWriting(Duration::ZERO),
        Kill::AfterWriting(Duration::from_millis(3)),
        Kill::AfterWriting(Duration::from_millis(10)),
        Kill::AfterWriting(Duration::from_millis(25)),
        Kill::AfterWriting(Duration::from_millis(60)),
    ];
    let mut temporaries_seen = 0;
    for (k, when) in kills.into_iter().enumerate() {
        let (campaign, new) = if k % 2 == 0 {
            (&b, &ref_b)
        } else {
            (&a, &ref_a)
        };
        let before = snapshot(&out);
        let killed = run_and_kill(campaign, &out, when);
        let after = snapshot(&out);
        assert_eq!(
            after.files.keys().collect::<Vec<_>>(),
            new.files.keys().collect::<Vec<_>>(),
            "kill {k} ({when:?}): the set of outputs changed"
        );
        let mut fresh = 0;
        for (name, bytes) in &after.files {
            assert_complete(name, bytes, &new.files[name]);
            let previous = before.files.get(name);
            if name == MANIFEST && bytes != &new.files[name] && Some(bytes) != previous {
                // Killed while writing: the manifest lists the same files and says so.
                let new = String::from_utf8_lossy(&new.files[name]);
                let writing = new.replace("\n# complete: true\n", "\n# complete: false\n");
                assert_eq!(
                    String::from_utf8_lossy(bytes),
                    writing,
                    "kill {k} ({when:?})"
                );
                continue;
            }
            if bytes == &new.files[name] {
                fresh += 1;
            } else {
                assert_eq!(
                    bytes, &before.files[name],
                    "kill {k} ({when:?}): {name} is neither the previous nor the new output"
                );
            }
        }
        for t in &after.temporaries {
            let name = t.rsplit('/').next().unwrap();
            assert!(name.starts_with('.'), "{t}: temporary files are hidden");
        }
        temporaries_seen += after.temporaries.len();
        eprintln!(
            "kill {k} ({when:?}): killed {killed}, {fresh} of {} files new, {} temporary files left",
            after.files.len(),
            after.temporaries.len()
        );
    }

    // A complete run after the kills: exactly A's outputs, no temporary file left.
    let (code, log) = run(&a, &out, &["--jobs", "2"]);
    assert!(code == 0 || code == 1, "{log}");
    let last = snapshot(&out);
    assert_eq!(last.files, ref_a.files);
    assert!(last.temporaries.is_empty(), "{:?}", last.temporaries);
    assert!(
        !out.join(axcheck::lock::LOCK_FILE).exists(),
        "the lock file is taken over and removed"
    );
    eprintln!("{temporaries_seen} temporary files left by kills, removed by the next run");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A small campaign of two machines (both with ISO 230-2's Table 2, which passes) in `dir`.
fn small_campaign(dir: &Path) -> PathBuf {
    copy_data(dir, "iso230-2_table2.csv");
    let campaign = dir.join("campaign.yaml");
    std::fs::write(
        &campaign,
        "campaign: {name: Outputs, date: 2026-11-20, spec: general}\nmachines:\n  - id: M1\n    axes:\n      - {name: X, kind: linear, data: data/iso230-2_table2.csv}\n  - id: M2\n    axes:\n      - {name: Z, kind: linear, data: data/iso230-2_table2.csv}\n",
    )
    .unwrap();
    campaign
}

/// Temporary files that killed runs left beside axcheck's outputs (in the folder and in
/// reports/MACHINE/, and the manifest's own) are removed by the next run; files that only
/// look alike (another name, no leading dot, a process that still runs) stay.
#[test]
fn the_next_run_removes_stale_temporary_files() {
    let dir = scratch("outputs-temps");
    let campaign = small_campaign(&dir);
    let out = dir.join("out");
    let (code, log) = run(&campaign, &out, &[]);
    assert_eq!(code, 0, "{log}");
    let reference = snapshot(&out);
    // Process ids above Linux's largest pid_max (2^22) never run.
    let stale = [
        ".summary.csv.axcheck-tmp-4194305",
        ".results.json.axcheck-tmp-4194306",
        "reports/M1/.X.pdf.axcheck-tmp-4194307",
        "..axcheck-outputs.axcheck-tmp-4194308",
    ];
    let mut keep = vec![
        ".notes.txt.axcheck-tmp-4194309".to_string(),
        "summary.csv.axcheck-tmp-4194310".to_string(),
        "reports/M1/.X.pdf.axcheck-tmp-abc".to_string(),
    ];
    // A process that still runs (this test) may be writing: its file stays (Linux, where
    // axcheck can tell from /proc).
    if cfg!(target_os = "linux") {
        keep.push(format!(".summary.pdf.axcheck-tmp-{}", std::process::id()));
    }
    for name in stale.iter().copied().chain(keep.iter().map(String::as_str)) {
        std::fs::write(out.join(name), b"partial").unwrap();
    }
    let (code, log) = run(&campaign, &out, &[]);
    assert_eq!(code, 0, "{log}");
    for name in stale {
        assert!(!out.join(name).exists(), "{name} was not removed");
    }
    for name in &keep {
        assert_eq!(std::fs::read(out.join(name)).unwrap(), b"partial", "{name}");
    }
    assert_eq!(snapshot(&out).files, reference.files);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A first run into a folder that does not exist or is empty works, and so does a re-run
/// into its own folder; the manifest lists exactly the outputs (and the folders axcheck
/// made), and the same input gives the same bytes.
#[test]
fn first_runs_and_reruns_work() {
    let dir = scratch("outputs-first");
    let campaign = small_campaign(&dir);
    let fresh = dir.join("fresh/out");
    let (code, log) = run(&campaign, &fresh, &[]);
    assert_eq!(code, 0, "{log}");
    let empty = dir.join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    let (code, log) = run(&campaign, &empty, &[]);
    assert_eq!(code, 0, "{log}");
    let first = snapshot(&fresh);
    assert_eq!(snapshot(&empty).files, first.files);
    let outputs: Vec<&String> = first.files.keys().filter(|k| *k != MANIFEST).collect();
    assert_eq!(outputs.len(), 10, "{outputs:?}");
    let mut expected: Vec<String> = outputs.iter().map(|s| s.to_string()).collect();
    expected.extend(["reports/", "reports/M1/", "reports/M2/"].map(String::from));
    expected.sort();
    assert_eq!(manifest_entries(&fresh), expected);
    let (code, log) = run(&campaign, &fresh, &[]);
    assert_eq!(code, 0, "{log}");
    assert_eq!(snapshot(&fresh), first);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A `summary.csv` that axcheck did not write is refused with exit 2 and a message naming
/// it and what to do; nothing is written (no manifest, no other output) and it is intact.
#[test]
fn a_foreign_file_at_an_output_path_is_refused_before_anything_is_written() {
    let dir = scratch("outputs-foreign");
    let campaign = small_campaign(&dir);
    let out = dir.join("out");
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(out.join("summary.csv"), "my own table\n").unwrap();
    std::fs::write(out.join("notes.txt"), "mine\n").unwrap();
    let before = snapshot(&out);
    let (code, stdout, stderr) = axcheck(&["run", s(&campaign), "--out", s(&out)]);
    assert_eq!(code, 2, "{stdout}{stderr}");
    let csv = out.join("summary.csv");
    assert!(
        stderr.contains(&format!(
            "{} already exists and was not written by axcheck",
            csv.display()
        )) && stderr.contains("remove or move it, or choose another --out"),
        "{stderr}"
    );
    assert_eq!(snapshot(&out), before, "nothing written, nothing removed");
    assert!(!out.join(MANIFEST).exists());

    // With a manifest from an earlier run without PDFs, a user's summary.pdf is refused
    // too: the PDFs are checked before any table is replaced.
    std::fs::remove_file(&csv).unwrap();
    let (code, log) = run(&campaign, &out, &["--no-pdf"]);
    assert_eq!(code, 0, "{log}");
    std::fs::write(out.join("summary.pdf"), "my own pdf").unwrap();
    std::fs::write(
        &campaign,
        std::fs::read_to_string(&campaign)
            .unwrap()
            .replace("2026-11-20", "2026-11-21"),
    )
    .unwrap();
    let before = snapshot(&out);
    let (code, stdout, stderr) = axcheck(&["run", s(&campaign), "--out", s(&out)]);
    assert_eq!(code, 2, "{stdout}{stderr}");
    assert!(stderr.contains("summary.pdf already exists"), "{stderr}");
    assert_eq!(snapshot(&out), before, "nothing written, nothing removed");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A user's files in the output folder (beside the outputs, in a folder axcheck writes
/// into, in a folder of their own) are left alone by every run.
#[test]
fn a_users_other_files_are_left_alone() {
    let dir = scratch("outputs-user");
    let campaign = small_campaign(&dir);
    let out = dir.join("out");
    let (code, log) = run(&campaign, &out, &[]);
    assert_eq!(code, 0, "{log}");
    let mine = ["notes.txt", "reports/M1/remarks.txt", "archive/summary.csv"];
    for name in mine {
        std::fs::create_dir_all(out.join(name).parent().unwrap()).unwrap();
        std::fs::write(out.join(name), name).unwrap();
    }
    for extra in [&[][..], &["--no-pdf"][..], &[][..]] {
        let (code, log) = run(&campaign, &out, extra);
        assert_eq!(code, 0, "{log}");
        for name in mine {
            assert_eq!(std::fs::read_to_string(out.join(name)).unwrap(), name);
        }
        assert!(
            !manifest_entries(&out)
                .iter()
                .any(|e| mine.contains(&e.as_str()))
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Outputs of the previous run that this run no longer produces (an axis taken out of the
/// campaign; the PDFs after --no-pdf) were axcheck's: they are removed, with the folders
/// axcheck made for them when nothing else is in them, so the folder holds exactly the
/// last run's outputs.
#[test]
fn outputs_the_new_run_no_longer_produces_are_removed() {
    let dir = scratch("outputs-stale");
    let campaign = small_campaign(&dir);
    let out = dir.join("out");
    let (code, log) = run(&campaign, &out, &[]);
    assert_eq!(code, 0, "{log}");
    assert!(out.join("reports/M2/Z.pdf").exists());
    std::fs::write(out.join("reports/M1/remarks.txt"), "mine").unwrap();
    let yaml = std::fs::read_to_string(&campaign).unwrap();
    let without_m2 = &yaml[..yaml.find("  - id: M2").unwrap()];
    std::fs::write(&campaign, without_m2).unwrap();
    let (code, log) = run(&campaign, &out, &[]);
    assert_eq!(code, 0, "{log}");
    assert!(
        !out.join("reports/M2").exists(),
        "M2's report and folder removed"
    );
    assert!(out.join("reports/M1/X.pdf").exists());
    // Without PDFs: every PDF goes; reports/M1 stays for the user's file.
    let (code, log) = run(&campaign, &out, &["--no-pdf"]);
    assert_eq!(code, 0, "{log}");
    assert!(!out.join("summary.pdf").exists() && !out.join("reports/M1/X.pdf").exists());
    assert_eq!(
        std::fs::read_to_string(out.join("reports/M1/remarks.txt")).unwrap(),
        "mine"
    );
    assert_eq!(
        manifest_entries(&out),
        [
            "junit.xml",
            "results.json",
            "summary.csv",
            "summary.html",
            "summary.md",
            "summary.parquet",
            "summary.xlsx"
        ]
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A manifest is trusted only for paths inside the folder: one that lists `../victim` is
/// refused (exit 2) and the victim stays; a folder on an output path that is a symbolic
/// link is refused rather than written through.
#[test]
fn a_tampered_manifest_or_a_link_in_the_way_is_refused() {
    let dir = scratch("outputs-tampered");
    let campaign = small_campaign(&dir);
    let out = dir.join("out");
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(dir.join("victim.txt"), "precious").unwrap();
    std::fs::write(
        out.join(MANIFEST),
        "# axcheck output manifest\nresults.json\n../victim.txt\n",
    )
    .unwrap();
    let (code, stdout, stderr) = axcheck(&["run", s(&campaign), "--out", s(&out)]);
    assert_eq!(code, 2, "{stdout}{stderr}");
    assert!(
        stderr.contains("is not a valid axcheck output manifest (line 3"),
        "{stderr}"
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("victim.txt")).unwrap(),
        "precious"
    );
    assert!(!out.join("results.json").exists());
    #[cfg(unix)]
    {
        std::fs::remove_file(out.join(MANIFEST)).unwrap();
        let elsewhere = dir.join("elsewhere");
        std::fs::create_dir_all(&elsewhere).unwrap();
        std::os::unix::fs::symlink(&elsewhere, out.join("reports")).unwrap();
        let (code, stdout, stderr) = axcheck(&["run", s(&campaign), "--out", s(&out)]);
        assert_eq!(code, 2, "{stdout}{stderr}");
        assert!(stderr.contains("is a symbolic link"), "{stderr}");
        assert_eq!(std::fs::read_dir(&elsewhere).unwrap().count(), 0);
        assert!(!out.join("results.json").exists());
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A write that fails (issue 42: a full disk; here, deterministically, a file-size limit of
/// the process, `ulimit -f`, which the kernel enforces with EFBIG as it does a full disk)
/// leaves the other outputs written, removes the older copies of the missing ones, marks the
/// manifest `complete: false` with each missing output, and `run` names them and exits 2.
/// The next run without the limit completes the folder again.
#[test]
fn a_failed_write_marks_the_folder_incomplete_and_names_what_is_missing() {
    let dir = scratch("outputs-incomplete");
    let campaign = small_campaign(&dir);
    let out = dir.join("out");
    let (code, log) = run(&campaign, &out, &[]);
    assert_eq!(code, 0, "{log}");
    let complete = snapshot(&out);
    assert!(
        std::fs::read_to_string(out.join(MANIFEST))
            .unwrap()
            .contains("\n# complete: true\n")
    );
    // The limit in KiB: below the three largest outputs, above the others.
    let mut sizes: Vec<(usize, &String)> = (complete.files.iter())
        .map(|(name, bytes)| (bytes.len(), name))
        .collect();
    sizes.sort();
    let limit_kib = sizes[sizes.len() - 4].0 / 1024 + 1;
    let too_big: Vec<&String> = (sizes.iter())
        .filter(|(n, _)| *n > limit_kib * 1024)
        .map(|(_, name)| *name)
        .collect();
    assert_eq!(too_big.len(), 3, "{sizes:?}");

    let limited = std::process::Command::new("bash")
        .args([
            "-c",
            "trap '' XFSZ; ulimit -f \"$1\"; shift; exec \"$@\"",
            "bash",
        ])
        .arg(limit_kib.to_string())
        .arg(env!("CARGO_BIN_EXE_axcheck"))
        .args(["run", s(&campaign), "--out", s(&out)])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&limited.stderr);
    assert_eq!(limited.status.code(), Some(2), "{stderr}");
    let total = complete.files.len() - 1;
    assert!(
        stderr.contains(&format!(
            "the outputs are incomplete: {} of {total} written; missing: ",
            total - 3
        )),
        "{stderr}"
    );
    let manifest = std::fs::read_to_string(out.join(MANIFEST)).unwrap();
    assert!(manifest.contains("\n# complete: false\n"), "{manifest}");
    let after = snapshot(&out);
    for name in &too_big {
        assert!(stderr.contains(name.as_str()), "{name}: {stderr}");
        assert!(
            manifest.contains(&format!("\n# missing: {name}\n")),
            "{manifest}"
        );
        assert!(
            !after.files.contains_key(*name),
            "{name}: the older copy is removed"
        );
        assert!(
            !manifest_entries(&out).contains(name),
            "{name} listed as written"
        );
    }
    assert!(after.temporaries.is_empty(), "{:?}", after.temporaries);
    assert_eq!(after.files.len(), complete.files.len() - 3);
    for (name, bytes) in &after.files {
        if name != MANIFEST {
            assert_eq!(bytes, &complete.files[name], "{name}");
        }
    }

    let (code, log) = run(&campaign, &out, &[]);
    assert_eq!(code, 0, "{log}");
    assert_eq!(snapshot(&out), complete);
    std::fs::remove_dir_all(&dir).unwrap();
}
