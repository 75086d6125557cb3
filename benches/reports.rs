//! `cargo bench --bench reports`: time per axis report, split into charts, typesetting and
//! PDF export, on one core. Uses the example campaign.
use axcheck::batch;
use axcheck::campaign::Campaign;
use axcheck::report::{Reports, charts, data};
use std::path::Path;
use std::time::Instant;

fn main() {
    let campaign =
        Campaign::load(Path::new("example-campaign/campaign.yaml")).expect("example campaign");
    let result = batch::run(
        &campaign,
        batch::BatchOptions {
            diagnose: true,
            drop_data: false,
            compensate: true,
            record_inputs: false,
        },
        &|_| {},
    );
    let reports = Reports::new(None).expect("templates");
    let tests: Vec<_> = result
        .tests
        .iter()
        .filter(|t| t.evaluated().is_some())
        .collect();
    // Warm up: fonts, library, caches.
    for t in &tests {
        reports.axis(&result, t).expect("report");
    }
    let rounds = 5;
    let start = Instant::now();
    let mut charts_s = 0.0;
    for _ in 0..rounds {
        for t in &tests {
            let c0 = Instant::now();
            let (chart, up, down) = data::axis_chart(&t.evaluated().unwrap().evaluation);
            let style = charts::Style {
                width_px: 900,
                height_px: 420,
            };
            let a = charts::bidirectional(&chart, &style);
            let b = charts::unidirectional(&chart, &up, &down, &style);
            charts_s += c0.elapsed().as_secs_f64();
            std::hint::black_box((a, b));
        }
    }
    let charts_ms = charts_s * 1000.0 / (rounds * tests.len()) as f64;
    let total = Instant::now();
    let mut bytes = 0usize;
    let (mut typeset_s, mut export_s) = (0.0, 0.0);
    for _ in 0..rounds {
        for t in &tests {
            let rendered = reports.axis(&result, t).expect("report");
            bytes += rendered.pdf.len();
            typeset_s += rendered.typeset_time.as_secs_f64();
            export_s += rendered.export_time.as_secs_f64();
        }
        axcheck::report::evict_caches();
    }
    let per_report = total.elapsed().as_secs_f64() * 1000.0 / (rounds * tests.len()) as f64;
    let s = Instant::now();
    for _ in 0..rounds {
        reports.summary(&result).expect("summary");
    }
    let summary_ms = s.elapsed().as_secs_f64() * 1000.0 / rounds as f64;
    println!(
        "axis reports: {} per round, {rounds} rounds, {:.1} s total",
        tests.len(),
        start.elapsed().as_secs_f64()
    );
    let per = |s: f64| s * 1000.0 / (rounds * tests.len()) as f64;
    println!(
        "per axis report (4 pages with the diagnosis): {per_report:.1} ms on one core: layout (Typst's compile) {:.1} ms, PDF export {:.1} ms, the rest (report data, charts as scenes) {:.1} ms; the two ISO charts alone {charts_ms:.1} ms; mean PDF {} KB",
        per(typeset_s),
        per(export_s),
        per_report - per(typeset_s) - per(export_s),
        bytes / (rounds * tests.len()) / 1024
    );
    println!("summary report: {summary_ms:.1} ms");
}
