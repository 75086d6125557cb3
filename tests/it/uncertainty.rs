//! The uncertainty budget (issue 14): hand-computed budgets, U against the length a
//! parameter spans, the ISO 230-2 Table 2 example under its stated conditions, and a
//! rotary axis in arcseconds.

use crate::common::{assert_close, load};
use axcheck::evaluate::ParamKey;
use axcheck::evaluate::{StandardId, evaluate};
use axcheck::measurement::{AxisData, RawReading};
use axcheck::uncertainty::{self, Budget, InstrumentKind, Setup, Uncertainty};
use axcheck::units::{AxisKind, Direction};

/// A test with `targets` (mm or deg), n = 5, deviations from `f(target index, direction,
/// run)`.
fn axis(kind: AxisKind, targets: &[f64], f: impl Fn(usize, Direction, usize) -> f64) -> AxisData {
    let mut raw = Vec::new();
    for run in 0..5 {
        for d in Direction::BOTH {
            for (i, &target) in targets.iter().enumerate() {
                raw.push(RawReading {
                    target,
                    direction: d,
                    run: run as u32 + 1,
                    deviation: f(i, d, run),
                    time_s: None,
                    temps_c: Vec::new(),
                    line: 0,
                });
            }
        }
    }
    AxisData::from_raw(kind, raw, Vec::new(), "synthetic").unwrap()
}

/// A wavy error curve with scatter and a reversal of 1.5: the same in index space
/// whatever the targets' spacing.
fn wavy(i: usize, d: Direction, run: usize) -> f64 {
    let curve = [0.0, 2.0, 3.5, 1.0, -2.0][i];
    let scatter = [0.2, -0.4, 0.1, 0.5, -0.3][(run + i) % 5];
    curve + scatter + if d == Direction::Up { 0.75 } else { -0.75 }
}

fn linear_test(travel: f64) -> AxisData {
    let targets: Vec<f64> = (0..5).map(|i| travel * i as f64 / 4.0).collect();
    axis(AxisKind::Linear, &targets, wavy)
}

/// Checks a line's c·u and, when given, its share of u_c².
fn check(budget: &Budget, contributor: &str, contribution: f64, share: Option<f64>) {
    let line = budget
        .line(contributor)
        .unwrap_or_else(|| panic!("{contributor} missing from {:?}", budget.lines));
    assert_close(contributor, line.contribution, contribution, 2e-6);
    if let Some(share) = share {
        assert_close(&format!("{contributor} share"), line.share, share, 1e-4);
    }
}

/// The laser set-up of configuration 1 (with the NDE correction) over a 1000 mm travel.
fn laser_setup(nde_corrected: bool) -> Setup {
    let mut setup = Setup::default();
    setup.thermal.nde_corrected = nde_corrected;
    setup.thermal.mean_c = Some(21.0);
    setup.thermal.change_c = 0.4;
    setup.air.as_mut().unwrap().temperature_change_c = 0.2;
    setup
}

