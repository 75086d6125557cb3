//! What can go wrong when a table is loaded, one file each (as the diagnosis keeps one
//! file per effect): each effect predicts the change the re-measurement would show if it
//! had happened, as one or more candidates (a factor, a shift, another axis's table). The
//! measured change is tested against the table as loaded and against every candidate by
//! the χ² of their differences, each difference weighted by its uncertainty and a constant
//! offset between the measurements left free (a different laser datum: no ISO 230-2
//! parameter sees it). An effect is named when the table as loaded is rejected and the
//! effect explains the change far better.
//!
//! Adding an effect is one file here and one line in [`EFFECTS`].

pub mod applied_twice;
pub mod backlash_not_loaded;
pub mod backlash_relative;
pub mod not_active;
pub mod position_shift;
pub mod scale;
pub mod sign_inverted;
pub mod wrong_axis;

use super::compare::{ComparedTarget, weighted_mean};
use crate::compensate::Table;
use crate::compensate::controllers::Controller;
use crate::units::Direction;
use serde::Serialize;

/// The stable keys of the effects.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Key {
    NotActive,
    SignInverted,
    AppliedTwice,
    PositionShift,
    Scale,
    WrongAxis,
    BacklashNotLoaded,
    BacklashRelative,
    /// Not an effect: the change follows neither the table named nor any effect (see
    /// [`super::explain::mismatch`]).
    TableMismatch,
}

impl Key {
    pub fn name(self) -> &'static str {
        match self {
            Key::NotActive => "not_active",
            Key::SignInverted => "sign_inverted",
            Key::AppliedTwice => "applied_twice",
            Key::PositionShift => "position_shift",
            Key::Scale => "scale",
            Key::WrongAxis => "wrong_axis",
            Key::BacklashNotLoaded => "backlash_not_loaded",
            Key::BacklashRelative => "backlash_relative",
            Key::TableMismatch => "table_mismatch",
        }
    }
}

/// Another axis of the machine whose table may have been loaded on this one.
#[derive(Debug, Clone)]
pub struct Other {
    /// The axis's name (`Y`).
    pub axis: String,
    /// The table loaded for it, as its controller adds it.
    pub new: Table,
}

/// What the effects see: the rows, the tables and the machine's other axes.
pub struct EffectContext<'a> {
    pub rows: &'a [ComparedTarget],
    /// The correction active before (None: nothing).
    pub old: Option<&'a Table>,
    /// The correction loaded since.
    pub new: &'a Table,
    pub others: &'a [Other],
    /// The controller the tables are loaded on; `None`: not known (its own effects are
    /// not tried).
    pub controller: Option<&'a dyn Controller>,
}

impl EffectContext<'_> {
    /// The change at each row if `new` acted at positions shifted by `shift` and `old`
    /// were replaced: new(P − shift) − old(P).
    pub(crate) fn change_with(&self, new: &Table, shift: f64) -> Vec<f64> {
        self.rows
            .iter()
            .map(|r| {
                let old = self
                    .old
                    .map_or(0.0, |t| t.correction(r.position, r.direction));
                new.correction(r.position - shift, r.direction) - old
            })
            .collect()
    }

    /// The change the table as loaded predicts at each row.
    pub fn applied(&self) -> Vec<f64> {
        self.rows.iter().map(|r| r.applied).collect()
    }

    /// The change at each row if `new` and `old` acted as `acted` makes them act (the
    /// controller reading both files alike): acted(new)(P) − acted(old)(P).
    pub(crate) fn change_acted(&self, acted: impl Fn(&Table) -> Table) -> Vec<f64> {
        let (new, old) = (acted(self.new), self.old.map(&acted));
        self.rows
            .iter()
            .map(|r| {
                let before = old
                    .as_ref()
                    .map_or(0.0, |t| t.correction(r.position, r.direction));
                new.correction(r.position, r.direction) - before
            })
            .collect()
    }

    /// The mean interval between the new table's points (mm or deg; its interval when
    /// equidistant), 0 for one point.
    pub fn interval(&self) -> f64 {
        let p = &self.new.positions;
        match (p.first(), p.last()) {
            (Some(a), Some(b)) if p.len() > 1 => (b - a) / (p.len() - 1) as f64,
            _ => 0.0,
        }
    }
}

