//! The hostile file-system catalogue: a campaign folder prepared by someone else, with
//! links that lead out of it, pipes, sockets, devices and folders where files should be,
//! and two runs on one output folder. Each case asserts the error's words, that every
//! other axis is still evaluated, and that nothing read from a refused file (a marker
//! in the files outside) reaches any output. Every run has a deadline, so a regression
//! that blocks on a pipe or a lock fails instead of hanging the test binary.

use crate::common::{
    DEADLINE, data_path, finish, run_args, scratch, small_campaign, spawn, while_swapping,
};
use std::os::unix::fs::symlink;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// Written into every file outside the campaign folder: it must appear in no output.
const MARKER: &str = "OUTSIDE_MARKER_5f1c";

/// `axcheck ARGS` with the deadline.
fn axcheck(args: &[&str]) -> (i32, String, String) {
    finish(spawn(args), DEADLINE)
}

fn real(path: &Path) -> String {
    std::fs::canonicalize(path).unwrap().display().to_string()
}

fn fifo(path: &Path) {
    rustix::fs::mkfifoat(
        rustix::fs::CWD,
        path,
        rustix::fs::Mode::from_raw_mode(0o600),
    )
    .unwrap();
}

/// The folder outside every campaign (one for each test, `name`): files with the marker,
/// a good measurement, a pipe.
fn outside(name: &str) -> PathBuf {
    let away = scratch(&format!("hostile-outside-{name}"));
    let secret = format!("{MARKER},direction,run,deviation_um\n0,up,1,1\n0,down,1,1\n");
    std::fs::write(away.join("secret.csv"), &secret).unwrap();
    std::fs::create_dir_all(away.join("folder")).unwrap();
    std::fs::write(away.join("folder/x.csv"), &secret).unwrap();
    let spec =
        format!("name: {MARKER}\nlinear:\n  - {{up_to_mm: 10, tolerances: {{{MARKER}: 1}}}}\n");
    std::fs::write(away.join("spec.yaml"), &spec).unwrap();
    std::fs::write(away.join("folder/spec.yaml"), &spec).unwrap();
    std::fs::copy(data_path("iso230-2_table2.csv"), away.join("good.csv")).unwrap();
    fifo(&away.join("pipe.csv"));
    away
}

/// Every output file, the console and the error texts hold no byte of the files outside
/// (in either case: the readers quote a column's name in lower case).
fn assert_nothing_leaked(out: &Path, console: &str) {
    let lower = MARKER.to_lowercase();
    for secret in [MARKER, lower.as_str(), "root:x:0:0"] {
        assert!(
            !console.contains(secret),
            "`{secret}` on the console:\n{console}"
        );
        for entry in walkdir::WalkDir::new(out)
            .into_iter()
            .filter_map(Result::ok)
        {
            if entry.file_type().is_file() {
                let bytes = std::fs::read(entry.path()).unwrap();
                assert!(
                    !bytes.windows(secret.len()).any(|w| w == secret.as_bytes()),
                    "`{secret}` in {}",
                    entry.path().display()
                );
            }
        }
    }
}

/// A case: axis name, its `data:` (and keys), the verdict, and the words of its error.
struct Case {
    name: &'static str,
    entry: String,
    verdict: &'static str,
    words: Vec<String>,
}

fn case(name: &'static str, entry: &str, verdict: &'static str, words: &[String]) -> Case {
    Case {
        name,
        entry: entry.to_string(),
        verdict,
        words: words.to_vec(),
    }
}

