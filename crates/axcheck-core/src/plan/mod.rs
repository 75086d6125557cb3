//! Test plans before the laser is set up: the targets a standard asks for on an axis,
//! spaced as ISO 230-2 4.2 says with offsets that sample the declared periods ([`targets`]),
//! checked by the same test-plan rules the measurement will be judged by ([`crate::rules`]);
//! the part programs that run it on a control ([`programs`]) and the target list for the
//! laser software ([`laser`]). A campaign's `plan:` compares the measured targets with it
//! (the rule `plan-targets`). The plan as a file is read and written above this crate.

pub mod laser;
pub mod programs;
pub mod targets;

use crate::axis_model::{Cycle, TestPlan};
use crate::evaluate::StandardId;
use crate::measurement::{AxisData, RawReading};
use crate::rules::{self, PlanContext, Violation};
use crate::units::{AxisKind, Direction, Travel, fmt_position};

/// The axis a plan is for.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    pub kind: AxisKind,
    pub standard: StandardId,
    /// The axis travel (ISO 230-2 2.1), mm or deg.
    pub travel: Travel,
    /// A rotary axis that turns freely (no ends): measured over its whole travel with the
    /// overruns beyond it. Any other axis keeps every move of its test inside its travel.
    pub continuous: bool,
    /// The measurement travel (2.2); `None`: the axis travel less twice the overrun at each
    /// end.
    pub measurement_travel: Option<[f64; 2]>,
    /// The lead-screw pitch and the scale's (encoder's) pitch, mm or deg: periods the
    /// targets must not alias (4.2).
    pub pitch: Option<f64>,
    pub scale_pitch: Option<f64>,
}

/// How the axis is driven through the test.
#[derive(Debug, Clone, PartialEq)]
pub struct Motion {
    /// Approaches per direction n; `None`: the standard's (5, or 1 over the full travel
    /// of a linear axis over 2000 mm or a rotary one over 360°).
    pub runs: Option<usize>,
    pub cycle: Cycle,
    /// Travel beyond a target before each reversal, mm or deg (ISO 230-2 Fig. 1).
    pub overrun: f64,
    /// Dwell at each target, s: the laser's averaging time and the axis's settling.
    pub dwell_s: f64,
    /// Feed between targets, mm/min or deg/min.
    pub feed: f64,
}

impl Default for Motion {
    fn default() -> Motion {
        Motion {
            runs: None,
            cycle: Cycle::Standard,
            overrun: 5.0,
            dwell_s: 4.0,
            feed: 1000.0,
        }
    }
}

/// A plan: the targets, the measurement travel they span, the runs and the motion, and
/// what the rules find in it (nothing, for a plan axcheck made).
#[derive(Debug, Clone, PartialEq)]
pub struct Plan {
    pub axis: Axis,
    pub measurement_travel: [f64; 2],
    pub targets: Vec<f64>,
    pub runs: usize,
    pub motion: Motion,
    /// The seed the offsets were drawn from; `None` for targets given.
    pub seed: Option<u64>,
    pub findings: Vec<Violation>,
}

/// Why no plan can be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PlanError {
    #[error("{0}")]
    Travel(String),
    #[error("{0}")]
    Targets(String),
    #[error("{0}")]
    Motion(String),
}

/// Most targets a plan holds (a measurement file of 5 runs holds them all).
pub const MAX_TARGETS: usize = 10_000;

/// A plan for `axis` with the standard's targets, offsets drawn from `seed`.
pub fn plan(axis: &Axis, motion: &Motion, seed: u64) -> Result<Plan, PlanError> {
    check_motion(motion)?;
    let [first, last] = measurement_travel(axis, motion.overrun)?;
    let fixed = targets::fixed(axis.kind, axis.standard, first, last);
    let (least, widest) = targets::least(axis.kind, axis.standard, last - first);
    let periods: Vec<f64> = [axis.pitch, axis.scale_pitch]
        .into_iter()
        .flatten()
        .collect();
    // By construction the rules on targets hold; should one not, one target more is tried.
    // (A rule on runs, say n = 1 asked for a short axis, is reported as it is.)
    let mut count = least.max(fixed.len());
    loop {
        let placed = targets::place(&fixed, count, widest, &periods, seed);
        let plan = checked(axis, motion, [first, last], placed, Some(seed))?;
        let more_helps = plan.findings.iter().any(|f| ON_TARGETS.contains(&f.id));
        if !more_helps || count >= least + 8 {
            return Ok(plan);
        }
        count += 1;
    }
}