/// Configuration 1: laser defaults (±0.05 ppm, ±0.2 °C, ±0.1 kPa, ±6 %RH, dead path
/// 100 mm, 0.5 mm walk, ±0.1 °C material sensors, α = 11.5 ± 2 µm/(m·°C)), the NDE
/// correction applied at T = 21.0 °C, the material warming 0.4 °C and the air 0.2 °C
/// during the test; budget over the full travel L = 1 m. All rectangular (u = a/√3):
///
/// | contributor | a | c | c·u (µm) | share |
/// |---|---|---|---|---|
/// | calibration | 0.05 µm | 1 | 0.028868 | 0.0002 |
/// | resolution | 0.0005 µm | 1 | 0.000289 | 0.0000 |
/// | air_temperature | 0.2 °C | 0.93 µm/°C | 0.107387 | 0.0032 |
/// | air_pressure | 0.1 kPa | 2.7 µm/kPa | 0.155885 | 0.0068 |
/// | air_humidity | 6 %RH | 0.0085 µm/%RH | 0.029445 | 0.0002 |
/// | dead_path | 0.93 × 0.2 = 0.186 ppm | 0.1 µm/ppm | 0.010739 | 0.0000 |
/// | misalignment | 1 − cos(atan(0.5/1000)) = 0.125 ppm | 1 µm/ppm | 0.072169 | 0.0015 |
/// | material_temperature | 0.1 °C | 11.5 µm/°C | 0.663953 | 0.1231 |
/// | expansion_coefficient | 2 µm/(m·°C) | |21 − 20| × 1 m | 1.154701 | 0.3724 |
/// | temperature_change | 0.4/2 = 0.2 °C | 11.5 µm/°C | 1.327906 | 0.4925 |
///
/// u_c = √Σ(c·u)² = 1.892183 µm, U = 2·u_c = 3.784366 µm.
#[test]
fn hand_computed_budget_with_the_nde_correction() {
    let e = evaluate(&linear_test(1000.0), StandardId::Iso230_2);
    let u = uncertainty::evaluate(&laser_setup(true), &e);
    let b = &u.budget;
    assert_eq!(b.length, 1000.0);
    assert_eq!(b.lines.len(), 10);
    check(b, "calibration", 0.028_868, Some(0.0002));
    check(b, "resolution", 0.000_289, None);
    check(b, "air_temperature", 0.107_387, Some(0.0032));
    check(b, "air_pressure", 0.155_885, Some(0.0068));
    check(b, "air_humidity", 0.029_445, Some(0.0002));
    check(b, "dead_path", 0.010_739, None);
    check(b, "misalignment", 0.072_169, Some(0.0015));
    check(b, "material_temperature", 0.663_953, Some(0.1231));
    check(b, "expansion_coefficient", 1.154_701, Some(0.3724));
    check(b, "temperature_change", 1.327_906, Some(0.4925));
    assert!(b.line("uncorrected_expansion").is_none());
    assert_close("u_c", b.combined, 1.892_183, 2e-6);
    assert_close("U", b.expanded, 3.784_366, 4e-6);
}

/// Configuration 2: the same test without the NDE correction. The sensor and the
/// coefficient no longer enter; the expansion itself does: a = |21 − 20| = 1 °C,
/// u = 0.577350 °C, c = 11.5 µm/°C, c·u = 6.639528 µm (share 0.9606); the other lines as
/// in configuration 1 (temperature_change 1.327906 µm, share 0.0384). u_c = 6.774181 µm,
/// U = 13.548361 µm: 3.6 times the corrected test's.
#[test]
fn hand_computed_budget_without_the_nde_correction() {
    let e = evaluate(&linear_test(1000.0), StandardId::Iso230_2);
    let u = uncertainty::evaluate(&laser_setup(false), &e);
    let b = &u.budget;
    assert!(b.line("material_temperature").is_none());
    assert!(b.line("expansion_coefficient").is_none());
    check(b, "uncorrected_expansion", 6.639_528, Some(0.9606));
    check(b, "temperature_change", 1.327_906, Some(0.0384));
    check(b, "air_pressure", 0.155_885, Some(0.0005));
    assert_close("u_c", b.combined, 6.774_181, 2e-6);
    assert_close("U", b.expanded, 13.548_361, 4e-6);
}

#[test]
fn u_grows_with_the_measured_length_of_ranges_only() {
    let setup = laser_setup(true);
    let at = |travel: f64| -> Uncertainty {
        let e = evaluate(&linear_test(travel), StandardId::Iso230_2);
        uncertainty::evaluate(&setup, &e)
    };
    let (short, mid, long) = (at(500.0), at(1000.0), at(2000.0));
    for key in ["A", "A_up", "A_down", "E", "E_up", "E_down", "M"] {
        let u = |x: &Uncertainty| x.expanded_of(ParamKey::parse(key).unwrap()).unwrap();
        assert!(u(&short) < u(&mid) && u(&mid) < u(&long), "{key}");
        // The length is the distance between the targets of the two terms: E spans
        // targets 2 (max 3.5 + 0.75) and 4 (min −2 − 0.75), half the travel.
        let length = |x: &Uncertainty| x.parameter(ParamKey::parse(key).unwrap()).unwrap().length;
        assert_close(key, length(&long), 2.0 * length(&mid), 1e-9);
    }
    assert_close(
        "E length",
        mid.parameter(ParamKey::E).unwrap().length,
        500.0,
        1e-9,
    );
    for key in ["R", "R_up", "R_down", "B", "B_mean"] {
        let u = |x: &Uncertainty| x.expanded_of(ParamKey::parse(key).unwrap()).unwrap();
        assert_close(key, u(&short), u(&long), 1e-12);
        assert_eq!(
            mid.parameter(ParamKey::parse(key).unwrap()).unwrap().length,
            0.0,
            "{key}"
        );
    }
}

