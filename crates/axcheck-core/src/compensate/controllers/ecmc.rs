//! `ecmc`: an encoder correction lookup table (LUT) of the EPICS EtherCAT motion
//! controller ecmc (ESS / PSI): one line `position correction` per point, separated by one
//! space, in the axis's engineering units (mm, or degrees on a rotary axis: axcheck assumes
//! the encoder is scaled in them), `#` comment lines at the top, no blank line (the loader
//! rejects a line that is not two numbers, a comment only when `#` is its first character).
//!
//! Sign: ECMC 10.0.0 and later subtract the table's value, interpolated at the uncorrected
//! encoder position, from the encoder's actual position (`actPos -= scale · LUT(actPos)`,
//! scale 1 by default; `ecmcEncoder.cpp`, and `ecmcLookupTable.h`: the table "represents
//! the error that should be subtracted"). Measured without the table, the encoder reads P
//! where the laser reads P + e: the encoder reads e too little, so the value to subtract is
//! −e, the correction (−x̄) itself. ECMC 9.6.x and earlier *add* the value: the sign was
//! changed by commit 6c5b500 (2025-01-27, "Change sign of encoder lookup-table"; RELEASE.md
//! of 10.0.0: "The loaded table will be subtracted instead of added"), and the scale
//! command `Cfg.SetAxisEncLookupTableScale` came only in 10.0.9, so on 9.6.x the file
//! itself must hold +x̄: the controller `ecmc-9.6` writes it so. Check once on the machine
//! (the actual position with the table enabled and disabled at one point).
//!
//! Positions increasing (ecmc checks non-decreasing; axcheck writes them strictly
//! increasing), any spacing; `PREC=` lines only set how ecmc echoes the table, and
//! axcheck writes none. At least 3 rows (fewer are refused here, as ecmc refuses them),
//! no upper limit (a `std::vector`).
//! Linear interpolation between rows; beyond the first and last row their values hold. The
//! correction acts on the feedback, in both directions: one table per axis, the mean of ↑
//! and ↓, and no backlash (the reversal stays, as the prediction shows). Applied only once
//! the encoder is homed (an absolute encoder at start-up). The values are the corrections
//! as measured; `--reference` shifts them to 0 at a reference point (the homing position,
//! say: homing is then unchanged), a constant no ISO 230-2 parameter sees. A rotary axis
//! measured over a whole revolution gets a table of 0…360° (0° and 360° one position, one
//! value), looked up at the position modulo 360 with
//! `Cfg.SetAxisEncLookupTableRange(axis,360)`, which the file says in a comment.
//!
//! Loaded in the IOC start-up script after the axis's encoder is configured:
//! `ecmcConfigOrDie "Cfg.LoadAxisEncLookupTable(${ECMC_AXIS_NO},FILE)"` and
//! `ecmcConfigOrDie "Cfg.SetAxisEncLookupTableEnable(${ECMC_AXIS_NO},1)"`. Sources (read in
//! the code): epics-modules/ecmc `devEcmcSup/misc/ecmcLookupTable.h` (syntax, `PREC=`,
//! ≥ 3 rows, sorting, interpolation, end values); anderssandstrom/ecmc
//! `devEcmcSup/motion/ecmcEncoder.cpp` `readHwActPos` (subtraction, homed, range);
//! `devEcmcSup/motion/ecmcMotion.h` (the `Cfg.` commands); ecmccfg documents the YAML keys
//! `encoder.lookuptable.filename` ("Value will be subtracted from encoder value"),
//! `.enable`, `.scale`, `.range`. Notes go in the `#` comments at the top.
//!
//! Read back as `ecmcLookupTable.h` reads (epics-modules/ecmc 11.0): `#` in the first
//! column starts a comment, an empty line is skipped, `PREC=n` only sets how ecmc echoes
//! the table; each other line is two numbers (`istream >> double`), separated by blanks or,
//! since 10.0.0, commas, anything after the second ignored. Refused as ecmc refuses them: a
//! comment that does not start in the first column, a line of blanks only (a blank line of
//! a CRLF file too), a `P` line that is not `PREC=n`, fewer than 3 rows, positions that do
//! not increase strictly (ecmc 11.0.5 refuses equal ones). Refused as ecmc would read them
//! otherwise than they seem: numbers not separated (`1.5.3` is 1.5 and 0.3) and a third
//! number after a comma (`1,5 2,3`, decimal commas, is the row 1, 5). For 9.6.x, blank lines
//! and commas are refused too, as that loader refuses them. A rotary table over exactly 0…360°
//! is read as one revolution (the range is set by its own command).

