//! The bad-input catalogue: every broken input gets a clear error naming the file (and
//! line/column where there is one), and the rest of the campaign is still evaluated.

use crate::common::{axcheck, data_path, scratch};

const HEADER: &str = "target_mm,direction,run,deviation_um\n";

/// A valid small test (2 targets, n = 2) with its rows transformed by `f`.
fn rows(extra: &str) -> String {
    format!(
        "{HEADER}0,up,1,1\n0,down,1,2\n100,up,1,3\n100,down,1,4\n0,up,2,1\n0,down,2,2\n100,up,2,3\n100,down,2,4\n{extra}"
    )
}

/// A small Renishaw `.rtl` (2 targets, 2 cycles) with `target_count` on its line, these
/// `deviations` lines (run, target, µm) and `end` after them.
fn rtl(target_count: usize, deviations: &str, end: &str) -> Vec<u8> {
    format!(
        "HEADER::\nFile type : rtl\n\nTARGET DATA::\nTarget-count: {target_count}\nTargets :\n0.000000  100.000000 \nFlags: 0 0 2 0\n\nRUNS::\nRun-count:4\n\nDEVIATIONS::\n{deviations}\n{end}"
    )
    .into_bytes()
}

/// The deviations of [`rtl`]: even runs from the last target down.
const RTL_RUNS: &str = "1 1 1.0\n1 2 2.0\n2 2 2.5\n2 1 1.5\n3 1 1.1\n3 2 2.1\n4 2 2.4\n4 1 1.4\n";

/// Broken lab files: Renishaw `.rtl` and wide tables.
fn broken_lab_files() -> Vec<(&'static str, Vec<u8>, &'static str)> {
    let junk: Vec<u8> = (0..2048u32)
        .map(|k| (k.wrapping_mul(40503) >> 7) as u8)
        .collect();
    vec![
        ("cut-short.rtl", rtl(2, RTL_RUNS, ""), "without `EOF::`"),
        (
            "target-count.rtl",
            rtl(3, RTL_RUNS, "EOF::\n"),
            "Target-count says 3 but 2 targets follow",
        ),
        (
            "missing-reading.rtl",
            rtl(2, &RTL_RUNS.replace("3 2 2.1\n", ""), "EOF::\n"),
            "run 3 has no reading at target 2 (100 mm)",
        ),
        (
            "twice.rtl",
            rtl(2, &format!("{RTL_RUNS}3 1 1.2\n"), "EOF::\n"),
            "run 3 lists target 1 (0 mm) twice",
        ),
        (
            "junk.rtl",
            junk,
            "Renishaw .rtl/.rta: the first line is not `HEADER::`",
        ),
        (
            "wide-no-down.csv",
            "target_mm,up_1_um,up_2_um\n0,1,2\n100,2,3\n".into(),
            "down_1_um",
        ),
        (
            "wide-text.csv",
            "target_mm,up_1_um,down_1_um\n0,1,x\n100,2,3\n".into(),
            "`x`",
        ),
    ]
}

