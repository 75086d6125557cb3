//! summary.html in a real browser (headless Chromium through its DevTools protocol): the
//! example campaign's page, and a campaign whose names are written to break out of the
//! page's script and markup.

use crate::browser::cdp::Browser;
use crate::common::{axcheck, copy_data, copy_tree, scratch};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use std::time::Duration;

/// The example campaign run once for all tests of this file.
fn example_page() -> &'static Path {
    static OUT: OnceLock<PathBuf> = OnceLock::new();
    OUT.get_or_init(|| {
        let out = std::env::temp_dir().join(format!("axcheck-html-ex-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&out);
        let out_s = out.to_str().unwrap();
        let args = ["run", "example-campaign/campaign.yaml", "--out", out_s];
        let (code, stdout, stderr) = axcheck(&args);
        assert_eq!(code, 1, "the example has failing axes: {stdout}{stderr}");
        assert!(stdout.contains("summary.html"), "{stdout}");
        out.join("summary.html")
    })
}

fn url(path: &Path) -> String {
    format!("file://{}", path.display())
}

/// The page opened, its first rows drawn, with nothing on the console and no request but
/// the page itself.
fn open(page: &Path) -> Browser {
    let mut b = Browser::launch().unwrap_or_else(|e| panic!("{e}"));
    b.open(&url(page)).unwrap();
    b.wait_for("window.axcheckFirstRowsMs", Duration::from_secs(10))
        .unwrap();
    b
}

fn shown(b: &mut Browser) -> String {
    let v = b.eval("document.getElementById('shown-count').textContent");
    v.unwrap().as_str().unwrap_or_default().to_string()
}

/// The test ids of the rows in the document, in order.
fn row_ids(b: &mut Browser) -> Vec<String> {
    let js =
        "[...document.querySelectorAll('#rows tr[data-test-id]')].map(tr => tr.dataset.testId)";
    let v = b.eval(js).unwrap();
    let ids = v.as_array().unwrap().iter();
    ids.map(|x| x.as_str().unwrap().to_string()).collect()
}

/// (test id, E) of every axis test in results.json.
fn results_e(out: &Path) -> Vec<(String, Option<f64>)> {
    let text = std::fs::read(out.join("results.json")).unwrap();
    let results: Value = serde_json::from_slice(&text).unwrap();
    let axes = results["axes"].as_array().unwrap();
    axes.iter()
        .map(|a| {
            // The axis with the other laser tests' symbol (`X EYX`, `X-Y squareness`).
            let axis = match (&a["geometry"]["symbol"], &a["geometry"]["test"]) {
                (Value::String(symbol), _) => format!("{} {symbol}", str(&a["axis"])),
                (_, Value::String(t)) if t == "squareness" => {
                    format!("{} squareness", str(&a["axis"]))
                }
                _ => str(&a["axis"]).to_string(),
            };
            let id = format!("{}|{axis}|{}", str(&a["machine"]), a["test"]);
            (id, a["parameters"]["E"].as_f64())
        })
        .collect()
}

fn str(v: &Value) -> &str {
    v.as_str().unwrap()
}

#[test]
fn the_example_page_renders_quietly_and_on_its_own() {
    let page = example_page();
    let mut b = open(page);
    assert_eq!(b.console_errors(), Vec::<String>::new());
    // No request but the page: no script, style, font or image from anywhere else.
    assert_eq!(b.requests(), [url(page)]);
    assert_eq!(shown(&mut b), "33 of 33 tests");
    let title = b
        .eval("document.getElementById('title').textContent")
        .unwrap();
    assert_eq!(title, "Plant 2 annual inspection");
    // The verdict counts, each a button with its number and its verdict as text.
    let counts = b
        .eval("[...document.querySelectorAll('#counts button')].map(x => x.textContent)")
        .unwrap();
    let want = [
        "33 tests",
        "2 FAIL",
        "1 NONCOMPLIANT",
        "1 INCONCLUSIVE",
        "0 ERROR",
        "1 NOT JUDGED",
        "28 PASS",
    ];
    assert_eq!(counts, serde_json::json!(want));
    // Verdicts are words in the rows, not colours only.
    let verdict = "document.querySelector('tr[data-test-id=\"VMC-07|Y|1\"]').dataset.verdict + ' ' + \
         document.querySelector('tr[data-test-id=\"VMC-07|Y|1\"] .badge').textContent";
    assert_eq!(b.eval(verdict).unwrap(), "fail FAIL");
}

#[test]
fn typing_a_machine_name_shows_its_tests() {
    let page = example_page();
    let mut b = open(page);
    b.click("#search").unwrap();
    b.type_text("LATHE").unwrap();
    assert_eq!(shown(&mut b), "3 of 33 tests");
    let ids = row_ids(&mut b);
    assert_eq!(ids, ["LATHE-5|X|1", "LATHE-5|Z|1", "LATHE-5|C|1"]);
    // Words narrow together (machine and verdict), and the verdict buttons filter too.
    b.type_text(" noncompliant").unwrap();
    assert_eq!(shown(&mut b), "1 of 33 tests");
    assert_eq!(row_ids(&mut b), ["LATHE-5|X|1"]);
    for _ in 0.."LATHE noncompliant".len() {
        b.press_key("Backspace").unwrap();
    }
    assert_eq!(shown(&mut b), "33 of 33 tests");
    b.click("#counts button[data-verdict=\"fail\"]").unwrap();
    assert_eq!(shown(&mut b), "2 of 33 tests");
    assert_eq!(row_ids(&mut b), ["VMC-07|Y|1", "MILL-3|Y|1"]);
    let pressed = "document.querySelector('#counts button[data-verdict=\"fail\"]').ariaPressed";
    assert_eq!(b.eval(pressed).unwrap(), "true");
    assert_eq!(b.console_errors(), Vec::<String>::new());
}

#[test]
fn sorting_by_e_puts_the_largest_first() {
    let page = example_page();
    let mut expected = results_e(page.parent().unwrap());
    // Numbers as numbers, largest first; tests without E (GOST) last.
    expected.sort_by(|a, b| match (a.1, b.1) {
        (Some(x), Some(y)) => y.total_cmp(&x),
        (x, y) => x.is_none().cmp(&y.is_none()),
    });
    let mut b = open(page);
    b.click("button[data-column=\"E\"]").unwrap();
    let ids = row_ids(&mut b);
    assert!(ids.len() >= 10, "{ids:?}");
    let want: Vec<&str> = expected.iter().map(|(id, _)| id.as_str()).collect();
    assert_eq!(ids, want[..ids.len()]);
    assert_eq!(ids[0], "GANTRY-1|X|1", "E = 25.11 µm is the largest");
    let sort = "document.querySelector('button[data-column=\"E\"]').parentElement.ariaSort";
    assert_eq!(b.eval(sort).unwrap(), "descending");
    // A second click turns the order round (the test without E stays last).
    b.click("button[data-column=\"E\"]").unwrap();
    assert_eq!(
        row_ids(&mut b)[0],
        "MILL-3|X|1",
        "E = 1.07 µm is the smallest"
    );
}

#[test]
fn clicking_a_row_shows_its_detail_with_its_charts() {
    let page = example_page();
    let mut b = open(page);
    b.click("tr[data-test-id=\"MILL-3|Y|1\"]").unwrap();
    let charts = "document.querySelectorAll('#detail svg[role=img]').length >= 2 && \
                  document.getElementById('detail').innerText";
    let text = b.wait_for(charts, Duration::from_secs(10)).unwrap();
    let text = text.as_str().unwrap();
    for want in [
        "MILL-3 Y",
        "FAIL",
        "ISO 230-2 2.20",
        "23.00",
        "Bidirectional positional deviations (ISO 230-2 Fig. 2a)",
        "Unidirectional positional deviations (ISO 230-2 Fig. 2b)",
        "sign_inverted",
    ] {
        assert!(text.contains(want), "{want:?} not in the detail:\n{text}");
    }
    // The charts are the PDF's scenes: polylines and marks, with their axis labels.
    let marks = b
        .eval("document.querySelectorAll('#detail svg path, #detail svg polyline').length")
        .unwrap();
    assert!(marks.as_u64().unwrap() > 20, "{marks}");
    let link = b
        .eval("document.querySelector('#detail a[href$=\".pdf\"]').getAttribute('href')")
        .unwrap();
    assert_eq!(link, "reports/MILL-3/Y.pdf");
    assert!(page.parent().unwrap().join(str(&link)).is_file());
    // The address names the test, so the link can be sent; Escape closes the detail.
    let hash = b.eval("decodeURIComponent(location.hash)").unwrap();
    assert_eq!(hash, "#MILL-3|Y|1");
    b.press_key("Escape").unwrap();
    assert_eq!(
        b.eval("document.getElementById('detail').hidden").unwrap(),
        true
    );
    assert_eq!(b.console_errors(), Vec::<String>::new());
}

#[test]
fn the_keyboard_reaches_every_row_and_opens_it() {
    let page = example_page();
    let mut b = open(page);
    b.click("#search").unwrap();
    b.type_text("lathe").unwrap();
    // Down from the search box: the first row; then the next; Enter opens it.
    b.press_key("ArrowDown").unwrap();
    b.press_key("ArrowDown").unwrap();
    let focused = b.eval("document.activeElement.dataset.testId").unwrap();
    assert_eq!(focused, "LATHE-5|Z|1");
    b.press_key("Enter").unwrap();
    let title = "!document.getElementById('detail').hidden && document.activeElement.textContent";
    let title = b.wait_for(title, Duration::from_secs(10)).unwrap();
    assert!(title.as_str().unwrap().starts_with("LATHE-5 Z"), "{title}");
}

/// A campaign (`campaign: {head}`) of one machine and axis, named as given (in YAML's
/// single quotes), measured as ISO 230-2 Table 2, run with `--no-pdf` and `extra` in the
/// scratch folder `name`. Returns the output folder, the exit status and the console.
fn run_table2(
    name: &str,
    head: &str,
    machine: &str,
    axis: &str,
    extra: &[&str],
) -> (PathBuf, i32, String) {
    let dir = scratch(name);
    copy_data(&dir, "iso230-2_table2.csv");
    let campaign = format!(
        "campaign: {{{head}}}\nmachines:\n  - id: '{machine}'\n    axes:\n      - {{name: '{axis}', kind: linear, data: data/iso230-2_table2.csv}}\n"
    );
    let c = dir.join("campaign.yaml");
    std::fs::write(&c, campaign).unwrap();
    let out = dir.join("out");
    let mut args = vec![
        "run",
        c.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
    ];
    args.extend(extra);
    let (code, stdout, stderr) = axcheck(&args);
    (out, code, stdout + &stderr)
}

/// Names that would end the data's script element or become markup stay text.
#[test]
fn hostile_names_appear_as_text() {
    let machine = "</script><img src=x onerror=alert(1)>";
    let head = "name: '<!-- </SCRIPT> <b>bold</b>', date: 2026-11-20, spec: general";
    let (out, code, stdout) = run_table2("html-hostile", head, machine, "\u{2028}<i>X</i>", &[]);
    assert!(code == 0 || code == 1, "{stdout}");
    let html = std::fs::read_to_string(out.join("summary.html")).unwrap();
    assert!(
        !html.contains(machine),
        "the name is escaped in the page's source"
    );

    let mut b = open(&out.join("summary.html"));
    let cell = b.eval("document.querySelector('#rows tr[data-test-id] td').textContent");
    assert_eq!(cell.unwrap(), machine);
    let title = b
        .eval("document.getElementById('title').textContent")
        .unwrap();
    assert_eq!(title, "<!-- </SCRIPT> <b>bold</b>");
    let markup = "document.querySelectorAll('img, b, i').length";
    assert_eq!(b.eval(markup).unwrap(), 0);
    b.click("#rows tr[data-test-id]").unwrap();
    let detail = "!document.getElementById('detail').hidden && document.getElementById('detail-title').textContent";
    let detail = b.wait_for(detail, Duration::from_secs(10)).unwrap();
    assert!(detail.as_str().unwrap().starts_with(machine), "{detail}");
    assert_eq!(b.eval(markup).unwrap(), 0);
    assert_eq!(b.console_errors(), Vec::<String>::new());
    assert_eq!(b.requests(), [url(&out.join("summary.html"))]);
}

#[test]
fn no_html_skips_the_page() {
    let head = "name: Skip, date: 2026-11-20, spec: general";
    let (out, code, stdout) = run_table2("html-skip", head, "M1", "X", &[]);
    assert_eq!(code, 0, "{stdout}");
    assert!(out.join("summary.html").is_file());
    // Again into the same folder, without the page.
    let c = out.parent().unwrap().join("campaign.yaml");
    let (c, o) = (c.to_str().unwrap(), out.to_str().unwrap());
    let (code, stdout, _) = axcheck(&["run", c, "--out", o, "--no-pdf", "--no-html"]);
    assert_eq!(code, 0, "{stdout}");
    // The run's manifest removes the page the earlier run wrote.
    assert!(!out.join("summary.html").exists(), "{stdout}");
    assert!(!stdout.contains("summary.html"), "{stdout}");
}

/// With a history, the table has the trend flags and a test's detail its history charts.
#[test]
fn a_run_with_a_history_shows_trends_and_history_charts() {
    let dir = scratch("html-history");
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let history = dir.join("history");
    copy_tree(&root.join("example-campaign/history"), &history);
    let out = dir.join("out");
    let args = [
        "run",
        "example-campaign/campaign.yaml",
        "--out",
        out.to_str().unwrap(),
        "--history",
        history.to_str().unwrap(),
        "--no-pdf",
    ];
    let (code, stdout, stderr) = axcheck(&args);
    assert_eq!(code, 1, "{stdout}{stderr}");
    let mut b = open(&out.join("summary.html"));
    let trend =
        "document.querySelector('tr[data-test-id=\"VMC-07|Y|1\"] td:last-child').textContent";
    assert_eq!(b.eval(trend).unwrap(), "flagged: A, B, B_mean, E, R");
    b.click("button[data-column=\"trend\"]").unwrap();
    b.click("tr[data-test-id=\"VMC-07|Y|1\"]").unwrap();
    let charts = "document.querySelectorAll('#detail .charts-history svg').length";
    let n = b.wait_for(charts, Duration::from_secs(10)).unwrap();
    // One chart per parameter with a limit or a trend: A, A↑, E, R, B, B̄ for this axis.
    assert_eq!(n, 6);
    assert_eq!(b.console_errors(), Vec::<String>::new());
}

/// Every path and text of an SVG chart in the detail, as the page set them: per path its
/// fill, stroke, stroke width, dashes, opacity and outline; per text its position,
/// baseline offset, anchor, size, colour, weight, rotation and content.
const DRAWN: &str = "[...document.querySelectorAll('#detail svg[role=img]')].map(svg => ({
    size: [svg.getAttribute('width'), svg.getAttribute('height'), svg.getAttribute('viewBox')],
    paths: [...svg.querySelectorAll('path')].map(p => ['fill', 'stroke', 'stroke-width',
        'stroke-dasharray', 'opacity', 'd'].map(a => p.getAttribute(a))),
    texts: [...svg.querySelectorAll('text')].map(t => ['x', 'y', 'dy', 'text-anchor', 'font-size',
        'fill', 'font-weight', 'transform'].map(a => t.getAttribute(a)).concat([t.textContent])),
  }))";

