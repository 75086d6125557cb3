//! A straightness or angular test of a campaign axis (ISO 230-1): read, evaluated with
//! U, and judged against the axis's `tolerance:` by the campaign's decision rule, as a
//! positioning test is by its parameters' limits.

use super::Slot;
use crate::campaign::{AxisSpec, CampaignInfo};
use crate::compensate::cross::build::CrossCompensation;
use crate::geometry::TestKind;
use crate::geometry::judge::{Value, judge, limits};
use crate::geometry::{angular, straightness};
use crate::judge::Decision;
use crate::measurement::{AxisData, Recognised};
use crate::one_file::{OtherOptions, OtherResult, evaluate_other};
use crate::param_key::ParamKey;
use crate::results::{AxisTest, CrossOutcome, OtherTested, Outcome};

/// The test of `data` as `axis` states it, judged; an error names why it could not be.
pub(super) fn run(
    slot: Slot,
    axis: &AxisSpec,
    campaign: &CampaignInfo,
    (data, recognised): (AxisData, Recognised),
    cross: Option<Result<CrossCompensation, String>>,
) -> AxisTest {
    let raw = &axis.raw;
    let local = raw.local_mm.or_else(|| {
        raw.tolerance
            .iter()
            .find_map(|(_, t)| t.local().map(|l| l.1))
    });
    let other = OtherOptions {
        straightness: straightness::Options {
            line: raw.line.unwrap_or_default(),
            local_length_mm: local,
        },
        optics: raw.optics,
    };
    let Some((result, mut uncertainty)) = evaluate_other(&data, raw.test, &other) else {
        let message = format!(
            "{}: a {} test needs at least two targets",
            slot.file.as_deref().unwrap_or(""),
            raw.test.key()
        );
        return slot.unread(message, Some(recognised));
    };
    let length_mm = data.targets.last().unwrap_or(&0.0) - data.targets.first().unwrap_or(&0.0);
    let limits = match limits(raw.test, &raw.tolerance, length_mm) {
        Ok(l) => l,
        // Checked when the campaign was read; kept as the test's error all the same.
        Err(e) => return slot.unread(e.to_string(), Some(recognised)),
    };
    let values = values(&result, uncertainty.expanded, &mut uncertainty.notes);
    let rule = super::stages::judge::decision_rule(axis, None, campaign.decision_rule);
    let decision = Decision {
        rule,
        expanded: None,
    };
    let judgement = judge(&values, &limits, &decision);
    let mut context = super::stages::rules::context(axis);
    context.calibration =
        super::stages::rules::calibration(axis, &slot.machine, campaign, &recognised);
    let findings = crate::rules::check_instrument(&context, &data);
    let verdict = judgement.verdict(crate::rules::breaks_plan(&findings));
    let symbol = crate::campaign::geometry::symbol(raw).unwrap_or_default();
    slot.with(Outcome::Other(Box::new(OtherTested {
        verdict,
        recognised: Some(recognised),
        test: raw.test,
        symbol,
        trace: (raw.test == TestKind::Angular).then(|| angular::Trace::of(&data)),
        // Kept for a squareness of the machine; the batch drops it at its end.
        data: Some(data),
        sources: Vec::new(),
        tolerance: raw.tolerance.iter().map(|(text, _)| text.clone()).collect(),
        cross: cross.map(|table| {
            Box::new(CrossOutcome {
                table: Some(table),
                verification: None,
            })
        }),
        result,
        uncertainty,
        judgement,
        findings,
    })))
}

/// The values a tolerance may limit, with U: the straightness (and its local value, whose
/// U is taken as the whole travel's, as its note says) or the angular deviation.
fn values(result: &OtherResult, expanded: f64, notes: &mut Vec<String>) -> Vec<Value> {
    if result.value(ParamKey::StraightnessLocal).is_some() {
        notes.push(
            "U of the local straightness is taken as the whole travel's (the scatter at its own extremes is not computed)"
                .into(),
        );
    }
    (ParamKey::GEOMETRY.into_iter())
        .filter_map(|key| {
            Some(Value {
                key,
                value: result.value(key)?,
                expanded: Some(expanded),
            })
        })
        .collect()
}

/// Whether an axis entry holds another test than positioning.
pub(super) fn is_other(axis: &AxisSpec) -> bool {
    !matches!(axis.raw.test, TestKind::Positioning)
}
