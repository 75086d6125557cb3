//! The file-system rules where Windows differs from Linux, run on every platform and under
//! Wine in CI (`.ci/windows`): paths written with `\\` or `/`, drive letters, reserved
//! device names and names that differ only in case as machine and axis names, the folder
//! lock (held, waited for, taken over from a killed run) and outputs replaced in place.

use crate::common::{DEADLINE, data_path, finish, run_args, scratch, small_campaign, spawn};
use axcheck::lock::{FolderLock, LOCK_FILE};
use std::io::BufRead;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// `axcheck ARGS` with the deadline.
fn axcheck(args: &[&str]) -> (i32, String, String) {
    finish(spawn(args), DEADLINE)
}

/// A released lock: the lock file removed (unix), or left empty (Windows, where a file
/// another process may hold open is not removed), so no run takes it over.
fn assert_released(dir: &Path) {
    let lock = dir.join(LOCK_FILE);
    if cfg!(windows) {
        let text = std::fs::read(&lock).unwrap();
        assert!(text.is_empty(), "{}", String::from_utf8_lossy(&text));
    } else {
        assert!(!lock.exists(), "the lock file is removed after the run");
    }
}

/// The manifest's lines that name outputs (not its comments).
fn manifest_entries(out: &Path) -> Vec<String> {
    let text = std::fs::read_to_string(out.join(axcheck::atomic::MANIFEST)).unwrap();
    text.lines()
        .filter(|l| !l.starts_with('#'))
        .map(str::to_string)
        .collect()
}

/// A campaign of one machine with a controller (so each axis writes a compensation
/// table) and the axes `(name, data)` given, in `dir`.
fn campaign_with(dir: &Path, machines: &[(&str, &[(&str, &str)])]) -> PathBuf {
    let mut yaml =
        String::from("campaign: {name: W, date: 2026-11-20, unjudged: allowed}\nmachines:\n");
    for (machine, axes) in machines {
        yaml.push_str(&format!(
            "  - id: \"{machine}\"\n    controller: siemens-840d\n    axes:\n"
        ));
        for (axis, data) in *axes {
            yaml.push_str(&format!(
                "      - {{name: \"{axis}\", kind: linear, data: '{data}', compensation: {{axis: X1}}}}\n"
            ));
        }
    }
    let campaign = dir.join("campaign.yaml");
    std::fs::write(&campaign, yaml).unwrap();
    campaign
}

/// The run that failed on Windows: the exporters join output paths with `\\`, which the
/// output folder's check refused ("not a relative path inside the output folder"), so
/// nothing was written. Now every output is written, the manifest lists them with `/` on
/// every platform, and a second run replaces them.
#[test]
fn a_run_writes_its_outputs_with_the_platform_separator() {
    let dir = scratch("win-separator");
    let campaign = small_campaign(&dir);
    std::fs::write(
        &campaign,
        std::fs::read_to_string(&campaign)
            .unwrap()
            .replace("  - id: M\n", "  - id: M\n    controller: siemens-840d\n"),
    )
    .unwrap();
    let out = dir.join("out");
    for round in 0..2 {
        let (code, stdout, stderr) = axcheck(&run_args(&campaign, &out, &["--no-html"]));
        assert_eq!(code, 0, "round {round}: {stdout}{stderr}");
        let entries = manifest_entries(&out);
        for want in [
            "compensation/",
            "compensation/M/",
            "compensation/M/X.ini",
            "results.json",
        ] {
            assert!(entries.iter().any(|e| e == want), "{want}: {entries:?}");
        }
        assert!(entries.iter().all(|e| !e.contains('\\')), "{entries:?}");
    }
    let ini = std::fs::read_to_string(out.join("compensation").join("M").join("X.ini")).unwrap();
    assert!(ini.contains("X1"), "{ini}");
    std::fs::remove_dir_all(dir).unwrap();
}

