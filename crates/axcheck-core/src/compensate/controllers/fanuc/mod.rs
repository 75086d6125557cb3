//! `fanuc`: FANUC stored pitch error compensation (Series 0i / 16i / 18i / 21i / 30i),
//! bidirectional: a set-up sheet with the axis's parameters 3605#0 and 3620–3627, the pitch
//! error data as a table (point number → value) and the same data in the punch format.
//!
//! **Format.** The data are *incremental*: the value at point number N is the change of
//! the correction over the section that ends at N's position ("the compensation value is
//! output at the compensation position No. corresponding to each section", FANUC 0i-PB
//! Parameter Manual B-63980EN/01 p. 100), in detection units (1 µm or 0.001° assumed: IS-B)
//! × the magnification 3623, an integer in −128…127 per point (FOCAS `IODBPI.data` is a
//! `char`, its header comment says "incremental"; old controls hold only −7…+7: the file
//! states its largest value). The points are equidistant (3624, written in 0.001 mm or
//! 0.001°) and numbered around the reference point 3620, whose number covers the section
//! that *ends* at the reference position; the − end of the travel is 3620 − (its distance
//! / 3624) + 1 (3621), the + end 3620 + distance / 3624 (3622) [recalled from the 16i
//! manual's example, consistent with p. 100]; so the correction is zero at the reference
//! and the running sum of the values elsewhere. Point numbers 0…1023 are shared by all axes
//! of the control \[recalled\]; two tables per axis use two ranges of them, so axcheck holds
//! at most 512 points per direction.
//!
//! **Numbering.** Point number = grid index: number i covers the section from grid point
//! i − 1 to i, the − end (index 0) has no number, 3620 = the reference's index, 3621 = 1,
//! 3622 = the last index m; the − direction table follows at m + 1…2m (3626 = m + 1). A
//! rotary axis measured over a whole turn gets a modulo table (3625 = 360°): 3620 = 3621 =
//! 0, 3622 = 360°/interval, numbers 1… from the reference position on, number 0 the same
//! value as the last one, the values summing to 0 over the turn (B-63980EN/01 p. 100).
//!
//! **Sign.** The value is the compensation output: positive moves the axis further in +, so
//! it is the increment of the correction −x̄ (−Δe) [recalled; FANUC calls the data
//! "compensation values", not errors — verify on the machine with one point].
//!
//! **Holding.** The smallest magnification 1…100 that keeps every value in −128…127; the
//! correction at each grid point rounded to detection unit × magnification (the remainder
//! carried, so nothing drifts), shifted so that the + direction correction is 0 at the
//! reference (a constant changes no ISO 230-2 parameter). The − direction correction at the
//! reference goes to 3627, in detection units (FANUC 16i/18i Technical Report A-77810E: the
//! absolute value at the reference when approached against the reference return direction;
//! its unit is recalled). Refused: a value beyond 127 × 100 (`Range`), a reference position
//! off the grid, too many numbers, an interval not a whole 0.001 (`Grid`).
//!
//! **Interpolation.** FANUC outputs a section's value as pulses where the axis passes the
//! point ("the compensation value is output at the circled position", B-63980EN/01), a
//! staircase: the prediction applies each point's held correction from that point to the
//! next ([`Interpolation::Steps`]; which end of the section the step sits at is read from
//! the manual's figure, not confirmed). Between points the staircase leaves up to one
//! section's increment: a finer `--interval` follows the error more closely.
//!
//! **Backlash.** Bidirectional compensation (3605#0 = 1, A-77810E) keeps a table per
//! direction; backlash 1851/1852 is left as it was during the measurement (the − direction
//! table corrects the reversal that remained) \[recalled\]. It assumes the reference return
//! in + (1006#5 = 0) and an axis measured with its pitch error data cleared.
//!
//! **Loading.** Parameters on the parameter screen (PWE = 1); the data on the pitch error
//! screen by hand, or read in from the punch block (`%`, `N10000+number P value`, `%`) —
//! the punch syntax is recalled, not confirmed: the file says so; or FOCAS `cnc_wrpitchr`.
//! Power off and on, then return to the reference position.
//!
//! Unconfirmed: the sign, the punch syntax, the unit of 3627, the 1024 numbers (30i-series
//! more; the old 0-series had 128 per axis), the − end formula, the range 3623 ≤ 100,
//! backlash with bidirectional compensation, how the ↓ table's increments are counted (here
//! like the ↑ one, from the − end towards +).