/// (name, file content, what the error must say).
fn broken_files() -> Vec<(&'static str, Vec<u8>, &'static str)> {
    let mut huge_line = HEADER.as_bytes().to_vec();
    huge_line.extend(std::iter::repeat_n(b'7', 1 << 20));
    huge_line.push(b'\n');
    let mut invalid_utf8 = rows("").into_bytes();
    invalid_utf8.extend_from_slice(b"0,up,3,\xc3\x28\n");
    let garbage: Vec<u8> = (0..4096u32)
        .map(|k| (k.wrapping_mul(2654435761) >> 13) as u8)
        .collect();
    let mut many = String::from(HEADER);
    for k in 0..100_001 {
        many.push_str(&format!("{k},up,1,0.5\n"));
    }
    vec![
        ("empty.csv", Vec::new(), "empty"),
        ("header-only.csv", HEADER.into(), "no readings"),
        ("comments-only.csv", "# nothing\n# here\n".into(), "empty"),
        ("garbage.csv", garbage, "garbage.csv"),
        ("invalid-utf8.csv", invalid_utf8, "UTF-8"),
        ("one-mb-line.csv", huge_line, "longer than"),
        (
            "too-many.csv",
            many.into_bytes(),
            "more than 100000 readings",
        ),
        (
            "nan.csv",
            rows("0,up,3,NaN\n").into(),
            "expected a finite number, found `NaN`",
        ),
        (
            "inf.csv",
            rows("0,up,3,inf\n").into(),
            "expected a finite number, found `inf`",
        ),
        (
            "huge.csv",
            rows("0,up,3,1e308\n").into(),
            "is not a plausible deviation",
        ),
        (
            "unknown-column.csv",
            "target_mm,direction,run,deviation_um,colour\n".into(),
            "unknown column `colour`",
        ),
        (
            "typo-column.csv",
            "target_mm,direction,run,deviaton_um\n".into(),
            "did you mean `deviation_um`",
        ),
        (
            "duplicate-column.csv",
            "target_mm,direction,run,run,deviation_um\n".into(),
            "appears twice",
        ),
        (
            "missing-column.csv",
            "target_mm,direction,deviation_um\n0,up,1\n".into(),
            "missing column `run`",
        ),
        (
            "missing-unit.csv",
            "target,direction,run,deviation_um\n".into(),
            "has no unit",
        ),
        (
            "mixed-units.csv",
            "target_mm,direction,run,deviation_arcsec\n".into(),
            "holds angles at targets in mm",
        ),
        (
            "direction-typo.csv",
            rows("0,dwon,3,1\n").into(),
            "did you mean `down`",
        ),
        (
            "run-zero.csv",
            rows("0,up,0,1\n").into(),
            "expected a run number",
        ),
        (
            "run-negative.csv",
            rows("0,up,-1,1\n").into(),
            "expected a run number",
        ),
        (
            "run-fraction.csv",
            rows("0,up,2.5,1\n").into(),
            "expected a run number",
        ),
        (
            "one-direction.csv",
            rows("200,up,1,1\n200,up,2,1\n").into(),
            "has readings in direction up only",
        ),
        ("ragged.csv", rows("0,up,3,1\n").into(), "ragged runs"),
        (
            "duplicate-reading.csv",
            rows("0,up,1,9\n").into(),
            "duplicate reading",
        ),
        (
            "field-count.csv",
            rows("0,up,3\n").into(),
            "expected 4 fields",
        ),
        (
            "bad-target.csv",
            rows("x,up,3,1\n").into(),
            "expected a number, found `x`",
        ),
        (
            "unit-kind.csv",
            "target_deg,direction,run,deviation_arcsec\n0,up,1,1\n0,down,1,1\n".into(),
            "rotary axis",
        ),
        (
            "kv-bad-value.dat",
            "TGT_DATA[1]=0\nREF_DATA_FWD[1,1]=oops\n".into(),
            "expected a finite number",
        ),
        (
            "kv-unknown-key.dat",
            "TGT_DATA[1]=0\nFOO[1]=2\n".into(),
            "unknown key `FOO[…]`",
        ),
        (
            "kv-no-targets.dat",
            "UNIT=mm\nCYCLES=5\n".into(),
            "no TGT_DATA",
        ),
        (
            "kv-unit.dat",
            "UNIT=inch\nTGT_DATA[1]=0\n".into(),
            "unknown unit `inch`",
        ),
        (
            "kv-positions.dat",
            "POSITIONS=3\nTGT_DATA[1]=0\n".into(),
            "POSITIONS=3",
        ),
        (
            "kv-order.dat",
            "TGT_DATA[1]=20\nTGT_DATA[2]=10\n".into(),
            "does not increase",
        ),
        (
            "kv-orphan.dat",
            "TGT_DATA[1]=0\nREF_DATA_BWD[2,1]=0.001\n".into(),
            "which has no TGT_DATA[2]",
        ),
        (
            "kv-cycles.dat",
            "CYCLES=1\nTGT_DATA[1]=0\nREF_DATA_FWD[1,2]=0.001\n".into(),
            "but CYCLES=1",
        ),
        ("kv-bracket.dat", "TGT_DATA[1=0\n".into(), "closing `]`"),
        (
            "kv-duplicate.dat",
            "TGT_DATA[1]=0\nTGT_DATA[1]=1\n".into(),
            "given twice",
        ),
    ]
}