/// A second run on a folder that another run holds stops at once with who holds it
/// (exit 2), or with `--wait` waits for it and then writes; a history folder is held
/// the same way.
#[test]
fn a_held_output_folder_stops_a_second_run_or_makes_it_wait() {
    let dir = scratch("hostile-lock");
    let campaign = small_campaign(&dir);
    let out = dir.join("out");
    let held = FolderLock::acquire(&out, false, |_| {}).unwrap();
    let start = Instant::now();
    let (code, stdout, stderr) = axcheck(&run_args(&campaign, &out, &[]));
    assert_eq!(code, 2, "{stdout}{stderr}");
    assert!(start.elapsed() < Duration::from_secs(30), "stops at once");
    let want = format!("another axcheck run (pid {}, started ", std::process::id());
    assert!(stderr.contains(&want), "{stderr}");
    assert!(
        stderr.contains(&format!(") is writing to {}", out.display())),
        "{stderr}"
    );
    assert!(stderr.contains("run again with --wait"), "{stderr}");
    assert!(!stderr.contains("was not written by axcheck"), "{stderr}");
    assert!(!out.join("results.json").exists());

    // --wait: the run waits while the folder is held, then writes.
    let mut waiting = spawn(&run_args(&campaign, &out, &["--wait"]));
    let mut first_line = String::new();
    std::io::BufReader::new(waiting.stderr.as_mut().unwrap())
        .read_line(&mut first_line)
        .unwrap();
    assert!(
        first_line.contains("is writing to")
            && first_line.contains("waiting for it to finish (--wait)"),
        "{first_line}"
    );
    std::thread::sleep(Duration::from_millis(300));
    assert!(
        waiting.try_wait().unwrap().is_none(),
        "still waiting while the folder is held"
    );
    assert!(!out.join("results.json").exists());
    drop(held);
    let (code, stdout, stderr) = finish(waiting, DEADLINE);
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(out.join("results.json").exists());
    assert_released(&out);

    // The history folder is held the same way.
    let history = dir.join("history");
    let held = FolderLock::acquire(&history, false, |_| {}).unwrap();
    let (code, _, stderr) = axcheck(&run_args(
        &campaign,
        &out,
        &["--history", history.to_str().unwrap()],
    ));
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains(&format!(") is writing to {}", history.display())),
        "{stderr}"
    );
    drop(held);
    let (code, _, stderr) = axcheck(&run_args(
        &campaign,
        &out,
        &["--history", history.to_str().unwrap()],
    ));
    assert_eq!(code, 0, "{stderr}");

    std::fs::remove_dir_all(dir).unwrap();
}

