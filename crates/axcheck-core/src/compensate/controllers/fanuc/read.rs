//! ReadAs a FANUC set-up sheet back: the axis line (the grid in the measurement's
//! coordinates, which the control does not know), the parameters 3605#0 and 3620–3627, and
//! the pitch error data from the punch block between `%` lines (`N10000+number P value`,
//! a space between allowed). The corrections are rebuilt as the control applies them: 0 at
//! the reference on the + table, 3627 there on the − table, and the running sum of the
//! increments from the reference outwards; on a turn, the increments of a table must sum
//! to 0 and number 0 repeat the last one. A set-up sheet whose numbers were moved (an
//! offset added to 3620, 3621, 3622, 3626 and every number) is read at its numbers.

use super::super::controller::{ReadAs, Unreadable};
use super::super::reading::{self, Points, numbered};
use super::limits::{
    DETECTION_ARCSEC, DETECTION_UM, MAX_VALUE, MIN_VALUE, PER_POSITION_UNIT, PUNCH_BASE,
};
use crate::compensate::{Interpolation, Table, TableSlot};
use crate::units::AxisKind;
use std::collections::BTreeMap;

/// What the sheet says.
struct Sheet {
    /// The axis line and its line number.
    axis: (String, usize),
    /// Parameter number (`3620`, `3605#0`) → value and line.
    parameters: BTreeMap<String, (i64, usize)>,
    /// Pitch error number → value and line.
    data: BTreeMap<usize, (i64, usize)>,
}

/// The grid the axis line gives.
struct Grid {
    positions: Vec<f64>,
    reference: f64,
    modulo: bool,
}

pub fn read(text: &str, reading: ReadAs) -> Result<Table, Unreadable> {
    let sheet = Sheet::parse(text)?;
    let grid = sheet.grid(reading.kind)?;
    let parameter = |n: &str| sheet.parameter(n);
    if parameter("3605#0")?.0 != 1 {
        return Err(Unreadable::field(
            parameter("3605#0")?.1,
            "3605#0",
            "expected 1: axcheck reads bidirectional pitch error compensation",
        ));
    }
    let m = grid.positions.len() - 1;
    let first = sheet.numbers(&grid, m)?;
    let reference = sheet.reference_index(&grid, first)?;
    let magnification = parameter("3623")?.0.max(1);
    let interval = parameter("3624")?;
    let step = grid.positions[1] - grid.positions[0];
    if (interval.0 as f64 - step * PER_POSITION_UNIT).abs() > 0.5 {
        return Err(Unreadable::field(
            interval.1,
            "3624",
            format!(
                "{} (0.001 units) is not the axis line's interval {step}",
                interval.0
            ),
        ));
    }
    let (at_reference_down, line) = parameter("3627")?;
    if at_reference_down % magnification != 0 {
        return Err(Unreadable::field(
            line,
            "3627",
            format!(
                "{at_reference_down} is not a whole number of magnification {magnification} steps"
            ),
        ));
    }
    let down_first = sheet.parameter("3626")?.0;
    let walk = |table_first: i64, at_reference: i64| {
        let numbers = Numbers {
            first: table_first,
            sections: m,
            reference,
            modulo: grid.modulo,
        };
        numbers.corrections(&sheet.data, at_reference)
    };
    let up = walk(first, 0)?;
    let down = walk(down_first, at_reference_down / magnification)?;
    let quantum = detection_unit(reading.kind) * magnification as f64;
    let points = Points {
        kind: reading.kind,
        up: up.iter().map(|q| *q as f64 * quantum).collect(),
        down: down.iter().map(|q| *q as f64 * quantum).collect(),
        positions: grid.positions,
    };
    let place = TableSlot {
        number: Some(first as usize),
        ..TableSlot::default()
    };
    Ok(points.table(
        Some(grid.reference),
        grid.modulo,
        place,
        Interpolation::Steps,
    ))
}

fn detection_unit(kind: AxisKind) -> f64 {
    match kind {
        AxisKind::Linear => DETECTION_UM,
        AxisKind::Rotary => DETECTION_ARCSEC,
    }
}

