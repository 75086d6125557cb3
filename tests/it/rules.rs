//! Test-plan rules at their boundaries.
use axcheck::evaluate::StandardId;
use axcheck::measurement::{AxisData, RawReading};
use axcheck::rules::{PlanContext, RULES, Severity, check};
use axcheck::simulate::rng::Rng;
use axcheck::units::Travel;
use axcheck::units::{AxisKind, Direction};

/// A test at `targets` with `n` runs of independent scatter (no trend).
fn data(kind: AxisKind, targets: &[f64], n: u32) -> AxisData {
    let mut rng = Rng::new(targets.len() as u64 * 31 + n as u64, 7);
    let mut raw = Vec::new();
    for run in 1..=n {
        for d in Direction::BOTH {
            for &t in targets {
                raw.push(RawReading {
                    target: t,
                    direction: d,
                    run,
                    deviation: rng.normal(),
                    time_s: None,
                    temps_c: vec![],
                    line: 0,
                });
            }
        }
    }
    AxisData::from_raw(kind, raw, vec![], "t").unwrap()
}

/// `count` targets from `first` to `last` with slightly uneven spacing (no 4.2 warning).
fn spread(first: f64, last: f64, count: usize) -> Vec<f64> {
    let step = (last - first) / (count - 1) as f64;
    (0..count)
        .map(|i| {
            let wiggle = if i == 0 || i == count - 1 {
                0.0
            } else if i % 2 == 0 {
                0.1
            } else {
                -0.1
            };
            ((first + i as f64 * step + wiggle) * 1000.0).round() / 1000.0
        })
        .collect()
}

fn ctx(kind: AxisKind) -> PlanContext {
    PlanContext {
        kind,
        standard: StandardId::Iso230_2,
        axis_travel: None,
        measurement_travel: None,
        pitch: None,
        planned: None,
        unstated: None,
        calibration: None,
    }
}

fn ids(ctx: &PlanContext, d: &AxisData) -> Vec<&'static str> {
    check(ctx, d).iter().map(|f| f.id).collect()
}

fn errors(ctx: &PlanContext, d: &AxisData) -> Vec<&'static str> {
    check(ctx, d)
        .iter()
        .filter(|f| f.severity == Severity::Error)
        .map(|f| f.id)
        .collect()
}

#[test]
fn five_targets_per_metre_and_five_in_all() {
    let c = ctx(AxisKind::Linear);
    assert!(errors(&c, &data(AxisKind::Linear, &spread(0.0, 1000.0, 5), 5)).is_empty());
    let four = check(&c, &data(AxisKind::Linear, &spread(0.0, 1000.0, 4), 5));
    assert_eq!(four[0].id, "iso-4.3.2-targets");
    assert_eq!(four[0].clause, "ISO 230-2 4.3.2");
    assert!(
        four[0].message.contains("add 1 target"),
        "{}",
        four[0].message
    );
    // 1200 mm needs 6; a short axis still needs 5 in all.
    assert_eq!(
        errors(&c, &data(AxisKind::Linear, &spread(0.0, 1200.0, 5), 5)),
        vec!["iso-4.3.2-targets"]
    );
    assert!(errors(&c, &data(AxisKind::Linear, &spread(0.0, 1200.0, 6), 5)).is_empty());
    assert_eq!(
        errors(&c, &data(AxisKind::Linear, &spread(0.0, 100.0, 4), 5)),
        vec!["iso-4.3.2-targets"]
    );
}

#[test]
fn exactly_2000_mm_is_a_clause_4_3_2_test() {
    let c = ctx(AxisKind::Linear);
    // 2000 mm: 10 targets and n = 5.
    assert!(errors(&c, &data(AxisKind::Linear, &spread(0.0, 2000.0, 10), 5)).is_empty());
    assert_eq!(
        errors(&c, &data(AxisKind::Linear, &spread(0.0, 2000.0, 9), 5)),
        vec!["iso-4.3.2-targets"]
    );
    assert_eq!(
        errors(&c, &data(AxisKind::Linear, &spread(0.0, 2000.0, 10), 1)),
        vec!["iso-4.3.2-runs"]
    );
    // Just over 2000 mm: n = 1 is allowed (4.3.3).
    assert!(errors(&c, &data(AxisKind::Linear, &spread(0.0, 2000.5, 10), 1)).is_empty());
    assert_eq!(
        errors(&c, &data(AxisKind::Linear, &spread(0.0, 2000.5, 10), 3)),
        vec!["iso-4.3.3-runs"]
    );
}

#[test]
fn mean_spacing_of_250_mm() {
    let c = ctx(AxisKind::Linear);
    assert!(errors(&c, &data(AxisKind::Linear, &spread(0.0, 2500.0, 11), 1)).is_empty());
    let f = check(&c, &data(AxisKind::Linear, &spread(0.0, 2500.0, 10), 1));
    assert_eq!(f[0].id, "iso-4.3.3-spacing");
    assert!(
        f[0].message.contains("at least 11 targets"),
        "{}",
        f[0].message
    );
}