/// Two runs started together on one output folder: without `--wait` each writes or stops
/// with the lock message (never "not written by axcheck"); with `--wait` both write.
#[test]
fn two_runs_at_once_on_one_output_folder() {
    let dir = scratch("hostile-concurrent");
    let (code, _, stderr) = axcheck(&[
        "simulate",
        "--fleet",
        "60",
        "--seed",
        "3",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stderr}");
    let campaign = dir.join("campaign.yaml");
    let out = dir.join("out");
    for wait in [false, true] {
        let extra: &[&str] = if wait { &["--wait"] } else { &[] };
        let children = [
            spawn(&run_args(&campaign, &out, extra)),
            spawn(&run_args(&campaign, &out, extra)),
        ];
        let mut written = 0;
        for child in children {
            let (code, stdout, stderr) = finish(child, DEADLINE);
            assert!(!stderr.contains("was not written by axcheck"), "{stderr}");
            match code {
                0 | 1 => written += 1,
                2 => assert!(
                    !wait && stderr.contains("another axcheck run (pid "),
                    "{stdout}{stderr}"
                ),
                _ => panic!("{stdout}{stderr}"),
            }
        }
        assert!(
            written >= 1 && (!wait || written == 2),
            "wait {wait}: {written} runs wrote"
        );
        let results: serde_json::Value =
            serde_json::from_slice(&std::fs::read(out.join("results.json")).unwrap()).unwrap();
        assert_eq!(results["axes"].as_array().unwrap().len(), 60);
    }
    std::fs::remove_dir_all(dir).unwrap();
}

/// The lock of a run that was killed is released by the system; the next run takes the
/// lock file over and says so.
#[test]
fn the_lock_of_a_killed_run_is_taken_over() {
    let dir = scratch("hostile-stale");
    let campaign = small_campaign(&dir);
    // A real run that holds its output folder: it waits (--wait) for the history folder
    // this test holds (folders are locked in the order of their paths: a-out first).
    let (out, history) = (dir.join("a-out"), dir.join("b-history"));
    let held = FolderLock::acquire(&history, false, |_| {}).unwrap();
    let mut holder = spawn(&run_args(
        &campaign,
        &out,
        &["--history", history.to_str().unwrap(), "--wait"],
    ));
    let mut line = String::new();
    std::io::BufReader::new(holder.stderr.as_mut().unwrap())
        .read_line(&mut line)
        .unwrap();
    assert!(
        line.contains(&format!("is writing to {}", history.display())),
        "{line}"
    );
    let lock_text = std::fs::read_to_string(out.join(LOCK_FILE)).unwrap();
    assert!(
        lock_text.contains(&format!("pid {}\n", holder.id())),
        "{lock_text}"
    );
    holder.kill().unwrap();
    holder.wait().unwrap();
    drop(held);
    assert!(
        out.join(LOCK_FILE).exists(),
        "a killed run leaves its lock file"
    );

    let (code, stdout, stderr) = axcheck(&run_args(&campaign, &out, &[]));
    assert_eq!(code, 0, "{stdout}{stderr}");
    let want = format!(
        "holds the lock file of a run that ended without removing it (pid {}, started ",
        holder.id()
    );
    assert!(stderr.contains(&want), "{stderr}");
    assert!(out.join("results.json").exists());
    assert_released(&out);
    std::fs::remove_dir_all(dir).unwrap();
}

/// `trend --out` and `simulate --fleet` write folders too: a held one stops them at once
/// with who holds it, and nothing is written into it.
#[test]
fn trend_and_simulate_stop_at_a_held_folder() {
    let dir = scratch("hostile-lock-other");
    let out = dir.join("trends");
    let held = FolderLock::acquire(&out, false, |_| {}).unwrap();
    let want = format!("another axcheck run (pid {}, started ", std::process::id());
    let history = Path::new(env!("CARGO_MANIFEST_DIR")).join("example-campaign/history");
    let (code, stdout, stderr) = axcheck(&[
        "trend",
        history.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 2, "{stdout}{stderr}");
    assert!(stderr.contains(&want), "{stderr}");
    assert!(!out.join("trends.csv").exists() && !out.join("trends.pdf").exists());

    let (code, stdout, stderr) =
        axcheck(&["simulate", "--fleet", "3", "--out", out.to_str().unwrap()]);
    assert_eq!(code, 2, "{stdout}{stderr}");
    assert!(stderr.contains(&want), "{stderr}");
    assert!(!out.join("campaign.yaml").exists());
    drop(held);
    let (code, stdout, stderr) =
        axcheck(&["simulate", "--fleet", "3", "--out", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(out.join("campaign.yaml").exists());
    assert_released(&out);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Campaign paths stay in the campaign's folder whichever separator they are written
/// with; a drive (`C:\…`, drive-relative `C:…`), a root (`\…`) or a share
/// (`\\server\share\…`) is refused unless the campaign allows outside paths.
#[test]
fn campaign_paths_stay_inside_with_either_separator() {
    let dir = scratch("win-campaign-paths");
    let root = axcheck::files::Root::campaign(&dir, false);
    let refused = |p: &str| root.resolve(p).expect_err(p).to_string();
    assert_eq!(root.resolve("data/x.csv").unwrap(), dir.join("data/x.csv"));
    for out in ["../x.csv", "data/../../x.csv"] {
        assert!(
            refused(out).contains("leaves the campaign's folder"),
            "{out}"
        );
    }
    if cfg!(windows) {
        assert_eq!(
            root.resolve("data\\x.csv").unwrap(),
            dir.join("data").join("x.csv")
        );
        for out in ["..\\x.csv", "data\\..\\..\\x.csv", "data/..\\../x.csv"] {
            assert!(
                refused(out).contains("leaves the campaign's folder"),
                "{out}"
            );
        }
        for absolute in [
            "C:\\Windows\\win.ini",
            "c:/x.csv",
            "\\x.csv",
            "\\\\server\\share\\x.csv",
            "\\\\?\\C:\\x.csv",
        ] {
            let e = refused(absolute);
            assert!(e.contains("is absolute"), "{absolute}: {e}");
        }
        let e = refused("C:x.csv");
        assert_eq!(
            e,
            "path `C:x.csv` names a drive; paths in a campaign are relative to its folder (set campaign.allow_outside_paths: true to allow it)"
        );
    } else {
        assert!(refused("/etc/passwd").contains("is absolute"));
    }
    let open = axcheck::files::Root::campaign(&dir, true);
    assert!(open.resolve("../x.csv").is_ok());
    std::fs::remove_dir_all(dir).unwrap();
}

/// A data file named by its absolute path (a drive-letter path on Windows: the temporary
/// folder is `C:\users\…\Temp`) is refused by `run` unless the campaign allows outside
/// paths, and then read.
#[test]
fn an_absolute_data_path_is_refused_unless_allowed() {
    let dir = scratch("win-absolute");
    let away = scratch("win-absolute-away");
    let data = away.join("data").join("x.csv");
    std::fs::copy(data_path("iso230-2_table2.csv"), &data).unwrap();
    let absolute = data.to_str().unwrap();
    if cfg!(windows) {
        assert_eq!(
            absolute.as_bytes()[1],
            b':',
            "a drive-letter path: {absolute}"
        );
    }
    let campaign = campaign_with(&dir, &[("M", &[("X", absolute)])]);
    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&run_args(&campaign, &out, &["--no-html"]));
    let all = format!("{stdout}{stderr}");
    assert_ne!(code, 0, "{all}");
    assert!(
        all.contains(&format!(
            "path `{absolute}` is absolute; paths in a campaign are relative to its folder"
        )),
        "{all}"
    );
    std::fs::write(
        &campaign,
        std::fs::read_to_string(&campaign).unwrap().replace(
            "unjudged: allowed}",
            "unjudged: allowed, allow_outside_paths: true}",
        ),
    )
    .unwrap();
    let (code, stdout, stderr) = axcheck(&run_args(&campaign, &out, &["--no-html"]));
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(out.join("compensation/M/X.ini").exists());
    std::fs::remove_dir_all(dir).unwrap();
    std::fs::remove_dir_all(away).unwrap();
}

/// Machine and axis names that Windows would open as devices (`CON`, `NUL`, `COM1`),
/// lose a trailing dot of (`aux.`) or fold together (`X` and `x`, `CON` and `con`) get
/// file names of their own, the same on every platform; each file holds its own axis.
#[test]
fn reserved_names_and_case_twins_get_files_of_their_own() {
    let dir = scratch("win-names");
    for (name, file) in [
        ("a.csv", "iso230-2_table2.csv"),
        ("b.csv", "gost27843_example.csv"),
    ] {
        std::fs::copy(data_path(file), dir.join("data").join(name)).unwrap();
    }
    let (a, b) = ("data/a.csv", "data/b.csv");
    let campaign = campaign_with(
        &dir,
        &[
            ("CON", &[("X", a), ("x", b), ("aux.", a), ("NUL", a)]),
            ("con", &[("COM1", b)]),
        ],
    );
    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&run_args(&campaign, &out, &["--no-html"]));
    assert!(code == 0 || code == 1, "{stdout}{stderr}");
    let results: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("results.json")).unwrap()).unwrap();
    let files: Vec<(String, String, String)> = results["axes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|axis| {
            let file = axis["compensation"]["file"].as_str().unwrap_or_default();
            (
                axis["machine"].as_str().unwrap().to_string(),
                axis["axis"].as_str().unwrap().to_string(),
                file.to_string(),
            )
        })
        .collect();
    let want = [
        ("CON", "X", "compensation/CON_/X.ini"),
        ("CON", "x", "compensation/CON_/x-2.ini"),
        ("CON", "aux.", "compensation/CON_/aux_.ini"),
        ("CON", "NUL", "compensation/CON_/NUL_.ini"),
        ("con", "COM1", "compensation/con_-2/COM1_.ini"),
    ];
    let want: Vec<(String, String, String)> = want
        .iter()
        .map(|(m, a, f)| (m.to_string(), a.to_string(), f.to_string()))
        .collect();
    assert_eq!(files, want);
    let read = |f: &str| std::fs::read_to_string(out.join(f)).unwrap();
    let (upper, lower) = (read(&want[0].2), read(&want[1].2));
    assert_ne!(upper, lower, "X and x are two files");
    assert_eq!(read(&want[2].2), upper, "the same data, the same table");
    assert_eq!(read(&want[4].2), lower);
    std::fs::remove_dir_all(dir).unwrap();
}

