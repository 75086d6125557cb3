//! The test plan: target positions, runs, the test cycle and its timing.
//!
//! Targets follow ISO 230-2 clause 4.2, `P_i = (i − 1)P + r`, with a seeded random r per
//! target so that periodic errors are sampled, or are listed. Cycles: the standard test
//! cycle (ISO 230-2 Fig. 1, GOST's linear cycle Черт. 1), the step cycle (ISO 230-2
//! Annex A) and GOST's pilgrim-step cycle (Черт. 2). Feed and dwell give each reading its
//! time from the start of the test.

use super::rng::Rng;
use crate::units::Direction;
use serde::{Deserialize, Serialize};

/// Evenly spread targets with a random offset r per target (clause 4.2).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TargetSpacing {
    /// First target (before its offset), mm or deg.
    #[serde(alias = "start_mm", alias = "start_deg")]
    pub start: f64,
    /// Last target (before its offset).
    #[serde(alias = "end_mm", alias = "end_deg")]
    pub end: f64,
    /// Number of targets m.
    pub count: usize,
    /// Largest |r|; the first target's r is ≥ 0 and the last's ≤ 0 so the targets stay
    /// inside [start, end].
    #[serde(default)]
    #[serde(alias = "jitter_mm", alias = "jitter_deg")]
    pub jitter: f64,
}

/// Order of approaches.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Cycle {
    /// Each run: all targets upwards, then all downwards (ISO 230-2 Fig. 1).
    #[default]
    Standard,
    /// Each target in turn: n approaches from each direction, alternating (Annex A).
    Step,
    /// Each run: two steps forward, one back, so each target is reached ↑ then ↓ within
    /// a short time (GOST 27843 Черт. 2).
    Pilgrim,
}

impl Cycle {
    pub fn name(self) -> &'static str {
        match self {
            Cycle::Standard => "standard",
            Cycle::Step => "step",
            Cycle::Pilgrim => "pilgrim",
        }
    }
}

fn default_runs() -> usize {
    5
}
fn default_feed() -> f64 {
    1000.0
}
fn default_dwell() -> f64 {
    4.0
}
fn default_overrun() -> f64 {
    5.0
}

/// A test plan.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TestPlan {
    /// Generated targets …
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub targets: Option<TargetSpacing>,
    /// … or an explicit list, mm or deg.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[serde(alias = "targets_mm", alias = "targets_deg")]
    pub target_list: Option<Vec<f64>>,
    /// Approaches per direction n.
    #[serde(default = "default_runs")]
    pub runs: usize,
    #[serde(default)]
    pub cycle: Cycle,
    /// Feed rate between targets, mm/min or deg/min.
    #[serde(default = "default_feed")]
    #[serde(alias = "feed_mm_per_min", alias = "feed_deg_per_min")]
    pub feed_per_min: f64,
    /// Dwell at each target before the reading, s.
    #[serde(default = "default_dwell")]
    pub dwell_s: f64,
    /// Travel beyond a target before reversing, mm or deg (ISO 230-2 Fig. 1).
    #[serde(default = "default_overrun")]
    #[serde(alias = "overrun_mm", alias = "overrun_deg")]
    pub overrun: f64,
}

/// Largest |position| of a target or an overrun, mm or deg: a kilometre of travel, or
/// a thousand turns; beyond it the positions would lose their thousandths.
const MAX_POSITION: f64 = 1e6;

/// Closest two generated targets may come before their offsets: twice the recording step,
/// so that they stay apart after rounding to it.
const MIN_GAP: f64 = 0.002;

/// Finite and within ±[`MAX_POSITION`].
fn within_travel(x: f64) -> bool {
    x.is_finite() && x.abs() <= MAX_POSITION
}

/// A number as a message shows it: `1e300`, not three hundred digits.
fn shown(x: f64) -> String {
    if x.abs() < 1e15 {
        x.to_string()
    } else {
        format!("{x:e}")
    }
}

/// A target as the simulated file records it: to 0.001 mm or deg.
fn round_to_recorded(x: f64) -> f64 {
    (x * 1000.0).round() / 1000.0 + 0.0
}

/// One approach in the order of measurement.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Visit {
    pub target: usize,
    pub direction: Direction,
    /// Run j, 0-based.
    pub run: usize,
    /// Seconds from the start of the test when the reading is taken (end of dwell).
    pub time_s: f64,
}

