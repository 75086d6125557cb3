//! `heidenhain`: a nonlinear axis-error compensation table `*.COM` of the HEIDENHAIN TNC
//! 620/640 generation (the table concept of the MANUALplus 620 Technical Manual), in the
//! control's table text format: `BEGIN NAME.COM MM`, a header line naming the columns, one
//! fixed-width row per point, `[END]`. Columns: `NR`; `AXISPOS`, the point's position
//! relative to the machine datum (MP_refPosition); a column named after the compensated
//! axis (its key in CfgAxes/axisList) holding the values; `BACKLASH`, "the compensation
//! values measured in the negative direction of traverse".
//!
//! The axis key names the value column and the table (`--axis X`, campaign
//! `compensation: {axis: X}`; the file `X.COM`). Without it both say `<AXIS?>`, and a note
//! on the console asks for the axis key from CfgAxes/axisList, keeping the columns aligned;
//! a wrong key would make it a cross compensation (the column's axis as a function of the
//! `.CMA` column's), so it is not guessed. `<`, `?` and `>` are not permitted in TNC file
//! names (TNC 620 User's Manual 340 56x-01, "File names", p. 80, lists them; the TNC 640
//! User's Manual 1/2015, p. 115, allows only letters, digits, `.`, `_` and `-`): the name
//! is no file the control holds and, as far as found, no axis key (earlier files said
//! `AXIS`, a plain name a key could have). Not confirmed: what the control does with a
//! `.COM` column that names none of its axes (refuses the table, or ignores the column).
//!
//! Units: mm (degrees on a rotary axis) for positions and values, printed to 4 decimals:
//! the table as held is the correction rounded to 0.1 µm or 0.0001° (0.36″), at
//! positions rounded to 0.0001 mm or °.
//!
//! Sign: HEIDENHAIN has the axis error entered "with the correct sign": positive when the
//! travel is too long (linear compensation MP720, TNC 407 Technical Manual §1.6.3), and its
//! nonlinear example enters the plotted "Error in Z \[mm\]" curve (§1.6.4). That is the
//! deviation e = actual − target, so the table holds −correction: −correction↑ in the axis
//! column, −correction↓ in `BACKLASH`. Inferred for the TNC 620/640 tables, not stated.
//!
//! Backlash: `BACKLASH` read as the ↓ values themselves, not their difference from the ↑
//! ones (the manual's wording; medium confidence: check by approaching one point from both
//! sides with the table active). The reversal is then in the table: set MP_backLash to 0,
//! which the control otherwise adds at every reversal, also of nonlinear compensation.
//!
//! Points: equidistant. The MANUALplus example spaces them 5 mm from a start point and the
//! TNC 407 generation required a power-of-two spacing from a datum; no source says an
//! AXISPOS column may be irregular, and equidistant points are valid either way. At most 256
//! per table (TNC 407 module 9095, error 3; the TNC 620/640 limit was not found), with a
//! total over all tables not stated. Linear interpolation between points (TNC 306/407
//! manuals); outside the table: not stated (the grid covers the measured travel).
//! Rotary axes: only entries 0…360° are recognised (TNC 407 §1.6.4), so a table outside
//! that is refused; measured over a whole revolution it is 0…360° with one value at both
//! ends. Reference point: positions are machine-datum positions, so the measured targets
//! must be too; `--reference` shifts the values to zero there.
//!
//! Loading: the `.COM` table is assigned in a `.CMA` table (standard name `config.cma`),
//! one column per compensated axis holding `.COM` names line by line, and an `ACTIVE`
//! column whose line marked `*` is active ([axis column in .COM] = F(axis column in .CMA));
//! several lines may exist, one active (MANUALplus 620 Technical Manual p. 718). Stored in
//! the PLC partition \[recalled\]; the machine parameter that enables nonlinear compensation
//! on TNC 620/640 (MP730 on the TNC 407) was not found.
//!
//! Sources: HEIDENHAIN Technical Manual MANUALplus 620 (01/2012) §6.10.3 pp. 713–718
//! (easymanua.ls/heidenhain/manualplus-620/manual/506189?p=716, ?p=718); Technical
//! Manual TNC 407/415/425 (01.98) §1.6.3–1.6.4 pp. 4-26…4-31 and module 9095
//! (azmanual.top/manuals/797826, pages 151, 153, 156, 622); the TNC table text format as
//! read and written by pyLSV2 (`drunsinn/pyLSV2`, `pyLSV2/table_reader.py`).
//! Unconfirmed: the exact `.COM` header and column widths (the `NR` column, the widths
//! chosen here), the sign for TNC 620/640, `BACKLASH` as absolute ↓ values, the 256-point
//! limit on TNC 620/640, the behaviour outside the table, the enabling parameter.
//!
//! Read back as the TNC table text format is read (pyLSV2's `table_reader.py`, the best
//! public description): the `BEGIN NAME.COM [MM|INCH]` line, an optional `#STRUCTBEGIN …
//! #STRUCTEND` block, the column line, rows cut at the columns' positions (a column runs
//! from its name to the next name, the last one to the end of the row), `[END]`. Columns
//! `AXISPOS`, the axis column (the one named, else the only one besides `NR`, `AXISPOS`
//! and `BACKLASH`) and `BACKLASH` if present (else the axis column in both directions);
//! INCH tables are converted to mm. Refused, with the line: a cell that is not a number
//! (a decimal comma too: it is not known how the control reads it), positions that do not
//! increase, more than 256 rows.

