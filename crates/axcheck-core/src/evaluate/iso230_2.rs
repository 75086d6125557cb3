//! ISO 230-2:1997 (= GB/T 17421.2-2000 with amendment No. 1): coverage factor 2.
//!
//! Per target (clause 5.1): X̄i↑, X̄i↓ (2.10), X̄i (2.11), Bi (2.12), Si↑, Si↓ (2.15), the
//! limit deviations X̄ ± 2S, Ri↑ = 4Si↑, Ri↓ (2.16), Ri (2.17). Per axis (7.2.1): A (2.23),
//! A↑ and A↓ (2.22; A↓ as corrected by amendment No. 1 of GB/T 17421.2:
//! `A↓ = max(X̄i↓ + 2Si↓) − min(X̄i↓ − 2Si↓)`), E (2.20), E↑, E↓ (2.19), M (2.21),
//! R (2.18), R↑, R↓ (2.18), B (2.13), B̄ (2.14). With n = 1 (clause 5.2, 7.2.2) only E,
//! E↑, E↓, M, B and B̄ apply.

use super::band;
use super::catalogue::iso230_2 as iso;
use super::stats::sample_sd;
use super::{Evaluation, Parameter, Standard, StandardId, TargetResult};
use crate::measurement::AxisData;
use crate::units::Direction::{Down, Up};

/// Coverage factor (clause 2.16: "coverage factor of 2").
pub const K: f64 = 2.0;

/// The ISO 230-2 evaluator; `id` chooses whether results are labelled ISO or GB/T.
pub struct Iso230_2 {
    pub id: StandardId,
}

impl Standard for Iso230_2 {
    fn id(&self) -> StandardId {
        self.id
    }

    fn evaluate(&self, data: &AxisData) -> Evaluation {
        let targets = band::per_target(data, K, sample_sd);
        let p = parameters(&targets);
        let mut notes = Vec::new();
        if data.runs() == 1 {
            notes.push("n = 1: S, R and A are not applicable (ISO 230-2 clause 5.2)".to_string());
        } else if data.runs() < 5 {
            notes.push(format!(
                "n = {}: the standard asks for 5 approaches per direction (clause 4.3.2)",
                data.runs()
            ));
        }
        Evaluation {
            standard: self.id,
            kind: data.kind,
            n: data.runs(),
            coverage_factor: K,
            parameters: p,
            targets,
            notes,
        }
    }
}

/// Clause 7.2.1's parameters in the standard's order; those that need S are left out
/// when n = 1 (clause 5.2).
fn parameters(targets: &[TargetResult]) -> Vec<Parameter> {
    let span = Parameter::spanned;
    // Room for all twelve at once: a fleet keeps 10 000 of these lists.
    let mut p = Vec::with_capacity(12);
    p.extend(band::accuracies(
        targets,
        [&iso::A, &iso::A_UP, &iso::A_DOWN],
    ));
    p.push(span(&iso::E, band::systematic(targets, &[Up, Down])));
    p.push(span(&iso::E_UP, band::systematic(targets, &[Up])));
    p.push(span(&iso::E_DOWN, band::systematic(targets, &[Down])));
    p.push(span(&iso::M, band::spread(targets.iter().map(|t| t.mean))));
    p.extend(band::repeatabilities(
        targets,
        [&iso::R, &iso::R_UP, &iso::R_DOWN],
    ));
    p.push(Parameter::located(&iso::B, band::max_reversal(targets)));
    p.push(Parameter::plain(&iso::B_MEAN, band::mean_reversal(targets)));
    p
}
