//! Measurement uncertainty of the reported parameters: a GUM budget (JCGM 100:2008) per
//! parameter and its expanded uncertainty U = k·u_c with k = 2 (GUM 6.2.1, 6.3.3), as
//! ISO/TR 230-9:2005 applies the GUM to machine tool tests.
//!
//! Pure: from a [`Setup`] (what the campaign says about the instrument and the
//! conditions, with documented defaults) and an [`Evaluation`] to an [`Uncertainty`]. One
//! file per contributor in [`contributors`]; [`extent`] says what each parameter spans
//! and computes the statistical part of its estimates. The judge compares values with
//! limits ± U (ISO 14253-1); this module only computes U.

pub mod budget;
pub mod contributors;
pub mod extent;
pub mod setup;

pub use budget::{Budget, BudgetLine, Distribution, Input};
pub use setup::{AirCompensation, Instrument, InstrumentKind, Setup, Thermal};

use crate::evaluate::{Evaluation, ParamKey};
use contributors::Context;
use extent::Extent;
use serde::Serialize;
use std::collections::BTreeMap;

/// The coverage factor of U (GUM 6.3.3: about 95 % for a normal distribution).
pub const K: f64 = 2.0;

/// One parameter's budget.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ParameterBudget {
    /// The parameter's key: `A`, `E_up`, `R_max` …
    pub key: ParamKey,
    #[serde(flatten)]
    pub budget: Budget,
}

/// The uncertainty of one axis test's parameters.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Uncertainty {
    /// Coverage factor, 2.
    pub k: f64,
    /// Deviation unit of U and of every budget's result: `um` or `arcsec`.
    pub unit: &'static str,
    /// U by parameter key, deviation unit; levels (which take no tolerance) are left out.
    #[serde(rename = "U")]
    pub expanded: BTreeMap<String, f64>,
    /// The instrument-and-environment budget over the full measurement travel: what any
    /// range over the whole axis carries before the statistics of its own estimates.
    pub budget: Budget,
    /// Each parameter's budget, in the standard's order.
    pub parameters: Vec<ParameterBudget>,
    /// What was assumed.
    pub notes: Vec<String>,
}

impl Uncertainty {
    /// U of parameter `key`, deviation unit.
    pub fn expanded_of(&self, key: ParamKey) -> Option<f64> {
        self.expanded.get(key.as_str()).copied()
    }

    /// The budget of parameter `key`.
    pub fn parameter(&self, key: ParamKey) -> Option<&Budget> {
        self.parameters
            .iter()
            .find(|p| p.key == key)
            .map(|p| &p.budget)
    }
}

/// The budget of every parameter of `evaluation` measured as `setup` says.
pub fn evaluate(setup: &Setup, evaluation: &Evaluation) -> Uncertainty {
    let kind = evaluation.kind;
    let travel = extent::travel(evaluation);
    let budget_of = |extent: &Extent| {
        let ctx = Context {
            setup,
            kind,
            travel,
            extent,
        };
        Budget::new(extent.length, contributors::lines(&ctx), K)
    };
    let parameters: Vec<ParameterBudget> = evaluation
        .parameters
        .iter()
        .filter_map(|p| {
            let extent = extent::of(evaluation, p)?;
            Some(ParameterBudget {
                key: p.def.key,
                budget: budget_of(&extent),
            })
        })
        .collect();
    Uncertainty {
        k: K,
        unit: kind.deviation_unit(),
        expanded: parameters
            .iter()
            .map(|p| (p.key.to_string(), p.budget.expanded))
            .collect(),
        budget: budget_of(&Extent::range(travel)),
        parameters,
        notes: notes(setup, evaluation),
    }
}

/// What the budget assumed, for the report.
fn notes(setup: &Setup, e: &Evaluation) -> Vec<String> {
    use crate::evaluate::StandardId;
    use crate::units::AxisKind;
    let mut notes = Vec::new();
    if let Some(m) = setup.instrument.kind.measures().filter(|&m| m != e.kind) {
        notes.push(format!(
            "an instrument for {m} axes on a {} axis: its stated accuracy is taken in {}",
            e.kind,
            e.kind.deviation_symbol()
        ));
    }
    let t = &setup.thermal;
    if e.kind == AxisKind::Linear && t.mean_c.is_none() {
        notes.push(format!(
            "material temperature not recorded: |T − 20 °C| ≤ {} °C assumed (rectangular)",
            t.unrecorded_band_c
        ));
    }
    let band = matches!(
        e.standard,
        StandardId::Iso230_2 | StandardId::Gbt17421_2 | StandardId::Gost27843
    );
    if e.n < 2
        && band
        && let Some(s) = extent::single_reading_s(e)
    {
        notes.push(format!(
            "n = 1: the scatter of one reading estimated from the reversals over the {} targets, s = s(Bi)/√2 = {} {} (GUM 4.2.4; assumed: the reversal is the same at every target, so a real change along the axis counts as scatter and U errs high)",
            e.targets.len(),
            crate::units::fmt_fixed(s, 3),
            e.kind.deviation_symbol()
        ));
    } else if e.n < 2 && band {
        notes.push(format!(
            "n = 1: the scatter of the means is unknown (fewer than {} targets to estimate it from); the statistical part is left out and U holds the instrument and the environment only",
            extent::SINGLE_READING_MIN_TARGETS
        ));
    } else if e.n < 2 {
        notes.push(
            "n = 1: the scatter of the means is unknown; the statistical part is left out"
                .to_string(),
        );
    } else if matches!(e.standard, StandardId::Vdi3441 | StandardId::Nmtba) {
        notes.push(format!(
            "{}: instrument and environment only (the statistical part is computed for \
             ISO 230-2 and GOST 27843)",
            e.standard.title()
        ));
    }
    notes
}