#[test]
fn rotary_table_1_minima() {
    let c = ctx(AxisKind::Rotary);
    let r = AxisKind::Rotary;
    // ≤ 90°: 3 targets.
    assert!(errors(&c, &data(r, &[0.0, 45.0, 90.0], 5)).is_empty());
    assert_eq!(
        errors(&c, &data(r, &[0.0, 90.0], 5)),
        vec!["iso-4.3.4-targets"]
    );
    // ≤ 180°: 5 targets.
    assert!(errors(&c, &data(r, &[0.0, 40.0, 90.0, 130.0, 180.0], 5)).is_empty());
    assert_eq!(
        errors(&c, &data(r, &[0.0, 90.0, 130.0, 180.0], 5)),
        vec!["iso-4.3.4-targets"]
    );
    // 90.5°: more than 90°, so 5.
    assert_eq!(
        errors(&c, &data(r, &[0.0, 45.0, 90.0, 90.5], 5)),
        vec!["iso-4.3.4-targets"]
    );
    // > 180°: 8 targets, up to exactly 360°.
    let eight = [0.0, 40.0, 90.0, 130.0, 180.0, 230.0, 270.0, 320.0];
    assert!(errors(&c, &data(r, &eight, 5)).is_empty());
    assert_eq!(
        errors(&c, &data(r, &eight[..7], 5)),
        vec!["iso-4.3.4-targets"]
    );
    let to_360 = [0.0, 45.0, 90.0, 135.0, 180.0, 225.0, 270.0, 315.0, 360.0];
    assert!(errors(&c, &data(r, &to_360, 5)).is_empty());
    assert_eq!(errors(&c, &data(r, &to_360, 1)), vec!["iso-4.3.4-runs"]);
}

#[test]
fn principal_positions_must_be_targets() {
    let c = ctx(AxisKind::Rotary);
    let f = check(
        &c,
        &data(
            AxisKind::Rotary,
            &[0.0, 40.0, 90.0, 130.0, 180.0, 230.0, 265.0, 320.0],
            5,
        ),
    );
    assert_eq!(f[0].id, "iso-4.3.4-cardinal");
    assert!(f[0].message.contains("270°"), "{}", f[0].message);
    // Only those inside the travel are needed.
    assert!(errors(&c, &data(AxisKind::Rotary, &[0.0, 30.0, 60.0], 5)).is_empty());
}

#[test]
fn over_360_degrees_spacing_of_45() {
    let c = ctx(AxisKind::Rotary);
    let step = |s: f64, end: f64| {
        (0..=((end / s).round() as usize))
            .map(|k| k as f64 * s)
            .collect::<Vec<_>>()
    };
    assert!(errors(&c, &data(AxisKind::Rotary, &step(45.0, 720.0), 1)).is_empty());
    let wide: Vec<f64> = step(45.0, 720.0)
        .into_iter()
        .map(|x| if x == 405.0 { 405.5 } else { x })
        .collect();
    assert_eq!(
        errors(&c, &data(AxisKind::Rotary, &wide, 1)),
        vec!["iso-4.3.5-spacing"]
    );
    assert_eq!(
        errors(&c, &data(AxisKind::Rotary, &step(45.0, 720.0), 2)),
        vec!["iso-4.3.5-runs"]
    );
    // Beyond 1800° (5 revolutions): flagged.
    let f = ids(&c, &data(AxisKind::Rotary, &step(45.0, 1845.0), 1));
    assert!(f.contains(&"iso-4.3.5-range"), "{f:?}");
    assert!(!ids(&c, &data(AxisKind::Rotary, &step(45.0, 1800.0), 1)).contains(&"iso-4.3.5-range"));
}

#[test]
fn first_and_last_targets_need_room_to_reverse() {
    let d = data(AxisKind::Linear, &spread(0.0, 1000.0, 6), 5);
    let mut c = ctx(AxisKind::Linear);
    c.axis_travel = Some(Travel::Length(1000.0));
    assert_eq!(errors(&c, &d), vec!["iso-2.2-reversal-room"]);
    c.axis_travel = Some(Travel::Length(1010.0));
    assert!(errors(&c, &d).is_empty());
    c.axis_travel = Some(Travel::Range([-5.0, 1005.0]));
    assert!(errors(&c, &d).is_empty());
    c.axis_travel = Some(Travel::Range([0.0, 1005.0]));
    assert_eq!(errors(&c, &d), vec!["iso-2.2-reversal-room"]);
    c.axis_travel = None;
    c.measurement_travel = Some([10.0, 990.0]);
    assert_eq!(errors(&c, &d), vec!["iso-2.2-measurement-travel"]);
}

#[test]
fn spacing_warnings() {
    let c = ctx(AxisKind::Linear);
    let even: Vec<f64> = (0..6).map(|k| k as f64 * 200.0).collect();
    let f = check(&c, &data(AxisKind::Linear, &even, 5));
    assert_eq!(f.len(), 1);
    assert_eq!(
        (f[0].id, f[0].severity),
        ("iso-4.2-uniform-spacing", Severity::Warning)
    );
    let mut c = ctx(AxisKind::Linear);
    c.pitch = Some(10.0);
    let aliased = [0.0, 190.0, 400.0, 610.0, 800.0, 1000.0];
    assert_eq!(
        ids(&c, &data(AxisKind::Linear, &aliased, 5)),
        vec!["iso-4.2-pitch-alias"]
    );
    let fine = [0.0, 193.1, 402.7, 611.9, 798.4, 1000.0];
    assert!(ids(&c, &data(AxisKind::Linear, &fine, 5)).is_empty());
}