/// Runs `cases` as the axes of one campaign in `dir` beside a good axis; checks each
/// verdict and error, the good axis, and that no marker leaked. Returns the cases checked.
fn run_catalogue(dir: &Path, head: &str, cases: &[Case]) -> usize {
    let mut yaml = format!(
        "campaign: {{name: Hostile, spec: general{head}}}\nmachines:\n  - id: GOOD\n    axes:\n      - {{name: X, kind: linear, data: data/good.csv}}\n  - id: HOSTILE\n    axes:\n"
    );
    for c in cases {
        yaml.push_str(&format!(
            "      - {{name: {}, kind: linear, {}}}\n",
            c.name, c.entry
        ));
    }
    let campaign = dir.join("campaign.yaml");
    std::fs::write(&campaign, yaml).unwrap();
    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&crate::common::run_args(&campaign, &out, &[]));
    assert_eq!(code, 1, "{stdout}{stderr}");
    let results: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("results.json")).unwrap()).unwrap();
    let entries = results["axes"].as_array().unwrap();
    let good = entries.iter().find(|a| a["machine"] == "GOOD").unwrap();
    assert_eq!(good["verdict"], "pass", "the good axis is still evaluated");
    let junit = std::fs::read_to_string(out.join("junit.xml")).unwrap();
    for c in cases {
        let axis = entries
            .iter()
            .find(|a| a["machine"] == "HOSTILE" && a["axis"] == c.name)
            .unwrap_or_else(|| panic!("{} missing from results.json", c.name));
        assert_eq!(axis["verdict"], c.verdict, "{}: {axis}", c.name);
        let error = axis["error"].as_str().unwrap_or("");
        for word in &c.words {
            assert!(
                error.contains(word.as_str()),
                "{}: `{error}` should say `{word}`",
                c.name
            );
        }
        assert!(junit.contains(c.name), "{} in junit.xml", c.name);
    }
    assert_nothing_leaked(&out, &format!("{stdout}{stderr}"));
    cases.len()
}

