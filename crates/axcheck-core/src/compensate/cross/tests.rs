use super::*;

/// A small deterministic generator (xorshift64*), so that the 1 000 tables are the same
/// on every run.
struct Random(u64);

impl Random {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }

    fn between(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.next()
    }
}

/// A table `format` can hold: equidistant (CEC needs it), axes named as it names them.
fn random_table(r: &mut Random, format: &dyn CrossFormat) -> CrossTable {
    let n = 2 + (r.next() * 199.0) as usize;
    // Steps of whole 0.1 mm and a start of whole 0.1 µm: what every format writes exactly.
    let step = (r.between(1.0, 5000.0)).round() / 10.0;
    let first = (r.between(-2000.0, 2000.0) * 10_000.0).round() / 10_000.0;
    let (input, output) = match format.name() {
        "twincat" => ("1".to_string(), "2".to_string()),
        "siemens-840d" => ("AX1".to_string(), "AX2".to_string()),
        _ => ("X".to_string(), "Y".to_string()),
    };
    CrossTable {
        input,
        output,
        positions_mm: (0..n).map(|k| first + k as f64 * step).collect(),
        corrections_um: (0..n).map(|_| r.between(-80.0, 80.0)).collect(),
    }
}

/// Every format reads back what it writes: the axes, the positions, each correction
/// within the format's resolution; 1 000 tables each.
#[test]
fn every_format_reads_back_what_it_writes() {
    for format in formats() {
        let mut r = Random(0x9E37_79B9_7F4A_7C15);
        for case in 0..1000 {
            let t = random_table(&mut r, format);
            let parts = format
                .write(&t, "")
                .unwrap_or_else(|e| panic!("{} {case}: {e}", format.name()));
            let texts: Vec<&str> = parts.iter().map(|p| p.text.as_str()).collect();
            let back = format
                .read(&texts)
                .unwrap_or_else(|e| panic!("{} {case}: {e}", format.name()));
            assert_eq!(
                (&back.input, &back.output),
                (&t.input, &t.output),
                "{}",
                format.name()
            );
            assert_eq!(
                back.positions_mm.len(),
                t.positions_mm.len(),
                "{} {case}",
                format.name()
            );
            for (a, b) in back.positions_mm.iter().zip(&t.positions_mm) {
                assert!(
                    (a - b).abs() < 1e-6,
                    "{} {case}: position {a} for {b}",
                    format.name()
                );
            }
            let worst = (back.corrections_um.iter().zip(&t.corrections_um))
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            assert!(
                worst <= format.resolution_um() + 1e-9,
                "{} {case}: {worst} µm",
                format.name()
            );
        }
    }
}

/// The SINUMERIK file of the research note's example (EYX on AX2 along AX1, 0 to 400 mm
/// every 100 mm): the manual's keys, values in mm, and a grid CEC cannot take refused.
#[test]
fn a_cec_table_as_the_manual_writes_it() {
    let t = CrossTable {
        input: "AX1".into(),
        output: "AX2".into(),
        positions_mm: vec![0.0, 100.0, 200.0, 300.0, 400.0],
        corrections_um: vec![0.0, 2.1, 3.5, 1.8, 0.0],
    };
    let text = &siemens_cec::SiemensCec.write(&t, "").unwrap()[0].text;
    for line in [
        "%_N_NC_CEC_INI",
        "CHANDATA(1)",
        "$AN_CEC[0,1]=0.002100",
        "$AN_CEC[0,2]=0.003500",
        "$AN_CEC_INPUT_AXIS[0]=(AX1)",
        "$AN_CEC_OUTPUT_AXIS[0]=(AX2)",
        "$AN_CEC_STEP[0]=100.000000",
        "$AN_CEC_MAX[0]=400.000000",
        "$AN_CEC_DIRECTION[0]=0",
        "M17",
    ] {
        assert!(text.lines().any(|l| l == line), "{line} in\n{text}");
    }
    let uneven = CrossTable {
        positions_mm: vec![0.0, 100.0, 250.0],
        corrections_um: vec![0.0; 3],
        ..t.clone()
    };
    let e = siemens_cec::SiemensCec
        .write(&uneven, "")
        .unwrap_err()
        .to_string();
    assert!(e.contains("equidistant"), "{e}");
    // One point missing: the count the grid makes is named.
    let missing = text.replace("$AN_CEC[0,3]=0.001800\n", "");
    let e = siemens_cec::SiemensCec
        .read(&[&missing])
        .unwrap_err()
        .to_string();
    assert!(e.contains("make 5 points"), "{e}");
}