#[test]
fn thermal_drift_over_runs_warns() {
    let targets = spread(0.0, 1000.0, 6);
    let clean = data(AxisKind::Linear, &targets, 5);
    assert!(ids(&ctx(AxisKind::Linear), &clean).is_empty());
    // 1 µm per run on top of σ = 1 µm scatter... too weak to be monotonic everywhere;
    // 3 µm per run is a clear warm-up drift.
    let drifting = clean.map_deviations(|r| r.deviation * 0.3 + 3.0 * r.run as f64);
    let f = check(&ctx(AxisKind::Linear), &drifting);
    assert_eq!(f.len(), 1);
    assert_eq!(f[0].id, "iso-3.3-thermal");
    assert!(
        f[0].message.contains("increase run after run"),
        "{}",
        f[0].message
    );
}

#[test]
fn deviations_in_the_wrong_unit_warn() {
    let d = data(AxisKind::Linear, &spread(0.0, 1000.0, 6), 5);
    let in_mm = d.map_deviations(|r| r.deviation / 1000.0);
    assert_eq!(ids(&ctx(AxisKind::Linear), &in_mm), vec!["data-unit"]);
    assert!(ids(&ctx(AxisKind::Linear), &d).is_empty());
}

/// Issue 42: every deviation exactly 0 (a zero-filled column) passed every limit silently.
#[test]
fn all_zero_deviations_warn() {
    let d = data(AxisKind::Linear, &spread(0.0, 1000.0, 6), 5);
    let zero = d.map_deviations(|_| 0.0);
    let f = check(&ctx(AxisKind::Linear), &zero);
    assert_eq!(
        f.iter().map(|f| f.id).collect::<Vec<_>>(),
        vec!["data-unit"]
    );
    assert_eq!(f[0].severity, Severity::Warning);
    assert!(
        f[0].message.starts_with("every deviation is exactly 0 µm"),
        "{}",
        f[0].message
    );
    let rotary = data(
        AxisKind::Rotary,
        &[0.0, 45.0, 90.0, 135.0, 180.0, 225.0, 270.0, 315.0],
        5,
    );
    let f = check(&ctx(AxisKind::Rotary), &rotary.map_deviations(|_| 0.0));
    assert!(
        f.iter()
            .any(|f| f.id == "data-unit" && f.message.contains("exactly 0 arcsec")),
        "{f:?}"
    );
}

#[test]
fn gost_profile() {
    let mut c = ctx(AxisKind::Linear);
    c.standard = StandardId::Gost27843;
    assert!(errors(&c, &data(AxisKind::Linear, &spread(0.0, 1500.0, 11), 5)).is_empty());
    assert_eq!(
        errors(&c, &data(AxisKind::Linear, &spread(0.0, 1500.0, 10), 5)),
        vec!["gost-2.7-targets"]
    );
    assert_eq!(
        errors(&c, &data(AxisKind::Linear, &spread(0.0, 1500.0, 11), 4)),
        vec!["gost-2.10-runs"]
    );
    // 4 m: any 2 m window needs 11.
    assert!(errors(&c, &data(AxisKind::Linear, &spread(0.0, 4000.0, 22), 5)).is_empty());
    assert_eq!(
        errors(&c, &data(AxisKind::Linear, &spread(0.0, 4000.0, 19), 5)),
        vec!["gost-2.7-targets"]
    );
    let mut r = ctx(AxisKind::Rotary);
    r.standard = StandardId::Gost27843;
    assert_eq!(
        errors(&r, &data(AxisKind::Rotary, &[0.0, 90.0, 170.0, 270.0], 5)),
        vec!["gost-2.8-cardinal"]
    );
}

/// The README's rule table lists every rule, in the order they run, with its clause,
/// severity and what it checks: the two cannot drift apart.
#[test]
fn readme_rule_table_matches_the_rules() {
    let readme = include_str!("../../README.md");
    let section = readme
        .split("### Test-plan rules")
        .nth(1)
        .expect("README has a Test-plan rules section");
    let rows: Vec<Vec<String>> = section
        .lines()
        .skip_while(|l| !l.starts_with("| id |"))
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .map(|l| {
            l.trim_matches('|')
                .split(" | ")
                .map(|cell| cell.trim().trim_matches('`').to_string())
                .collect()
        })
        .collect();
    let rules: Vec<Vec<String>> = RULES
        .iter()
        .map(|r| {
            [r.id, r.clause, r.severity.name(), r.checks]
                .map(str::to_string)
                .to_vec()
        })
        .collect();
    assert_eq!(rows, rules);
}

/// Ids are unique: a finding names its rule.
#[test]
fn rule_ids_are_unique() {
    let mut ids: Vec<&str> = RULES.iter().map(|r| r.id).collect();
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(ids.len(), RULES.len());
}