/// Links out of the campaign folder are refused by their real path and named; links that
/// stay inside work; pipes, sockets, devices and folders are refused by their type.
#[test]
fn links_out_and_special_files_fail_their_axis_alone() {
    let away = outside("links");
    let dir = scratch("hostile");
    let data = dir.join("data");
    let good = data_path("iso230-2_table2.csv");
    std::fs::copy(&good, data.join("good.csv")).unwrap();
    let (secret, folder) = (away.join("secret.csv"), away.join("folder"));
    let link = |target: &Path, name: &str| symlink(target, dir.join(name)).unwrap();
    link(&secret, "data/link-abs.csv");
    let away_name = away.file_name().unwrap().to_str().unwrap();
    link(
        Path::new(&format!("../../{away_name}/secret.csv")),
        "data/link-rel.csv",
    );
    link(Path::new("chain-2.csv"), "data/chain-1.csv");
    link(Path::new("chain-3.csv"), "data/chain-2.csv");
    link(&secret, "data/chain-3.csv");
    link(&folder, "data/out-dir");
    std::fs::create_dir_all(data.join("mixed")).unwrap();
    std::fs::copy(&good, data.join("mixed/x-1.csv")).unwrap();
    link(&secret, "data/mixed/x-2.csv");
    link(Path::new("/etc/passwd"), "data/passwd.csv");
    link(Path::new("/dev/zero"), "data/zero.csv");
    link(&away.join("absent.csv"), "data/dangling-out.csv");
    std::fs::create_dir_all(dir.join("specs")).unwrap();
    link(&away.join("spec.yaml"), "specs/outside.yaml");
    link(&folder, "other");
    // Links that stay inside.
    link(Path::new("good.csv"), "data/alias.csv");
    link(&data.join("good.csv"), "data/alias-abs.csv");
    link(Path::new("alias.csv"), "data/alias-chain.csv");
    std::fs::create_dir_all(data.join("sub")).unwrap();
    std::fs::copy(&good, data.join("sub/x-1.csv")).unwrap();
    link(Path::new("sub"), "data/inside-dir");
    // Files that are not regular files.
    fifo(&data.join("pipe.csv"));
    link(Path::new("pipe.csv"), "data/pipe-link.csv");
    std::fs::create_dir_all(data.join("pipes")).unwrap();
    fifo(&data.join("pipes/x-1.csv"));
    std::fs::copy(&good, data.join("pipes/x-2.csv")).unwrap();
    let _socket = std::os::unix::net::UnixListener::bind(data.join("socket.csv")).unwrap();
    std::fs::create_dir_all(data.join("dir.csv")).unwrap();
    link(Path::new("dir.csv"), "data/dir-link.csv");
    fifo(&dir.join("specs/pipe.yaml"));
    std::fs::create_dir_all(dir.join("specs/folder.yaml")).unwrap();
    link(Path::new("absent.csv"), "data/dangling-in.csv");
    link(Path::new("loop-2.csv"), "data/loop-1.csv");
    link(Path::new("loop-1.csv"), "data/loop-2.csv");

    let root = real(&dir);
    let out_of = |what: &str, to: &str| {
        vec![format!(
            "{what} is a link to {to}, outside the campaign folder {root}; set campaign.allow_outside_paths: true to allow it"
        )]
    };
    let through = |what: &str, link: &str, to: &str| {
        vec![format!(
            "{what} lies in {link}, a link to {to}, outside the campaign folder {root}; set campaign.allow_outside_paths: true"
        )]
    };
    let (secret_real, folder_real) = (real(&secret), real(&folder));
    let words = |w: &str| vec![w.to_string()];
    let pipe = "it is a named pipe (FIFO), not a regular file; axcheck reads only regular files";
    let cases = vec![
        case(
            "link-abs",
            "data: data/link-abs.csv",
            "error",
            &out_of("data/link-abs.csv", &secret_real),
        ),
        case(
            "link-rel",
            "data: data/link-rel.csv",
            "error",
            &out_of("data/link-rel.csv", &secret_real),
        ),
        case(
            "link-chain",
            "data: data/chain-1.csv",
            "error",
            &out_of("data/chain-1.csv", &secret_real),
        ),
        case(
            "folder-link",
            "data: data/out-dir/x.csv",
            "error",
            &through("data/out-dir/x.csv", "data/out-dir", &folder_real),
        ),
        case(
            "glob-folder-link",
            "data: {dir: data/out-dir, glob: \"*.csv\"}",
            "error",
            &out_of("data/out-dir", &folder_real),
        ),
        case(
            "glob-match-link",
            "data: {dir: data/mixed, glob: \"x-*.csv\"}",
            "error",
            &out_of("data/mixed/x-2.csv", &secret_real),
        ),
        case(
            "climb-after-link",
            "data: data/out-dir/../secret.csv",
            "error",
            &through("data/out-dir/../secret.csv", "data/out-dir", &folder_real),
        ),
        case(
            "list-with-link",
            "data: [data/good.csv, data/link-abs.csv]",
            "error",
            &out_of("data/link-abs.csv", &secret_real),
        ),
        case(
            "etc-passwd",
            "data: data/passwd.csv",
            "error",
            &out_of("data/passwd.csv", &real(Path::new("/etc/passwd"))),
        ),
        case(
            "dev-zero-link",
            "data: data/zero.csv",
            "error",
            &out_of("data/zero.csv", "/dev/zero"),
        ),
        case(
            "dangling-out",
            "data: data/dangling-out.csv",
            "error",
            &out_of(
                "data/dangling-out.csv",
                &format!("{}/absent.csv", real(&away)),
            ),
        ),
        case(
            "spec-link",
            "data: data/good.csv, spec: outside",
            "error",
            &out_of(
                "spec `outside`: specs/outside.yaml",
                &real(&away.join("spec.yaml")),
            ),
        ),
        case(
            "spec-path-link",
            "data: data/good.csv, spec: specs/outside.yaml",
            "error",
            &out_of("specs/outside.yaml", &real(&away.join("spec.yaml"))),
        ),
        case(
            "spec-folder-link",
            "data: data/good.csv, spec: other/spec.yaml",
            "error",
            &through("other/spec.yaml", "other", &folder_real),
        ),
        case("alias", "data: data/alias.csv", "pass", &[]),
        case("alias-abs", "data: data/alias-abs.csv", "pass", &[]),
        case("alias-chain", "data: data/alias-chain.csv", "pass", &[]),
        case(
            "inside-folder-glob",
            "data: {dir: data/inside-dir, glob: \"*.csv\"}",
            "pass",
            &[],
        ),
        case(
            "inside-folder-file",
            "data: data/inside-dir/x-1.csv",
            "pass",
            &[],
        ),
        case("fifo", "data: data/pipe.csv", "error", &words(pipe)),
        case(
            "fifo-link",
            "data: data/pipe-link.csv",
            "error",
            &words(pipe),
        ),
        case(
            "socket",
            "data: data/socket.csv",
            "error",
            &words("it is a socket, not a regular file"),
        ),
        case(
            "dir-named-csv",
            "data: data/dir.csv",
            "error",
            &words("data/dir.csv: could not read the file: it is a folder, not a regular file"),
        ),
        case(
            "link-to-dir",
            "data: data/dir-link.csv",
            "error",
            &words("it is a folder, not a regular file"),
        ),
        case(
            "spec-fifo",
            "data: data/good.csv, spec: pipe",
            "error",
            &words(&format!("pipe.yaml: cannot read the spec: {pipe}")),
        ),
        case(
            "spec-folder",
            "data: data/good.csv, spec: folder",
            "error",
            &words("folder.yaml: cannot read the spec: it is a folder, not a regular file"),
        ),
        case(
            "dangling-in",
            "data: data/dangling-in.csv",
            "error",
            &words("No such file or directory"),
        ),
        case(
            "link-loop",
            "data: data/loop-1.csv",
            "error",
            &words("symbolic links"),
        ),
    ];
    let mut count = run_catalogue(&dir, "", &cases);

    // A glob that matches a pipe fails that test alone; the other file is evaluated.
    let (code, stdout, stderr) = {
        let yaml = "campaign: {name: Pipes}\nmachines:\n  - id: M\n    axes:\n      - {name: X, kind: linear, data: {dir: data/pipes, glob: \"x-*.csv\"}}\n";
        std::fs::write(dir.join("pipes.yaml"), yaml).unwrap();
        axcheck(&["check", dir.join("pipes.yaml").to_str().unwrap()])
    };
    assert_eq!(code, 1, "{stdout}{stderr}");
    assert!(
        stdout.contains("2 tests: 0 pass, 0 fail, 0 noncompliant, 1 error, 1 not judged"),
        "{stdout}"
    );
    assert!(
        stdout.contains(&format!(
            "data/pipes/x-1.csv: could not read the file: {pipe}"
        )),
        "{stdout}"
    );
    count += 1;
    eprintln!("hostile file-system cases: {count}");
    assert!(count >= 29, "{count}");
    std::fs::remove_dir_all(dir).unwrap();
    std::fs::remove_dir_all(away).unwrap();
}