/// HEIDENHAIN: the value in the column of the axis corrected, the .COM entered in the
/// input axis's column of the .CMA, its line active.
#[test]
fn a_heidenhain_table_and_its_assignment() {
    let t = CrossTable {
        input: "X".into(),
        output: "Y".into(),
        positions_mm: vec![0.0, 100.0],
        corrections_um: vec![0.0, 2.1],
    };
    let parts = heidenhain::Heidenhain.write(&t, "").unwrap();
    assert_eq!(parts[0].text.lines().next(), Some("BEGIN YX.COM MM"));
    assert!(parts[0].text.contains("+0.0021"), "{}", parts[0].text);
    assert_eq!(parts[1].text.lines().nth(2), Some("0    *       YX.COM"));
    let named = heidenhain::Heidenhain.write(&t, "X-EYX").unwrap();
    assert_eq!(named[0].text.lines().next(), Some("BEGIN X-EYX.COM MM"));
    assert_eq!(named[1].text.lines().nth(2), Some("0    *       X-EYX.COM"));
    let inactive = parts[1].text.replace('*', " ");
    let e = heidenhain::Heidenhain
        .read(&[&parts[0].text, &inactive])
        .unwrap_err();
    assert!(e.to_string().contains("ACTIVE"), "{e}");
}

/// TwinCAT: the slave's list in 0.1 µm, axes by number; names refused.
#[test]
fn a_twincat_list_in_tenths_of_a_micrometre() {
    let t = CrossTable {
        input: "1".into(),
        output: "2".into(),
        positions_mm: vec![0.0, 100.0],
        corrections_um: vec![0.0, 2.1],
    };
    let text = &twincat::TwinCat.write(&t, "").unwrap()[0].text;
    assert!(text.contains("kw.crosscomp.table[1].setpoint"), "{text}");
    assert!(
        text.lines()
            .any(|l| l.starts_with("kw.crosscomp.table[1].correction") && l.ends_with(" 21")),
        "{text}"
    );
    let named = CrossTable {
        input: "X".into(),
        ..t
    };
    assert!(twincat::TwinCat.write(&named, "").is_err());
}

/// A straightness bow of 8 µm (residuals +4 in the middle, −4 at the ends about the
/// least-squares line) gives corrections of the opposite sign; between points they are
/// linear, beyond the ends held; resampled every 250 mm.
#[test]
fn the_table_cancels_the_residuals() {
    use crate::compensate::testing::axis;
    use crate::geometry::straightness::{Options, evaluate};
    use crate::units::AxisKind;
    let targets = [0.0, 250.0, 500.0, 750.0, 1000.0];
    // A parabola through 0 at the ends and 8 in the middle, on a slope of 15 µm/m.
    let data = axis(AxisKind::Linear, &targets, 3, |x, _| {
        8.0 * (1.0 - ((x - 500.0) / 500.0).powi(2)) + 0.015 * x
    });
    let s = evaluate(&data, &Options::default()).unwrap();
    let t = from_straightness(&s, &targets, "X", "Y");
    for (c, r) in t.corrections_um.iter().zip(&s.residuals_um) {
        assert!((c + r).abs() < 1e-12);
    }
    // The residuals of a parabola about its least-squares line sum to zero.
    assert!(t.corrections_um.iter().sum::<f64>().abs() < 1e-9);
    assert!((t.at(125.0) - (t.corrections_um[0] + t.corrections_um[1]) / 2.0).abs() < 1e-12);
    assert_eq!(t.at(-10.0), t.corrections_um[0]);
    assert_eq!(t.at(2000.0), t.corrections_um[4]);
    let r = t.resampled(100.0);
    assert_eq!(r.positions_mm.len(), 11);
    assert_eq!(r.step_mm(), Some(100.0));
    assert!((r.corrections_um[5] - t.corrections_um[2]).abs() < 1e-12);
}