/// An output that exists is replaced whole by the next run (a new file renamed over it),
/// with no temporary file left; a tampered manifest line written with `\` is refused
/// before anything is written.
#[test]
fn an_existing_output_is_replaced_whole() {
    let dir = scratch("win-replace");
    let campaign = small_campaign(&dir);
    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&run_args(&campaign, &out, &["--no-html"]));
    assert_eq!(code, 0, "{stdout}{stderr}");
    let results = out.join("results.json");
    let first = std::fs::read_to_string(&results).unwrap();
    // Another campaign name: another results.json, written over the open one.
    std::fs::write(
        &campaign,
        std::fs::read_to_string(&campaign)
            .unwrap()
            .replace("name: L,", "name: Second,"),
    )
    .unwrap();
    // A reader holding it open keeps its old file (unix; Windows replaces a file open
    // for reading only with the POSIX-semantics rename of Windows 10 1809 and later,
    // which Wine 8 lacks: see `an_output_held_open_by_another_program_is_named`).
    let reader = cfg!(unix).then(|| std::fs::File::open(&results).unwrap());
    let (code, stdout, stderr) = axcheck(&run_args(&campaign, &out, &["--no-html"]));
    assert_eq!(code, 0, "{stdout}{stderr}");
    drop(reader);
    let second = std::fs::read_to_string(&results).unwrap();
    assert!(
        first.contains("\"L\"") && second.contains("\"Second\""),
        "{second}"
    );
    let leftovers: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.contains(".axcheck-tmp-"))
        .collect();
    assert!(leftovers.is_empty(), "{leftovers:?}");

    let manifest = out.join(axcheck::atomic::MANIFEST);
    let text = std::fs::read_to_string(&manifest).unwrap();
    std::fs::write(&manifest, format!("{text}..\\..\\victim.txt\n")).unwrap();
    let (code, _, stderr) = axcheck(&run_args(&campaign, &out, &["--no-html"]));
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("`..\\..\\victim.txt` is not a relative path inside the folder"),
        "{stderr}"
    );
    assert_eq!(std::fs::read_to_string(&results).unwrap(), second);
    std::fs::remove_dir_all(dir).unwrap();
}

