//! `scale`: the table's values acted scaled by a unit mistaken by a factor: µm for
//! 0.1 µm (10), mm for µm (1000), inch for mm (25.4), or the inverse. The factors tried are
//! those of units, not a free fit: a free factor near 1 is the scatter or the machine
//! changing, not a mistake.

use super::{Candidate, EffectContext, Key, VerifyEffect};

pub struct Scale;

/// The factors tried: units mistaken by powers of ten, inch for mm, and their inverses.
const FACTORS: [f64; 8] = [10.0, 100.0, 1000.0, 25.4, 0.1, 0.01, 0.001, 1.0 / 25.4];

impl VerifyEffect for Scale {
    fn candidates(&self, ctx: &EffectContext) -> Vec<Candidate> {
        let applied = ctx.applied();
        FACTORS
            .iter()
            .map(|&f| Candidate {
                key: Key::Scale,
                change: applied.iter().map(|c| f * c).collect(),
                params: vec![("factor", f)],
                what: format!(
                    "the table acted with its values {} {}: a unit mistaken by that factor",
                    if f > 1.0 { "×" } else { "÷" },
                    crate::units::fmt_position(f.max(1.0 / f))
                ),
            })
            .collect()
    }
}