impl Sheet {
    fn parse(text: &str) -> Result<Sheet, Unreadable> {
        let mut axis = None;
        let mut parameters = BTreeMap::new();
        let mut data = BTreeMap::new();
        let mut in_punch = false;
        for (line, l) in numbered(text) {
            let t = l.trim();
            if t == "%" {
                in_punch = !in_punch;
            } else if in_punch {
                let (number, value) = punch_line(t, line)?;
                data.insert(number, (value, line));
            } else if let Some(rest) = t.strip_prefix("Axis:") {
                axis = Some((rest.trim().to_string(), line));
            } else if let Some((number, value)) = parameter_line(t) {
                parameters.insert(number, (reading::integer(value, line, t)?, line));
            }
        }
        let axis = axis.ok_or_else(|| {
            Unreadable::file(
                "no `Axis:` line: axcheck reads the set-up sheet it writes (the axis line gives the points' positions, which the control does not hold)",
            )
        })?;
        if data.is_empty() {
            return Err(Unreadable::file(
                "no pitch error data between `%` lines (N10000+number P value)",
            ));
        }
        Ok(Sheet {
            axis,
            parameters,
            data,
        })
    }

    fn parameter(&self, number: &str) -> Result<(i64, usize), Unreadable> {
        self.parameters.get(number).copied().ok_or_else(|| {
            Unreadable::file(format!("no parameter {number} (a line `{number} = value`)"))
        })
    }

    /// `linear, 5 points every 50.000 mm from 0.000 to 200.000 mm, reference position
    /// 100.000 mm` (with ` (one turn)` after the last position on a turn).
    fn grid(&self, kind: AxisKind) -> Result<Grid, Unreadable> {
        let (text, line) = (&self.axis.0, self.axis.1);
        let bad = |why: &str| Unreadable::field(line, "Axis", format!("{why}: `{text}`"));
        let words: Vec<&str> = text.split([' ', ',']).filter(|w| !w.is_empty()).collect();
        let unit = kind.position_unit();
        let [
            written_kind,
            count,
            "points",
            "every",
            interval,
            u1,
            "from",
            first,
            "to",
            last,
            u2,
            rest @ ..,
        ] = words.as_slice()
        else {
            return Err(bad(
                "expected `KIND, N points every STEP UNIT from FIRST to LAST UNIT, reference position REF UNIT`",
            ));
        };
        if *written_kind != kind.to_string() || [u1, u2] != [&unit, &unit] {
            return Err(bad(&format!(
                "the sheet is not for a {kind} axis in {unit}"
            )));
        }
        let (modulo, rest) = match rest {
            ["(one", "turn)", rest @ ..] => (true, rest),
            rest => (false, rest),
        };
        let ["reference", "position", reference, u3] = rest else {
            return Err(bad("expected `reference position REF UNIT` at the end"));
        };
        if u3 != &unit {
            return Err(bad(&format!("the reference position is not in {unit}")));
        }
        let number = |w: &str| reading::number(w, line, "Axis");
        let count = reading::whole(count, line, "Axis")?;
        let (interval, first, last) = (number(interval)?, number(first)?, number(last)?);
        if !(2..=super::MAX_POINTS).contains(&count) || interval <= 0.0 {
            return Err(bad(&format!(
                "expected 2 to {} points and an interval > 0",
                super::MAX_POINTS
            )));
        }
        let positions: Vec<f64> = (0..count).map(|k| first + k as f64 * interval).collect();
        if (positions[count - 1] - last).abs() > 1e-3 {
            return Err(bad("the points every STEP from FIRST do not end at LAST"));
        }
        Ok(Grid {
            positions,
            reference: number(reference)?,
            modulo,
        })
    }

    /// 3621, checked against 3622 and 3626 for `m` sections.
    fn numbers(&self, grid: &Grid, m: usize) -> Result<i64, Unreadable> {
        let (first, _) = self.parameter("3621")?;
        let (last, line) = self.parameter("3622")?;
        let (down_first, down_line) = self.parameter("3626")?;
        let sections = if grid.modulo {
            last - first
        } else {
            last - first + 1
        };
        if sections != m as i64 {
            return Err(Unreadable::field(
                line,
                "3622",
                format!("3621 = {first} to 3622 = {last} is not the {m} sections of the axis line"),
            ));
        }
        let expected = first + m as i64 + i64::from(grid.modulo);
        if down_first != expected {
            return Err(Unreadable::field(
                down_line,
                "3626",
                format!("expected {expected}: the − table follows the + table's numbers"),
            ));
        }
        Ok(first)
    }