use super::controller::{Controller, Directions, Format, ReadAs, Refused, Spacing, Unreadable};
use super::reading::{self, Points, numbered};
use crate::compensate::grid::REVOLUTION_DEG;
use crate::compensate::{Table, TableSlot};
use crate::units::{AxisKind, fmt_fixed};

pub struct Heidenhain;

/// Entries per `.COM` table (TNC 407 module 9095).
const MAX_POINTS: usize = 256;

/// Decimals of positions and values (0.0001 mm or °).
const DECIMALS: usize = 4;

/// The value column's name until the user gives the axis key.
const AXIS_KEY: &str = super::AXIS_PLACEHOLDER;

/// The placeholder of files written before `<AXIS?>`, read as naming no axis too.
const OLD_AXIS_KEY: &str = "AXIS";

/// The columns and their widths.
const COLUMNS: [(&str, usize); 4] = [("NR", 6), ("AXISPOS", 14), (AXIS_KEY, 14), ("BACKLASH", 14)];

/// One value step in the deviation unit: 0.1 µm, or 0.0001° = 0.36″.
fn value_step(kind: AxisKind) -> f64 {
    match kind {
        AxisKind::Linear => 0.1,
        AxisKind::Rotary => 0.36,
    }
}

/// `value` to 4 decimals with its sign, as TNC tables print numbers (`+0.0025`).
fn signed(value: f64) -> String {
    let s = fmt_fixed(value, DECIMALS);
    if s.starts_with('-') {
        s
    } else {
        format!("+{s}")
    }
}

/// `position` on the table's 0.0001 step.
fn snapped(position: f64) -> f64 {
    let scale = 10f64.powi(DECIMALS as i32);
    (position * scale).round() / scale + 0.0
}

/// Why the control cannot hold `table`, if it cannot.
fn check(table: &Table) -> Result<(), Refused> {
    let positions: Vec<f64> = table.positions.iter().map(|p| snapped(*p)).collect();
    if positions.len() > MAX_POINTS {
        return Err(Refused::Grid(format!(
            "{} points, but a .COM table holds at most {MAX_POINTS}",
            positions.len()
        )));
    }
    if positions.windows(2).any(|w| w[1] <= w[0]) {
        return Err(Refused::Grid(
            "the positions must increase by 0.0001 or more".into(),
        ));
    }
    let (first, last) = (positions[0], positions[positions.len() - 1]);
    if table.kind == AxisKind::Rotary && (first < 0.0 || last > REVOLUTION_DEG) {
        return Err(Refused::Range(format!(
            "the table runs from {}° to {}°, but the control recognises only 0…360°",
            fmt_fixed(first, DECIMALS),
            fmt_fixed(last, DECIMALS)
        )));
    }
    Ok(())
}

/// `fields` padded to the columns' widths.
/// `fields` padded to the columns' widths; refused when one does not fit with a blank
/// after it (the control cuts the columns at their positions).
fn row(fields: [&str; 4]) -> Result<String, Refused> {
    let mut line = String::new();
    for ((name, width), field) in COLUMNS.iter().zip(fields) {
        if field.chars().count() >= *width {
            return Err(Refused::Range(format!(
                "`{field}` does not fit the table's {width}-character column {name}"
            )));
        }
        line.push_str(&format!("{field:<width$}"));
    }
    line.push('\n');
    Ok(line)
}