impl TestPlan {
    /// Checks a plan before use.
    pub(crate) fn validate(&self) -> Result<(), String> {
        if self.runs == 0 {
            return Err("plan.runs must be at least 1".into());
        }
        if !(self.feed_per_min > 0.0 && self.feed_per_min.is_finite()) {
            return Err("plan.feed must be > 0".into());
        }
        if !(self.dwell_s >= 0.0 && self.dwell_s.is_finite()) {
            return Err("plan.dwell_s must be a finite number ≥ 0".into());
        }
        if !(self.overrun >= 0.0 && self.overrun < MAX_POSITION) {
            return Err(format!(
                "plan.overrun must be ≥ 0 and less than {MAX_POSITION}"
            ));
        }
        self.check_size()?;
        match (&self.targets, &self.target_list) {
            (Some(_), Some(_)) => {
                Err("plan: give either targets or a target list, not both".into())
            }
            (None, None) => {
                Err("plan: give targets {start, end, count, jitter} or a target list".into())
            }
            (Some(t), None) => {
                if t.count == 0 {
                    return Err("plan.targets.count must be at least 1".into());
                }
                for (key, x) in [("start", t.start), ("end", t.end)] {
                    if !within_travel(x) {
                        return Err(format!(
                            "plan.targets.{key} must be a number within ±{MAX_POSITION}, found {}",
                            shown(x)
                        ));
                    }
                }
                if t.count > 1 && t.end.partial_cmp(&t.start) != Some(std::cmp::Ordering::Greater) {
                    return Err("plan.targets: end must be greater than start".into());
                }
                let spacing = if t.count > 1 {
                    (t.end - t.start) / (t.count - 1) as f64
                } else {
                    f64::INFINITY
                };
                if !(t.jitter >= 0.0 && t.jitter < spacing / 2.0) {
                    return Err(format!(
                        "plan.targets.jitter must be ≥ 0 and less than half the spacing ({:.3})",
                        spacing / 2.0
                    ));
                }
                if spacing - 2.0 * t.jitter < MIN_GAP {
                    return Err(format!(
                        "plan.targets: targets {spacing:.4} apart, each moved by up to {} \
                         (jitter), can come closer than {MIN_GAP}, and positions are recorded \
                         to 0.001; widen the spacing or lower the jitter",
                        t.jitter
                    ));
                }
                Ok(())
            }
            (None, Some(list)) => {
                if list.is_empty() {
                    return Err("plan: the target list is empty".into());
                }
                if let Some(x) = list.iter().find(|x| !within_travel(**x)) {
                    return Err(format!(
                        "plan.target_list: targets must be numbers within ±{MAX_POSITION}, found {}",
                        shown(*x)
                    ));
                }
                if list
                    .windows(2)
                    .any(|w| w[1].partial_cmp(&w[0]) != Some(std::cmp::Ordering::Greater))
                {
                    return Err("plan: listed targets must increase".into());
                }
                if let Some(w) = list
                    .windows(2)
                    .find(|w| round_to_recorded(w[1]) <= round_to_recorded(w[0]))
                {
                    return Err(format!(
                        "plan.target_list: targets {} and {} are the same position as recorded \
                         (to 0.001)",
                        w[0], w[1]
                    ));
                }
                Ok(())
            }
        }
    }

    /// Refuses a plan whose file no reader would take (every cycle reads each target once
    /// in each direction per run): it would only exhaust the memory.
    fn check_size(&self) -> Result<(), String> {
        let targets = match (&self.targets, &self.target_list) {
            (Some(t), _) => t.count,
            (None, Some(list)) => list.len(),
            (None, None) => 0,
        };
        let readings = self.runs.saturating_mul(targets).saturating_mul(2);
        let limit = crate::measurement::MAX_READINGS;
        if readings > limit {
            return Err(format!(
                "plan.runs: {} runs × {targets} targets × 2 directions = {readings} readings; a measurement file holds at most {limit}",
                self.runs
            ));
        }
        Ok(())
    }

    /// The target positions, rounded to 0.001 (what a file records).
    pub fn target_positions(&self, seed: u64) -> Vec<f64> {
        let round = round_to_recorded;
        if let Some(list) = &self.target_list {
            return list.iter().map(|&x| round(x)).collect();
        }
        let Some(t) = &self.targets else {
            return Vec::new();
        };
        if t.count == 1 {
            return vec![round(t.start)];
        }
        let mut rng = Rng::new(seed, 1);
        let spacing = (t.end - t.start) / (t.count - 1) as f64;
        (0..t.count)
            .map(|i| {
                let (lo, hi) = if i == 0 {
                    (0.0, t.jitter)
                } else if i == t.count - 1 {
                    (-t.jitter, 0.0)
                } else {
                    (-t.jitter, t.jitter)
                };
                round(t.start + i as f64 * spacing + rng.range(lo, hi))
            })
            .collect()
    }

    /// The approaches in the order of the cycle, with their times.
    pub fn schedule(&self, targets: &[f64]) -> Vec<Visit> {
        let seconds_per_unit = 60.0 / self.feed_per_min;
        let mut position = targets[0] - self.overrun;
        let mut time_s = 0.0;
        let mut visits = Vec::new();
        for step in self.steps(targets) {
            time_s += (step.position() - position).abs() * seconds_per_unit;
            position = step.position();
            if let Step::Read {
                target,
                direction,
                run,
                ..
            } = step
            {
                time_s += self.dwell_s;
                visits.push(Visit {
                    target,
                    direction,
                    run,
                    time_s,
                });
            }
        }
        visits
    }

