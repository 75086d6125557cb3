//! VDI 3441, NMTBA, and what applies when n = 1 (ISO 230-2 clause 5.2).

use crate::common::assert_close;
use axcheck::evaluate::ParamKey;
use axcheck::evaluate::{StandardId, evaluate};
use axcheck::measurement::{AxisData, RawReading};
use axcheck::units::{AxisKind, Direction};

/// Builds an axis from `cells[i] = (up readings, down readings)` at targets 0, 100, 200 …
fn axis(kind: AxisKind, cells: &[(Vec<f64>, Vec<f64>)]) -> AxisData {
    let mut raw = Vec::new();
    for (i, (up, down)) in cells.iter().enumerate() {
        for (d, values) in [(Direction::Up, up), (Direction::Down, down)] {
            for (j, &v) in values.iter().enumerate() {
                raw.push(RawReading {
                    target: 100.0 * i as f64,
                    direction: d,
                    run: j as u32 + 1,
                    deviation: v,
                    time_s: None,
                    temps_c: vec![],
                    line: 0,
                });
            }
        }
    }
    AxisData::from_raw(kind, raw, vec![], "built").unwrap()
}

/// n readings with mean `m` and range `w`.
fn cell(m: f64, w: f64) -> Vec<f64> {
    vec![m - w / 2.0, m, m + w / 2.0, m, m]
}

#[test]
fn vdi3441_reproduces_the_papers_figure_2() {
    // X̄max = 5.3, X̄min = −0.2, every range W = 6σ·d/6 with d(5) = 2.33 and 6σ = 5.8.
    let w = 5.8 / 6.0 * 2.33;
    let data = axis(
        AxisKind::Linear,
        &[
            (cell(5.3, w), cell(5.0, w)),
            (cell(2.0, w), cell(1.5, w)),
            (cell(-0.2, w), cell(0.3, w)),
        ],
    );
    let e = evaluate(&data, StandardId::Vdi3441);
    assert_close("X̄max", e.value(ParamKey::XMax).unwrap(), 5.3, 1e-9);
    assert_close("X̄min", e.value(ParamKey::XMin).unwrap(), -0.2, 1e-9);
    assert_close("Ā", e.value(ParamKey::AMean).unwrap(), 2.55, 1e-9);
    assert_close("T", e.value(ParamKey::T).unwrap(), 11.3, 1e-9);
    assert_close("Rp", e.value(ParamKey::Rp).unwrap(), 5.8, 1e-9);
    assert_close("G_o", e.value(ParamKey::GUpper).unwrap(), 2.55 + 5.65, 1e-9);
    assert_close("G_u", e.value(ParamKey::GLower).unwrap(), 2.55 - 5.65, 1e-9);
    assert_close("σ_i", e.targets[0].up.s.unwrap(), w / 2.33, 1e-12);
}

#[test]
fn nmtba_zero_line_accuracy_and_lost_motion() {
    let data = axis(
        AxisKind::Linear,
        &[
            (vec![1.0, 3.0], vec![-1.0, 1.0]),
            (vec![0.0, 0.0], vec![0.0, 0.0]),
        ],
    );
    let e = evaluate(&data, StandardId::Nmtba);
    let sigma_b = (8.0f64 / 3.0).sqrt();
    assert_close("zero", e.value(ParamKey::Zero).unwrap(), 0.5, 1e-12);
    assert_close(
        "A_b",
        e.value(ParamKey::A).unwrap(),
        0.5 + 3.0 * sigma_b,
        1e-12,
    );
    assert_close(
        "A_u↑",
        e.value(ParamKey::AUp).unwrap(),
        1.0 + 3.0 * 2f64.sqrt(),
        1e-12,
    );
    assert_close(
        "A_u↓",
        e.value(ParamKey::ADown).unwrap(),
        3.0 * 2f64.sqrt(),
        1e-12,
    );
    assert_close("L_max", e.value(ParamKey::LMax).unwrap(), 2.0, 1e-12);
    assert_eq!(e.parameter(ParamKey::LMax).unwrap().at_target, Some(0));
    assert_close("L̄", e.value(ParamKey::LMean).unwrap(), 1.0, 1e-12);
}