/// ISO 230-2 Table 2 (GB/T 17421.2-2000) under the conditions its Figure 2 states: NDE
/// correction applied with α = 11 µm/(m·°C); material sensors 21.8 → 22.9 °C (X = 50 mm)
/// and 22.4 → 23.1 °C (X = 1700 mm), so T̄ = 22.55 °C and ΔT = 23.0 − 22.1 = 0.9 °C; air
/// 20.6 → 20.9 °C. The instrument is not named ("×××"): laser defaults. Over the
/// measurement travel L = 1750.920 − 6.711 = 1744.209 mm (u = a/√3 throughout):
///
/// | contributor | a | u | c | c·u (µm) | share |
/// |---|---|---|---|---|---|
/// | calibration | 0.05 ppm × L = 0.087210 µm | 0.050351 µm | 1 | 0.050351 | 0.0000 |
/// | resolution | 0.0005 µm | 0.000289 µm | 1 | 0.000289 | 0.0000 |
/// | air_temperature | 0.2 °C | 0.115470 °C | 0.93 × L = 1.622114 | 0.187306 | 0.0007 |
/// | air_pressure | 0.1 kPa | 0.057735 kPa | 2.7 × L = 4.709364 | 0.271895 | 0.0014 |
/// | air_humidity | 6 %RH | 3.464102 %RH | 0.0085 × L = 0.014826 | 0.051358 | 0.0001 |
/// | dead_path | 0.93 × 0.3 = 0.279 ppm | 0.161081 ppm | 0.1 m | 0.016108 | 0.0000 |
/// | misalignment | 0.041088 ppm | 0.023722 ppm | L = 1.744209 | 0.041376 | 0.0000 |
/// | material_temperature | 0.1 °C | 0.057735 °C | 11 × L = 19.186299 | 1.107721 | 0.0233 |
/// | expansion_coefficient | 2 µm/(m·°C) | 1.154701 | 2.55 × L = 4.447733 | 5.135800 | 0.5018 |
/// | temperature_change | 0.45 °C | 0.259808 °C | 19.186299 | 4.984747 | 0.4727 |
///
/// u_c = 7.250334 µm, U = 14.500667 µm. The parameters: E = 7.700 spans 175.077 mm
/// (X̄↓ = 3.42, tied with 353.834 mm: the longer is taken) to 1234.304 mm (X̄↑ = −4.28),
/// L = 1059.227 mm; its means add √(0.2588² + 0.6301²)/√5 = 0.304631 µm:
/// u_c(E) = 4.413543, U(E) = 8.827085 µm. A = 9.586 spans 353.834 to 1408.462 mm
/// (L = 1054.628 mm), means 0.355528 µm, estimates of S 2·√(u(0.2950)² + u(0.7382)²) =
/// 0.577157 µm with u(s) = 0.36300·s (n = 5): U(A) = 8.871999 µm. R = 6.551 at i = 9
/// (2S↑ + 2S↓ + |B|): U(R) = 1.609169 µm; R↑ at i = 10: 4·0.36300·0.7463 = 1.083661,
/// U(R↑) = 2.167562 µm; B at i = 2: √((0.3536² + 0.2588²)/5) = 0.195959,
/// U(B) = 0.393241 µm; B̄: U = 0.192384 µm.
#[test]
fn iso_table_2_budget_checked_by_hand() {
    let e = evaluate(&load("iso230-2_table2.csv"), StandardId::Iso230_2);
    let mut setup = Setup::default();
    setup.thermal.nde_corrected = true;
    setup.thermal.coefficient_um_per_m_c = 11.0;
    setup
        .thermal
        .set_from_sensors(&[(21.8, 22.9), (22.4, 23.1)]);
    setup.air.as_mut().unwrap().temperature_change_c = 20.9 - 20.6;
    let u = uncertainty::evaluate(&setup, &e);
    let b = &u.budget;
    assert_close("travel", b.length, 1744.209, 1e-9);
    check(b, "calibration", 0.050_351, Some(0.0000));
    check(b, "resolution", 0.000_289, Some(0.0000));
    check(b, "air_temperature", 0.187_306, Some(0.0007));
    check(b, "air_pressure", 0.271_895, Some(0.0014));
    check(b, "air_humidity", 0.051_358, Some(0.0001));
    check(b, "dead_path", 0.016_108, Some(0.0000));
    check(b, "misalignment", 0.041_376, Some(0.0000));
    check(b, "material_temperature", 1.107_721, Some(0.0233));
    check(b, "expansion_coefficient", 5.135_800, Some(0.5018));
    check(b, "temperature_change", 4.984_747, Some(0.4727));
    assert_eq!(b.lines.len(), 10);
    assert_close("u_c", b.combined, 7.250_334, 2e-6);
    assert_close("U", b.expanded, 14.500_667, 4e-6);

    let length = |k: &str| u.parameter(ParamKey::parse(k).unwrap()).unwrap().length;
    assert_close("E length", length("E"), 1059.227, 1e-9);
    assert_close("A length", length("A"), 1054.628, 1e-9);
    check(
        u.parameter(ParamKey::E).unwrap(),
        "mean_of_n",
        0.304_631,
        None,
    );
    check(u.parameter(ParamKey::A).unwrap(), "s_of_n", 0.577_157, None);
    check(
        u.parameter(ParamKey::RUp).unwrap(),
        "s_of_n",
        1.083_661,
        None,
    );
    check(
        u.parameter(ParamKey::B).unwrap(),
        "mean_of_n",
        0.195_959,
        None,
    );
    for (key, want) in [
        ("E", 8.827_085),
        ("A", 8.871_999),
        ("A_up", 8.890_991),
        ("A_down", 11.676_523),
        ("E_up", 7.352_648),
        ("E_down", 8.817_337),
        ("M", 7.331_796),
        ("R", 1.609_169),
        ("R_up", 2.167_562),
        ("R_down", 1.980_523),
        ("B", 0.393_241),
        ("B_mean", 0.192_384),
    ] {
        assert_close(
            key,
            u.expanded_of(ParamKey::parse(key).unwrap()).unwrap(),
            want,
            4e-6,
        );
    }
    assert_eq!(u.expanded.len(), 12);
    assert!(u.notes.is_empty(), "{:?}", u.notes);
}

