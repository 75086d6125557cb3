//! Each positioning test with a `tool_point:` carried from the beam to the tool point
//! through the angular tests of its axis in the campaign (Abbe, [`crate::geometry::abbe`]),
//! then evaluated and judged as the measured test is, so that a pitch or yaw that
//! changes the verdict at the tool point is seen (ISO 230-2 asks for the instrument's
//! position to be recorded; HP 5528A User's Guide, Appendix B, the offset times the
//! angle's tangent).

use super::Tested;
use crate::campaign::geometry::{across, axis_letter, rotation_about};
use crate::campaign::{AxisSpec, ToolPointRaw};
use crate::geometry::TestKind;
use crate::geometry::abbe::{self, Offset, Rotations};
use crate::geometry::angular::Trace;
use crate::judge::{self, Decision};
use crate::results::{AxisTest, Evaluated, ToolPoint};
use std::sync::Arc;

/// An angular test of the campaign: machine, axis, the rotation's letter, its symbol and
/// its mean angles.
pub(super) struct Angular {
    pub machine: String,
    pub axis: String,
    pub about: char,
    pub symbol: String,
    pub trace: Trace,
}

/// Every positioning test with a tool point carried to it (or the reason it cannot be).
pub(crate) fn carry_all(tests: &mut [Tested]) {
    let angular: Vec<Angular> = tests.iter().filter_map(|(t, _)| angular_of(t)).collect();
    for (t, _) in tests.iter_mut() {
        let Some(spec) = t.spec.clone() else { continue };
        let Some(tool) = spec.raw.tool_point else {
            continue;
        };
        let machine = t.machine.id.clone();
        let Some(e) = t.evaluated_mut() else { continue };
        let carried = carry(&spec, tool, e, |about| {
            (angular.iter())
                .find(|a| a.machine == machine && a.axis == spec.raw.name && a.about == about)
        });
        e.tool_point = Some(Box::new(carried));
    }
}

pub(super) fn angular_of(t: &AxisTest) -> Option<Angular> {
    let o = t.other().filter(|o| o.test == TestKind::Angular)?;
    let raw = &t.spec.as_ref()?.raw;
    Some(Angular {
        machine: t.machine.id.clone(),
        axis: raw.name.clone(),
        about: raw.about?.to_ascii_uppercase(),
        symbol: o.symbol.clone(),
        trace: o.trace.clone()?,
    })
}

/// The test `e` of `spec` at the tool point `tool`, with `find` giving the axis's
/// angular test about a rotation letter.
fn carry<'a>(
    spec: &Arc<AxisSpec>,
    tool: ToolPointRaw,
    e: &Evaluated,
    find: impl Fn(char) -> Option<&'a Angular>,
) -> Result<ToolPoint, String> {
    let name = &spec.raw.name;
    let own = axis_letter(name).ok_or("the axis is not named X, Y or Z")?;
    let [v, w] = across(own);
    let offset = Offset {
        v_mm: tool.along(v),
        w_mm: tool.along(w),
    };
    // A rotation about v moves the tool point by its lever along w, and the other way.
    let needed = |about: char, lever_mm: f64, lever: char| match find(rotation_about(about)) {
        Some(a) => Ok(Some(a)),
        None if lever_mm == 0.0 => Ok(None),
        None => Err(format!(
            "the tool point's offset of {lever_mm} mm along {lever} needs the rotation of {name} about {about} (E{}{name}), which the campaign does not measure: add its angular test (`test: angular`, `about: {}`)",
            rotation_about(about),
            rotation_about(about)
        )),
    };
    let about_v = needed(v, offset.w_mm, w)?;
    let about_w = needed(w, offset.v_mm, v)?;
    let data = e.data.as_ref().ok_or("the readings were not kept")?;
    let rotations = Rotations {
        about_v: about_v.map(|a| &a.trace),
        about_w: about_w.map(|a| &a.trace),
    };
    let carried = abbe::to_tool_point(data, rotations, offset).map_err(|e| e.to_string())?;
    let evaluation = crate::campaign::stages::evaluate::evaluate(spec, &carried);
    let decision = |rule| Decision {
        rule,
        expanded: e.uncertainty.as_ref().map(|u| &u.expanded),
    };
    let judgement = (e.judgement.as_ref())
        .map(|j| judge::judge(&evaluation, j.limits.clone(), &decision(j.rule)));
    let plan_broken = crate::rules::breaks_plan(&e.findings);
    let verdict = judgement
        .as_ref()
        .map_or(e.verdict, |j| j.verdict(plan_broken));
    Ok(ToolPoint {
        offsets_mm: [(v, offset.v_mm), (w, offset.w_mm)],
        rotations: [about_v, about_w].into_iter().flatten().map(|a| a.symbol.clone()).collect(),
        evaluation,
        judgement,
        verdict,
        notes: vec![
            "U at the tool point is the beam's: the angular tests' own uncertainty times the offset is not added".into(),
        ],
    })
}