mod limits;
mod read;

use super::controller::{
    Backlash, Controller, Directions, Format, ReadAs, Refused, Spacing, Unreadable,
};
use crate::compensate::table::wrap;
use crate::compensate::table::{Interpolation, Table};
use crate::units::{AxisKind, fmt_fixed, fmt_position};
use limits::*;
use std::fmt::Write;

pub struct Fanuc;

impl Controller for Fanuc {
    fn name(&self) -> &'static str {
        "fanuc"
    }

    fn extension(&self) -> &'static str {
        "txt"
    }

    /// Equidistant, a table per direction, modulo over a turn, up to 512 points per
    /// direction (the control's 1024 numbers, shared by all axes); detection unit × 1.
    /// A staircase: each point's value from that point to the next.
    fn interpolation(&self) -> Interpolation {
        Interpolation::Steps
    }

    /// Backlash 1851/1852 stays as it was during the measurement: the − direction table
    /// corrects the reversal that remained.
    fn backlash(&self) -> Backlash {
        Backlash::Kept
    }

    fn format(&self) -> Format {
        Format {
            spacing: Spacing::Equidistant,
            max_points: MAX_POINTS,
            directions: Directions::Bidirectional,
            modulo: true,
            quantum_um: DETECTION_UM,
            quantum_arcsec: DETECTION_ARCSEC,
        }
    }

    /// Rounded at the smallest magnification that fits, zero at the reference on ↑.
    fn hold(&self, table: Table) -> Result<Table, Refused> {
        let stored = Stored::fit(&table, Rounding::Nearest)?;
        Ok(stored.held(table))
    }

    /// The set-up sheet axcheck writes (the control holds no positions, the sheet does).
    fn read(&self, text: &str, reading: ReadAs) -> Result<Table, Unreadable> {
        read::read(text, reading)
    }

    fn write(&self, table: &Table, notes: &[String]) -> Result<String, Refused> {
        super::finite(table)?;
        let stored = Stored::fit(table, Rounding::Exact)?;
        let mut out = stored.header(table);
        out.push_str(&super::commented("Note: ", notes));
        stored.parameters(table, &mut out);
        stored.data_table(table, &mut out);
        stored.punch(&mut out);
        Ok(out)
    }
}

/// Whether the corrections may be rounded (holding) or must already be whole steps
/// (writing a held table).
#[derive(Clone, Copy, PartialEq)]
enum Rounding {
    Nearest,
    Exact,
}

/// The table as FANUC stores it.
struct Stored {
    magnification: i64,
    /// Detection unit × magnification, µm or arcsec.
    quantum: f64,
    /// Grid index of the reference point.
    reference: usize,
    /// Whether the table wraps over a turn (3625).
    modulo: bool,
    /// Added to every pitch error number: the table's place (an active table's 3621, or
    /// another axis's numbers before this one's).
    offset: usize,
    /// Held corrections at the grid points in quanta, ↑ zero at the reference.
    up: Vec<i64>,
    down: Vec<i64>,
}

/// One stored value: its number within its table, its value, and the grid indices where
/// its section starts and ends.
struct Point {
    offset: usize,
    value: i64,
    start: usize,
    end: usize,
}

impl Stored {
    /// The smallest magnification at which every value fits.
    fn fit(table: &Table, rounding: Rounding) -> Result<Stored, Refused> {
        let sections = table.positions.len().saturating_sub(1);
        if sections == 0 {
            return Err(Refused::Grid("a pitch error table needs two points".into()));
        }
        let reference = reference_index(table)?;
        let offset = number_offset(table)?;
        interval_in_input_units(table)?;
        let detection = detection_unit(table.kind);
        let shift = table.up[reference];
        for magnification in 1..=MAX_MAGNIFICATION {
            let quantum = detection * magnification as f64;
            let steps = |v: &[f64]| quanta(v, shift, quantum, rounding);
            let (Some(up), Some(down)) = (steps(&table.up), steps(&table.down)) else {
                continue;
            };
            let stored = Stored {
                magnification,
                quantum,
                reference,
                modulo: table.modulo_deg.is_some(),
                offset,
                up,
                down,
            };
            if stored.fits() {
                stored.numbers_fit()?;
                return Ok(stored);
            }
        }
        Err(too_steep(table, rounding))
    }