fn n_equals_one() -> AxisData {
    axis(
        AxisKind::Rotary,
        &[
            (vec![1.0], vec![-2.0]),
            (vec![4.0], vec![0.5]),
            (vec![-3.0], vec![-1.0]),
        ],
    )
}

#[test]
fn n_equals_one_keeps_only_clause_5_2_parameters() {
    let data = n_equals_one();
    for standard in [StandardId::Iso230_2, StandardId::Gbt17421_2] {
        let e = evaluate(&data, standard);
        let keys: Vec<&str> = e.parameters.iter().map(|p| p.key()).collect();
        assert_eq!(keys, vec!["E", "E_up", "E_down", "M", "B", "B_mean"]);
        assert_close("E", e.value(ParamKey::E).unwrap(), 7.0, 1e-12);
        assert_close("E↑", e.value(ParamKey::EUp).unwrap(), 7.0, 1e-12);
        assert_close("E↓", e.value(ParamKey::EDown).unwrap(), 2.5, 1e-12);
        assert_close("M", e.value(ParamKey::M).unwrap(), 2.25 - (-2.0), 1e-12);
        assert_close("B", e.value(ParamKey::B).unwrap(), 3.5, 1e-12);
        assert_close(
            "B̄",
            e.value(ParamKey::BMean).unwrap(),
            (3.0 + 3.5 - 2.0) / 3.0,
            1e-12,
        );
        assert_eq!(e.unit(), "arcsec");
        for t in &e.targets {
            assert!(t.up.s.is_none() && t.up.upper.is_none() && t.repeatability.is_none());
        }
        let json = serde_json::to_value(e.json()).unwrap();
        let params = json["parameters"].as_object().unwrap();
        assert!(
            !params.contains_key("A") && !params.contains_key("R"),
            "absent, never 0"
        );
        assert!(json["targets"][0]["up"].get("s").is_none());
    }
    let gost = evaluate(&data, StandardId::Gost27843);
    let keys: Vec<&str> = gost.parameters.iter().map(|p| p.key()).collect();
    assert_eq!(keys, vec!["B_max", "B_mean"]);
    let vdi = evaluate(&data, StandardId::Vdi3441);
    assert!(vdi.value(ParamKey::T).is_none() && vdi.value(ParamKey::AMean).is_some());
    let nmtba = evaluate(&data, StandardId::Nmtba);
    assert!(nmtba.value(ParamKey::A).is_none() && nmtba.value(ParamKey::LMax).is_some());
}

#[test]
fn rotary_axes_use_the_same_formulas_in_arcsec() {
    let cells = [
        (cell(1.0, 2.0), cell(-1.0, 1.0)),
        (cell(3.0, 1.0), cell(0.0, 2.0)),
    ];
    let lin = evaluate(&axis(AxisKind::Linear, &cells), StandardId::Iso230_2);
    let rot = evaluate(&axis(AxisKind::Rotary, &cells), StandardId::Iso230_2);
    assert_eq!(lin.parameters.len(), rot.parameters.len());
    for (a, b) in lin.parameters.iter().zip(&rot.parameters) {
        assert_eq!(a.value, b.value, "{}", a.key());
    }
    let json = serde_json::to_value(rot.json()).unwrap();
    assert_eq!(json["unit"], "arcsec");
    assert_eq!(json["position_unit"], "deg");
}

#[test]
fn standard_names_parse() {
    assert_eq!(StandardId::parse("iso230-2"), Some(StandardId::Iso230_2));
    assert_eq!(
        StandardId::parse("ISO 230-2:1997"),
        Some(StandardId::Iso230_2)
    );
    assert_eq!(
        StandardId::parse("gbt17421.2-2000"),
        Some(StandardId::Gbt17421_2)
    );
    assert_eq!(
        StandardId::parse("GB/T 17421.2"),
        Some(StandardId::Gbt17421_2)
    );
    assert_eq!(
        StandardId::parse("gost27843-88"),
        Some(StandardId::Gost27843)
    );
    assert_eq!(StandardId::parse("vdi3441"), Some(StandardId::Vdi3441));
    assert_eq!(StandardId::parse("nmtba"), Some(StandardId::Nmtba));
    assert_eq!(StandardId::parse("iso9999"), None);
}
