//! GOST 27843-88: the worked example of the appendix (restored data, see tests/data).

use crate::common::{assert_close, load};
use axcheck::evaluate::ParamKey;
use axcheck::evaluate::gost27843::{Gost27843, SMethod};
use axcheck::evaluate::{Standard, StandardId, evaluate};

#[test]
fn axis_parameters() {
    let e = evaluate(&load("gost27843_example.csv"), StandardId::Gost27843);
    assert_eq!(e.coverage_factor, 3.0);
    // (key, exact from the reference README, printed, position printed)
    for (key, exact, printed) in [
        ("A", 18.004, 18.01),
        ("A_up", 15.217, 15.22),
        ("A_down", 17.388, 17.39),
        ("R_max", 13.499, 13.49),
        ("R_up", 11.838, 11.84),
        ("R_down", 9.892, 9.92),
        ("B_max", 4.480, 4.48),
        ("B_mean", -1.529, -1.53), // printed 1.53 without its sign
    ] {
        let got = e
            .value(ParamKey::parse(key).unwrap())
            .unwrap_or_else(|| panic!("{key} missing"));
        assert_close(&format!("{key} exact"), got, exact, 0.001);
        assert_close(&format!("{key} printed"), got, printed, 0.03);
    }
    let at = |key: &str| {
        e.parameter(ParamKey::parse(key).unwrap())
            .unwrap()
            .at_target
            .unwrap()
            + 1
    };
    assert_eq!(at("R_max"), 11);
    assert_eq!(at("R_up"), 10);
    assert_eq!(at("R_down"), 10);
    assert_eq!(at("B_max"), 2);
    // Formula (9): mean of all 6S over the positions and directions.
    let r_mean: f64 = e
        .targets
        .iter()
        .map(|t| t.up.repeatability.unwrap() + t.down.repeatability.unwrap())
        .sum::<f64>()
        / 22.0;
    assert_close("R̄", e.value(ParamKey::RMean).unwrap(), r_mean, 1e-12);
    assert!(e.value(ParamKey::E).is_none(), "E is ISO's, not GOST's");
}

/// Printed rows (↑, ↓) per position: 3S, X̄ + 3S, X̄ − 3S.
const ROWS: [[(f64, f64); 3]; 11] = [
    [(2.24, 2.49), (0.32, 4.61), (-4.16, -0.37)],
    [(2.09, 1.49), (3.01, 6.89), (-1.17, 3.92)],
    // X̄3↑ + 3S printed "0,17": its sign was lost (−4.18 + 4.01 = −0.17).
    [(4.01, 2.28), (-0.17, 0.94), (-8.19, -3.62)],
    [(2.64, 1.86), (4.10, 4.50), (-1.18, 0.78)],
    [(2.63, 1.98), (-4.69, -6.54), (-9.95, -10.50)],
    // 3S6↓ printed "3,98": 3 × 1.296 = 3.89 (the limit rows confirm it).
    [(3.16, 3.89), (-0.64, -0.71), (-6.96, -8.49)],
    [(3.68, 3.08), (-1.18, -1.64), (-8.54, -7.80)],
    [(4.46, 4.03), (0.72, -0.20), (-8.20, -8.27)],
    [(5.44, 4.90), (-0.24, 0.70), (-11.12, -9.10)],
    // Position 10 ↓ prints 3S = 4.96 and X̄ + 3S = 1.54, but its printed S = 1.649 and
    // X̄ = −3.46 give 3S = 4.95 and X̄ + 3S = 1.49 (its X̄ − 3S = −8.41 agrees).
    [(5.92, 4.95), (1.08, 1.49), (-10.76, -8.41)],
    [(5.55, 4.15), (0.23, 2.61), (-10.87, -5.69)],
];
/// Printed Rj row; position 7 prints 6.90 (3S↑ + 3S↓ + |B|) where formula (8) gives 6S↑ = 7.36,
/// and position 10 prints 12.26 = 5.92 + 4.96 + 1.38 with the 3S10↓ erratum above (12.25).
const R_ROW: [f64; 11] = [
    8.77, 8.06, 9.13, 5.68, 5.81, 7.85, 7.36, 8.99, 11.82, 12.25, 13.49,
];
const B_ROW: [f64; 11] = [
    -4.04, -4.48, -2.84, -1.18, 1.20, 0.80, -0.14, 0.50, -1.48, -1.38, -3.79,
];

#[test]
fn per_target_three_s_and_limit_rows() {
    let e = evaluate(&load("gost27843_example.csv"), StandardId::Gost27843);
    // Printed to 0.01 from S rounded to 0.001. Position 11 ↓ prints S = 1.384 (and limits
    // built on it) where its readings give 1.3885, so 3S differs by 0.014: tolerance 0.02.
    let tol = 0.02;
    for (i, t) in e.targets.iter().enumerate() {
        let [(s3u, s3d), (uu, ud), (lu, ld)] = ROWS[i];
        let p = i + 1;
        assert_close(&format!("3S{p}↑"), 3.0 * t.up.s.unwrap(), s3u, tol);
        assert_close(&format!("3S{p}↓"), 3.0 * t.down.s.unwrap(), s3d, tol);
        assert_close(&format!("X̄{p}↑+3S"), t.up.upper.unwrap(), uu, tol);
        assert_close(&format!("X̄{p}↓+3S"), t.down.upper.unwrap(), ud, tol);
        assert_close(&format!("X̄{p}↑−3S"), t.up.lower.unwrap(), lu, tol);
        assert_close(&format!("X̄{p}↓−3S"), t.down.lower.unwrap(), ld, tol);
        assert_close(&format!("R{p}"), t.repeatability.unwrap(), R_ROW[i], 0.011);
        assert_close(&format!("B{p}"), t.reversal, B_ROW[i], 0.011);
        assert_close(
            &format!("6S{p}↑"),
            t.up.repeatability.unwrap(),
            6.0 * t.up.s.unwrap(),
            1e-12,
        );
    }
}

#[test]
fn s_from_ranges_uses_a_n() {
    let data = load("gost27843_example.csv");
    let e = Gost27843 {
        s_method: SMethod::Ranges,
    }
    .evaluate(&data);
    let t = &e.targets[0];
    // Position 1 ↑: readings −2.6 −1.6 −2.7 −1.8 −0.9, W = 1.8, S = 1.8 × 0.4299.
    assert_close("W1↑", t.up.range.unwrap(), 1.8, 1e-9);
    assert_close("S1↑ by (6)", t.up.s.unwrap(), 1.8 * 0.4299, 1e-9);
    assert!(e.notes.iter().any(|n| n.contains("formula (6)")));
}