/// The rules on the targets' number and spacing, which more targets can satisfy.
const ON_TARGETS: &[&str] = &[
    "iso-4.3.2-targets",
    "iso-4.3.3-spacing",
    "iso-4.3.4-targets",
    "iso-4.3.5-spacing",
    "gost-2.7-targets",
    "iso-4.2-uniform-spacing",
    "iso-4.2-pitch-alias",
];

/// The plan of `targets` given for `axis`, as the rules find it.
pub fn with_targets(axis: &Axis, motion: &Motion, targets: Vec<f64>) -> Result<Plan, PlanError> {
    check_motion(motion)?;
    if targets.is_empty() || targets.len() > MAX_TARGETS {
        return Err(PlanError::Targets(format!(
            "expected 1 to {MAX_TARGETS} targets, got {}",
            targets.len()
        )));
    }
    let mut targets: Vec<f64> = targets.into_iter().map(targets::recorded).collect();
    if targets.iter().any(|t| !t.is_finite()) {
        return Err(PlanError::Targets("the targets must be numbers".into()));
    }
    targets.sort_by(f64::total_cmp);
    if let Some(w) = targets.windows(2).find(|w| w[1] <= w[0]) {
        return Err(PlanError::Targets(format!(
            "the target {} is given twice (to 0.001)",
            fmt_position(w[0])
        )));
    }
    let travel = axis
        .measurement_travel
        .unwrap_or([targets[0], targets[targets.len() - 1]]);
    checked(axis, motion, travel, targets, None)
}

/// The plan with the rules' findings on its targets.
fn checked(
    axis: &Axis,
    motion: &Motion,
    travel: [f64; 2],
    targets: Vec<f64>,
    seed: Option<u64>,
) -> Result<Plan, PlanError> {
    let runs = motion
        .runs
        .unwrap_or_else(|| default_runs(axis, travel[1] - travel[0]));
    let mut plan = Plan {
        axis: axis.clone(),
        measurement_travel: travel,
        targets,
        runs,
        motion: motion.clone(),
        seed,
        findings: Vec::new(),
    };
    plan.findings = findings(&plan)?;
    Ok(plan)
}

/// n the standard asks for: 5, or 1 over the full travel of a linear axis over 2000 mm
/// (ISO 230-2 4.3.3) or a rotary one over 360° (4.3.5); GOST 27843 2.10: 5.
fn default_runs(axis: &Axis, travel: f64) -> usize {
    let long = match axis.kind {
        AxisKind::Linear => travel > rules::LINEAR_SHORT_MM + 1e-9,
        AxisKind::Rotary => travel > rules::ROTARY_SHORT_DEG + 1e-9,
    };
    if long && axis.standard != StandardId::Gost27843 {
        1
    } else {
        5
    }
}