impl Controller for Heidenhain {
    fn name(&self) -> &'static str {
        "heidenhain"
    }

    fn extension(&self) -> &'static str {
        "com"
    }

    /// Equidistant points, up to 256, the ↑ values and the ↓ ones (`BACKLASH`), 0…360°
    /// tables for rotary axes, values printed to 0.0001 mm or ° (0.1 µm, 0.36″).
    fn format(&self) -> Format {
        Format {
            spacing: Spacing::Equidistant,
            max_points: MAX_POINTS,
            directions: Directions::Bidirectional,
            modulo: true,
            quantum_um: value_step(AxisKind::Linear),
            quantum_arcsec: value_step(AxisKind::Rotary),
        }
    }

    /// The corrections rounded to the printed step and the points moved onto it.
    fn hold(&self, table: Table) -> Result<Table, Refused> {
        let step = value_step(table.kind);
        let mut table = table.quantised(step);
        check(&table)?;
        for p in table.positions.iter_mut() {
            *p = snapped(*p);
        }
        table.reference = snapped(table.reference);
        Ok(table)
    }

    fn read(&self, text: &str, reading: ReadAs) -> Result<Table, Unreadable> {
        read(text, reading)
    }

    /// `notes` are not written: the table format has no comments (they are in the console,
    /// the report and `results.json`).
    fn write(&self, table: &Table, _notes: &[String]) -> Result<String, Refused> {
        super::finite(table)?;
        check(table)?;
        // Corrections in µm or arcsec, the table in mm or degrees; it holds the error.
        let per_unit = table.kind.deviation_units_per_position_unit();
        // The axis key names the value column and the table (X.COM).
        let key = super::axis_name(table)?;
        let names = COLUMNS.map(|(name, _)| if name == AXIS_KEY { key } else { name });
        let mut out = format!("BEGIN {key}.COM MM\n");
        out.push_str(&row(names)?);
        for (nr, ((p, u), d)) in table
            .positions
            .iter()
            .zip(&table.up)
            .zip(&table.down)
            .enumerate()
        {
            let nr = nr.to_string();
            let (p, u, d) = (signed(*p), signed(-u / per_unit), signed(-d / per_unit));
            out.push_str(&row([&nr, &p, &u, &d])?);
        }
        out.push_str("[END]\n");
        Ok(out)
    }

    fn unnamed_axis(&self, table: &Table) -> Option<String> {
        table.place.axis.is_none().then(|| {
            format!(
                "the table names no axis: replace {AXIS_KEY} in its BEGIN line and its value column by the axis key from CfgAxes/axisList (X, Y, ...; as written it names no axis of the control), keep the columns aligned and save it as KEY.COM; or give the key with --axis (compensation: {{axis}} in a campaign)"
            )
        })
    }
}

/// A `.COM` table's columns: each name and the byte where its cell starts.
struct Columns {
    names: Vec<(String, usize)>,
}

impl Columns {
    fn of(line: &str) -> Columns {
        let mut names = Vec::new();
        let mut start = None;
        for (i, c) in line.char_indices().chain([(line.len(), ' ')]) {
            match (c.is_whitespace(), start) {
                (false, None) => start = Some(i),
                (true, Some(s)) => {
                    names.push((line[s..i].to_string(), s));
                    start = None;
                }
                _ => {}
            }
        }
        Columns { names }
    }

    fn index(&self, name: &str) -> Option<usize> {
        self.names
            .iter()
            .position(|(n, _)| n.eq_ignore_ascii_case(name))
    }

