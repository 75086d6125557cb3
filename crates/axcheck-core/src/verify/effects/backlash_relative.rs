//! `backlash_relative`: a HEIDENHAIN `.COM` table's `BACKLASH` column was read by the control
//! as a difference from the axis column, not as the ↓ values themselves (axcheck writes
//! and reads it absolute: "the compensation values measured in the negative direction of
//! traverse", HEIDENHAIN Technical Manual MANUALplus 620 (01/2012) §6.10.3 pp. 713–718;
//! absolute is inferred from that wording, not confirmed for the TNC 620/640).
//!
//! The file holds errors e = −correction: the axis column A = e↑, `BACKLASH` B = e↓. Read
//! as a difference the ↓ error is A + B (the column as the ↓ values less the ↑ ones) or
//! A − B (as a reversal value, ISO 230-2's B = x̄↑ − x̄↓), so the ↓ correction that acts is
//! c↑ + c↓ or c↑ − c↓, the ↑ one unchanged. The reverse mix-up shows the same way: a file
//! whose `BACKLASH` column was written as differences, read by axcheck as absolute values
//! and by a control that reads differences, acts as c↑ + c↓ of axcheck's reading. (A file
//! of differences on a control that reads absolute values acts as axcheck reads it: its
//! re-measurement follows the prediction, and the prediction shows what it does.) The
//! control reads the table active before alike, so both are read so.
//!
//! What the data show: the ↑ changes follow the table named (their χ² within the
//! scatter), the ↓ ones do not, and follow the ↑ column combined with the ↓ one. Tried only
//! on `heidenhain`, whose table has such a column.

use super::{Candidate, EffectContext, Key, VerifyEffect, chi2_of};
use crate::compensate::Table;
use crate::compensate::controllers::Controller;
use crate::compensate::controllers::heidenhain::Heidenhain;
use crate::units::{Direction, fmt_fixed};

pub struct BacklashRelative;

impl VerifyEffect for BacklashRelative {
    fn candidates(&self, ctx: &EffectContext) -> Vec<Candidate> {
        if ctx.controller.map(|c| c.name()) != Some(Heidenhain.name()) {
            return Vec::new();
        }
        [1.0, -1.0]
            .into_iter()
            .map(|sign| {
                let change = ctx.change_acted(|t| relative(t, sign));
                let what = evidence(ctx, &change, sign);
                Candidate {
                    key: Key::BacklashRelative,
                    change,
                    params: vec![("sign", sign)],
                    what,
                }
            })
            .collect()
    }
}

/// The table as a control acts on it that reads its ↓ column as a difference: c↓ becomes
/// c↑ + sign · c↓.
fn relative(table: &Table, sign: f64) -> Table {
    let down = table
        .up
        .iter()
        .zip(&table.down)
        .map(|(u, d)| u + sign * d)
        .collect();
    Table {
        down,
        ..table.clone()
    }
}

/// What the data show: ↑ follows the table named, ↓ the combined columns.
fn evidence(ctx: &EffectContext, change: &[f64], sign: f64) -> String {
    let applied = ctx.applied();
    let (up, n_up) = chi2_of(ctx.rows, &applied, Direction::Up);
    let (down, n_down) = chi2_of(ctx.rows, &applied, Direction::Down);
    let (down_relative, _) = chi2_of(ctx.rows, change, Direction::Down);
    let read = if sign > 0.0 {
        "↓ = axis column + BACKLASH: the column as the ↓ values less the axis column"
    } else {
        "↓ = axis column − BACKLASH: the column as a reversal value"
    };
    format!(
        "the BACKLASH column acted as a difference from the axis column ({read}), not as the ↓ values themselves: the ↑ changes follow the table named (χ²↑ = {} on {n_up} targets), the ↓ changes do not (χ²↓ = {} on {n_down}) and follow the columns so combined (χ²↓ = {})",
        fmt_fixed(up, 1),
        fmt_fixed(down, 1),
        fmt_fixed(down_relative, 1)
    )
}