/// A straightness test of EYX (a bow of 8 µm on 15 µm/m, scatter 0.3 µm, 5 runs) with its
/// readings' noise from `r`, plus `added` at each target (a table acting on it).
fn eyx(r: &mut Random, bow_um: f64, added: &dyn Fn(f64) -> f64) -> crate::measurement::AxisData {
    use crate::compensate::testing::axis;
    use crate::units::AxisKind;
    use std::cell::RefCell;
    let targets: Vec<f64> = (0..11).map(|k| k as f64 * 100.0).collect();
    let noise = RefCell::new(Random(r.0 ^ 0x5851_F42D_4C95_7F2D));
    r.next();
    axis(AxisKind::Linear, &targets, 5, |x, _| {
        let mut n = noise.borrow_mut();
        // Two uniforms: a scatter of 0.3 µm (s of a uniform on ±0.52).
        let e = (n.next() - 0.5) * 1.04;
        bow_um * (1.0 - ((x - 500.0) / 500.0).powi(2)) + 0.015 * x + e + added(x)
    })
}

/// 50 seeds: a table loaded as written is effective; loaded with the wrong sign it is
/// found `made_worse` with `sign_inverted`; loaded on Z instead of Y it is found
/// `not_effective` with `wrong_axis` naming Z — each in at least 95 % of the seeds.
#[test]
fn verify_names_the_wrong_sign_and_the_wrong_axis() {
    use crate::geometry::line::ReferenceLine;
    use crate::geometry::straightness::{Options, evaluate};
    use verify::{CrossFinding, CrossVerdict, OtherOutput, verify};
    let (mut ok, mut inverted, mut wrong) = (0, 0, 0);
    for seed in 0..50u64 {
        let mut r = Random(0x2545_F491 + seed * 7919);
        let before = eyx(&mut r, 8.0, &|_| 0.0);
        let s = evaluate(&before, &Options::default()).unwrap();
        let table = from_straightness(&s, &before.targets, "X1", "Y1");
        let c = |x: f64| table.at(x);
        let right = eyx(&mut r, 8.0, &c);
        let minus = eyx(&mut r, 8.0, &|x| -c(x));
        let unchanged = eyx(&mut r, 8.0, &|_| 0.0);
        // Z's straightness along X (another bow), before and with the table on Z.
        let z_before = eyx(&mut r, -3.0, &|_| 0.0);
        let z_after = eyx(&mut r, -3.0, &c);
        let z = [OtherOutput {
            output: "Z1",
            before: &z_before,
            after: &z_after,
            own: None,
        }];
        let line = ReferenceLine::LeastSquares;
        let v = verify(&before, &right, (&table, None), line, &z).unwrap();
        ok += usize::from(v.verdict == CrossVerdict::Effective && v.achieved_um < 1.5);
        let v = verify(&before, &minus, (&table, None), line, &z).unwrap();
        inverted += usize::from(
            v.verdict == CrossVerdict::MadeWorse && v.findings == [CrossFinding::SignInverted],
        );
        let v = verify(&before, &unchanged, (&table, None), line, &z).unwrap();
        let named = v.findings
            == [CrossFinding::WrongAxis {
                output: "Z1".into(),
            }];
        wrong += usize::from(v.verdict == CrossVerdict::NotEffective && named);
    }
    assert!(ok >= 48, "effective in {ok} of 50");
    assert!(inverted >= 48, "sign inverted found in {inverted} of 50");
    assert!(wrong >= 48, "wrong axis found in {wrong} of 50");
}

/// EYX of a bow of 8 µm on 15 µm/m at unequal targets, without scatter.
fn bowed(active: &dyn Fn(f64) -> f64) -> crate::measurement::AxisData {
    use crate::compensate::testing::axis;
    use crate::units::AxisKind;
    let targets = [0.0, 150.0, 250.0, 500.0, 750.0, 1000.0];
    axis(AxisKind::Linear, &targets, 3, |x, _| {
        8.0 * (1.0 - ((x - 500.0) / 500.0).powi(2)) + 0.015 * x - active(x)
    })
}