/// Windows: an output another program holds open without letting it be deleted (as some
/// PDF viewers and Excel do) cannot be replaced; the run names it and says to close it,
/// writes every other output, and the next run, once it is closed, writes it.
#[cfg(windows)]
#[test]
fn an_output_held_open_by_another_program_is_named() {
    use std::os::windows::fs::OpenOptionsExt;
    const FILE_SHARE_READ: u32 = 1;
    let dir = scratch("win-in-use");
    let campaign = small_campaign(&dir);
    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&run_args(&campaign, &out, &["--no-html"]));
    assert_eq!(code, 0, "{stdout}{stderr}");
    let csv = out.join("summary.csv");
    let viewer = std::fs::OpenOptions::new()
        .read(true)
        .share_mode(FILE_SHARE_READ)
        .open(&csv)
        .unwrap();
    let (code, _, stderr) = axcheck(&run_args(&campaign, &out, &["--no-html"]));
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains(&format!("cannot replace {}: ", csv.display()))
            && stderr.contains("close it there and run again"),
        "{stderr}"
    );
    drop(viewer);
    let (code, stdout, stderr) = axcheck(&run_args(&campaign, &out, &["--no-html"]));
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(csv.exists());
    std::fs::remove_dir_all(dir).unwrap();
}

/// Windows: `NUL`, `CON`, `COM1` name devices in every folder (`data\nul.csv` too); named
/// as a measurement they are refused at once (reading `CON` would wait for the console).
#[cfg(windows)]
#[test]
fn device_names_are_never_read_as_files() {
    for name in ["NUL", "CON", "COM1", "data\\nul.csv", "AUX.csv"] {
        let (code, stdout, stderr) = axcheck(&["eval", name]);
        assert_eq!(code, 2, "{name}: {stdout}{stderr}");
        assert!(
            stderr.contains(&format!("{name}: could not read the file: ")),
            "{stderr}"
        );
    }
}