/// One explanation of the measured change: the change it predicts per row, its
/// parameters, and the sentence that names it.
#[derive(Debug, Clone)]
pub(crate) struct Candidate {
    pub key: Key,
    pub change: Vec<f64>,
    pub params: Vec<(&'static str, f64)>,
    /// What happened, for the evidence ("the table was applied with the opposite sign").
    pub what: String,
}

/// One effect of the vocabulary.
pub(crate) trait VerifyEffect: Sync {
    /// Its candidates for this verification.
    fn candidates(&self, ctx: &EffectContext) -> Vec<Candidate>;
}

/// Every effect, in the order in which they are preferred when two explain the change
/// alike (the simpler mistake first).
pub(crate) const EFFECTS: &[&dyn VerifyEffect] = &[
    &not_active::NotActive,
    &sign_inverted::SignInverted,
    &applied_twice::AppliedTwice,
    &backlash_not_loaded::BacklashNotLoaded,
    &backlash_relative::BacklashRelative,
    &position_shift::PositionShift,
    &scale::Scale,
    &wrong_axis::WrongAxis,
];

/// The χ² of the measured change against `change`, a constant offset fitted: Σ ((Δx −
/// change − offset)/u)².
pub fn chi2(rows: &[ComparedTarget], change: &[f64]) -> f64 {
    let residual = |k: usize| rows[k].change() - change[k];
    let offset = weighted_mean((0..rows.len()).map(|k| (residual(k), rows[k].u)));
    (0..rows.len())
        .map(|k| ((residual(k) - offset) / rows[k].u).powi(2))
        .sum()
}

/// The χ² of the rows of one direction against `change` (as [`chi2`], its own offset),
/// and their number.
pub(crate) fn chi2_of(
    rows: &[ComparedTarget],
    change: &[f64],
    direction: Direction,
) -> (f64, usize) {
    let (r, c): (Vec<ComparedTarget>, Vec<f64>) = rows
        .iter()
        .zip(change)
        .filter(|(r, _)| r.direction == direction)
        .map(|(r, c)| (r.clone(), *c))
        .unzip();
    (chi2(&r, &c), r.len())
}

/// The mean reversal B̄ = mean of x̄↑ − x̄↓ over the targets (ISO 230-2 2.14) of
/// `value` (before, predicted or achieved) in the rows.
pub(crate) fn mean_reversal(
    rows: &[ComparedTarget],
    value: impl Fn(&ComparedTarget) -> f64,
) -> f64 {
    let mean = |d: Direction| {
        let v: Vec<f64> = rows
            .iter()
            .filter(|r| r.direction == d)
            .map(&value)
            .collect();
        v.iter().sum::<f64>() / v.len().max(1) as f64
    };
    mean(Direction::Up) - mean(Direction::Down)
}

/// The factor f that best scales the predicted change to the measured one (least
/// squares, offset free): 1 when the table acted as loaded.
pub(crate) fn fitted_factor(rows: &[ComparedTarget]) -> f64 {
    let weights: Vec<f64> = rows.iter().map(|r| 1.0 / (r.u * r.u)).collect();
    let total: f64 = weights.iter().sum();
    let centred = |f: &dyn Fn(&ComparedTarget) -> f64| {
        let mean = rows
            .iter()
            .zip(&weights)
            .map(|(r, w)| w * f(r))
            .sum::<f64>()
            / total;
        rows.iter().map(|r| f(r) - mean).collect::<Vec<f64>>()
    };
    let (x, y) = (centred(&|r| r.applied), centred(&|r| r.change()));
    let sxx: f64 = x.iter().zip(&weights).map(|(a, w)| w * a * a).sum();
    let sxy: f64 = x
        .iter()
        .zip(&y)
        .zip(&weights)
        .map(|((a, b), w)| w * a * b)
        .sum();
    if sxx > 0.0 { sxy / sxx } else { f64::NAN }
}