/// What [`DRAWN`] reads from the page, made from a scene as the PDF report draws it.
fn drawn(scene: &axcheck_charts::chart_kit::scene::Scene) -> Value {
    use axcheck_charts::chart_kit::scene::{Align, Paint};
    let number = |x: f64| Value::from(x.to_string());
    let paths: Vec<Value> = (scene.drawing.shapes.iter())
        .map(|shape| {
            let (fill, stroke, width, dash) = match &shape.paint {
                Paint::Fill(c) => (c.hex(), "none".to_string(), Value::Null, Value::Null),
                Paint::Stroke {
                    colour,
                    width,
                    dash,
                } => {
                    let dash = dash.iter().map(|d| d.to_string()).collect::<Vec<_>>();
                    let dash = Some(dash.join(" ")).filter(|d| !d.is_empty());
                    (
                        "none".into(),
                        colour.hex(),
                        width.to_string().into(),
                        dash.into(),
                    )
                }
            };
            let opacity = (shape.opacity != 1.0).then(|| number(shape.opacity));
            serde_json::json!([fill, stroke, width, dash, opacity, shape.path_data()])
        })
        .collect();
    let texts: Vec<Value> = (scene.texts.iter())
        .map(|t| {
            let (x, y) = t.at;
            let anchor = match t.align {
                Align::Left => "start",
                Align::Center => "middle",
                Align::Right => "end",
            };
            let weight = t.bold.then_some("bold");
            let rotate = (t.rotate != 0).then(|| format!("rotate({}, {x}, {y})", t.rotate));
            serde_json::json!([
                x.to_string(),
                y.to_string(),
                number(t.dy()),
                anchor,
                number(t.size),
                t.colour.hex(),
                weight,
                rotate,
                t.text
            ])
        })
        .collect();
    let (w, h) = (scene.drawing.width, scene.drawing.height);
    serde_json::json!({
        "size": [w.to_string(), h.to_string(), format!("0 0 {w} {h}")],
        "paths": paths,
        "texts": texts,
    })
}