/// The measurement travel: given, or the axis travel less twice the overrun at each end:
/// room to approach the first and last targets from both sides (ISO 230-2 2.2), with the
/// overrun moves kept an overrun clear of the travel's ends, linear and rotary alike; a
/// continuous rotary axis (one that turns freely) has no ends, and is measured over its
/// whole travel.
pub fn measurement_travel(axis: &Axis, overrun: f64) -> Result<[f64; 2], PlanError> {
    let (start, end) = match axis.travel {
        Travel::Length(l) => (0.0, l),
        Travel::Range([a, b]) => (a, b),
    };
    if !(end > start && start.is_finite() && end.is_finite()) {
        return Err(PlanError::Travel(format!(
            "the axis travel must run from a start to a greater end, got {start} to {end}"
        )));
    }
    if axis.continuous && axis.kind != AxisKind::Rotary {
        return Err(PlanError::Travel(
            "continuous: only a rotary axis turns freely; a linear axis has ends".into(),
        ));
    }
    if axis.continuous && end - start < rules::ROTARY_SHORT_DEG - 1e-9 {
        return Err(PlanError::Travel(format!(
            "continuous: a rotary axis that turns freely has a travel of a turn or more; got {} to {} deg",
            fmt_position(start),
            fmt_position(end)
        )));
    }
    if let Some([a, b]) = axis.measurement_travel {
        if !(b > a && a >= start && b <= end) {
            return Err(PlanError::Travel(format!(
                "the measurement travel [{}, {}] must lie inside the axis travel [{}, {}]",
                fmt_position(a),
                fmt_position(b),
                fmt_position(start),
                fmt_position(end)
            )));
        }
        return Ok([a, b]);
    }
    if axis.continuous {
        return Ok([targets::recorded(start), targets::recorded(end)]);
    }
    // The overrun beyond the first and last targets, and as much again to the ends of the
    // travel, which the program then never reaches.
    let room = 2.0 * overrun;
    let (a, b) = (
        targets::recorded(start + room),
        targets::recorded(end - room),
    );
    if b - a < 0.01 {
        return Err(PlanError::Travel(format!(
            "the axis travel {} to {} leaves no measurement travel once twice the overrun of {} is kept at each end",
            fmt_position(start),
            fmt_position(end),
            fmt_position(overrun)
        )));
    }
    Ok([a, b])
}

fn check_motion(m: &Motion) -> Result<(), PlanError> {
    let bad = |what: &str| Err(PlanError::Motion(what.to_string()));
    if m.runs.is_some_and(|n| n == 0 || n > 100) {
        return bad("runs: expected 1 to 100");
    }
    if !(m.overrun >= 0.0 && m.overrun < 1e6) {
        return bad("overrun: expected a length ≥ 0");
    }
    if !(m.dwell_s >= 0.0 && m.dwell_s < 3600.0) {
        return bad("dwell: expected a time ≥ 0 s");
    }
    if !(m.feed > 0.0 && m.feed.is_finite()) {
        return bad("feed: expected a feed > 0");
    }
    Ok(())
}

/// What the test-plan rules find in the plan, as they will in its measurement: its targets
/// read `runs` times each way, the declared travels, each declared period in turn (the
/// rules on the measured values left out).
fn findings(plan: &Plan) -> Result<Vec<Violation>, PlanError> {
    let data = readings(plan)?;
    let ctx = |pitch| PlanContext {
        kind: plan.axis.kind,
        standard: plan.axis.standard,
        axis_travel: Some(plan.axis.travel),
        measurement_travel: Some(plan.measurement_travel),
        pitch,
        planned: None,
        unstated: None,
        calibration: None,
    };
    let mut out = rules::check(&ctx(plan.axis.pitch), &data);
    // The plan's deviations are placeholders (all 0): what the rules say of measured
    // values (`data-unit`) waits for the measurement.
    out.retain(|f| f.id != "data-unit");
    if let Some(scale) = plan.axis.scale_pitch {
        let aliased = rules::check(&ctx(Some(scale)), &data);
        out.extend(
            aliased
                .into_iter()
                .filter(|f| f.id == "iso-4.2-pitch-alias"),
        );
    }
    Ok(out)
}

/// The readings a measurement of the plan holds (every deviation 0): what the rules count.
fn readings(plan: &Plan) -> Result<AxisData, PlanError> {
    let mut raw = Vec::with_capacity(2 * plan.runs * plan.targets.len());
    for run in 1..=plan.runs as u32 {
        for direction in [Direction::Up, Direction::Down] {
            for &target in &plan.targets {
                raw.push(RawReading {
                    target,
                    direction,
                    run,
                    deviation: 0.0,
                    time_s: None,
                    temps_c: vec![],
                    line: 0,
                });
            }
        }
    }
    AxisData::from_raw(plan.axis.kind, raw, vec![], "plan")
        .map_err(|e| PlanError::Targets(e.to_string()))
}

impl Plan {
    /// The plan as the simulator runs it.
    pub fn test_plan(&self) -> TestPlan {
        TestPlan {
            targets: None,
            target_list: Some(self.targets.clone()),
            runs: self.runs,
            cycle: self.motion.cycle,
            feed_per_min: self.motion.feed,
            dwell_s: self.motion.dwell_s,
            overrun: self.motion.overrun,
        }
    }
}
