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