    fn fits(&self) -> bool {
        let in_range = |v: &[i64]| {
            self.points(v)
                .iter()
                .all(|p| (MIN_VALUE..=MAX_VALUE).contains(&p.value))
        };
        in_range(&self.up) && in_range(&self.down) && self.at_reference_down().abs() <= MAX_WORD
    }

    /// 3627: the ↓ correction at the reference, detection units.
    fn at_reference_down(&self) -> i64 {
        self.down[self.reference] * self.magnification
    }

    fn sections(&self) -> usize {
        self.up.len() - 1
    }

    /// The values of one direction's table in number order.
    fn points(&self, quanta: &[i64]) -> Vec<Point> {
        let m = self.sections();
        if !self.modulo {
            return (1..=m)
                .map(|i| Point {
                    offset: i,
                    value: quanta[i] - quanta[i - 1],
                    start: i - 1,
                    end: i,
                })
                .collect();
        }
        // From the reference on; number 0 repeats the last section (the one ending at
        // the reference).
        (0..=m)
            .map(|j| {
                let section = if j == 0 { m } else { j };
                let end = (self.reference + section) % m;
                let start = (self.reference + section - 1) % m;
                Point {
                    offset: j,
                    value: quanta[end] - quanta[start],
                    start,
                    end,
                }
            })
            .collect()
    }

    /// Parameter values: 3620, 3621, 3622, 3626.
    fn numbers(&self) -> [usize; 4] {
        let m = self.sections();
        let numbers = if self.modulo {
            [0, 0, m, m + 1]
        } else {
            [self.reference, 1, m, m + 1]
        };
        numbers.map(|n| n + self.offset)
    }

    /// The first number of the ↓ table's offsets (offset 0 or 1 is 3626).
    fn down_base(&self) -> usize {
        let [_, first, _, down_first] = self.numbers();
        down_first - first
    }

    /// The last number of the ↓ table.
    fn last_number(&self) -> usize {
        self.offset + self.down_base() + self.sections()
    }

    fn numbers_fit(&self) -> Result<(), Refused> {
        let last = self.last_number();
        if last >= PITCH_NUMBERS {
            return Err(Refused::Grid(format!(
                "the two tables need pitch error numbers up to {last}, the control has 0…{}",
                PITCH_NUMBERS - 1
            )));
        }
        Ok(())
    }

    /// The table with the corrections the control applies.
    fn held(&self, mut table: Table) -> Table {
        let value = |q: &i64| *q as f64 * self.quantum;
        table.up = self.up.iter().map(value).collect();
        table.down = self.down.iter().map(value).collect();
        table
    }
}

/// The corrections `values` − `shift` in steps of `quantum`: rounded, or `None` when
/// `Exact` and one is not a whole step.
fn quanta(values: &[f64], shift: f64, quantum: f64, rounding: Rounding) -> Option<Vec<i64>> {
    values
        .iter()
        .map(|v| {
            let steps = (v - shift) / quantum;
            let whole = steps.round();
            (rounding == Rounding::Nearest || (steps - whole).abs() < 1e-6).then_some(whole as i64)
        })
        .collect()
}

fn detection_unit(kind: AxisKind) -> f64 {
    match kind {
        AxisKind::Linear => DETECTION_UM,
        AxisKind::Rotary => DETECTION_ARCSEC,
    }
}

/// The first number of the + direction table (3621) without an offset: 0 on a turn (its
/// number 0 repeats the last section), else 1 (the − end has no number).
fn first_number(table: &Table) -> usize {
    usize::from(table.modulo_deg.is_none())
}

/// The offset of every number that puts 3621 where the table's place says.
fn number_offset(table: &Table) -> Result<usize, Refused> {
    let first = first_number(table);
    match table.place.number {
        None => Ok(0),
        Some(n) if n >= first => Ok(n - first),
        Some(n) => Err(Refused::Grid(format!(
            "the first pitch error number (3621) {n} is below {first}, the first this table can take"
        ))),
    }
}

