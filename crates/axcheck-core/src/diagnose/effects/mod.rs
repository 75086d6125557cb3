//! The vocabulary of effects, one file each (as a linter keeps one file per rule): its
//! decision on its test (each effect's `Rule::find`: the finding with its typed estimate), its term
//! of the held-out model ([`Rule::term`]) and the unrelated terms it is compared with
//! ([`Rule::unrelated`]), what it adds to the extended simulation model
//! ([`Rule::extend`]) and its "effect removed" correction ([`Rule::removed`]). Here too
//! the [`Finding`] the rules write, whose estimate is one of theirs ([`Estimate`]); its
//! parts that need no effect ([`Units`], [`Evidence`], [`Fields`]) are in `finding.rs`.
//!
//! Each effect's file is whole: its test (the statistics and what they are read
//! against), its estimate and advice, its finding, its model term and validation switch.
//! The analysis above (`analysis.rs`, and `time.rs` for the four effects in time, which
//! share one time model) runs the tests in order and hands each effect its own; the
//! effects see only what they share ([`Basis`], and [`Fitted`] for the extended model).
//!
//! Adding an effect is one file here, one line in the list at the end of this file and
//! one in `Analysis::findings` (and, when its term is one of the held-out reading model,
//! its switch in `model_terms::ModelTerms` and its part of the fit that the switch turns
//! on).

pub mod drift;
pub mod outlier;
pub mod periodic;
pub mod reversal_variation;
pub mod run_offset;
pub mod scatter_variation;
#[cfg(test)]
pub(crate) mod testing;
pub mod thermal_growth;
pub mod warm_up;

use super::basis::Basis;
pub(crate) use super::confirm::Unrelated;
use super::finding::{Evidence, Fields, Keyed, Units};
use super::fitted::Fitted;
use super::model_terms::ModelTerms;
use crate::axis_model::ErrorModel;
use serde::Serialize;
use serde::ser::Serializer;

/// The label of a finding along the axis beside run offsets where the plan could not test
/// a warm-up, whose course within the first runs would make the same pattern (the
/// reversal and the scatter variation; `untested_warm_up` in `analysis.rs` decides it).
pub(crate) const WARM_UP_UNTESTED: (&str, &str) = ("warm_up", "untested beside the run offsets");

/// The measure a term is judged on before the extended model takes it (it must lower it
/// by more than unrelated terms of the same size do: [`super::confirm`]).
#[derive(Clone, Copy)]
pub(crate) enum Term {
    /// A term of the reading model: the held-out RMS of the readings.
    Readings(fn(&mut ModelTerms)),
    /// A term of the target means: their leave-targets-out RMS.
    TargetMeans,
    /// A term of the reading model along the axis in a shape ([`super::shape::Shape`]):
    /// the held-out RMS of the readings, the shape chosen by it, compared with tests
    /// simulated without the term ([`super::shaped`]).
    Shaped(fn(&mut ModelTerms, super::shape::Shape)),
    /// A term of the reading model's scatter along the axis in a shape: the held-out
    /// negative log density (an RMS cannot see it), the shape chosen by it, compared with tests simulated without
    /// the term.
    ShapedDensity(fn(&mut ModelTerms, super::shape::Shape)),
}

/// One effect of the vocabulary. Its findings come from its own test (each effect's
/// `Rule::find`, given its test by the analysis that runs them in order).
pub(crate) trait Rule: Sync {
    /// How its term is judged.
    fn term(&self) -> Term;
    /// The unrelated terms of the same size its term's gain is compared with.
    fn unrelated(&self) -> Unrelated;
    /// Adds the kept term to the extended model (whose plan is the file's plan).
    fn extend(&self, a: &Basis, fit: &Fitted, model: &mut ErrorModel);
    /// The effect per row of `a.prep` to subtract from the readings for the "effect
    /// removed" parameters; None when it cannot be subtracted.
    fn removed(&self, a: &Basis, fit: &Fitted) -> Option<Vec<f64>>;
}

/// Access to one effect's estimate in a finding.
pub trait Typed: Sized {
    fn of(estimate: &Estimate) -> Option<&Self>;
}

/// One named cause.
#[derive(Debug, Clone, PartialEq)]
pub struct Finding {
    pub estimate: Estimate,
    pub units: Units,
    pub evidence: Evidence,
    pub message: String,
}

impl Finding {
    pub fn effect(&self) -> Effect {
        self.estimate.effect()
    }

    /// The estimate as the parameters of the stable interface: keys with units, in order.
    pub fn params(&self) -> Vec<(String, f64)> {
        self.estimate.fields().params(self.units)
    }