use super::controller::{Controller, Directions, Format, ReadAs, Refused, Spacing, Unreadable};
use super::reading::{self, Points};
use crate::compensate::table::Table;
use crate::units::{AxisKind, fmt_fixed};

/// An ecmc lookup table for one family of versions: the sign the encoder applies it with.
pub(crate) struct Ecmc {
    name: &'static str,
    /// The versions it is for, as the file's head says.
    versions: &'static str,
    /// +1: the value is subtracted from the encoder (10.0.0 and later), so the file holds
    /// the correction; −1: it is added (9.6.x), so the file holds minus the correction.
    sign: f64,
}

impl Ecmc {
    /// ECMC 10.0.0 and later: the table subtracted.
    pub const CURRENT: Ecmc = Ecmc {
        name: "ecmc",
        versions: "ECMC 10.0.0 and later",
        sign: 1.0,
    };
    /// ECMC 9.6.x and earlier: the table added, and no scale command to invert it.
    pub const V9_6: Ecmc = Ecmc {
        name: "ecmc-9.6",
        versions: "ECMC 9.6.x and earlier",
        sign: -1.0,
    };
}

/// Fewest rows ecmc accepts (`ERROR_LOOKUP_TABLE_ERROR` otherwise).
const MIN_ROWS: usize = 3;

impl Controller for Ecmc {
    fn name(&self) -> &'static str {
        self.name
    }

    fn extension(&self) -> &'static str {
        "lut"
    }

    /// Any increasing points, no upper limit, one feedback table without backlash, modulo
    /// tables; printed to 0.1 nm or 1e-7°.
    fn format(&self) -> Format {
        Format {
            spacing: Spacing::Free,
            max_points: usize::MAX,
            directions: Directions::Unidirectional { backlash: false },
            modulo: true,
            quantum_um: 1e-4,
            quantum_arcsec: 3.6e-4,
        }
    }

    fn read(&self, text: &str, reading: ReadAs) -> Result<Table, Unreadable> {
        let mut points = Points::empty(reading.kind);
        let per_unit = reading.kind.deviation_units_per_position_unit();
        let mut lines = Vec::new();
        // The piece after the last line end is no line (an empty one there is the file's end).
        let lines_in_file = text.split('\n').count();
        for (k, raw) in text.split('\n').enumerate() {
            let line = k + 1;
            let Some([position, value]) = self.row(raw, line, line == lines_in_file)? else {
                continue;
            };
            points.positions.push(position);
            let correction = self.sign * value * per_unit;
            points.up.push(correction);
            points.down.push(correction);
            lines.push(line);
        }
        if points.positions.len() < MIN_ROWS {
            return Err(Unreadable::file(format!(
                "{} rows: ecmc loads a lookup table of at least {MIN_ROWS}",
                points.positions.len()
            )));
        }
        reading::increasing(&points.positions, &lines, "position")?;
        let modulo = reading::one_revolution(reading.kind, &points.positions);
        Ok(points.table(None, modulo, Default::default(), self.interpolation()))
    }

    fn write(&self, table: &Table, notes: &[String]) -> Result<String, Refused> {
        super::finite(table)?;
        let p = &table.positions;
        if p.len() < MIN_ROWS {
            return Err(too_few(table));
        }
        super::printed_increasing(p, 6)?;
        let per_unit = table.kind.deviation_units_per_position_unit();
        let mut out = self.header(table);
        out.push_str(&super::commented("# ", notes));
        for (position, correction) in p.iter().zip(table.mean()) {
            out.push_str(&format!(
                "{} {}\n",
                fmt_fixed(*position, 6),
                fmt_fixed(self.sign * correction / per_unit, 7)
            ));
        }
        Ok(out)
    }
}

