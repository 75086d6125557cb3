//! ReadAs a `kw.ssfk.*` list as the ISG list parser documents it (Beckhoff Infosys, TF5200
//! list syntax): `key value` per line, anything after the value and a blank a comment,
//! whole-line comments starting with `#`, blank lines, blanks inside `[ ]` allowed; keys in
//! any order; `End` (which axcheck writes, and no Beckhoff example shows) ends the list.
//! Metric lists only (`kw.ssfk.unit 1`: 0.1 µm and 0.0001°); equidistant points (`interval`,
//! `kw_startpos`, decimals allowed since V3.1.3132) or, with `interval 0`, a `setpoint` per
//! entry; `.pos` and `.neg` integers. A unilateral list (`bilateral 0`) holds `.pos` for
//! both directions [unconfirmed: no Beckhoff page says which key it uses]; a `.neg` that
//! differs is refused rather than guessed. Other `kopf.*` and `kw.ssfk.*` keys are not used.

use super::super::controller::{ReadAs, Unreadable};
use super::super::reading::{self, Points, numbered};
use super::limits::{MAX_POINTS, STEPS_PER_POSITION_UNIT, value_step};
use crate::compensate::{Interpolation, Table, TableSlot};
use crate::units::AxisKind;
use std::collections::BTreeMap;

/// A value as written and its line.
type At<T> = Option<(T, usize)>;

/// The list's keys that make the table.
#[derive(Default)]
struct List {
    axis_number: At<usize>,
    unit: At<i64>,
    interval: At<f64>,
    start: At<f64>,
    count: At<usize>,
    bilateral: At<i64>,
    modulo: At<i64>,
    /// Entry index → `.pos`, `.neg`, `.setpoint`.
    pos: BTreeMap<usize, (i64, usize)>,
    neg: BTreeMap<usize, (i64, usize)>,
    setpoint: BTreeMap<usize, (i64, usize)>,
}

pub fn read(text: &str, reading: ReadAs) -> Result<Table, Unreadable> {
    let list = List::parse(text)?;
    list.table(reading.kind)
}

/// `line` with the blanks inside `[ ]` removed (`table[ 0].pos` is `table[0].pos`).
fn closed_brackets(line: &str) -> String {
    let mut depth = 0usize;
    line.chars()
        .filter(|c| {
            match c {
                '[' => depth += 1,
                ']' => depth = depth.saturating_sub(1),
                _ => {}
            }
            depth == 0 || !c.is_whitespace()
        })
        .collect()
}

impl List {
    fn parse(text: &str) -> Result<List, Unreadable> {
        let mut list = List::default();
        let mut any = false;
        for (line, raw) in numbered(text) {
            let t = raw.trim();
            if t.is_empty() || t.starts_with('#') {
                continue;
            }
            if t.eq_ignore_ascii_case("end") {
                break;
            }
            let joined = closed_brackets(t);
            let mut words = joined.split_whitespace();
            let key = words.next().unwrap_or_default();
            let Some(value) = words.next() else {
                return Err(Unreadable::field(line, key, "no value after the key"));
            };
            any |= key.starts_with("kw.ssfk.");
            list.set(key, value, line)?;
        }
        if !any {
            return Err(Unreadable::file(
                "no `kw.ssfk.` key: not a leadscrew error compensation list",
            ));
        }
        Ok(list)
    }

    fn set(&mut self, key: &str, value: &str, line: usize) -> Result<(), Unreadable> {
        let int = || reading::integer(value, line, key).map(|v| Some((v, line)));
        match key {
            "kopf.achs_nr" | "kopf.log_achs_nr" => {
                self.axis_number = Some((reading::whole(value, line, key)?, line));
            }
            "kw.ssfk.unit" => self.unit = int()?,
            "kw.ssfk.interval" => self.interval = Some((reading::number(value, line, key)?, line)),
            "kw.ssfk.kw_startpos" => self.start = Some((reading::number(value, line, key)?, line)),
            "kw.ssfk.kw_nr_max" => self.count = Some((reading::whole(value, line, key)?, line)),
            "kw.ssfk.bilateral" => self.bilateral = int()?,
            "kw.ssfk.modulo" => self.modulo = int()?,
            _ => {
                if let Some((index, column)) = entry(key) {
                    let index = reading::whole(index, line, key)?;
                    let map = match column {
                        "pos" => &mut self.pos,
                        "neg" => &mut self.neg,
                        "setpoint" => &mut self.setpoint,
                        _ => return Ok(()),
                    };
                    map.insert(index, (reading::integer(value, line, key)?, line));
                }
            }
        }
        Ok(())
    }

    fn table(&self, kind: AxisKind) -> Result<Table, Unreadable> {
        let (count, count_line) = required(self.count, "kw.ssfk.kw_nr_max")?;
        self.check_unit()?;
        if count == 0 || count > MAX_POINTS {
            return Err(Unreadable::field(
                count_line,
                "kw.ssfk.kw_nr_max",
                format!("{count} entries: expected 1 to {MAX_POINTS}"),
            ));
        }
        let bilateral = flag(self.bilateral, "kw.ssfk.bilateral")?;
        let positions = self.positions(count)?;
        let step = value_step(kind);
        let up = values(&self.pos, count, "pos")?;
        let down = if bilateral {
            values(&self.neg, count, "neg")?
        } else {
            self.unilateral(&up)?;
            up.clone()
        };
        let correction = |v: &Vec<i64>| v.iter().map(|q| -(*q as f64) * step).collect();
        let modulo = self.modulo(kind, &positions)?;
        let points = Points {
            kind,
            up: correction(&up),
            down: correction(&down),
            positions,
        };
        let place = TableSlot {
            // 0, which the CNC does not allow, is the placeholder of an unnamed axis.
            number: self.axis_number.map(|(n, _)| n).filter(|&n| n > 0),
            ..TableSlot::default()
        };
        Ok(points.table(None, modulo, place, Interpolation::Linear))
    }