    /// Non-numeric facts (an outlier's direction …), in order.
    pub fn labels(&self) -> Vec<(&'static str, &'static str)> {
        self.estimate.fields().labels()
    }

    /// `key = value, …, label = text`: the parameters and labels, numbers written by `num`.
    pub fn params_text(&self, num: impl Fn(f64) -> String) -> String {
        self.params()
            .iter()
            .map(|(k, v)| format!("{k} = {}", num(*v)))
            .chain(self.labels().iter().map(|(k, v)| format!("{k} = {v}")))
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// What to do next about this cause (`advice` in the JSON).
    pub fn advice(&self) -> String {
        self.estimate.fields().advice(self.units)
    }

    /// The parameter with `key` (a key of [`Finding::params`]).
    pub fn param(&self, key: &str) -> Option<f64> {
        self.params()
            .into_iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v)
    }
}

/// A finding as the stable JSON has it.
#[derive(serde::Serialize)]
struct FindingJson<'a> {
    effect: Effect,
    params: Keyed<String, f64>,
    labels: Keyed<&'static str, &'static str>,
    evidence: &'a Evidence,
    message: &'a str,
    advice: String,
}

impl Serialize for Finding {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        FindingJson {
            effect: self.effect(),
            params: Keyed(self.params()),
            labels: Keyed(self.labels()),
            evidence: &self.evidence,
            message: &self.message,
            advice: self.advice(),
        }
        .serialize(s)
    }
}

/// Declares the vocabulary from one list: the [`Effect`] enum (in the order of the
/// findings), the [`Estimate`] enum of the typed estimates and each effect's [`Rule`].
/// Each line names the variant, its stable name and its module, which holds a struct of
/// the variant's name (the estimate) and a unit struct `Rule`.
macro_rules! effects {
    ($( $(#[$doc:meta])* $name:ident = $key:literal in $module:ident, )+) => {
        /// The vocabulary of causes.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
        #[serde(rename_all = "snake_case")]
        pub enum Effect {
            $( $(#[$doc])* $name, )+
        }

        impl Effect {
            pub const ALL: &'static [Effect] = &[$(Effect::$name),+];

            /// The stable name: `drift`, `thermal_growth`, …
            pub fn name(self) -> &'static str {
                match self {
                    $( Effect::$name => $key, )+
                }
            }

            pub(crate) fn rule(self) -> &'static dyn Rule {
                match self {
                    $( Effect::$name => &$module::Rule, )+
                }
            }
        }

        /// A finding's estimate, one type per effect.
        #[derive(Debug, Clone, PartialEq)]
        pub enum Estimate {
            $( $name($module::$name), )+
        }

        impl Estimate {
            pub fn effect(&self) -> Effect {
                match self {
                    $( Estimate::$name(_) => Effect::$name, )+
                }
            }

            pub(crate) fn fields(&self) -> &dyn Fields {
                match self {
                    $( Estimate::$name(e) => e, )+
                }
            }
        }

        $(
            impl From<$module::$name> for Estimate {
                fn from(e: $module::$name) -> Estimate {
                    Estimate::$name(e)
                }
            }

            impl Typed for $module::$name {
                fn of(estimate: &Estimate) -> Option<&Self> {
                    match estimate {
                        Estimate::$name(e) => Some(e),
                        _ => None,
                    }
                }
            }
        )+
    };
}

effects! {
    /// Deviations move linearly with time, uniformly along the axis (ISO 230-2 3.3).
    Drift = "drift" in drift,
    /// Deviations approach a new level exponentially: the machine still warming up
    /// (ISO 230-2 3.3).
    WarmUp = "warm_up" in warm_up,
    /// A time-dependent error proportional to position (screw or scale expansion).
    ThermalGrowth = "thermal_growth" in thermal_growth,
    /// Each run shifted as a whole, not ordered in time (zero-point instability).
    RunOffset = "run_offset" in run_offset,
    /// Periodic error along the axis (lead screw, scale).
    Periodic = "periodic" in periodic,
    /// The reversal value changes along the axis.
    ReversalVariation = "reversal_variation" in reversal_variation,
    /// Readings inconsistent with the rest.
    Outlier = "outlier" in outlier,
    /// Scatter that changes along the axis.
    ScatterVariation = "scatter_variation" in scatter_variation,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_the_serialised_names() {
        for e in Effect::ALL {
            assert_eq!(serde_json::to_value(e).unwrap(), e.name());
        }
    }
}