    /// The grid index of the reference position (3620).
    fn reference_index(&self, grid: &Grid, first: i64) -> Result<usize, Unreadable> {
        let (number, line) = self.parameter("3620")?;
        let at = grid
            .positions
            .iter()
            .position(|p| (p - grid.reference).abs() < 1e-6);
        let expected = match at {
            Some(k) if grid.modulo => Some((k % (grid.positions.len() - 1), first)),
            Some(k) => Some((k, first + k as i64 - 1)),
            None => None,
        };
        match expected {
            Some((k, n)) if n == number => Ok(k),
            _ => Err(Unreadable::field(
                line,
                "3620",
                format!(
                    "{number} is not the number of the reference position {} given on the axis line",
                    grid.reference
                ),
            )),
        }
    }
}

/// How one direction's table is numbered.
struct Numbers {
    /// Its first number (3621 or 3626).
    first: i64,
    sections: usize,
    /// Grid index of the reference position.
    reference: usize,
    modulo: bool,
}

impl Numbers {
    /// The value of the section numbered `first + offset`.
    fn value(
        &self,
        data: &BTreeMap<usize, (i64, usize)>,
        offset: usize,
    ) -> Result<i64, Unreadable> {
        let number = self.first as usize + offset;
        let Some(&(value, line)) = data.get(&number) else {
            return Err(Unreadable::file(format!(
                "no pitch error value for number {number} (N{})",
                PUNCH_BASE + number
            )));
        };
        if !(MIN_VALUE..=MAX_VALUE).contains(&value) {
            return Err(Unreadable::field(
                line,
                format!("N{}", PUNCH_BASE + number),
                format!("{value}: a pitch error value is {MIN_VALUE}…{MAX_VALUE}"),
            ));
        }
        Ok(value)
    }

    /// The held correction at each grid point, in steps: `at_reference` at the reference,
    /// the increments summed from it.
    fn corrections(
        &self,
        data: &BTreeMap<usize, (i64, usize)>,
        at_reference: i64,
    ) -> Result<Vec<i64>, Unreadable> {
        let m = self.sections;
        let mut q = vec![0; m + 1];
        q[self.reference] = at_reference;
        if self.modulo {
            for j in 1..m {
                let (end, start) = ((self.reference + j) % m, (self.reference + j - 1) % m);
                q[end] = q[start] + self.value(data, j)?;
            }
            let closing = self.value(data, m)?;
            if q[(self.reference + m - 1) % m] + closing != q[self.reference] {
                return Err(Unreadable::file(format!(
                    "the values numbered {}…{} do not sum to 0 over the turn",
                    self.first + 1,
                    self.first + m as i64
                )));
            }
            if self.value(data, 0)? != closing {
                return Err(Unreadable::file(format!(
                    "number {} must repeat number {} (the section that ends at the reference)",
                    self.first,
                    self.first + m as i64
                )));
            }
            q[m] = q[0];
            return Ok(q);
        }
        for i in self.reference + 1..=m {
            q[i] = q[i - 1] + self.value(data, i - 1)?;
        }
        for i in (1..=self.reference).rev() {
            q[i - 1] = q[i] - self.value(data, i - 1)?;
        }
        Ok(q)
    }
}

/// `N10001P-10`, `N10001 P-10` or `N10001P-10;` → (pitch error number, value).
fn punch_line(t: &str, line: usize) -> Result<(usize, i64), Unreadable> {
    let t = t.strip_suffix(';').unwrap_or(t).trim();
    let bad = || {
        Unreadable::at(
            line,
            format!("`{t}` is not a pitch error line `N(10000+number)P(value)`"),
        )
    };
    let rest = t.strip_prefix('N').ok_or_else(bad)?;
    let (n, v) = rest.split_once('P').ok_or_else(bad)?;
    let n = reading::whole(n, line, "N")?;
    if n < PUNCH_BASE {
        return Err(bad());
    }
    Ok((n - PUNCH_BASE, reading::integer(v, line, "P")?))
}

/// `3620   = 2        comment` → (`3620`, `2`).
fn parameter_line(t: &str) -> Option<(String, &str)> {
    let (name, rest) = t.split_once('=')?;
    let name = name.trim();
    let digits = name.split('#').next()?;
    if digits.len() != 4 || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    let value = rest.split_whitespace().next()?;
    Some((name.to_string(), value))
}