/// The grid index of the reference position (folded into the turn on a modulo table).
fn reference_index(table: &Table) -> Result<usize, Refused> {
    let reference = table
        .modulo_deg
        .map_or(table.reference, |r| wrap(table.reference, r));
    let last = table.positions.len() - 1;
    let found = table
        .positions
        .iter()
        .position(|p| (p - reference).abs() < 1e-6);
    match found {
        Some(k) if table.modulo_deg.is_some() => Ok(k % last),
        Some(k) => Ok(k),
        None => Err(Refused::Grid(format!(
            "the reference position {} {unit} is not a point of the table ({} … {} {unit} every {} {unit}); FANUC counts its points from it",
            fmt_fixed(table.reference, 3),
            fmt_fixed(table.positions[0], 3),
            fmt_fixed(table.positions[last], 3),
            fmt_fixed(interval(table), 3),
            unit = table.kind.position_unit(),
        ))),
    }
}

fn interval(table: &Table) -> f64 {
    table.positions[1] - table.positions[0]
}

/// 3624 in 0.001 mm or 0.001°: the interval must be a whole number of them.
fn interval_in_input_units(table: &Table) -> Result<i64, Refused> {
    let units = interval(table) * PER_POSITION_UNIT;
    if (units - units.round()).abs() > 1e-6 {
        return Err(Refused::Grid(format!(
            "the interval {} {} is not a whole number of 0.001 {}; FANUC parameter 3624 is",
            interval(table),
            table.kind.position_unit(),
            table.kind.position_unit()
        )));
    }
    Ok(units.round() as i64)
}

/// Why no magnification holds the table: its steepest section.
fn too_steep(table: &Table, rounding: Rounding) -> Refused {
    let unit = table.kind.deviation_unit();
    if rounding == Rounding::Exact {
        return Refused::Range(format!(
            "the corrections are not whole steps of the detection unit × magnification with values in {MIN_VALUE}…{MAX_VALUE}: hold the table first"
        ));
    }
    let (change, k) = [&table.up, &table.down]
        .iter()
        .flat_map(|v| {
            v.windows(2)
                .enumerate()
                .map(|(k, w)| ((w[1] - w[0]).abs(), k))
        })
        .fold((0.0, 0), |best, c| if c.0 > best.0 { c } else { best });
    Refused::Range(format!(
        "the correction changes by {} {unit} between {} and {} {}, more than {MAX_VALUE} × {} {unit} × magnification {MAX_MAGNIFICATION} per point; choose a smaller --interval",
        fmt_fixed(change, 1),
        fmt_fixed(table.positions[k], 3),
        fmt_fixed(table.positions[k + 1], 3),
        table.kind.position_unit(),
        fmt_position(detection_unit(table.kind)),
    ))
}

impl Stored {
    fn header(&self, table: &Table) -> String {
        let (pos, dev) = (table.kind.position_unit(), table.kind.deviation_unit());
        let largest = [&self.up, &self.down]
            .iter()
            .flat_map(|q| self.points(q))
            .map(|p| p.value.abs())
            .max()
            .unwrap_or(0);
        let last = table.positions.len() - 1;
        let mut out = String::new();
        let _ = writeln!(
            out,
            "FANUC stored pitch error compensation, bidirectional, one axis; written by axcheck\n\
             Axis: {}, {} points every {} {pos} from {} to {} {pos}{}, reference position {} {pos}\n\
             Values: the increment of the correction over the section that ends at each point,\n\
             \x20 in detection units (assumed {} {dev}) x magnification 3623 = {} {dev};\n\
             \x20 positive = more travel in +. Correction = -(mean deviation), 0 at the reference\n\
             \x20 position in the + direction (reference return in +, 1006#5 = 0).\n\
             Largest |value|: {largest} (i-series controls hold {MIN_VALUE}...{MAX_VALUE} per point, older ones -7...+7).\n\
             Numbers {}...{} of the 0...{} that all axes share: if another axis uses them, add one\n\
             \x20 offset to 3620, 3621, 3622, 3626 and every number below.\n\
             Not confirmed: the sign, the punch syntax below, the unit of 3627.",
            table.kind,
            table.positions.len(),
            fmt_fixed(interval(table), 3),
            fmt_fixed(table.positions[0], 3),
            fmt_fixed(table.positions[last], 3),
            if self.modulo { " (one turn)" } else { "" },
            fmt_fixed(table.positions[self.reference], 3),
            fmt_position(detection_unit(table.kind)),
            fmt_position(self.quantum),
            self.numbers()[1],
            self.last_number(),
            PITCH_NUMBERS - 1,
        );
        out
    }

