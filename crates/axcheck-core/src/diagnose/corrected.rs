//! The standard's parameters as measured and, beside them, with each kept effect removed
//! from the readings (and with all of them removed when there are several): the types
//! ([`Corrected`]) and how they are computed.

use super::analysis::Analysis;
use super::effects::Effect;
use super::fitted::Fitted;
use crate::evaluate::{ParamKey, StandardId, evaluate};

/// One parameter as measured and with an effect removed.
#[derive(Debug, Clone, PartialEq)]
pub struct CorrectedParameter {
    pub key: ParamKey,
    pub measured: f64,
    pub corrected: f64,
}

/// The standard's parameters with one kept effect (or `all`) removed.
#[derive(Debug, Clone, PartialEq)]
pub struct Corrected {
    pub effect: String,
    pub parameters: Vec<CorrectedParameter>,
}

/// The parameters of `standard` without each of the `kept` effects; an effect that cannot
/// be subtracted gets a note instead.
pub(crate) fn corrected(
    a: &Analysis,
    fit: &Fitted,
    kept: &[Effect],
    standard: StandardId,
    notes: &mut Vec<String>,
) -> Vec<Corrected> {
    let mut effects: Vec<(String, Vec<f64>)> = Vec::new();
    let mut not_subtracted = Vec::new();
    for e in kept {
        match e.rule().removed(&a.basis, fit) {
            Some(v) => effects.push((e.name().to_string(), v)),
            None => not_subtracted.push(*e),
        }
    }
    for e in not_subtracted {
        notes.push(format!(
            "{} cannot be subtracted from the readings: no \"effect removed\" parameters for it",
            e.name()
        ));
    }
    if effects.len() > 1 {
        let mut sum = vec![0.0; a.basis.x.len()];
        for (_, v) in &effects {
            for (s, e) in sum.iter_mut().zip(v) {
                *s += e;
            }
        }
        effects.push(("all".to_string(), sum));
    }
    let (data, p) = (a.basis.data, &a.basis.prep);
    let measured = evaluate(data, standard);
    let key = |i: usize, d: usize, j: usize| (i * 2 + d) * p.n + j;
    effects
        .iter()
        .map(|(name, effect)| {
            let mut grid = vec![0.0; 2 * p.m * p.n];
            for (r, e) in p.rows.iter().zip(effect) {
                grid[key(r.i, r.d, r.run)] = *e;
            }
            let fixed = data
                .map_deviations(|r| r.deviation - grid[key(r.target, r.direction.index(), r.run)]);
            let ev = evaluate(&fixed, standard);
            Corrected {
                effect: name.clone(),
                parameters: measured
                    .parameters
                    .iter()
                    .filter_map(|m| {
                        ev.value(m.def.key).map(|c| CorrectedParameter {
                            key: m.def.key,
                            measured: m.value,
                            corrected: c,
                        })
                    })
                    .collect(),
            }
        })
        .collect()
}