/// The page's charts are the report's scenes, drawn element for element: the scenes of
/// ISO 230-2 Fig. 2a and 2b made here from the same file are what the browser shows.
#[test]
fn the_drawn_charts_are_the_scenes_of_the_report() {
    let head = "name: Scenes, date: 2026-11-20, spec: general";
    let (out, code, stdout) = run_table2("html-scenes", head, "M1", "X", &[]);
    assert!(code == 0 || code == 1, "{stdout}");
    let csv = std::fs::read(crate::common::data_path("iso230-2_table2.csv")).unwrap();
    let data = axcheck::measurement::read(csv.as_slice(), "iso230-2_table2.csv").unwrap();
    let evaluation =
        axcheck::evaluate::evaluate(&data.data, axcheck::evaluate::StandardId::Iso230_2);
    let want: Vec<Value> = (axcheck_charts::figures::iso_charts(&evaluation).iter())
        .map(drawn)
        .collect();

    let mut b = open(&out.join("summary.html"));
    b.click("#rows tr[data-test-id]").unwrap();
    let two = "document.querySelectorAll('#detail svg[role=img]').length === 2";
    b.wait_for(two, Duration::from_secs(10)).unwrap();
    let got = b.eval(DRAWN).unwrap();
    let got = got.as_array().unwrap();
    assert_eq!(got.len(), 2);
    for (got, want) in got.iter().zip(&want) {
        assert_eq!(got["size"], want["size"]);
        // Element by element, so that a difference names its element.
        for part in ["paths", "texts"] {
            let (g, w) = (
                got[part].as_array().unwrap(),
                want[part].as_array().unwrap(),
            );
            for (k, (g, w)) in g.iter().zip(w).enumerate() {
                assert_eq!(g, w, "{part} {k}");
            }
            assert_eq!(g.len(), w.len(), "{part}");
        }
    }
    // The readings' dots: 11 targets × 5 runs up, each a circle of radius 2.
    let dots = want[0]["paths"].as_array().unwrap().iter();
    let dots = dots.map(|p| p[5].as_str().unwrap().matches(" a2,2 0 1,0 4,0").count());
    assert!(dots.max().unwrap() >= 55);
    assert_eq!(b.console_errors(), Vec::<String>::new());
}