    /// The axis's path through the test in the order of the cycle, from the start below the
    /// first target (its first step): moves beyond a target by the overrun before each
    /// reversal, and the targets read, each approached from its direction.
    pub fn steps(&self, targets: &[f64]) -> Vec<Step> {
        let mut path = Path::default();
        let m = targets.len();
        let first = targets[0];
        let last = targets[m - 1];
        for run in 0..self.runs {
            match self.cycle {
                Cycle::Standard => {
                    path.go(first - self.overrun);
                    for (i, &p) in targets.iter().enumerate() {
                        path.read(p, i, Direction::Up, run);
                    }
                    path.go(last + self.overrun);
                    for (i, &p) in targets.iter().enumerate().rev() {
                        path.read(p, i, Direction::Down, run);
                    }
                }
                Cycle::Pilgrim => {
                    path.go(first - self.overrun);
                    path.read(first, 0, Direction::Up, run);
                    for i in 1..m {
                        path.read(targets[i], i, Direction::Up, run);
                        path.read(targets[i - 1], i - 1, Direction::Down, run);
                    }
                    path.go(last + self.overrun);
                    path.read(last, m - 1, Direction::Down, run);
                }
                Cycle::Step => {}
            }
        }
        if self.cycle == Cycle::Step {
            for (i, &p) in targets.iter().enumerate() {
                for run in 0..self.runs {
                    path.go(p - self.overrun);
                    path.read(p, i, Direction::Up, run);
                    path.go(p + self.overrun);
                    path.read(p, i, Direction::Down, run);
                }
            }
        }
        path.steps
    }
}

/// One step of the axis's path through a test.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Step {
    /// Travel to a position: an overrun beyond a target before a reversal.
    Move(f64),
    /// Travel to target `target` (0-based) at `position`, approached in `direction`, and
    /// read it after the dwell; run `run`, 0-based.
    Read {
        position: f64,
        target: usize,
        direction: Direction,
        run: usize,
    },
}

impl Step {
    /// Where the step ends.
    pub fn position(&self) -> f64 {
        match *self {
            Step::Move(p) | Step::Read { position: p, .. } => p,
        }
    }
}

/// The steps of a path, in order.
#[derive(Default)]
struct Path {
    steps: Vec<Step>,
}

impl Path {
    fn go(&mut self, to: f64) {
        self.steps.push(Step::Move(to));
    }

    fn read(&mut self, position: f64, target: usize, direction: Direction, run: usize) {
        self.steps.push(Step::Read {
            position,
            target,
            direction,
            run,
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plan(cycle: Cycle) -> TestPlan {
        TestPlan {
            targets: None,
            target_list: Some(vec![0.0, 100.0, 200.0]),
            runs: 2,
            cycle,
            feed_per_min: 600.0,
            dwell_s: 1.0,
            overrun: 10.0,
        }
    }

    fn order(v: &[Visit]) -> Vec<(usize, Direction, usize)> {
        v.iter().map(|v| (v.target, v.direction, v.run)).collect()
    }

    #[test]
    fn standard_cycle_order_and_times() {
        use Direction::{Down as D, Up as U};
        let p = plan(Cycle::Standard);
        let v = p.schedule(&[0.0, 100.0, 200.0]);
        assert_eq!(v.len(), 12);
        assert_eq!(
            order(&v[..6]),
            vec![
                (0, U, 0),
                (1, U, 0),
                (2, U, 0),
                (2, D, 0),
                (1, D, 0),
                (0, D, 0)
            ]
        );
        // 10 units at 10 units/s = 1 s, then 1 s dwell.
        assert!((v[0].time_s - 2.0).abs() < 1e-12);
        assert!((v[1].time_s - 13.0).abs() < 1e-12);
    }

    #[test]
    fn pilgrim_and_step_visit_everything_once_per_run() {
        for cycle in [Cycle::Pilgrim, Cycle::Step] {
            let v = plan(cycle).schedule(&[0.0, 100.0, 200.0]);
            assert_eq!(v.len(), 12);
            let mut seen = order(&v);
            seen.sort();
            seen.dedup();
            assert_eq!(seen.len(), 12, "{cycle:?}");
            assert!(v.windows(2).all(|w| w[1].time_s > w[0].time_s));
        }
        use Direction::{Down as D, Up as U};
        let v = plan(Cycle::Pilgrim).schedule(&[0.0, 100.0, 200.0]);
        assert_eq!(
            order(&v[..6]),
            vec![
                (0, U, 0),
                (1, U, 0),
                (0, D, 0),
                (2, U, 0),
                (1, D, 0),
                (2, D, 0)
            ]
        );
    }

    #[test]
    fn generated_targets_follow_clause_4_2() {
        let p = TestPlan {
            targets: Some(TargetSpacing {
                start: 0.0,
                end: 1000.0,
                count: 11,
                jitter: 20.0,
            }),
            target_list: None,
            ..plan(Cycle::Standard)
        };
        p.validate().unwrap();
        let t = p.target_positions(3);
        assert_eq!(t.len(), 11);
        assert!(t[0] >= 0.0 && t[10] <= 1000.0);
        for (i, x) in t.iter().enumerate() {
            assert!((x - 100.0 * i as f64).abs() <= 20.0);
        }
        let gaps: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).collect();
        assert!(
            gaps.iter().any(|g| (g - gaps[0]).abs() > 0.5),
            "spacing varies"
        );
        assert_eq!(t, p.target_positions(3), "deterministic");
    }
}