    /// The cell of column `k` in `row`: from its start to the next column's, the last one
    /// to the end of the row.
    fn cell<'r>(&self, row: &'r str, k: usize) -> &'r str {
        let start = self.names[k].1.min(row.len());
        let end = self
            .names
            .get(k + 1)
            .map_or(row.len(), |(_, s)| (*s).min(row.len()));
        row.get(start..end.max(start)).unwrap_or("").trim()
    }

    /// The value column: the one named `axis`, else the only one that is not `NR`,
    /// `AXISPOS` or `BACKLASH`.
    fn axis(&self, axis: Option<&str>, line: usize) -> Result<usize, Unreadable> {
        let others: Vec<usize> = (0..self.names.len())
            .filter(|&k| {
                let n = self.names[k].0.to_ascii_uppercase();
                !matches!(n.as_str(), "NR" | "AXISPOS" | "BACKLASH")
            })
            .collect();
        let wanted: Vec<usize> = match axis {
            Some(a) => others
                .iter()
                .copied()
                .filter(|&k| self.names[k].0.eq_ignore_ascii_case(a))
                .collect(),
            None => others.clone(),
        };
        let listed: Vec<&str> = others.iter().map(|&k| self.names[k].0.as_str()).collect();
        match (wanted.as_slice(), axis) {
            ([k], _) => Ok(*k),
            ([], Some(a)) => Err(Unreadable::at(
                line,
                format!(
                    "no column `{a}`; the table's axis columns: {}",
                    listed.join(", ")
                ),
            )),
            ([], None) => Err(Unreadable::at(
                line,
                "no axis column beside NR, AXISPOS and BACKLASH",
            )),
            _ => Err(Unreadable::at(
                line,
                format!(
                    "several axis columns ({}): name the axis (--axis, or compensation: {{axis}})",
                    listed.join(", ")
                ),
            )),
        }
    }
}

/// The unit of a `BEGIN NAME.COM [MM|INCH]` line: mm per table unit.
fn begin_line(line: &str, at: usize) -> Result<f64, Unreadable> {
    let words: Vec<&str> = line.split_whitespace().collect();
    match words.as_slice() {
        ["BEGIN", name, rest @ ..] if name.to_ascii_uppercase().ends_with(".COM") => match rest {
            [] | ["MM", ..] => Ok(1.0),
            ["INCH", ..] => Ok(25.4),
            [other, ..] => Err(Unreadable::at(
                at,
                format!("unknown unit `{other}` (MM or INCH)"),
            )),
        },
        _ => Err(Unreadable::at(
            at,
            format!("expected `BEGIN NAME.COM MM`, got `{}`", line.trim()),
        )),
    }
}