/// With `allow_outside_paths: true` links and absolute paths out are followed, but a
/// device or a pipe is still refused by its type, and a folder is not a file.
#[test]
fn allowed_outside_paths_still_read_only_regular_files() {
    let away = outside("allowed");
    let dir = scratch("hostile-allowed");
    std::fs::copy(data_path("iso230-2_table2.csv"), dir.join("data/good.csv")).unwrap();
    symlink("/dev/zero", dir.join("data/zero.csv")).unwrap();
    symlink(away.join("good.csv"), dir.join("data/away.csv")).unwrap();
    let device = "it is a character device, not a regular file";
    let words = |w: &str| vec![w.to_string()];
    let cases = vec![
        case(
            "dev-zero",
            "data: /dev/zero",
            "error",
            &words(&format!("/dev/zero: could not read the file: {device}")),
        ),
        case(
            "dev-zero-link",
            "data: data/zero.csv",
            "error",
            &words(device),
        ),
        case("dev-null", "data: /dev/null", "error", &words(device)),
        case(
            "outside-fifo",
            &format!("data: {}", away.join("pipe.csv").display()),
            "error",
            &words("it is a named pipe (FIFO)"),
        ),
        case(
            "outside-folder",
            &format!("data: {}", away.join("folder").display()),
            "error",
            &words("it is a folder, not a regular file"),
        ),
        case("outside-good-link", "data: data/away.csv", "pass", &[]),
    ];
    let count = run_catalogue(&dir, ", allow_outside_paths: true", &cases);
    assert_eq!(count, 6);
    std::fs::remove_dir_all(dir).unwrap();
    std::fs::remove_dir_all(away).unwrap();
}