/// Fewer rows than ecmc loads, with the interval that gives three.
fn too_few(table: &Table) -> Refused {
    let p = &table.positions;
    let unit = table.kind.position_unit();
    let hint = match (p.first(), p.last()) {
        (Some(first), Some(last)) if last > first => format!(
            ": choose an interval of {} {unit} or less (--interval, or compensation: {{interval}} in a campaign)",
            fmt_fixed(((last - first) / 2.0 * 1000.0).floor() / 1000.0, 3)
        ),
        _ => String::new(),
    };
    Refused::Grid(format!(
        "{} points, but an ecmc lookup table needs at least {MIN_ROWS}{hint}",
        p.len()
    ))
}

impl Ecmc {
    /// One line of a table as ecmc reads it: a row, or `None` for a comment, `PREC=` or an
    /// empty line (`last`: the file's end after its final line end).
    fn row(&self, raw: &str, line: usize, last: bool) -> Result<Option<[f64; 2]>, Unreadable> {
        let current = self.sign > 0.0;
        if raw.is_empty() {
            return if current || last {
                Ok(None)
            } else {
                Err(Unreadable::at(
                    line,
                    format!("an empty line: {} refuses it", self.versions),
                ))
            };
        }
        if raw.starts_with('#') {
            return Ok(None);
        }
        let t = raw.trim();
        if t.is_empty() {
            return Err(Unreadable::at(
                line,
                "a line of blanks only (or a `\\r`): ecmc refuses it; leave it empty or remove it",
            ));
        }
        if t.starts_with('#') {
            return Err(Unreadable::at(
                line,
                "a comment must start in the first column: ecmc refuses `#` after a blank",
            ));
        }
        if raw.starts_with('P') {
            return prec(raw, line).map(|_| None);
        }
        if raw.contains(',') && !current {
            return Err(Unreadable::at(
                line,
                format!(
                    "a comma: {} separates numbers by blanks only",
                    self.versions
                ),
            ));
        }
        two_numbers(&raw.replace(',', " "), raw.contains(','), line).map(Some)
    }

    /// The `#` comments: versions, columns, units, sign, backlash, modulo and the lines
    /// that load it.
    fn header(&self, table: &Table) -> String {
        let unit = table.kind.position_unit();
        let modulo = match (table.kind, table.modulo_deg) {
            (AxisKind::Rotary, Some(revolution)) => format!(
                "# One revolution: looked up at the position modulo {0}, with\n\
                 # ecmcConfigOrDie \"Cfg.SetAxisEncLookupTableRange(${{ECMC_AXIS_NO}},{0})\"\n",
                fmt_fixed(revolution, 0)
            ),
            _ => String::new(),
        };
        let (column, applied) = if self.sign > 0.0 {
            ("correction", "subtracted from")
        } else {
            ("error", "added to")
        };
        let value = if self.sign > 0.0 {
            "correction = -(actual - target)"
        } else {
            "error = actual - target"
        };
        format!(
            "# ecmc encoder correction table written by axcheck for {}: encoder position, {column} ({unit})\n\
             # The value is {applied} the encoder position: {value},\n\
             # the mean of both directions (no backlash: the reversal stays).\n\
             {modulo}\
             # Load it (FILE: the path of this file) after the axis's encoder is configured:\n\
             # ecmcConfigOrDie \"Cfg.LoadAxisEncLookupTable(${{ECMC_AXIS_NO}},FILE)\"\n\
             # ecmcConfigOrDie \"Cfg.SetAxisEncLookupTableEnable(${{ECMC_AXIS_NO}},1)\"\n",
            self.versions
        )
    }
}

/// `PREC=n` (`sscanf("PREC=%d")`); another line starting with `P` is refused.
fn prec(raw: &str, line: usize) -> Result<(), Unreadable> {
    let digits = raw
        .strip_prefix("PREC=")
        .map(|r| r.trim_start())
        .map(|r| r.strip_prefix(['+', '-']).unwrap_or(r))
        .filter(|r| r.starts_with(|c: char| c.is_ascii_digit()));
    match digits {
        Some(_) => Ok(()),
        None => Err(Unreadable::at(
            line,
            format!("`{}` is not `PREC=n`: ecmc refuses it", raw.trim()),
        )),
    }
}

