//! Issue 47, point 5: a run records its inputs (`results.json` `inputs`: the version,
//! every file read with its SHA-256, the options), and `axcheck reproduce` checks them and
//! runs the campaign again, saying whether the outputs are byte for byte the same.

use crate::common::{axcheck, copy_tree, scratch};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// The example campaign copied into `dir/camp`; its campaign file.
fn example_in(dir: &Path) -> PathBuf {
    let example = Path::new(env!("CARGO_MANIFEST_DIR")).join("example-campaign");
    copy_tree(&example, &dir.join("camp"));
    dir.join("camp/campaign.yaml")
}

fn results(out: &Path) -> Value {
    serde_json::from_slice(&std::fs::read(out.join("results.json")).unwrap()).unwrap()
}

fn reproduce(args: &[&str]) -> (i32, String, String) {
    let mut all = vec!["reproduce"];
    all.extend_from_slice(args);
    axcheck(&all)
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn the_example_reproduces_and_a_changed_byte_is_named() {
    let dir = scratch("reproduce-example");
    let campaign = example_in(&dir);
    let out = dir.join("out");
    let (code, _, err) = axcheck(&["run", s(&campaign), "--out", s(&out), "--no-pdf"]);
    // The example fails on purpose (two axes out of tolerance …).
    assert_eq!(code, 1, "{err}");

    // The inputs: the version, every file read with its SHA-256, sorted, relative.
    let inputs = &results(&out)["inputs"];
    assert_eq!(inputs["axcheck"], env!("CARGO_PKG_VERSION"));
    // Named from the campaign's folder: nothing of where it lies on this machine.
    assert_eq!(inputs["campaign"], "campaign.yaml");
    assert_eq!(inputs["options"]["no_pdf"], true);
    assert_eq!(inputs["options"]["history"], Value::Null);
    assert_eq!(inputs["history"], Value::Null);
    assert_eq!(inputs["command"], "axcheck run campaign.yaml --no-pdf");
    let files = inputs["files"].as_array().unwrap();
    let paths: Vec<&str> = files.iter().map(|f| f["path"].as_str().unwrap()).collect();
    let mut sorted = paths.clone();
    sorted.sort();
    assert_eq!(paths, sorted);
    for expected in [
        "campaign.yaml",
        "data/vmc07-y.csv",
        "data/reference/iso230-2_table2.csv",
        "specs/gost-example.yaml",
        "active/VMC-07/Y.ini",
    ] {
        assert!(paths.contains(&expected), "{expected} not in {paths:?}");
    }
    // The 33 tests read 34 data files, 5 active tables, a spec and the campaign (built-in
    // specs are part of the version).
    assert_eq!(files.len(), 41, "{paths:?}");
    for f in files {
        let path = f["path"].as_str().unwrap();
        assert!(!path.starts_with('/') && !path.contains('\\'), "{path}");
        let bytes = std::fs::read(dir.join("camp").join(path)).unwrap();
        assert_eq!(f["sha256"], axcheck::files::sha256_hex(&bytes), "{path}");
    }

    let (code, stdout, err) = reproduce(&[s(&out)]);
    assert_eq!(code, 0, "{stdout}{err}");
    assert!(
        stdout.contains("Inputs: the 41 files recorded are unchanged (SHA-256)"),
        "{stdout}"
    );
    assert!(
        stdout.contains("identical: the 14 outputs of the re-run are byte for byte those in"),
        "{stdout}"
    );

    // One byte of one data file changed: named, nothing run again.
    let data = dir.join("camp/data/vmc07-y.csv");
    let original = std::fs::read(&data).unwrap();
    let mut changed = original.clone();
    let at = changed.iter().rposition(u8::is_ascii_digit).unwrap();
    changed[at] = if changed[at] == b'1' { b'2' } else { b'1' };
    std::fs::write(&data, &changed).unwrap();
    let (code, stdout, err) = reproduce(&[s(&out.join("results.json"))]);
    assert_eq!(code, 1, "{stdout}{err}");
    assert!(stdout.contains("Inputs changed since the run (nothing was run again):"));
    let line = format!(
        "  changed: data/vmc07-y.csv (SHA-256 recorded {}…, now {}…)",
        &axcheck::files::sha256_hex(&original)[..12],
        &axcheck::files::sha256_hex(&changed)[..12]
    );
    assert!(stdout.contains(&line), "{stdout}");
    assert_eq!(stdout.matches("  changed: ").count(), 1, "{stdout}");
    assert!(!stdout.contains("identical"), "{stdout}");
    std::fs::write(&data, &original).unwrap();

    // An input gone: named as missing.
    let spec = dir.join("camp/specs/gost-example.yaml");
    let spec_text = std::fs::read(&spec).unwrap();
    std::fs::remove_file(&spec).unwrap();
    let (code, stdout, _) = reproduce(&[s(&out)]);
    assert_eq!(code, 1, "{stdout}");
    assert!(
        stdout.contains("  missing: specs/gost-example.yaml"),
        "{stdout}"
    );
    // An input that cannot be read (a folder in its place): exit 2, as other input errors.
    std::fs::create_dir(&spec).unwrap();
    let (code, stdout, err) = reproduce(&[s(&out)]);
    assert_eq!(code, 2, "{stdout}{err}");
    assert!(err.contains("gost-example.yaml: it is a folder"), "{err}");
    std::fs::remove_dir(&spec).unwrap();
    std::fs::write(&spec, spec_text).unwrap();

    // An output deleted: named as missing from the run's folder.
    std::fs::remove_file(out.join("summary.md")).unwrap();
    let (code, stdout, _) = reproduce(&[s(&out)]);
    assert_eq!(code, 1, "{stdout}");
    assert!(
        stdout.contains("not identical: 1 of the 14 outputs differs from those in"),
        "{stdout}"
    );
    assert!(
        stdout.contains(
            "  missing: summary.md (the re-run writes it; the run's folder has no such file)"
        ),
        "{stdout}"
    );
    // An output changed: named as differing.
    std::fs::write(out.join("junit.xml"), "<testsuites/>").unwrap();
    let (code, stdout, _) = reproduce(&[s(&out)]);
    assert_eq!(code, 1, "{stdout}");
    assert!(stdout.contains("  differs: junit.xml"), "{stdout}");
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn with_pdfs_templates_and_a_history_the_copy_is_run_and_the_history_kept() {
    let dir = scratch("reproduce-pdf");
    let campaign = example_in(&dir);
    let out = dir.join("out");
    let history = dir.join("camp/history");
    let templates = dir.join("templates");
    copy_tree(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("templates"),
        &templates,
    );
    let run = [
        "run",
        s(&campaign),
        "--out",
        s(&out),
        "--history",
        s(&history),
        "--templates",
        s(&templates),
    ];
    let (code, _, err) = axcheck(&run);
    assert_eq!(code, 1, "{err}");
    let inputs = &results(&out)["inputs"];
    let template_files: Vec<&str> = (inputs["templates"]["files"].as_array().unwrap().iter())
        .map(|f| f["path"].as_str().unwrap())
        .collect();
    assert!(
        template_files.contains(&"summary.typ"),
        "{template_files:?}"
    );
    assert!(template_files.contains(&"style.typ"), "{template_files:?}");
    assert_eq!(inputs["templates"]["folder"], "../templates");
    assert_eq!(
        inputs["command"],
        "axcheck run campaign.yaml --templates ../templates --history history"
    );
    // The trends read the four earlier inspections; this run's own file is an output.
    let h = &inputs["history"];
    assert_eq!(h["folder"], "history");
    assert_eq!(h["files"].as_array().unwrap().len(), 4, "{h}");
    assert_eq!(
        h["written"],
        "year=2026/plant-2-annual-inspection_2026-11-20.parquet"
    );
    // The summary PDF lists the inputs with the start of their SHA-256.
    let text = crate::common::pdf_text(&out.join("summary.pdf"));
    let vmc = std::fs::read(dir.join("camp/data/vmc07-x.csv")).unwrap();
    assert!(text.contains("Inputs"), "{text}");
    let short = &axcheck::files::sha256_hex(&vmc)[..16];
    assert!(text.contains(short), "{text}");
    // And each axis report its measurement file's.
    let report = crate::common::pdf_text(&out.join("reports/VMC-07/X.pdf"));
    assert!(report.contains("File SHA-256"), "{report}");
    assert!(report.contains(&format!("{short}…")), "{report}");
    let listing = |dir: &Path| -> Vec<(PathBuf, Vec<u8>, std::time::SystemTime)> {
        let mut all: Vec<_> = (walkdir::WalkDir::new(dir).into_iter())
            .map(Result::unwrap)
            .filter(|e| e.file_type().is_file())
            .map(|e| {
                let modified = e.metadata().unwrap().modified().unwrap();
                (
                    e.path().to_path_buf(),
                    std::fs::read(e.path()).unwrap(),
                    modified,
                )
            })
            .collect();
        all.sort();
        all
    };
    let before = listing(&history);

    // Found through an axis report of the run.
    let report = out.join("reports/VMC-07/X.pdf");
    let (code, stdout, err) = reproduce(&[s(&report)]);
    assert_eq!(code, 0, "{stdout}{err}");
    assert!(
        stdout.contains("History: run again on a copy of"),
        "{stdout}"
    );
    assert!(stdout.contains("identical: the 48 outputs"), "{stdout}");
    assert_eq!(
        listing(&history),
        before,
        "reproduce appended to the history"
    );

    // An inspection added to the history since: the trends would differ.
    let added = history.join("year=2027/plant-2-annual-inspection_2027-11-20.parquet");
    std::fs::create_dir_all(added.parent().unwrap()).unwrap();
    std::fs::copy(
        history.join("year=2025/plant-2-annual-inspection_2025-11-20.parquet"),
        &added,
    )
    .unwrap();
    let (code, stdout, _) = reproduce(&[s(&out)]);
    assert_eq!(code, 1, "{stdout}");
    assert!(
        stdout.contains("  added: history/year=2027/plant-2-annual-inspection_2027-11-20.parquet"),
        "{stdout}"
    );
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn what_cannot_be_reproduced_is_said() {
    let dir = scratch("reproduce-refused");
    let campaign = example_in(&dir);
    // Another campaign than the example in the current folder, which has its SHA-256.
    let mut text = std::fs::read_to_string(&campaign).unwrap();
    text.push_str("# copied for a test\n");
    std::fs::write(&campaign, text).unwrap();
    let out = dir.join("out");
    let run = [
        "run",
        s(&campaign),
        "--out",
        s(&out),
        "--no-pdf",
        "--no-html",
    ];
    assert_eq!(axcheck(&run).0, 1);

    // Another version: its outputs are not claimed identical.
    let mut json = results(&out);
    json["inputs"]["axcheck"] = "0.0.1".into();
    let edited = dir.join("edited");
    copy_tree(&out, &edited);
    std::fs::write(
        edited.join("results.json"),
        serde_json::to_vec_pretty(&json).unwrap(),
    )
    .unwrap();
    let (code, stdout, _) = reproduce(&[s(&edited)]);
    assert_eq!(code, 1, "{stdout}");
    assert!(
        stdout.contains(&format!(
            "Note: the run was made by axcheck 0.0.1, this is axcheck {}",
            env!("CARGO_PKG_VERSION")
        )),
        "{stdout}"
    );
    assert!(stdout.contains("  differs: results.json"), "{stdout}");

    // A results.json of an axcheck that recorded no inputs.
    json.as_object_mut().unwrap().remove("inputs");
    std::fs::write(
        edited.join("results.json"),
        serde_json::to_vec_pretty(&json).unwrap(),
    )
    .unwrap();
    let (code, _, err) = reproduce(&[s(&edited)]);
    assert_eq!(code, 2);
    assert!(err.contains("no `inputs` block"), "{err}");

    // A PDF away from its run's folder carries no inputs.
    let (code, _, err) = axcheck(&["run", s(&campaign), "--out", s(&dir.join("pdf"))]);
    assert_eq!(code, 1, "{err}");
    let alone = dir.join("summary.pdf");
    std::fs::copy(dir.join("pdf/summary.pdf"), &alone).unwrap();
    let (code, _, err) = reproduce(&[s(&alone)]);
    assert_eq!(code, 2);
    assert!(
        err.contains("the PDF does not carry the inputs of its run"),
        "{err}"
    );

    // The campaign is found by its SHA-256 in a folder beside the output folder, renamed
    // or not; moved further away it is not found, and is given with --campaign.
    std::fs::rename(dir.join("camp"), dir.join("renamed")).unwrap();
    let (code, stdout, err) = reproduce(&[s(&out)]);
    assert_eq!(code, 0, "{stdout}{err}");
    assert!(
        stdout.contains(&format!(
            "Campaign: {}",
            s(&dir.join("renamed/campaign.yaml"))
        )),
        "{stdout}"
    );
    std::fs::create_dir_all(dir.join("far/away")).unwrap();
    std::fs::rename(dir.join("renamed"), dir.join("far/away/camp")).unwrap();
    let (code, _, err) = reproduce(&[s(&out)]);
    assert_eq!(code, 2);
    assert!(
        err.contains("cannot find the campaign file campaign.yaml as the run read it"),
        "{err}"
    );
    let moved = dir.join("far/away/camp/campaign.yaml");
    let (code, stdout, err) = reproduce(&[s(&out), "--campaign", s(&moved)]);
    assert_eq!(code, 0, "{stdout}{err}");
    assert!(stdout.contains("identical: the 13 outputs"), "{stdout}");
    std::fs::remove_dir_all(dir).unwrap();
}