#[test]
fn every_broken_input_fails_alone_with_a_clear_error() {
    let dir = scratch("catalogue");
    std::fs::create_dir_all(dir.join("data/empty-dir")).unwrap();
    std::fs::copy(data_path("iso230-2_table2.csv"), dir.join("data/good.csv")).unwrap();
    // A folder whose symbolic link points back at itself: globbing must not loop.
    #[cfg(unix)]
    {
        std::fs::create_dir_all(dir.join("data/loop")).unwrap();
        std::fs::copy(dir.join("data/good.csv"), dir.join("data/loop/x-1.csv")).unwrap();
        std::os::unix::fs::symlink(dir.join("data/loop"), dir.join("data/loop/again")).unwrap();
    }
    std::fs::create_dir_all(dir.join("specs")).unwrap();
    std::fs::write(
        dir.join("specs/broken.yaml"),
        "name: broken\nlinear:\n  - {up_to_mm: 10, tolerances: {AA: 1}}\n",
    )
    .unwrap();

    let mut files = broken_files();
    files.extend(broken_lab_files());
    let mut yaml = String::from(
        "campaign: {name: Catalogue, spec: general}\nmachines:\n  - id: GOOD\n    axes:\n      - {name: X, kind: linear, data: data/good.csv}\n  - id: FILES\n    axes:\n",
    );
    for (name, bytes, _) in &files {
        std::fs::write(dir.join("data").join(name), bytes).unwrap();
        yaml.push_str(&format!(
            "      - {{name: {name}, kind: linear, data: data/{name}}}\n"
        ));
    }
    // Broken axis entries (each fails alone).
    let axes: Vec<(&str, &str, &str)> = vec![
        (
            "missing-file",
            "{name: missing-file, kind: linear, data: data/nope.csv}",
            "nope.csv",
        ),
        (
            "empty-glob",
            "{name: empty-glob, kind: linear, data: {dir: data/empty-dir, glob: \"*.csv\"}}",
            "no file in",
        ),
        (
            "missing-dir",
            "{name: missing-dir, kind: linear, data: {dir: data/absent, glob: \"*.csv\"}}",
            "does not exist",
        ),
        (
            "bad-glob",
            "{name: bad-glob, kind: linear, data: {dir: data, glob: \"[\"}}",
            "bad glob",
        ),
        (
            "climbs-out",
            "{name: climbs-out, kind: linear, data: ../../etc/passwd}",
            "leaves the campaign's folder",
        ),
        (
            "absolute",
            "{name: absolute, kind: linear, data: /etc/passwd}",
            "is absolute",
        ),
        (
            "spec-climbs-out",
            "{name: spec-climbs-out, kind: linear, data: data/good.csv, spec: ../../etc/x.yaml}",
            "leaves the campaign's folder",
        ),
        (
            "spec-absolute",
            "{name: spec-absolute, kind: linear, data: data/good.csv, spec: /etc/x.yaml}",
            "is absolute",
        ),
        (
            "unknown-key",
            "{name: unknown-key, kind: linear, data: data/good.csv, tolerence: {A: 1}}",
            // The nearest key since issue 46; written as a mapping, `tolerance` then
            // points to `tolerances` (campaign::one_broken_axis_fails_alone).
            "did you mean `tolerance`",
        ),
        (
            "wrong-type",
            "{name: wrong-type, kind: linear, data: data/good.csv, travel: long}",
            "travel: expected a length (600) or its two ends ([0, 600]), got the text `long`",
        ),
        (
            "zero-travel",
            "{name: zero-travel, kind: linear, data: data/good.csv, travel: 0}",
            "expected a length > 0",
        ),
        (
            "bad-kind",
            "{name: bad-kind, kind: linar, data: data/good.csv}",
            "kind: unknown kind `linar` (did you mean `linear`?); expected linear or rotary",
        ),
        (
            "bad-standard",
            "{name: bad-standard, kind: linear, standard: iso9999, data: data/good.csv}",
            "unknown standard",
        ),
        (
            "unknown-spec",
            "{name: unknown-spec, kind: linear, spec: nope, data: data/good.csv}",
            "spec `nope` not found",
        ),
        (
            "broken-spec",
            "{name: broken-spec, kind: linear, spec: broken, data: data/good.csv}",
            "unknown parameter `AA`",
        ),
        (
            "bad-tolerance",
            "{name: bad-tolerance, kind: linear, data: data/good.csv, tolerances: {AA: 1}}",
            "unknown parameter `AA`",
        ),
        (
            "negative-tolerance",
            "{name: negative-tolerance, kind: linear, data: data/good.csv, tolerances: {A: -1}}",
            "expected a limit ≥ 0",
        ),
        (
            "reversed-travel",
            "{name: reversed-travel, kind: linear, data: data/good.csv, measurement_travel: [100, 0]}",
            "last > first",
        ),
        (
            "data-number",
            "{name: data-number, kind: linear, data: 12}",
            "data: expected a file path, a list of paths, {dir: FOLDER, glob: PATTERN} or {file: BOOK, sheet: NAME} ({file: REPORT, reference: N} for an ecmc ISO 230 app file), got the number 12",
        ),
        (
            "travel-four",
            "{name: travel-four, kind: linear, data: data/good.csv, travel: [0, 1, 2, 3]}",
            "travel: expected a length (600) or its two ends ([0, 600]), got a list of 4 items",
        ),
        (
            "kind-list",
            "{name: kind-list, kind: [linear], data: data/good.csv}",
            "kind: expected linear or rotary, got a list of 1 item",
        ),
        (
            "missing-kind",
            "{name: missing-kind, data: data/good.csv}",
            "missing key `kind`",
        ),
        (
            "pitch-text",
            "{name: pitch-text, kind: linear, data: data/good.csv, pitch: fine}",
            "pitch: expected a number, got the text `fine`",
        ),
        (
            "measurement-travel-three",
            "{name: measurement-travel-three, kind: linear, data: data/good.csv, measurement_travel: [0, 1, 2]}",
            "measurement_travel: expected [first, last], got a list of 3 items",
        ),
        (
            "cycle-unknown",
            "{name: cycle-unknown, kind: linear, data: data/good.csv, conditions: {cycle: pilgrm}}",
            "conditions.cycle: unknown cycle `pilgrm` (did you mean `pilgrim`?); expected standard, step or pilgrim",
        ),
        (
            "sensor-kind",
            "{name: sensor-kind, kind: linear, data: data/good.csv, conditions: {temperature_sensors: [{name: s, kind: [air]}]}}",
            "temperature_sensors[0].kind: expected material or air, got a list of 1 item",
        ),
        (
            "data-list-number",
            "{name: data-list-number, kind: linear, data: [data/good.csv, 7]}",
            "data[1]: expected a file path, got the number 7",
        ),
        (
            "data-dir-list",
            "{name: data-dir-list, kind: linear, data: {dir: [data], glob: \"*.csv\"}}",
            "data.dir: expected a folder, got a list of 1 item",
        ),
        (
            "data-glob-typo",
            "{name: data-glob-typo, kind: linear, data: {dir: data, glb: \"*.csv\"}}",
            "data.glb: unknown key `glb` (did you mean `glob`?); expected {dir: FOLDER, glob: PATTERN}",
        ),
        (
            "kind-mismatch",
            "{name: kind-mismatch, kind: rotary, data: data/good.csv}",
            "linear axis",
        ),
    ];
    yaml.push_str("  - id: ENTRIES\n    axes:\n");
    for (_, entry, _) in &axes {
        yaml.push_str(&format!("      - {entry}\n"));
    }
    #[cfg(unix)]
    yaml.push_str("  - id: LOOP\n    axes:\n      - {name: X, kind: linear, data: {dir: data/loop, glob: \"**/x-*.csv\"}}\n");
    let campaign = dir.join("campaign.yaml");
    std::fs::write(&campaign, &yaml).unwrap();

    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&crate::common::run_args(&campaign, &out, &[]));
    assert_eq!(code, 1, "{stdout}{stderr}");
    let results: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("results.json")).unwrap()).unwrap();
    let entries = results["axes"].as_array().unwrap();
    let find = |machine: &str, axis: &str| {
        entries
            .iter()
            .find(|a| a["machine"] == machine && a["axis"] == axis)
            .unwrap_or_else(|| panic!("{machine} {axis} missing from results.json"))
    };
    assert_eq!(
        find("GOOD", "X")["verdict"],
        "pass",
        "the good axis is still evaluated"
    );
    assert!((find("GOOD", "X")["parameters"]["A"].as_f64().unwrap() - 9.586).abs() < 0.001);
    let mut count = 0;
    for (name, _, want) in &files {
        let a = find("FILES", name);
        assert_eq!(a["verdict"], "error", "{name}");
        let e = a["error"].as_str().unwrap();
        assert!(e.contains(name), "{name}: the error names the file: {e}");
        assert!(e.contains(want), "{name}: `{e}` should say `{want}`");
        count += 1;
    }
    for (name, _, want) in &axes {
        let a = find("ENTRIES", name);
        assert_eq!(a["verdict"], "error", "{name}");
        let e = a["error"].as_str().unwrap();
        assert!(e.contains(want), "{name}: `{e}` should say `{want}`");
        count += 1;
    }
    assert!(count >= 50, "{count} broken inputs");
    #[cfg(unix)]
    assert_eq!(
        find("LOOP", "X")["verdict"],
        "pass",
        "the link loop is not followed; the one real file is read"
    );
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_campaign_that_cannot_be_read_exits_2_with_its_location() {
    let dir = scratch("catalogue-yaml");
    let mut laughs = String::from(
        "campaign: {name: x}\na: &a [\"lol\",\"lol\",\"lol\",\"lol\",\"lol\",\"lol\",\"lol\",\"lol\",\"lol\"]\n",
    );
    let mut prev = 'a';
    for k in "bcdefghi".chars() {
        laughs.push_str(&format!(
            "{k}: &{k} [{}]\n",
            vec![format!("*{prev}"); 9].join(",")
        ));
        prev = k;
    }
    laughs.push_str("machines: *i\n");
    let cases: Vec<(&str, String, &str)> = vec![
        ("tabs", "campaign:\n\tname: x\nmachines: []\n".into(), "indented with a tab"),
        ("duplicate", "campaign: {name: x}\ncampaign: {name: y}\nmachines: []\n".into(), "duplicate.yaml:2:1: key `campaign` is given twice"),
        ("laughs", laughs, "repetition limit exceeded"),
        ("top-key", "campaign: {name: x}\nmachine: []\n".into(), "did you mean `machines`"),
        ("no-campaign", "machines: []\n".into(), "missing the `campaign:` block"),
        ("not-a-map", "- 1\n- 2\n".into(), "expected a mapping"),
        ("bad-date", "campaign: {name: x, date: 2026-13-40}\nmachines: []\n".into(), "YYYY-MM-DD"),
        ("date-type", "campaign: {name: x, date: 20261120}\nmachines: []\n".into(), "date-type.yaml:1:27: campaign.date: expected a date YYYY-MM-DD, got the number 20261120"),
        ("machines-map", "campaign: {name: x}\nmachines: {M: 1}\n".into(), "machines-map.yaml:2:11: machines: expected a list of machines, got a mapping with 1 key"),
        ("two-documents", "campaign: {name: x}\nmachines: []\n---\nmachines: []\n".into(), "two-documents.yaml:3:1: more than one YAML document (a `---` line starts another); the file holds one"),
        ("unknown-anchor", "campaign: {name: x}\nmachines: *fleet\n".into(), "unknown-anchor.yaml:2:11: unknown anchor: an alias `*name` needs an anchor `&name` before it"),
        ("info-list", "campaign: [x]\nmachines: []\n".into(), "info-list.yaml:1:11: campaign: expected a mapping (key: value), got a list of 1 item"),
        ("bad-standard", "campaign: {name: x, standard: iso}\nmachines: [{id: M, axes: []}, {id: M, axes: []}]\n".into(), "used twice"),
        ("unclosed", "campaign: {name: x\n".into(), "unclosed.yaml:"),
        ("empty", String::new(), "empty.yaml:1:1: expected a mapping with `campaign:` and `machines:`, got an empty file"),
    ];
    for (name, text, want) in cases {
        let path = dir.join(format!("{name}.yaml"));
        std::fs::write(&path, text).unwrap();
        let (code, _, stderr) = axcheck(&["check", path.to_str().unwrap()]);
        assert_eq!(code, 2, "{name}: {stderr}");
        assert!(
            stderr.contains(&format!("{name}.yaml")),
            "{name}: names the file: {stderr}"
        );
        assert!(
            stderr.contains(want),
            "{name}: `{stderr}` should say `{want}`"
        );
    }
    std::fs::remove_dir_all(dir).unwrap();
}