/// A history folder and a template that lead out are refused before anything is written
/// there; a campaign file or a measurement that is a pipe, a device or a folder is
/// refused at once by `check` and `eval`.
#[test]
fn history_templates_and_named_files_are_checked_too() {
    let away = outside("named");
    let dir = scratch("hostile-named");
    std::fs::copy(data_path("iso230-2_table2.csv"), dir.join("data/good.csv")).unwrap();
    std::fs::create_dir_all(away.join("history")).unwrap();
    symlink(away.join("history"), dir.join("history")).unwrap();
    symlink(away.join("not-yet"), dir.join("later")).unwrap();
    let root = real(&dir);
    for (name, target) in [
        ("history", real(&away.join("history"))),
        ("later", format!("{}/not-yet", real(&away))),
    ] {
        let yaml = format!(
            "campaign: {{name: H, date: 2026-11-20, history: {name}}}\nmachines:\n  - id: M\n    axes:\n      - {{name: X, kind: linear, data: data/good.csv}}\n"
        );
        let campaign = dir.join(format!("{name}.yaml"));
        std::fs::write(&campaign, yaml).unwrap();
        let out = dir.join("out");
        let (code, _, stderr) = axcheck(&[
            "run",
            campaign.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--no-pdf",
        ]);
        assert_eq!(code, 2, "{stderr}");
        let want = format!(
            "campaign.history: {name} is a link to {target}, outside the campaign folder {root}; set campaign.allow_outside_paths: true to allow it"
        );
        assert!(stderr.contains(&want), "{stderr}");
    }
    assert_eq!(
        std::fs::read_dir(away.join("history")).unwrap().count(),
        0,
        "nothing written outside"
    );
    assert!(!away.join("not-yet").exists());

    // A template in a shared templates folder that links to another file.
    let templates = dir.join("templates");
    std::fs::create_dir_all(&templates).unwrap();
    for name in ["style.typ", "axis-report.typ", "summary.typ"] {
        let source = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("templates")
            .join(name);
        std::fs::copy(source, templates.join(name)).unwrap();
    }
    std::fs::remove_file(templates.join("summary.typ")).unwrap();
    symlink(away.join("spec.yaml"), templates.join("summary.typ")).unwrap();
    let yaml = "campaign: {name: T}\nmachines:\n  - id: M\n    axes:\n      - {name: X, kind: linear, data: data/good.csv}\n";
    std::fs::write(dir.join("t.yaml"), yaml).unwrap();
    let out = dir.join("out-t");
    let (code, stdout, stderr) = axcheck(&[
        "run",
        dir.join("t.yaml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--templates",
        templates.to_str().unwrap(),
    ]);
    assert_eq!(code, 2, "{stderr}");
    let want = format!(
        "summary.typ is a link to {}, outside the templates folder {}",
        real(&away.join("spec.yaml")),
        real(&templates)
    );
    assert!(stderr.contains(&want), "{stderr}");
    assert!(!format!("{stdout}{stderr}").contains(MARKER));
    assert!(
        !out.exists(),
        "a run that stops before writing leaves no folder"
    );

    // Files named on the command line.
    fifo(&dir.join("campaign-pipe.yaml"));
    fifo(&dir.join("data/pipe.csv"));
    let pipe = "it is a named pipe (FIFO), not a regular file";
    let named: Vec<(Vec<String>, String)> = vec![
        (
            vec![
                "check".into(),
                dir.join("campaign-pipe.yaml").display().to_string(),
            ],
            format!("campaign-pipe.yaml: cannot read the campaign file: {pipe}"),
        ),
        (
            vec![
                "eval".into(),
                dir.join("data/pipe.csv").display().to_string(),
            ],
            format!("pipe.csv: could not read the file: {pipe}"),
        ),
        (
            vec!["eval".into(), "/dev/zero".into()],
            "/dev/zero: could not read the file: it is a character device, not a regular file"
                .into(),
        ),
        (
            vec!["diagnose".into(), dir.join("data").display().to_string()],
            "data: could not read the file: it is a folder, not a regular file".into(),
        ),
    ];
    for (args, want) in named {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let (code, _, stderr) = axcheck(&args);
        assert_eq!(code, 2, "{args:?}: {stderr}");
        assert!(
            stderr.contains(&want),
            "{args:?}: `{stderr}` should say `{want}`"
        );
    }
    std::fs::remove_dir_all(dir).unwrap();
    std::fs::remove_dir_all(away).unwrap();
}

/// A link swapped between the path check and the open: while a thread keeps replacing
/// `data/x.csv` by a link inside the folder or one to the outside (each an atomic rename),
/// every run either reads the inside file, refuses the link by its real path, or refuses
/// what it opened; no byte of the outside file reaches the console, and the good axis is
/// evaluated every time.
#[test]
fn a_link_swapped_while_the_run_reads_never_leaks() {
    let dir = scratch("hostile-race");
    let away = outside("race");
    let campaign = small_campaign(&dir);
    let mut yaml = std::fs::read_to_string(&campaign).unwrap();
    yaml.push_str("      - {name: R, kind: linear, data: data/x.csv}\n");
    std::fs::write(&campaign, yaml).unwrap();
    let swapping = link_swapper(
        dir.join("data/x.csv"),
        [PathBuf::from("good.csv"), away.join("secret.csv")],
    );
    let tally = while_swapping(swapping, || {
        let mut tally = RaceTally::default();
        for _ in 0..60 {
            let (code, stdout, stderr) = axcheck(&["check", campaign.to_str().unwrap()]);
            let console = format!("{stdout}{stderr}");
            assert!(code == 0 || code == 1, "{console}");
            assert_nothing_leaked(&dir.join("no-outputs"), &console);
            assert!(
                !console.contains(" M X "),
                "the good axis passes: {console}"
            );
            if code == 0 {
                tally.read += 1;
            } else {
                tally.refused(&console, "outside the campaign folder");
            }
        }
        tally
    });
    eprintln!("swapped link: {tally}");
    std::fs::remove_dir_all(dir).unwrap();
    std::fs::remove_dir_all(away).unwrap();
}

/// While a thread swaps `style.typ` of a shared templates folder between a link to a
/// template inside it and a link to a file outside (not UTF-8, so that reading it shows),
/// every `Reports::new` reads the inside template or refuses the link, by its real path or
/// at the open; the outside file is never read.
#[test]
fn a_template_swapped_for_a_link_while_it_is_read_is_never_read() {
    let dir = scratch("hostile-template-race");
    let away = outside("template-race");
    std::fs::write(away.join("style.typ"), [0xff, 0xfe, 0x00]).unwrap();
    let templates = dir.join("templates");
    std::fs::create_dir_all(&templates).unwrap();
    let source = Path::new(env!("CARGO_MANIFEST_DIR")).join("templates");
    for (from, to) in [
        ("style.typ", "inside-style.typ"),
        ("axis-report.typ", "axis-report.typ"),
        ("summary.typ", "summary.typ"),
    ] {
        std::fs::copy(source.join(from), templates.join(to)).unwrap();
    }
    let swapping = link_swapper(
        templates.join("style.typ"),
        [PathBuf::from("inside-style.typ"), away.join("style.typ")],
    );
    let tally = while_swapping(swapping, || {
        let mut tally = RaceTally::default();
        let start = Instant::now();
        while tally.refused_at_open < 3 && start.elapsed() < Duration::from_secs(10) {
            let Err(e) = axcheck::report::Reports::new(Some(&templates)) else {
                tally.read += 1;
                continue;
            };
            let e = e.to_string();
            assert!(!e.contains("UTF-8"), "the outside file was read: {e}");
            tally.refused(&e, "outside the templates folder");
        }
        tally
    });
    eprintln!("swapped template: {tally}");
    std::fs::remove_dir_all(dir).unwrap();
    std::fs::remove_dir_all(away).unwrap();
}

/// What the reads of a link race came to: the inside target read, the link refused by its
/// real path, or what was opened refused before a byte of it was read.
#[derive(Default)]
struct RaceTally {
    read: usize,
    refused_by_path: usize,
    refused_at_open: usize,
}

impl RaceTally {
    /// Counts a refused read by its message: refused at the open, or else by its real path,
    /// which must then say `outside`.
    fn refused(&mut self, message: &str, outside: &str) {
        if message.contains("was changed after the path was checked); nothing was read from it") {
            self.refused_at_open += 1;
        } else {
            assert!(message.contains(outside), "{message}");
            self.refused_by_path += 1;
        }
    }
}

impl std::fmt::Display for RaceTally {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(
            f,
            "{} read inside, {} refused by path, {} refused when opened",
            self.read, self.refused_by_path, self.refused_at_open
        )
    }
}