    fn parameters(&self, table: &Table, out: &mut String) {
        out.push_str(
            "\nParameters of the axis (parameter screen, PWE = 1; then power off/on and return\n\
             to the reference position):\n",
        );
        for (number, value, comment) in self.parameter_rows(table) {
            let _ = writeln!(out, "  {number:<6} = {value:<8} {comment}");
        }
        let finer = match table.kind {
            AxisKind::Linear => "0.1 um",
            AxisKind::Rotary => "0.0001 deg",
        };
        let _ = writeln!(
            out,
            "  1851/1852 (backlash): as during the measurement; the - direction table corrects\n\
             \x20 the reversal that remained. If the detection unit is {finer} (IS-C), multiply\n\
             \x20 3623 and 3627 by 10."
        );
    }

    /// Parameter number, value, comment.
    fn parameter_rows(&self, table: &Table) -> Vec<(&'static str, String, String)> {
        let [reference, first, last, down_first] = self.numbers();
        let pos = table.kind.position_unit();
        let step = fmt_fixed(interval(table), 3);
        let input = interval_in_input_units(table).unwrap_or_default();
        let down_last = self.last_number();
        let at_reference = fmt_fixed(table.positions[self.reference], 3);
        let mut rows = vec![
            (
                "3605#0",
                1.to_string(),
                "bidirectional pitch error compensation".to_string(),
            ),
            (
                "3620",
                reference.to_string(),
                format!("point number of the reference position, {at_reference} {pos}"),
            ),
            (
                "3621",
                first.to_string(),
                "farthest point on the - side, + direction table".into(),
            ),
            (
                "3622",
                last.to_string(),
                "farthest point on the + side, + direction table".into(),
            ),
            (
                "3623",
                self.magnification.to_string(),
                "magnification".into(),
            ),
            (
                "3624",
                input.to_string(),
                format!("interval {step} {pos} in 0.001 {pos} (a real-type parameter: {step})"),
            ),
        ];
        if self.modulo {
            rows.push((
                "3625",
                "360000".into(),
                "travel per turn 360 deg in 0.001 deg (a real-type parameter: 360.000)".into(),
            ));
        }
        rows.push((
            "3626",
            down_first.to_string(),
            format!("farthest point on the - side, - direction table ({down_first}...{down_last})"),
        ));
        rows.push((
            "3627",
            self.at_reference_down().to_string(),
            format!(
                "- direction correction at the reference position, detection units ({} {})",
                fmt_fixed(self.down[self.reference] as f64 * self.quantum, 1),
                table.kind.deviation_unit()
            ),
        ));
        rows
    }

    fn data_table(&self, table: &Table, out: &mut String) {
        let (pos, dev) = (table.kind.position_unit(), table.kind.deviation_unit());
        let _ = writeln!(
            out,
            "\nPitch error data: each number's value, the section it covers and the correction\n\
             held at the section's end:\n  {:>7}  {:>5}  {:>10}  {:>10}  {:>10}",
            "number",
            "value",
            format!("from {pos}"),
            format!("to {pos}"),
            dev
        );
        for (name, quanta, base) in [("+", &self.up, 0), ("-", &self.down, self.down_base())] {
            let _ = writeln!(out, "  {name} direction");
            if !self.modulo {
                let start = fmt_fixed(table.positions[0], 3);
                let held = fmt_fixed(quanta[0] as f64 * self.quantum, 1);
                let _ = writeln!(
                    out,
                    "  {:>7}  {:>5}  {:>10}  {start:>10}  {held:>10}",
                    "(start)", "", ""
                );
            }
            for p in self.points(quanta) {
                // On a turn, a section ending at index 0 ends at 360°.
                let end = if p.end == 0 {
                    table.positions.len() - 1
                } else {
                    p.end
                };
                let _ = writeln!(
                    out,
                    "  {:>7}  {:>5}  {:>10}  {:>10}  {:>10}",
                    self.offset + base + p.offset,
                    p.value,
                    fmt_fixed(table.positions[p.start], 3),
                    fmt_fixed(table.positions[end], 3),
                    fmt_fixed(quanta[p.end] as f64 * self.quantum, 1)
                );
            }
        }
    }