/// Position and value, as `istream >> double` reads them twice; refused when they are not
/// two numbers, when they run together, or when a third follows a comma (decimal commas).
fn two_numbers(line_text: &str, had_comma: bool, line: usize) -> Result<[f64; 2], Unreadable> {
    let mut rest = line_text;
    let mut out = [0.0; 2];
    for (k, field) in ["position", "value"].into_iter().enumerate() {
        let t = rest.trim_start();
        if k > 0 && t.len() == rest.len() {
            return Err(Unreadable::field(
                line,
                field,
                format!(
                    "`{}`: the numbers run together; ecmc would split them where a number ends",
                    line_text.trim()
                ),
            ));
        }
        let n = reading::float_prefix(t);
        if n == 0 {
            return Err(Unreadable::field(
                line,
                field,
                format!(
                    "expected a number, got `{}`",
                    t.split_whitespace().next().unwrap_or("")
                ),
            ));
        }
        out[k] = reading::number(&t[..n], line, field)?;
        rest = &t[n..];
    }
    let after = rest.trim_start();
    if had_comma && after.starts_with(|c: char| c.is_ascii_digit() || matches!(c, '+' | '-' | '.'))
    {
        return Err(Unreadable::at(
            line,
            format!(
                "`{}`: three numbers once commas are separators; decimal commas? ecmc would read the row {}, {}",
                line_text.trim(),
                out[0],
                out[1]
            ),
        ));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compensate::testing::{axis, irregular_linear, whole_turn_rotary};
    use crate::compensate::{Settings, held_table};

    /// Targets 0, 30, 70, 100 mm (uneven, kept as they are): x̄↑ = 0, 3, −1, 2 µm, x̄↓ =
    /// x̄↑ + 2 µm; mean x̄ = 1, 4, 0, 3 µm. The LUT holds the correction −x̄ in mm: −0.001,
    /// −0.004, 0, −0.003 (the reversal of −2 µm is not in it).
    #[test]
    fn golden_linear_on_the_measured_targets() {
        let data = irregular_linear();
        let table = held_table(&Ecmc::CURRENT, &data, &Settings::default()).unwrap();
        assert_eq!(table.up, table.down);
        assert_eq!(
            Ecmc::CURRENT.write(&table, &[]).unwrap(),
            include_str!("../../../../../tests/data/compensation/ecmc-linear.lut")
        );
    }

    /// Targets 0, 90, 180, 270, 360°: x̄↑ = 0, 3.6, −7.2, 1.8, 3.6″, x̄↓ = x̄↑ + 3.6″. One
    /// revolution: 0° and 360° hold (0 + 3.6)/2 = 1.8″ ↑, 5.4″ ↓; mean x̄ = 3.6, 5.4, −5.4,
    /// 3.6, 3.6″; the LUT holds −x̄ in degrees: −0.001, −0.0015, 0.0015, −0.001, −0.001.
    #[test]
    fn golden_rotary_modulo() {
        let data = whole_turn_rotary();
        let table = held_table(&Ecmc::CURRENT, &data, &Settings::default()).unwrap();
        assert_eq!(table.modulo_deg, Some(360.0));
        assert_eq!(
            Ecmc::CURRENT.write(&table, &[]).unwrap(),
            include_str!("../../../../../tests/data/compensation/ecmc-rotary-modulo.lut")
        );
    }

    #[test]
    fn refuses_fewer_than_three_rows() {
        let data = axis(AxisKind::Linear, &[0.0, 100.0], 2, |_, _| 1.0);
        let table = held_table(&Ecmc::CURRENT, &data, &Settings::default()).unwrap();
        assert_eq!(
            Ecmc::CURRENT.write(&table, &[]).unwrap_err(),
            Refused::Grid(
                "2 points, but an ecmc lookup table needs at least 3: choose an interval of 50.000 mm or less (--interval, or compensation: {interval} in a campaign)"
                    .into()
            )
        );
    }
}