/// An output folder whose paths pass Windows' old limit of 260 characters
/// (`MAX_PATH`): the standard library gives such paths to Windows as `\\?\` paths, so
/// every output is written and a second run replaces them.
#[test]
fn outputs_deeper_than_260_characters_are_written() {
    let dir = scratch("win-long");
    let campaign = small_campaign(&dir);
    let out = ["a", "b", "c"]
        .iter()
        .fold(dir.clone(), |p, c| p.join(c.repeat(90)));
    let deepest = out.join("compensation").join("M").join("X.ini");
    assert!(deepest.as_os_str().len() > 300, "{}", deepest.display());
    std::fs::write(
        &campaign,
        std::fs::read_to_string(&campaign)
            .unwrap()
            .replace("  - id: M\n", "  - id: M\n    controller: siemens-840d\n"),
    )
    .unwrap();
    for round in 0..2 {
        let (code, stdout, stderr) = axcheck(&run_args(&campaign, &out, &["--no-html"]));
        assert_eq!(code, 0, "round {round}: {stdout}{stderr}");
        assert!(deepest.is_file() && out.join("summary.csv").is_file());
    }
    std::fs::remove_dir_all(dir).unwrap();
}

/// A campaign as Notepad saves it: CRLF line ends are read as any other; saved as "ANSI"
/// (Windows-1252, `ü` one byte 0xFC) it is refused naming the line, the column and what to
/// do, not as "stream did not contain valid UTF-8".
#[test]
fn a_notepad_campaign_is_read_or_named() {
    let dir = scratch("win-notepad");
    let campaign = small_campaign(&dir);
    let text = std::fs::read_to_string(&campaign).unwrap();
    let crlf = dir.join("crlf.yaml");
    std::fs::write(&crlf, text.replace('\n', "\r\n")).unwrap();
    let (code, stdout, stderr) = axcheck(&["check", crlf.to_str().unwrap()]);
    assert_ne!(code, 2, "{stdout}{stderr}");
    assert!(stdout.contains(" tests: "), "{stdout}");
    let ansi = dir.join("ansi.yaml");
    let mut bytes = b"# Pr\xFCfung\r\n".to_vec();
    bytes.extend_from_slice(text.replace('\n', "\r\n").as_bytes());
    std::fs::write(&ansi, bytes).unwrap();
    let (code, _, stderr) = axcheck(&["check", ansi.to_str().unwrap()]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains(
            "ansi.yaml: cannot read the campaign file: line 1, column 5: byte 0xFC is not UTF-8"
        ),
        "{stderr}"
    );
    std::fs::remove_dir_all(dir).unwrap();
}