/// A rotary axis (five targets from 0° to 330°) measured with an angular interferometer: ±1″
/// rectangular, 0.1″ steps, no length dependence, no air, no thermal expansion. Over the
/// travel: u = √((1/√3)² + (0.05/√3)²) = 0.578071″, U = 1.156143″, whatever the angle.
#[test]
fn rotary_budget_in_arcseconds() {
    let targets: Vec<f64> = (0..5).map(|i| 82.5 * i as f64).collect();
    let data = axis(AxisKind::Rotary, &targets, wavy);
    let e = evaluate(&data, StandardId::Iso230_2);
    let u = uncertainty::evaluate(&Setup::for_axis(AxisKind::Rotary), &e);
    assert_eq!(u.unit, "arcsec");
    let b = &u.budget;
    let names: Vec<&str> = b.lines.iter().map(|l| l.contributor).collect();
    assert_eq!(names, ["calibration", "resolution"]);
    assert_eq!(b.line("calibration").unwrap().unit, "arcsec");
    assert_close("u_c", b.combined, 0.578_071, 1e-6);
    assert_close("U", b.expanded, 1.156_143, 1e-6);
    // E (over its own angle) carries the same instrument part plus its means' scatter.
    let e_budget = u.parameter(ParamKey::E).unwrap();
    check(e_budget, "calibration", 0.577_350, None);
    assert!(e_budget.line("mean_of_n").is_some());
    assert!(u.notes.is_empty(), "{:?}", u.notes);
    // A laser's defaults on a rotary axis: its ppm part in arcsec, no air or thermal
    // lines, and a note.
    let u = uncertainty::evaluate(&Setup::default(), &e);
    let names: Vec<&str> = u.budget.lines.iter().map(|l| l.contributor).collect();
    assert_eq!(names, ["calibration", "resolution"]);
    // 0.05 ppm of 330° = 0.05e-6 × 330 × 3600″ = 0.0594″.
    assert_close("ppm of an angle", u.budget.lines[0].value, 0.0594, 1e-9);
    assert!(u.notes[0].starts_with("an instrument for linear axes on a rotary axis"));
}