    fn punch(&self, out: &mut String) {
        out.push_str(
            "\nThe same data in the punch format (recalled, NOT confirmed: N = 10000 + number,\n\
             P = value). Punch this control's pitch error data once and compare before reading\n\
             this in; copy the lines from % to % into a file of their own.\n%\n",
        );
        for (quanta, base) in [(&self.up, 0), (&self.down, self.down_base())] {
            for p in self.points(quanta) {
                let number = PUNCH_BASE + self.offset + base + p.offset;
                let _ = writeln!(out, "N{number}P{}", p.value);
            }
        }
        out.push_str("%\n");
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compensate::testing::axis;
    use crate::compensate::{Settings, held_table};
    use crate::units::Direction;

    /// A linear axis with irregular targets 0, 30, 70, 100, 160, 200 mm; x̄↑ = 0, 6, 13.4,
    /// 17, 7, −2 µm; x̄↓ = x̄↑ + 4 µm + 0.01 µm/mm × target (a reversal of 4…6 µm).
    ///
    /// Grid every 50 mm through the reference 100 mm: 0, 50, 100, 150, 200 (indices 0…4).
    /// x̄↑ there (linear between targets): 0; 6 + 7.4 × 20/40 = 9.7; 17; 17 − 10 × 50/60 =
    /// 8.667; −2. x̄↓ adds 4 + 0.01 × p: 4; 14.2; 22; 14.167; 4.
    /// Corrections −x̄, shifted by +17 so ↑ is 0 at 100 mm:
    ///   ↑ 17, 7.3, 0, 8.333, 19  → held (1 µm): 17, 7, 0, 8, 19
    ///   ↓ 13, 2.8, −5, 2.833, 13 → held: 13, 3, −5, 3, 13
    /// Values (increments, number = grid index of the section's end):
    ///   ↑ numbers 1…4: 7−17 = −10, 0−7 = −7, 8−0 = 8, 19−8 = 11; all in −128…127, so
    ///     magnification 1; 3620 = 2 (the section 50…100 ends at the reference), 3621 = 1,
    ///     3622 = 4;
    ///   ↓ numbers 5…8 (3626 = 5): 3−13 = −10, −5−3 = −8, 3+5 = 8, 13−3 = 10; 3627 = −5.
    #[test]
    fn linear_axis_resampled_around_a_middle_reference() {
        let targets = [0.0, 30.0, 70.0, 100.0, 160.0, 200.0];
        let up = [0.0, 6.0, 13.4, 17.0, 7.0, -2.0];
        let data = axis(AxisKind::Linear, &targets, 2, |p, dir| {
            let i = targets.iter().position(|t| *t == p).unwrap();
            match dir {
                Direction::Up => up[i],
                Direction::Down => up[i] + 4.0 + 0.01 * p,
            }
        });
        let settings = Settings {
            interval: Some(50.0),
            reference: Some(100.0),
            ..Default::default()
        };
        let table = held_table(&Fanuc, &data, &settings).unwrap();
        assert_eq!(table.positions, [0.0, 50.0, 100.0, 150.0, 200.0]);
        assert_eq!(table.up, [17.0, 7.0, 0.0, 8.0, 19.0]);
        assert_eq!(table.down, [13.0, 3.0, -5.0, 3.0, 13.0]);
        let file = Fanuc.write(&table, &[]).unwrap();
        assert_eq!(
            file,
            include_str!("../../../../../../tests/data/compensation/fanuc-linear.txt")
        );
    }

    /// A rotary axis measured 0…360° every 45°, turned to a modulo table every 90°
    /// (0, 90, 180, 270, 360; indices 0…4, 360° = 0°), reference 0°:
    ///   x̄↑ = 0, 11, 4, −9, 2″ at 0, 90, 180, 270, 360°; x̄↓ = x̄↑ + 6″ except 10.5″ at 180°.
    /// Corrections −x̄, the ends of the turn averaged ((0 − 2)/2 = −1 for ↑, (−6 − 8)/2 = −7
    /// for ↓), shifted by +1 so ↑ is 0 at 0°, in steps of 0.001° = 3.6″ (magnification 1):
    ///   ↑ 0, −10, −3, 10, 0     → 0, −2.78, −0.83, 2.78, 0 steps → 0, −3, −1, 3, 0
    ///   ↓ −6, −16, −9.5, 4, −6  → −1.67, −4.44, −2.64, 1.11, −1.67 → −2, −4, −3, 1, −2
    /// Values from the reference on (3620 = 3621 = 0, 3622 = 4, number 0 = number 4):
    ///   ↑ 1…4: −3, 2, 4, −3 (sum 0), number 0: −3;
    ///   ↓ 5…9 (3626 = 5): number 5 = number 9 = −3, 6…9: −2, 1, 4, −3 (sum 0); 3627 = −2.
    #[test]
    fn rotary_axis_over_one_turn_sums_to_zero() {
        let targets: Vec<f64> = (0..=8).map(|k| k as f64 * 45.0).collect();
        let up = |p: f64| match p as i64 {
            0 => 0.0,
            90 => 11.0,
            180 => 4.0,
            270 => -9.0,
            360 => 2.0,
            _ => 1.0,
        };
        let data = axis(AxisKind::Rotary, &targets, 2, |p, dir| {
            match (dir, p as i64) {
                (Direction::Up, _) => up(p),
                (Direction::Down, 180) => 10.5,
                (Direction::Down, _) => up(p) + 6.0,
            }
        });
        let settings = Settings {
            interval: Some(90.0),
            reference: None,
            ..Default::default()
        };
        let table = held_table(&Fanuc, &data, &settings).unwrap();
        assert_eq!(table.modulo_deg, Some(360.0));
        let steps =
            |v: &[f64]| -> Vec<i64> { v.iter().map(|x| (x / 3.6).round() as i64).collect() };
        assert_eq!(steps(&table.up), [0, -3, -1, 3, 0]);
        assert_eq!(steps(&table.down), [-2, -4, -3, 1, -2]);
        let file = Fanuc.write(&table, &[]).unwrap();
        assert_eq!(
            file,
            include_str!("../../../../../../tests/data/compensation/fanuc-rotary-modulo.txt")
        );
    }

    /// x̄↑ = 0, 301, 0 µm at 0, 100, 200 mm (x̄↓ the same): corrections 0, −301, 0; at
    /// magnification 1 or 2 the increments ±301 or ±151 (−150.5 rounded away from 0) exceed
    /// 127; at 3 they are ±100 (−301/3 = −100.33 → −100 steps): held 0, −300, 0 µm.
    #[test]
    fn the_smallest_magnification_that_fits() {
        let data = axis(AxisKind::Linear, &[0.0, 100.0, 200.0], 2, |p, _| {
            if p == 100.0 { 301.0 } else { 0.0 }
        });
        let settings = Settings {
            interval: Some(100.0),
            reference: Some(0.0),
            ..Default::default()
        };
        let table = held_table(&Fanuc, &data, &settings).unwrap();
        assert_eq!(table.up, [0.0, -300.0, 0.0]);
        let file = Fanuc.write(&table, &[]).unwrap();
        assert!(file.contains("\n  3623   = 3 "), "{file}");
        assert!(file.contains("\nN10001P-100\nN10002P100\n"), "{file}");
    }

    /// 13 mm over one 100 mm section is 130 steps at the largest magnification (100 µm).
    #[test]
    fn refuses_an_increment_beyond_the_largest_magnification() {
        let data = axis(AxisKind::Linear, &[0.0, 100.0, 200.0], 2, |p, _| {
            if p == 100.0 { 13000.0 } else { 0.0 }
        });
        let settings = Settings {
            interval: Some(100.0),
            reference: None,
            ..Default::default()
        };
        let err = held_table(&Fanuc, &data, &settings).unwrap_err();
        assert_eq!(
            err,
            Refused::Range(
                "the correction changes by 13000.0 um between 0.000 and 100.000 mm, more than 127 × 1 um × magnification 100 per point; choose a smaller --interval".into()
            )
        );
    }

    /// The points are counted from the reference position: it must be one of them.
    #[test]
    fn refuses_a_reference_off_the_grid() {
        let data = axis(AxisKind::Linear, &[0.0, 100.0, 200.0], 2, |_, _| 0.0);
        let outside = Settings {
            interval: Some(50.0),
            reference: Some(300.0),
            ..Default::default()
        };
        let err = held_table(&Fanuc, &data, &outside).unwrap_err();
        assert_eq!(
            err,
            Refused::Grid(
                "the reference position 300.000 mm is not a point of the table (0.000 … 200.000 mm every 50.000 mm); FANUC counts its points from it".into()
            )
        );
        let targets: Vec<f64> = (0..=4).map(|k| k as f64 * 90.0).collect();
        let rotary = axis(AxisKind::Rotary, &targets, 2, |_, _| 0.0);
        let between = Settings {
            interval: Some(90.0),
            reference: Some(100.0),
            ..Default::default()
        };
        assert!(matches!(
            held_table(&Fanuc, &rotary, &between),
            Err(Refused::Grid(_))
        ));
    }
}
