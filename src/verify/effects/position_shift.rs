//! `position_shift`: the table acted at positions shifted along the axis: the reference
//! point (machine zero) of the table is not the one of the measurement, the table's start
//! was entered off by an interval, or the laser's datum moved between the measurements.
//! Shifts of a quarter table interval up to two intervals, either way, are tried.

use super::{Candidate, Context, Effect, Key};

pub struct PositionShift;

impl Effect for PositionShift {
    fn key(&self) -> Key {
        Key::PositionShift
    }

    fn candidates(&self, ctx: &Context) -> Vec<Candidate> {
        let h = ctx.interval();
        if h <= 0.0 {
            return Vec::new();
        }
        let unit = ctx.new.kind.position_unit();
        // Smaller shifts first: of two that explain the change alike, the smaller is named.
        (1..=8)
            .flat_map(|m| [m, -m])
            .map(|k: i32| {
                let shift = k as f64 * h / 4.0;
                Candidate {
                    key: Key::PositionShift,
                    change: ctx.change_with(ctx.new, shift),
                    params: vec![("shift", shift), ("intervals", k as f64 / 4.0)],
                    what: format!(
                        "the table acted {} {unit} {} along the axis ({} table intervals): its reference point is not the measurement's",
                        crate::units::fmt_position(shift.abs()),
                        if shift > 0.0 { "further" } else { "back" },
                        crate::units::fmt_position(k as f64 / 4.0)
                    ),
                }
            })
            .collect()
    }
}
