//! Invariants of the ISO 230-2 and GOST 27843 parameters on random data.
use axcheck::evaluate::ParamKey;
use axcheck::evaluate::{Evaluation, StandardId, evaluate};
use axcheck::measurement::{AxisData, RawReading};
use axcheck::units::{AxisKind, Direction};
use proptest::prelude::*;

/// A random test: m targets, n runs, deviations[i][d][j].
#[derive(Debug, Clone)]
struct Test {
    targets: Vec<f64>,
    values: Vec<[Vec<f64>; 2]>,
}

fn test_strategy() -> impl Strategy<Value = Test> {
    (1usize..7, 2usize..6).prop_flat_map(|(m, n)| {
        (
            proptest::collection::vec(1.0f64..200.0, m),
            proptest::collection::vec(
                (
                    proptest::collection::vec(-50.0f64..50.0, n),
                    proptest::collection::vec(-50.0f64..50.0, n),
                ),
                m,
            ),
        )
            .prop_map(|(gaps, cells)| {
                let mut pos = 0.0;
                let targets = gaps
                    .iter()
                    .map(|g| {
                        pos += g;
                        pos
                    })
                    .collect();
                Test {
                    targets,
                    values: cells.into_iter().map(|(u, d)| [u, d]).collect(),
                }
            })
    })
}

fn build(
    t: &Test,
    f: impl Fn(usize, Direction, usize, f64) -> (Direction, usize, f64),
) -> AxisData {
    let mut raw = Vec::new();
    for (i, cell) in t.values.iter().enumerate() {
        for d in Direction::BOTH {
            for (j, &v) in cell[d.index()].iter().enumerate() {
                let (d2, j2, v2) = f(i, d, j, v);
                raw.push(RawReading {
                    target: t.targets[i],
                    direction: d2,
                    run: j2 as u32 + 1,
                    deviation: v2,
                    time_s: None,
                    temps_c: vec![],
                    line: 0,
                });
            }
        }
    }
    AxisData::from_raw(AxisKind::Linear, raw, vec![], "prop").unwrap()
}

fn iso(
    t: &Test,
    f: impl Fn(usize, Direction, usize, f64) -> (Direction, usize, f64),
) -> Evaluation {
    evaluate(&build(t, f), StandardId::Iso230_2)
}

const SHAPE: [&str; 10] = [
    "A", "A_up", "A_down", "E", "E_up", "E_down", "M", "R", "R_up", "R_down",
];

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn adding_a_constant_changes_nothing(t in test_strategy(), c in -1000.0f64..1000.0) {
        let a = iso(&t, |_, d, j, v| (d, j, v));
        let b = iso(&t, |_, d, j, v| (d, j, v + c));
        for key in SHAPE.iter().chain(&["B", "B_mean"]) {
            prop_assert!(close(a.value(ParamKey::parse(key).unwrap()).unwrap(), b.value(ParamKey::parse(key).unwrap()).unwrap()), "{key}");
        }
    }

    #[test]
    fn scaling_scales_by_the_magnitude(t in test_strategy(), k in -10.0f64..10.0) {
        let a = iso(&t, |_, d, j, v| (d, j, v));
        let b = iso(&t, |_, d, j, v| (d, j, k * v));
        for key in SHAPE.iter().chain(&["B"]) {
            prop_assert!(close(b.value(ParamKey::parse(key).unwrap()).unwrap(), k.abs() * a.value(ParamKey::parse(key).unwrap()).unwrap()), "{key}");
        }
        prop_assert!(close(b.value(ParamKey::BMean).unwrap(), k * a.value(ParamKey::BMean).unwrap()));
    }

    #[test]
    fn permuting_runs_changes_nothing(t in test_strategy(), seed in any::<u64>()) {
        let n = t.values[0][0].len();
        let a = iso(&t, |_, d, j, v| (d, j, v));
        // A different permutation for every target and direction.
        let b = iso(&t, |i, d, j, v| {
            let shift = (seed as usize).wrapping_add(7 * i + d.index()) % n;
            (d, (j + shift) % n, v)
        });
        for p in &a.parameters {
            prop_assert!(close(p.value, b.value(p.def.key).unwrap()), "{}", p.key());
        }
    }

    #[test]
    fn swapping_directions_swaps_results(t in test_strategy()) {
        let a = iso(&t, |_, d, j, v| (d, j, v));
        let b = iso(&t, |_, d, j, v| (d.opposite(), j, v));
        for (x, y) in [("A_up", "A_down"), ("E_up", "E_down"), ("R_up", "R_down")] {
            prop_assert!(close(a.value(ParamKey::parse(x).unwrap()).unwrap(), b.value(ParamKey::parse(y).unwrap()).unwrap()), "{x}");
            prop_assert!(close(a.value(ParamKey::parse(y).unwrap()).unwrap(), b.value(ParamKey::parse(x).unwrap()).unwrap()), "{y}");
        }
        for key in ["A", "E", "M", "R", "B"] {
            prop_assert!(close(a.value(ParamKey::parse(key).unwrap()).unwrap(), b.value(ParamKey::parse(key).unwrap()).unwrap()), "{key}");
        }
        prop_assert!(close(a.value(ParamKey::BMean).unwrap(), -b.value(ParamKey::BMean).unwrap()));
    }

    #[test]
    fn orderings_between_parameters(t in test_strategy()) {
        let e = iso(&t, |_, d, j, v| (d, j, v));
        let v = |k: &str| e.value(ParamKey::parse(k).unwrap()).unwrap();
        prop_assert!(v("A") >= v("A_up").max(v("A_down")));
        prop_assert!(v("A_up").min(v("A_down")) >= 0.0);
        prop_assert!(v("E") >= v("E_up").max(v("E_down")));
        prop_assert!(v("M") <= v("E") + 1e-12);
        prop_assert!(v("R") >= v("R_up").max(v("R_down")));
        prop_assert!(v("B") >= v("B_mean").abs() - 1e-12);
        let g = evaluate(&build(&t, |_, d, j, v| (d, j, v)), StandardId::Gost27843);
        let w = |k: &str| g.value(ParamKey::parse(k).unwrap()).unwrap();
        prop_assert!(w("A") >= w("A_up").max(w("A_down")));
        prop_assert!(w("R_max") >= w("R_up").max(w("R_down")));
        prop_assert!(w("B_max") >= w("B_mean").abs() - 1e-12);
        prop_assert!(w("R_max") >= w("R_mean") - 1e-12);
    }
}
