//! `backlash_not_loaded`: on a controller with one table per axis and a separate backlash
//! parameter whose new value the table's file states (SINUMERIK MD32450 `$MA_BACKLASH`,
//! machine data entered apart from the `%_N_AX_EEC_INI` table), the table was loaded but the
//! parameter was not: it still holds the value active before. The table's part of the
//! correction acts in both directions, the reversal stays as it was.
//!
//! What the data show: each direction's change follows the table (its χ² with its own
//! offset is within the scatter), the mean reversal B̄ (ISO 230-2 2.14) achieved is the one
//! before, not the one predicted. The candidate is the change predicted with the new
//! parameter replaced by the old one: the named change plus half the change of the
//! reversal correction Δr = r_new − r_old (r = c↓ − c↑, minus the parameter) on ↑
//! approaches, minus half on ↓ ones (the offset between the measurements is free).
//!
//! Tried only where the controller's backlash is [`Backlash::Stated`] (a table of one
//! direction holds no reversal of its own, so the tables' mean reversal is minus the
//! parameter), and only when the named parameter differs from the one before by more than
//! the rows' uncertainty (else the candidate is the named table itself). Source of
//! MD32450: SINUMERIK 840D sl / 828D Machine data and parameters, List Manual 08/2013
//! (6FC5397-8EP40-0BA0), MD32450 BACKLASH, as cited by the `siemens-840d` controller.

use super::{Candidate, EffectContext, Key, VerifyEffect, chi2_of, mean_reversal};
use crate::compensate::controllers::Backlash;
use crate::units::{Direction, fmt_fixed};

pub struct BacklashNotLoaded;

impl VerifyEffect for BacklashNotLoaded {
    fn candidates(&self, ctx: &EffectContext) -> Vec<Candidate> {
        if ctx.controller.map(|c| c.backlash()) != Some(Backlash::Stated) {
            return Vec::new();
        }
        let reversal =
            |t: Option<&crate::compensate::Table>| t.map_or(0.0, |t| t.reversal_correction());
        let delta = reversal(Some(ctx.new)) - reversal(ctx.old);
        let u = ctx.rows.iter().map(|r| r.u).fold(0.0, f64::max);
        if delta.abs() <= u {
            return Vec::new();
        }
        let change: Vec<f64> = ctx
            .rows
            .iter()
            .map(|r| match r.direction {
                Direction::Up => r.applied + delta / 2.0,
                Direction::Down => r.applied - delta / 2.0,
            })
            .collect();
        let what = evidence(ctx, &change, -reversal(Some(ctx.new)), -reversal(ctx.old));
        vec![Candidate {
            key: Key::BacklashNotLoaded,
            change,
            params: vec![
                ("backlash_named", -reversal(Some(ctx.new))),
                ("backlash_acting", -reversal(ctx.old)),
            ],
            what,
        }]
    }
}

/// What the data show: each direction follows the table, the reversal is as before.
fn evidence(ctx: &EffectContext, change: &[f64], named: f64, acting: f64) -> String {
    let unit = ctx.new.kind.deviation_symbol();
    let (up, n_up) = chi2_of(ctx.rows, change, Direction::Up);
    let (down, n_down) = chi2_of(ctx.rows, change, Direction::Down);
    let b = |f: fn(&super::ComparedTarget) -> f64| fmt_fixed(mean_reversal(ctx.rows, f), 2);
    format!(
        "the table acted but its backlash parameter was not loaded (SINUMERIK MD32450 still holds {} {unit}, not the {} {unit} named): each direction's change follows the table (χ²↑ = {} on {} targets, χ²↓ = {} on {}, each with its own offset), and the mean reversal B̄ is {} {unit} after, {} before, {} predicted",
        fmt_fixed(acting, 2),
        fmt_fixed(named, 2),
        fmt_fixed(up, 1),
        n_up,
        fmt_fixed(down, 1),
        n_down,
        b(|r| r.achieved),
        b(|r| r.before),
        b(|r| r.predicted)
    )
}
