//! The decision rule of a test as the campaign states it (ISO 14253-1 or simple).

use crate::campaign::AxisSpec;
use crate::judge::{DecisionRule, Spec};

/// The decision rule: the axis's, else its spec's, else the campaign's, else simple.
pub fn decision_rule(
    axis: &AxisSpec,
    spec: Option<&Spec>,
    campaign_rule: Option<DecisionRule>,
) -> DecisionRule {
    (axis.raw.decision_rule)
        .or(spec.and_then(|s| s.decision_rule))
        .or(campaign_rule)
        .unwrap_or_default()
}
