//! The plan file (YAML): the axis (`continuous: true` for a rotary axis that turns
//! freely), the targets in the axis unit, and how the axis is driven (`runs`, `cycle`, `overrun`, `dwell_s`, `feed`), as `axcheck plan -o` writes it;
//! `axcheck simulate --plan`, `plan --from` and a campaign's `plan:` read it.

use super::{Axis, Motion, Plan, PlanError};
use crate::axis_model::Cycle;
use crate::evaluate::StandardId;
use crate::units::{AxisKind, Travel};
use crate::yaml::{Located, YamlError};
use serde::{Deserialize, Serialize};

/// What the file holds.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct PlanFile {
    #[serde(deserialize_with = "crate::yaml::keyword")]
    pub kind: AxisKind,
    /// `iso230-2`, `gbt17421.2`, `gost27843`, `vdi3441` or `nmtba`.
    pub standard: String,
    /// mm or deg: a length or its two ends.
    pub axis_travel: Travel,
    /// A rotary axis that turns freely; absent: false (every move inside the travel).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub continuous: bool,
    /// [first, last] target, mm or deg.
    pub measurement_travel: [f64; 2],
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pitch: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub scale_pitch: Option<f64>,
    /// The seed the offsets were drawn from (absent: targets given).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// The target positions in order, mm or deg.
    pub targets: Vec<f64>,
    pub runs: usize,
    #[serde(deserialize_with = "crate::yaml::keyword")]
    pub cycle: Cycle,
    /// mm or deg.
    pub overrun: f64,
    pub dwell_s: f64,
    /// mm/min or deg/min.
    pub feed: f64,
}

/// The plan's file: a comment head, then the keys.
pub fn to_yaml(plan: &Plan) -> String {
    let file = PlanFile {
        kind: plan.axis.kind,
        standard: short_name(plan.axis.standard).to_string(),
        axis_travel: plan.axis.travel,
        continuous: plan.axis.continuous,
        measurement_travel: plan.measurement_travel,
        pitch: plan.axis.pitch,
        scale_pitch: plan.axis.scale_pitch,
        seed: plan.seed,
        targets: plan.targets.clone(),
        runs: plan.runs,
        cycle: plan.motion.cycle,
        overrun: plan.motion.overrun,
        dwell_s: plan.motion.dwell_s,
        feed: plan.motion.feed,
    };
    let (pos, per_min) = match plan.axis.kind {
        AxisKind::Linear => ("mm", "mm/min"),
        AxisKind::Rotary => ("deg", "deg/min"),
    };
    let head = format!(
        "# Test plan written by axcheck: {} targets in {pos} ({}), {} runs, {} cycle.\n\
         # Positions, overrun and travels in {pos}; feed in {per_min}; dwell in s.\n",
        plan.targets.len(),
        plan.axis.standard.title(),
        plan.runs,
        plan.motion.cycle.name()
    );
    let body = serde_norway::to_string(&file).expect("a plan serialises");
    head + &body
}

/// The plan in `text`, its targets checked by the rules again; `file` names it in
/// errors, which give line and column.
pub fn from_yaml(text: &str, file: &str) -> Result<Plan, YamlError> {
    let (value, index) = crate::yaml::parse(text, file)?;
    let raw: PlanFile =
        crate::yaml::deserialize_at(&value, "", &index).map_err(|located| located.in_file(file))?;
    let at = |key: &str| index.value(key);
    let fail = |key: &str, message: String| {
        Located::new(at(key), format!("{key}: {message}")).in_file(file)
    };
    let standard = StandardId::parse(&raw.standard).ok_or_else(|| {
        fail(
            "standard",
            format!(
                "unknown standard `{}`; expected iso230-2, gbt17421.2, gost27843, vdi3441 or nmtba",
                raw.standard
            ),
        )
    })?;
    let axis = Axis {
        kind: raw.kind,
        standard,
        travel: raw.axis_travel,
        continuous: raw.continuous,
        measurement_travel: Some(raw.measurement_travel),
        pitch: raw.pitch,
        scale_pitch: raw.scale_pitch,
    };
    let motion = Motion {
        runs: Some(raw.runs),
        cycle: raw.cycle,
        overrun: raw.overrun,
        dwell_s: raw.dwell_s,
        feed: raw.feed,
    };
    let key = |e: &PlanError| match e {
        PlanError::Travel(_) => "measurement_travel",
        PlanError::Targets(_) => "targets",
        PlanError::Motion(_) => "runs",
    };
    let plan = super::with_targets(&axis, &motion, raw.targets)
        .and_then(|mut plan| {
            super::measurement_travel(&axis, motion.overrun)?;
            plan.seed = raw.seed;
            Ok(plan)
        })
        .map_err(|e| fail(key(&e), e.to_string()))?;
    Ok(plan)
}

/// The standard's name as `--standard` takes it.
pub fn short_name(s: StandardId) -> &'static str {
    match s {
        StandardId::Iso230_2 => "iso230-2",
        StandardId::Gbt17421_2 => "gbt17421.2",
        StandardId::Gost27843 => "gost27843",
        StandardId::Vdi3441 => "vdi3441",
        StandardId::Nmtba => "nmtba",
    }
}