#[test]
fn gost_parameters_use_its_coverage_factor() {
    let e = evaluate(&load("gost27843_example.csv"), StandardId::Gost27843);
    let u = uncertainty::evaluate(&Setup::default(), &e);
    for key in [
        "A", "A_up", "A_down", "R_max", "R_up", "R_down", "R_mean", "B_max", "B_mean",
    ] {
        assert!(
            u.expanded_of(ParamKey::parse(key).unwrap())
                .is_some_and(|x| x > 0.0),
            "{key}"
        );
    }
    // A repeatability 6S: the resolution enters six-fold, u(S) six-fold.
    let r = u.parameter(ParamKey::RUp).unwrap();
    assert_eq!(r.line("resolution").unwrap().sensitivity, 6.0);
    let at = e.parameter(ParamKey::RUp).unwrap().at_target.unwrap();
    let s = e.targets[at].up.s.unwrap();
    check(r, "s_of_n", 6.0 * uncertainty::extent::u_of_s(s, 5), None);
    assert!(u.notes.iter().any(|n| n.contains("not recorded")));
}

#[test]
fn levels_take_no_uncertainty_and_n_1_has_no_statistics() {
    let e = evaluate(&load("iso230-2_table2.csv"), StandardId::Vdi3441);
    let u = uncertainty::evaluate(&Setup::default(), &e);
    for key in ["X_max", "X_min", "A_mean", "G_upper", "G_lower"] {
        assert!(
            u.expanded_of(ParamKey::parse(key).unwrap()).is_none(),
            "{key}"
        );
    }
    for key in ["T", "R_p", "sigma_mean"] {
        assert!(
            u.expanded_of(ParamKey::parse(key).unwrap()).is_some(),
            "{key}"
        );
    }
    let single = axis(AxisKind::Linear, &[0.0, 500.0, 1000.0], |i, _, _| i as f64);
    let single = AxisData::from_raw(
        AxisKind::Linear,
        single
            .readings
            .iter()
            .filter(|r| r.run == 0)
            .map(|r| RawReading {
                target: single.targets[r.target],
                direction: r.direction,
                run: 1,
                deviation: r.deviation,
                time_s: None,
                temps_c: Vec::new(),
                line: 0,
            })
            .collect(),
        Vec::new(),
        "n = 1",
    )
    .unwrap();
    let e = evaluate(&single, StandardId::Iso230_2);
    let u = uncertainty::evaluate(&Setup::default(), &e);
    assert_eq!(u.expanded.len(), 6, "E, E↑, E↓, M, B, B̄");
    assert!(
        u.parameters
            .iter()
            .all(|p| p.budget.line("mean_of_n").is_none())
    );
    assert!(u.notes.iter().any(|n| n.starts_with("n = 1")));
}

#[test]
fn json_has_the_keys_results_json_names() {
    let e = evaluate(&load("iso230-2_table2.csv"), StandardId::Iso230_2);
    let u = uncertainty::evaluate(&Setup::for_instrument(InstrumentKind::LinearEncoder), &e);
    let json = serde_json::to_value(&u).unwrap();
    assert_eq!(json["k"], 2.0);
    assert!(json["U"]["E"].as_f64().unwrap() > 0.0);
    let line = &json["budget"]["lines"][0];
    for key in [
        "contributor",
        "value",
        "unit",
        "distribution",
        "u",
        "sensitivity",
    ] {
        assert!(line.get(key).is_some(), "{key}: {line}");
    }
    assert_eq!(line["contributor"], "calibration");
    assert_eq!(line["distribution"], "rectangular");
    assert_eq!(json["parameters"][0]["key"], "A");
}