/// Bytes of summary.html per axis test: 15 MB for a plant of 10 000 axes (issue 48).
const BYTES_PER_TEST: u64 = 1_500;

/// A 1 000-axis fleet's page stays within [`BYTES_PER_TEST`], and a test of its last
/// machine (in the last, partial block of details) opens with its charts.
#[test]
fn a_fleets_page_stays_small_and_opens_its_last_test() {
    let dir = scratch("html-fleet");
    let fleet = dir.join("fleet");
    let fleet_s = fleet.to_str().unwrap();
    let (code, _, stderr) = axcheck(&[
        "simulate", "--fleet", "1000", "--seed", "3", "--out", fleet_s,
    ]);
    assert_eq!(code, 0, "{stderr}");
    let out = dir.join("out");
    let campaign = fleet.join("campaign.yaml");
    let args = [
        "run",
        campaign.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
    ];
    let (code, stdout, stderr) = axcheck(&args);
    assert!(code == 0 || code == 1, "{stdout}{stderr}");
    let page = out.join("summary.html");
    let size = std::fs::metadata(&page).unwrap().len();
    assert!(
        size <= 1_000 * BYTES_PER_TEST,
        "{size} bytes for 1000 tests"
    );

    let mut b = open(&page);
    assert_eq!(shown(&mut b), "1000 of 1000 tests");
    // The last machine first (sorted by machine, twice for descending).
    b.click("button[data-column=\"machine\"]").unwrap();
    b.click("button[data-column=\"machine\"]").unwrap();
    let last = row_ids(&mut b)[0].clone();
    b.click("#rows tr[data-test-id]").unwrap();
    let charts = "document.querySelectorAll('#detail svg[role=img]').length === 2 && \
                  document.getElementById('detail-title').textContent";
    let title = b.wait_for(charts, Duration::from_secs(10)).unwrap();
    let mut id = last.split('|');
    let (machine, axis) = (id.next().unwrap(), id.next().unwrap());
    assert!(machine.starts_with('M') && machine.len() >= 5, "{last}");
    let title = title.as_str().unwrap();
    assert!(title.starts_with(&format!("{machine} {axis}")), "{title}");
    assert_eq!(b.console_errors(), Vec::<String>::new());
    let _ = std::fs::remove_dir_all(&dir);
}