    /// Metric units (0.1 µm, 0.0001°); increments would need the axis's resolution.
    fn check_unit(&self) -> Result<(), Unreadable> {
        match self.unit {
            Some((1, _)) => Ok(()),
            Some((u, line)) => Err(Unreadable::field(
                line,
                "kw.ssfk.unit",
                format!(
                    "{u}: axcheck reads metric lists (1: 0.1 um and 0.0001 deg) only; increments need the axis's resolution"
                ),
            )),
            None => Err(Unreadable::file(
                "no `kw.ssfk.unit`: its default (increments) needs the axis's resolution; axcheck reads metric lists (kw.ssfk.unit 1)",
            )),
        }
    }

    /// The entries' positions, mm or degrees: equidistant, or the setpoints.
    fn positions(&self, count: usize) -> Result<Vec<f64>, Unreadable> {
        let (interval, line) = required(self.interval, "kw.ssfk.interval")?;
        if interval > 0.0 {
            let (start, _) = required(self.start, "kw.ssfk.kw_startpos")?;
            return Ok((0..count)
                .map(|i| (start + i as f64 * interval) / STEPS_PER_POSITION_UNIT)
                .collect());
        }
        if interval < 0.0 {
            return Err(Unreadable::field(
                line,
                "kw.ssfk.interval",
                format!("{interval}: expected an interval > 0, or 0 with a setpoint per entry"),
            ));
        }
        let setpoints = values(&self.setpoint, count, "setpoint")?;
        let positions: Vec<f64> = setpoints
            .iter()
            .map(|s| *s as f64 / STEPS_PER_POSITION_UNIT)
            .collect();
        let lines: Vec<usize> = self.setpoint.values().map(|(_, l)| *l).collect();
        reading::increasing(&positions, &lines, "setpoint")?;
        Ok(positions)
    }

    /// A unilateral list holds `.pos` for both directions: a `.neg` that differs is refused.
    fn unilateral(&self, pos: &[i64]) -> Result<(), Unreadable> {
        for (i, (neg, line)) in &self.neg {
            if pos.get(*i).is_some_and(|p| p != neg) {
                return Err(Unreadable::field(
                    *line,
                    format!("kw.ssfk.table[{i}].neg"),
                    "differs from .pos in a unilateral list (kw.ssfk.bilateral 0): set bilateral 1 if the list holds both directions",
                ));
            }
        }
        Ok(())
    }

    /// Whether the list wraps: `kw.ssfk.modulo 1` on a rotary axis over 0…360°.
    fn modulo(&self, kind: AxisKind, positions: &[f64]) -> Result<bool, Unreadable> {
        let on = flag(self.modulo, "kw.ssfk.modulo")?;
        if on && !reading::one_revolution(kind, positions) {
            let line = self.modulo.map_or(0, |(_, l)| l);
            return Err(Unreadable::field(
                line,
                "kw.ssfk.modulo",
                format!(
                    "a modulo list over {}…{}: axcheck reads modulo lists of a rotary axis over 0…360° only",
                    positions[0],
                    positions[positions.len() - 1]
                ),
            ));
        }
        Ok(on)
    }
}

/// `kw.ssfk.table[3].pos` → (`3`, `pos`).
fn entry(key: &str) -> Option<(&str, &str)> {
    let rest = key.strip_prefix("kw.ssfk.table[")?;
    let (index, column) = rest.split_once("].")?;
    Some((index, column))
}

fn required<T: Copy>(value: At<T>, key: &str) -> Result<(T, usize), Unreadable> {
    value.ok_or_else(|| Unreadable::file(format!("no `{key}`")))
}

/// A 0/1 switch (absent: 0).
fn flag(value: At<i64>, key: &str) -> Result<bool, Unreadable> {
    match value {
        None | Some((0, _)) => Ok(false),
        Some((1, _)) => Ok(true),
        Some((v, line)) => Err(Unreadable::field(
            line,
            key,
            format!("expected 0 or 1, got {v}"),
        )),
    }
}

/// Entries 0 … `count` − 1 of one column, each present; none beyond.
fn values(
    column: &BTreeMap<usize, (i64, usize)>,
    count: usize,
    name: &str,
) -> Result<Vec<i64>, Unreadable> {
    if let Some((i, (_, line))) = column.range(count..).next() {
        return Err(Unreadable::field(
            *line,
            format!("kw.ssfk.table[{i}].{name}"),
            format!("entry {i} is beyond kw.ssfk.kw_nr_max = {count}"),
        ));
    }
    (0..count)
        .map(|i| {
            column.get(&i).map(|(v, _)| *v).ok_or_else(|| {
                Unreadable::file(format!(
                    "no `kw.ssfk.table[{i}].{name}` (kw_nr_max = {count})"
                ))
            })
        })
        .collect()
}