/// Makes `link` a link to `targets[0]`, and gives what swaps it for a link to the other
/// target, by turns; each swap an atomic rename (a new link beside it, renamed over it).
fn link_swapper(link: PathBuf, targets: [PathBuf; 2]) -> impl FnMut() + Send {
    symlink(&targets[0], &link).unwrap();
    let swap = link.with_file_name(".swap");
    let mut k = 1;
    move || {
        let _ = std::fs::remove_file(&swap);
        symlink(&targets[k % 2], &swap).unwrap();
        std::fs::rename(&swap, &link).unwrap();
        k += 1;
    }
}

/// A link planted in place of the lock file is not followed (the lock itself is tested on
/// every platform in `windows`).
#[test]
fn a_link_in_place_of_the_lock_file_is_refused() {
    let dir = scratch("hostile-lock-link");
    let campaign = small_campaign(&dir);
    let out = dir.join("out");
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(dir.join("victim.txt"), "keep").unwrap();
    symlink(dir.join("victim.txt"), out.join(axcheck::lock::LOCK_FILE)).unwrap();
    let (code, _, stderr) = axcheck(&run_args(&campaign, &out, &[]));
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains(".axcheck.lock is a symbolic link, not axcheck's lock file"),
        "{stderr}"
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("victim.txt")).unwrap(),
        "keep"
    );
    std::fs::remove_dir_all(dir).unwrap();
}
