//! The real measurements of `tests/data/ecmc/` (published by the ecmc motion-control
//! project; see `SOURCES.md` there): every file is read, by the layout its content says,
//! and each original key=value file gives the parameters of the long CSV converted from
//! it, to below the printed 0.01 µm (the CSVs round the deviations to 0.0001 µm).

use crate::common::data_path;
use axcheck::evaluate::{StandardId, evaluate};
use axcheck::measurement::{self, Layout};

/// Every file of the folder with the extension `ext`, sorted.
fn files(ext: &str) -> Vec<std::path::PathBuf> {
    let mut out: Vec<_> = std::fs::read_dir(data_path("ecmc"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == ext))
        .collect();
    out.sort();
    out
}

#[test]
fn every_real_file_is_read_by_the_layout_of_its_content() {
    let (csv, dat) = (files("csv"), files("dat"));
    assert_eq!((csv.len(), dat.len()), (15, 9));
    for (path, layout) in csv
        .iter()
        .map(|p| (p, Layout::LongCsv))
        .chain(dat.iter().map(|p| (p, Layout::KeyValue)))
    {
        let read = measurement::read_file(path, None)
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert_eq!(read.recognised.layout, layout, "{}", path.display());
        let e = evaluate(&read.data, StandardId::Iso230_2);
        assert!(
            e.parameters
                .iter()
                .all(|p| p.value.is_finite() || read.data.runs() < 2)
        );
    }
}

#[test]
fn each_original_file_gives_the_parameters_of_its_csv() {
    for dat in files("dat") {
        let csv = dat.with_extension("csv");
        let of = |p: &std::path::Path| {
            let read = measurement::read_file(p, None).unwrap();
            evaluate(&read.data, StandardId::Iso230_2)
        };
        let (a, b) = (of(&dat), of(&csv));
        let positions = |e: &axcheck::evaluate::Evaluation| -> Vec<f64> {
            e.targets.iter().map(|t| t.position).collect()
        };
        assert_eq!(positions(&a), positions(&b), "{}", dat.display());
        for (x, y) in a.parameters.iter().zip(&b.parameters) {
            assert_eq!(x.key(), y.key());
            assert!(
                (x.value - y.value).abs() < 1e-3,
                "{}: {} = {} from the original, {} from the CSV",
                dat.display(),
                x.key(),
                x.value,
                y.value
            );
        }
    }
}

/// The ecmc motion system test reports of 2021: each Markdown original gives the
/// parameters of the long CSV made from it, and the results it prints are set beside
/// axcheck's with their causes: the 2021-11 report's directions swapped, its R the larger
/// of R↑ and R↓.
#[test]
fn the_2021_reports_are_read_and_their_results_explained() {
    for name in [
        "bifrost_11358_ax1",
        "bifrost_11360_ax1_slow",
        "bifrost_11360_ax1_scanfit",
    ] {
        let md = measurement::read_file(&data_path(&format!("ecmc/{name}.md")), None).unwrap();
        assert_eq!(md.recognised.layout, Layout::EcmcReport, "{name}");
        let csv = measurement::read_file(&data_path(&format!("ecmc/{name}.csv")), None).unwrap();
        let (a, b) = (
            evaluate(&md.data, StandardId::Iso230_2),
            evaluate(&csv.data, StandardId::Iso230_2),
        );
        for (p, q) in a.parameters.iter().zip(&b.parameters) {
            assert_eq!(p.key(), q.key());
            assert!(
                (p.value - q.value).abs() < 0.005,
                "{name} {}: {} against {}",
                p.key(),
                p.value,
                q.value
            );
        }
    }
    let md = measurement::read_file(&data_path("ecmc/bifrost_11358_ax1.md"), None).unwrap();
    assert!(
        md.recognised
            .notes
            .iter()
            .any(|n| n.contains("swaps the input's directions"))
    );
    let tool = axcheck::crosscheck::compare(md.recognised.reported.as_ref().unwrap(), &md.data);
    let agreeing: Vec<&str> = (tool.parameters.iter())
        .filter(|c| c.agree)
        .map(|c| c.parameter.as_str())
        .collect();
    assert_eq!(agreeing, ["B", "M", "A"]);
    let cause = |key: &str| {
        let d = tool
            .differences
            .iter()
            .find(|d| d.parameter == key)
            .unwrap();
        d.cause.clone().unwrap_or_default()
    };
    for key in [
        "B_mean", "R_up", "R_down", "E_up", "E_down", "A_up", "A_down",
    ] {
        assert!(
            cause(key).contains("the two directions the other way round"),
            "{key}: {}",
            cause(key)
        );
    }
    assert!(
        cause("R").contains("the larger of R↑ and R↓"),
        "{}",
        cause("R")
    );
    assert!(
        cause("E").contains("larger of their lowest"),
        "{}",
        cause("E")
    );
    // The 2021-10 report: B, B̄, E, M agree; every value made of s is the last-target slip.
    let md = measurement::read_file(&data_path("ecmc/bifrost_11360_ax1_slow.md"), None).unwrap();
    let tool = axcheck::crosscheck::compare(md.recognised.reported.as_ref().unwrap(), &md.data);
    let agreeing: Vec<&str> = (tool.parameters.iter())
        .filter(|c| c.agree)
        .map(|c| c.parameter.as_str())
        .collect();
    assert_eq!(agreeing, ["B", "B_mean", "E_up", "E_down", "E", "M"]);
    for d in &tool.differences {
        let cause = d.cause.as_deref().unwrap_or_default();
        assert!(
            cause.contains("from the last target's readings"),
            "{}: {cause}",
            d.parameter
        );
    }
}