/// Without an active table the table is −residual at the targets (csv keeps them), the
/// prediction flat, a warning says the active state is unstated; CEC's grid is the mean
/// spacing (200 mm) through both ends.
#[test]
fn a_table_on_the_measured_targets_or_the_mean_spacing() {
    use build::{CrossActive, CrossRequest, compensate};
    let data = bowed(&|_| 0.0);
    let request = CrossRequest {
        input: Some("X".into()),
        output: Some("Y".into()),
        ..CrossRequest::default()
    };
    let c = compensate(&csv::Csv, &data, &request).unwrap();
    assert_eq!(c.table.positions_mm, data.targets);
    assert_eq!(c.mode, crate::compensate::Mode::Absolute);
    assert!((c.measured_um - 8.0).abs() < 0.3, "{}", c.measured_um);
    assert!(c.predicted_um < 1e-9, "{}", c.predicted_um);
    assert_eq!(c.warnings.len(), 1);
    let cec = compensate(&siemens_cec::SiemensCec, &data, &request).unwrap();
    assert_eq!(
        cec.table.positions_mm,
        [0.0, 200.0, 400.0, 600.0, 800.0, 1000.0]
    );
    // Linear between targets: the prediction is not flat, but far below 8 µm.
    assert!(
        cec.predicted_um > 0.0 && cec.predicted_um < 1.0,
        "{}",
        cec.predicted_um
    );
    let none = CrossRequest {
        active: CrossActive::None,
        ..request
    };
    assert!(
        compensate(&csv::Csv, &data, &none)
            .unwrap()
            .warnings
            .is_empty()
    );
}

/// Measured with half the correction active, the table is the active one plus what is
/// left: the whole correction again, by hand (c = −residual of the bow without the
/// active half); the names come from the active table, and a contradicting name is
/// refused.
#[test]
fn a_table_builds_on_the_active_one() {
    use build::{CrossActive, CrossRequest, compensate};
    let whole = compensate(
        &csv::Csv,
        &bowed(&|_| 0.0),
        &CrossRequest {
            input: Some("X".into()),
            output: Some("Y".into()),
            active: CrossActive::None,
            ..CrossRequest::default()
        },
    )
    .unwrap()
    .table;
    let half = CrossTable {
        corrections_um: whole.corrections_um.iter().map(|c| c / 2.0).collect(),
        ..whole.clone()
    };
    // With `half` active the controller added it: the readings are the bow plus half.
    let data = bowed(&|x| -half.at(x));
    let mut request = CrossRequest {
        active: CrossActive::Table {
            table: half.clone(),
            file: "YX.csv".into(),
        },
        ..CrossRequest::default()
    };
    let c = compensate(&csv::Csv, &data, &request).unwrap();
    assert_eq!(c.mode, crate::compensate::Mode::Incremental);
    assert_eq!(
        (c.table.input.as_str(), c.table.output.as_str()),
        ("X", "Y")
    );
    for (got, want) in c.table.corrections_um.iter().zip(&whole.corrections_um) {
        assert!((got - want).abs() < 1e-9, "{got} {want}");
    }
    assert!((c.measured_um - 4.0).abs() < 0.3, "{}", c.measured_um);
    assert!(c.predicted_um < 1e-9);
    request.output = Some("Z".into());
    let refused = compensate(&csv::Csv, &data, &request).unwrap_err();
    assert!(refused.to_string().contains("`Y`, not `Z`"), "{refused}");
}

/// A name that would write lines of its own into the file (a line break, a bracket) is
/// refused by every format, before a byte is written.
#[test]
fn axis_names_that_would_inject_lines_are_refused() {
    for format in formats() {
        for (input, output) in [("X\nM17", "Y"), ("1", "2)\nM30"), ("", "Y"), ("X", "Y Z")] {
            let t = CrossTable {
                input: input.into(),
                output: output.into(),
                positions_mm: vec![0.0, 100.0],
                corrections_um: vec![0.0, 2.1],
            };
            let e = format.write(&t, "").unwrap_err();
            assert!(
                e.to_string().contains("is not a name the file can hold"),
                "{}: {e}",
                format.name()
            );
        }
    }
}