/// The table of a `.COM` file.
fn read(text: &str, reading: ReadAs) -> Result<Table, Unreadable> {
    let mut lines = numbered(text).filter(|(_, l)| !l.trim().is_empty());
    let (at, begin) = lines
        .next()
        .ok_or_else(|| Unreadable::file("empty file: expected `BEGIN NAME.COM MM`"))?;
    let mm = begin_line(begin, at)?;
    let (mut at, mut header) = lines
        .next()
        .ok_or_else(|| Unreadable::file("no column line after BEGIN"))?;
    if header.trim_start().starts_with("#STRUCTBEGIN") {
        lines.find(|(_, l)| l.trim_start().starts_with("#STRUCTEND"));
        (at, header) = lines
            .next()
            .ok_or_else(|| Unreadable::file("no column line after #STRUCTEND"))?;
    }
    let columns = Columns::of(header);
    let need = |name: &str| {
        columns
            .index(name)
            .ok_or_else(|| Unreadable::at(at, format!("no column `{name}`")))
    };
    let position = need("AXISPOS")?;
    let axis = columns.axis(reading.axis, at)?;
    let backlash = columns.index("BACKLASH");
    let per_unit = reading.kind.deviation_units_per_position_unit() * mm;
    let mut points = Points::empty(reading.kind);
    let mut rows = Vec::new();
    let mut ended = false;
    for (line, row) in lines {
        if matches!(row.trim(), "[END]" | "END") {
            ended = true;
            break;
        }
        let cell = |k: usize| {
            let c = columns.cell(row, k);
            if c.contains(',') {
                return Err(Unreadable::field(
                    line,
                    &columns.names[k].0,
                    format!("`{c}`: a decimal comma; write the number with a point"),
                ));
            }
            reading::number(c, line, &columns.names[k].0)
        };
        // The table holds the error: the correction is minus it.
        let up = -cell(axis)? * per_unit;
        points.positions.push(cell(position)? * mm);
        points.up.push(up);
        points
            .down
            .push(backlash.map_or(Ok(up), |b| cell(b).map(|v| -v * per_unit))?);
        rows.push(line);
    }
    if !ended {
        return Err(Unreadable::file(
            "no `[END]` line: the table may be cut short",
        ));
    }
    reading::enough(points.positions.len(), 1, "the table")?;
    if points.positions.len() > MAX_POINTS {
        return Err(Unreadable::at(
            rows[MAX_POINTS],
            format!(
                "row {}: a .COM table holds at most {MAX_POINTS}",
                MAX_POINTS + 1
            ),
        ));
    }
    reading::increasing(&points.positions, &rows, "AXISPOS")?;
    let modulo = reading::one_revolution(reading.kind, &points.positions);
    let key = columns.names[axis].0.clone();
    let place = TableSlot {
        axis: (key != AXIS_KEY && key != OLD_AXIS_KEY).then_some(key),
        ..TableSlot::default()
    };
    Ok(points.table(None, modulo, place, Default::default()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compensate::testing::{axis, negative_linear, quarter_turns_rotary};
    use crate::compensate::{Settings, held_table};

    /// The axis of the `twincat` example: irregular targets −100, −70, −55, −20, 0 mm,
    /// x̄↑ = 0, 3.0, 1.53, −2.0, 1.0 µm, x̄↓ = x̄↑ + 2.0 µm, --interval 25. Interpolated at
    /// −100, −75, −50, −25, 0 mm: x̄↑ = 0, 2.5, 1.025714, −1.495714, 1.0 µm; x̄↓ = 2.0,
    /// 4.5, 3.025714, 0.504286, 3.0 µm. Held corrections −x̄ to 0.1 µm; the table holds
    /// −correction in mm: AXIS +0.0000, +0.0025, +0.0010, −0.0015, +0.0010; BACKLASH
    /// +0.0020, +0.0045, +0.0030, +0.0005, +0.0030.
    #[test]
    fn golden_linear_table_resampled_on_an_interval() {
        let data = negative_linear();
        let settings = Settings {
            interval: Some(25.0),
            reference: None,
            ..Default::default()
        };
        let table = held_table(&Heidenhain, &data, &settings).unwrap();
        assert_eq!(
            Heidenhain.write(&table, &[]).unwrap(),
            include_str!("../../../../../tests/data/compensation/heidenhain-linear.com")
        );
    }

    /// A rotary axis measured every 45° over 0…360°, x̄↑ = 1.0, 3.6, 7.3, −1.8, 2.0″ at
    /// 0, 90, 180, 270, 360°, x̄↓ = x̄↑ − 1.44″, --interval 90: 0° and 360° one position
    /// (x̄↑ = 1.5″, x̄↓ = 0.06″). Held corrections −x̄ to 0.36″ = 0.0001°: ↑ −4, −10, −20,
    /// +5, −4 steps; ↓ 0, −6, −16, +9, 0. The table holds −correction in degrees: AXIS
    /// +0.0004, +0.0010, +0.0020, −0.0005, +0.0004; BACKLASH +0.0000, +0.0006, +0.0016,
    /// −0.0009, +0.0000.
    #[test]
    fn golden_rotary_table_over_one_revolution() {
        let data = quarter_turns_rotary();
        let settings = Settings {
            interval: Some(90.0),
            reference: None,
            ..Default::default()
        };
        let table = held_table(&Heidenhain, &data, &settings).unwrap();
        assert_eq!(
            Heidenhain.write(&table, &[]).unwrap(),
            include_str!("../../../../../tests/data/compensation/heidenhain-rotary.com")
        );
    }

    #[test]
    fn refuses_what_a_com_table_cannot_hold() {
        let data = crate::compensate::testing::straight(0.0, 1.0, MAX_POINTS + 1);
        let err = held_table(&Heidenhain, &data, &Default::default()).unwrap_err();
        assert_eq!(
            err.to_string(),
            "257 points, but the table holds at most 256; choose an interval of 1.004 mm or more (--interval, or compensation: {interval} in a campaign)"
        );
        // A rotary axis measured −45…45°: the control sees only 0…360°.
        let targets = [-45.0, 0.0, 45.0];
        let data = axis(AxisKind::Rotary, &targets, 2, |_, _| 1.0);
        let err = held_table(&Heidenhain, &data, &Default::default()).unwrap_err();
        assert_eq!(
            err,
            Refused::Range(
                "the table runs from -45.0000° to 45.0000°, but the control recognises only 0…360°"
                    .into()
            )
        );
    }
}
