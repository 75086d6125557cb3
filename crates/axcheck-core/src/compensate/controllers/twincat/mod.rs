//! `twincat`: a leadscrew error compensation list of the Beckhoff TwinCAT CNC (TF5200,
//! the ISG kernel), `kw.ssfk.*`, one ASCII list per axis (`achskw1.lis`): a bilateral
//! table (`kw.ssfk.bilateral 1`, a `.pos` value for motion in the positive direction and
//! a `.neg` one for the negative) on equidistant points `kw_startpos + i·interval`.
//!
//! Units (`kw.ssfk.unit 1`, metric): positions, interval and values are integers in
//! 0.1 µm on a linear axis and 0.0001° (0.36″) on a rotary one; the table as held is the
//! correction rounded to that step, at positions on that step.
//!
//! Sign: the values are "absolute position errors" (Beckhoff's table page), and the
//! worked example computes them as Δs = s_ist − s_soll: programmed 19866.7 µm, reached
//! 19856.5 µm moving positively, so `pos` = −102 (×0.1 µm). That is the deviation
//! e = actual − target of ISO 230-2, which the CNC takes off the position setpoint (and
//! off the displayed actual value again); the correction axcheck holds is c = −e, so the
//! list holds −c: −correction↑ in `.pos`, −correction↓ in `.neg`. (The example lists the
//! setpoint as −198667 but the table prints +19866.7 µm; Δs taken as printed.)
//!
//! Limits: `kw_nr_max` ≤ 1500 entries up to CNC build V3.1.3079.06; since then
//! `kw.ssfk.max_points` (P-COMP-00059, default 1500) sets it, so axcheck keeps 1500 (its
//! page says `kw_nr_max` "must be smaller than" it: 1500 itself is unconfirmed). `.pos` and
//! `.neg` are SGN32 (SGN16, ±3.2767 mm, in the old TwinCAT 2 TX1270 pages); `interval` and
//! `kw_startpos` SGN32 before V3.1.3132 (REAL64 since), so positions must fit SGN32 too.
//! The interval must be a whole number of steps (the points are computed from it).
//!
//! Interpolation: linear between points; outside the table: not stated (axcheck's grid
//! covers the measured travel). Compensation acts once the axis is homed (`LSEC::active`).
//! Reference point: none in the list; the values are absolute errors, so a `--reference`
//! shift is a constant offset. Backlash: a bilateral table holds the reversal, and Beckhoff
//! recommends it instead of the backlash parameter (P-AXIS-00103 `getriebe[i].lose`, leave
//! it 0); the switch-over can be spread over `lr_param.n_backlash_cyc` cycles (P-AXIS-00243).
//! Modulo: `kw.ssfk.modulo 1` wraps the table with the axis; the first and last entries
//! are the same position (0° and 360°), with one value.
//!
//! Loading: the axis parameter list activates it (`lr_param.ssfk 1`, P-AXIS-00175), the
//! start-up list \[STUP\] names it (`zahl_kw`, `achs_kw_log_ax_nr[i]`, `achs_kw[i]`; TwinCAT
//! XAE writes these when the list is configured there). `kopf.achs_nr` must be the axis's
//! logical number (a mismatch aborts the list, error 110229): `--axis 2` (campaign
//! `compensation: {axis: 2}`) gives it, else the active list's; without either the list
//! says 0, which P-COMP-00001 does not allow ("0 < achs_nr"; ISG kernel documentation,
//! "Logical axis number (P-COMP-00001)", isg-stuttgart.de/fileadmin/kernel/kernel-html/
//! en-GB/113373067.html), and a note asks for the number. Earlier lists said 1, a
//! valid number: an unedited list was checked against axis 1. An axis name (`X`) is
//! refused: the list names its axis by number only. Comment lines start with `# `; `End`
//! closes the list as in Beckhoff's plane-compensation example (the SSFK example shows
//! none).
//!
//! Sources (Beckhoff Infosys, TF5200 Axis compensation): "Leadscrew error compensation"
//! infosys.beckhoff.com/content/1033/tf5200_axis_compensation/308683659.html; parameters
//! P-COMP-00017…00025 and 00059 under content/1033/tf5200_axis_compensation_parameters/
//! (113420683, 113422219, 113423755, 113425291, 113428363, 113432971, 113434507,
//! 113436043, 654582667 .html); example list …/113439115.html; \[STUP\] lines and the
//! backlash advice …/tf5200_axis_compensation/308682123.html; P-AXIS-00175/00243
//! …/308693899.html; modulo entries …/tccncaxiscompensation/15274022795.html; comments
//! …/tccncaxisparameter/15280429451.html; error 110229 …/tf5200_diagnosis/262657163.html.
//! Unconfirmed: the behaviour outside the table, whether `End` is required, whether 1500
//! entries are allowed or 1499, whether the list loads without `kopf.log_achs_name`.

mod limits;
mod read;

use super::controller::{Controller, Directions, Format, ReadAs, Refused, Spacing, Unreadable};
use crate::compensate::table::Table;
use crate::units::{AxisKind, fmt_fixed};
use limits::*;

pub(crate) struct TwinCat;

/// The list as the CNC reads it: integers in 0.1 µm or 0.0001°.
#[derive(Debug, PartialEq)]
struct List {
    start: i64,
    interval: i64,
    pos: Vec<i64>,
    neg: Vec<i64>,
    modulo: bool,
}

impl List {
    /// The list of `table`, or why the CNC cannot hold it.
    fn of(table: &Table) -> Result<List, Refused> {
        let (start, interval) = equidistant_steps(&table.positions)?;
        let last = start + interval * (table.positions.len() as i64 - 1);
        for (what, steps) in [("start", start), ("end", last), ("interval", interval)] {
            if !fits_sgn32(steps) {
                return Err(Refused::Range(format!(
                    "the table {what} {} {} is beyond the list's 32-bit positions",
                    fmt_fixed(steps as f64 / STEPS_PER_POSITION_UNIT, 4),
                    table.kind.position_unit()
                )));
            }
        }
        let step = value_step(table.kind);
        // The list holds the error e = −correction.
        let values = |corrections: &[f64]| -> Result<Vec<i64>, Refused> {
            corrections
                .iter()
                .map(|c| {
                    let v = (-c / step).round() as i64;
                    if fits_sgn32(v) {
                        Ok(v)
                    } else {
                        Err(Refused::Range(format!(
                            "a correction of {} {} is beyond the list's 32-bit values",
                            fmt_fixed(*c, 1),
                            table.kind.deviation_unit()
                        )))
                    }
                })
                .collect()
        };
        Ok(List {
            start,
            interval,
            pos: values(&table.up)?,
            neg: values(&table.down)?,
            modulo: table.modulo_deg.is_some(),
        })
    }

    /// `axis_number`: `None` writes [`NO_AXIS_NUMBER`], which the CNC refuses.
    fn text(&self, kind: AxisKind, axis_number: Option<usize>, notes: &[String]) -> String {
        let unit = match kind {
            AxisKind::Linear => "0.1 um",
            AxisKind::Rotary => "0.0001 deg",
        };
        let mut out = String::new();
        out.push_str("# axcheck: leadscrew error compensation list (TwinCAT CNC, kw.ssfk.*)\n");
        out.push_str(&format!(
            "# positions kw_startpos + i * interval and values in {unit}; values = measured\n"
        ));
        out.push_str("# error actual - nominal (.pos moving +, .neg moving -)\n");
        out.push_str(
            "# kopf.achs_nr: the axis' logical number, as achs_kw_log_ax_nr[i] in [STUP]\n",
        );
        if axis_number.is_none() {
            out.push_str(
                "# Replace 0 in kopf.achs_nr by the axis' logical number before loading: the CNC allows no 0.\n",
            );
        }
        out.push_str(&super::commented("# ", notes));
        let mut line = |key: &str, value: i64| out.push_str(&format!("{key:<28} {value}\n"));
        line(
            "kopf.achs_nr",
            axis_number.map_or(NO_AXIS_NUMBER, |n| n as i64),
        );
        line("kw.ssfk.unit", 1);
        line("kw.ssfk.interval", self.interval);
        line("kw.ssfk.kw_startpos", self.start);
        line("kw.ssfk.kw_nr_max", self.pos.len() as i64);
        line("kw.ssfk.bilateral", 1);
        line("kw.ssfk.modulo", i64::from(self.modulo));
        for (i, (p, n)) in self.pos.iter().zip(&self.neg).enumerate() {
            line(&format!("kw.ssfk.table[{i}].pos"), *p);
            line(&format!("kw.ssfk.table[{i}].neg"), *n);
        }
        out.push_str("End\n");
        out
    }
}

/// `kopf.achs_nr` of a list whose axis was not given: P-COMP-00001 allows no 0.
const NO_AXIS_NUMBER: i64 = 0;

/// The axis's logical number: `--axis` (0 < n < 65535, P-COMP-00001), else the active list's;
/// `None` when neither gives one.
fn axis_number(table: &Table) -> Result<Option<usize>, Refused> {
    match &table.place.axis {
        None => Ok(table.place.number.filter(|&n| n > 0)),
        Some(text) => match text.trim().parse::<u16>() {
            Ok(n) if n > 0 && n < u16::MAX => Ok(Some(usize::from(n))),
            _ => Err(Refused::Grid(format!(
                "the axis `{}`: a TwinCAT list names its axis by the logical axis number (kopf.achs_nr, 1 to 65534), not by name; give that number (--axis 2, or compensation: {{axis: 2}} in a campaign)",
                text.escape_debug()
            ))),
        },
    }
}

fn fits_sgn32(v: i64) -> bool {
    i32::try_from(v).is_ok()
}

/// The start (rounded to a step) and the interval (a whole number of steps) of
/// equidistant `positions`, or why they are not.
fn equidistant_steps(positions: &[f64]) -> Result<(i64, i64), Refused> {
    let n = positions.len();
    if n < 2 {
        return Err(Refused::Grid(
            "a leadscrew table needs two points or more: give --interval".into(),
        ));
    }
    let steps: Vec<f64> = positions
        .iter()
        .map(|p| p * STEPS_PER_POSITION_UNIT)
        .collect();
    let interval = (steps[n - 1] - steps[0]) / (n - 1) as f64;
    if (interval - interval.round()).abs() > STEP_SLACK || interval.round() < 1.0 {
        return Err(Refused::Grid(format!(
            "an interval of {} is not a whole number of the list's steps (0.1 um, 0.0001 deg)",
            fmt_fixed(interval / STEPS_PER_POSITION_UNIT, 6)
        )));
    }
    let off_grid = steps
        .iter()
        .enumerate()
        .any(|(k, s)| (s - steps[0] - k as f64 * interval).abs() > STEP_SLACK * 10.0);
    if off_grid {
        return Err(Refused::Grid(
            "the list needs equidistant points: give --interval".into(),
        ));
    }
    Ok((steps[0].round() as i64, interval.round() as i64))
}

impl Controller for TwinCat {
    fn name(&self) -> &'static str {
        "twincat"
    }

    fn extension(&self) -> &'static str {
        "lis"
    }

    /// Equidistant points, up to 1500, a table per direction, modulo tables, values in
    /// 0.1 µm or 0.0001° (0.36″).
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

    /// The corrections rounded to the value step, the points moved onto the position
    /// step (at most 0.05 µm): what the CNC computes from `kw_startpos` and `interval`.
    fn hold(&self, table: Table) -> Result<Table, Refused> {
        let step = value_step(table.kind);
        let mut table = table.quantised(step);
        let list = List::of(&table)?;
        for (k, p) in table.positions.iter_mut().enumerate() {
            *p = (list.start + k as i64 * list.interval) as f64 / STEPS_PER_POSITION_UNIT;
        }
        table.reference =
            (table.reference * STEPS_PER_POSITION_UNIT).round() / STEPS_PER_POSITION_UNIT;
        Ok(table)
    }

    fn read(&self, text: &str, reading: ReadAs) -> Result<Table, Unreadable> {
        read::read(text, reading)
    }

    fn write(&self, table: &Table, notes: &[String]) -> Result<String, Refused> {
        super::finite(table)?;
        let axis_number = axis_number(table)?;
        Ok(List::of(table)?.text(table.kind, axis_number, notes))
    }

    fn unnamed_axis(&self, table: &Table) -> Option<String> {
        matches!(axis_number(table), Ok(None)).then(|| {
            "the list names no axis: replace 0 in kopf.achs_nr by the axis' logical number (achs_kw_log_ax_nr in [STUP]; the CNC allows no 0), or give it with --axis (compensation: {axis} in a campaign)".to_string()
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compensate::testing::{negative_linear, quarter_turns_rotary};
    use crate::compensate::{Settings, held_table};

    /// A linear axis measured at irregular targets −100, −70, −55, −20, 0 mm, x̄↑ = 0, 3.0,
    /// 1.53, −2.0, 1.0 µm and x̄↓ = x̄↑ + 2.0 µm, written with --interval 25 (points −100,
    /// −75, −50, −25, 0 mm from the first target). Interpolated x̄↑:
    ///   −75: 3.0·25/30 = 2.5;  −50: 1.53 − 3.53·5/35 = 1.025714;
    ///   −25: 1.53 − 3.53·30/35 = −1.495714;  −100: 0;  0: 1.0;
    /// x̄↓ = those + 2: 2.0, 4.5, 3.025714, 0.504286, 3.0. The held correction is −x̄
    /// rounded to 0.1 µm (−1.0257 → −1.0, +1.4957 → +1.5, −0.5043 → −0.5, −3.0257 → −3.0);
    /// the list holds −correction in 0.1 µm: `.pos` 0, 25, 10, −15, 10; `.neg` 20, 45, 30,
    /// 5, 30; interval 25 mm = 250000, start −100 mm = −1000000.
    #[test]
    fn golden_linear_list_resampled_on_an_interval() {
        let data = negative_linear();
        let settings = Settings {
            interval: Some(25.0),
            reference: None,
            ..Default::default()
        };
        let table = held_table(&TwinCat, &data, &settings).unwrap();
        assert_eq!(table.positions, [-100.0, -75.0, -50.0, -25.0, 0.0]);
        assert_eq!(
            TwinCat.write(&table, &[]).unwrap(),
            include_str!("../../../../../../tests/data/compensation/twincat-linear.lis")
        );
    }

    /// A rotary axis measured every 45° over 0…360°, x̄↑ = 1.0, 3.6, 7.3, −1.8, 2.0″ at
    /// 0, 90, 180, 270, 360° (0 at the odd multiples of 45°, which the 90° points skip)
    /// and x̄↓ = x̄↑ − 1.44″, written with --interval 90: a modulo table 0…360°.
    /// 0° and 360° are one position: x̄↑ = (1.0 + 2.0)/2 = 1.5, x̄↓ = 0.06. The held
    /// correction is −x̄ rounded to 0.36″ (0.0001°): −1.5/0.36 = −4.17 → −4 steps,
    /// −3.6 → −10, −7.3/0.36 = −20.28 → −20, +1.8 → +5; ↓: −0.06/0.36 = −0.17 → 0,
    /// −2.16 → −6, −5.86/0.36 = −16.28 → −16, +3.24 → +9. The list holds −correction:
    /// `.pos` 4, 10, 20, −5, 4; `.neg` 0, 6, 16, −9, 0; interval 90° = 900000.
    #[test]
    fn golden_rotary_modulo_list() {
        let data = quarter_turns_rotary();
        let settings = Settings {
            interval: Some(90.0),
            reference: None,
            ..Default::default()
        };
        let table = held_table(&TwinCat, &data, &settings).unwrap();
        assert_eq!(table.modulo_deg, Some(360.0));
        assert_eq!(
            TwinCat.write(&table, &[]).unwrap(),
            include_str!("../../../../../../tests/data/compensation/twincat-rotary-modulo.lis")
        );
    }

    #[test]
    fn refuses_what_the_list_cannot_hold() {
        let data = crate::compensate::testing::straight(0.0, 1.0, MAX_POINTS + 1);
        let err = held_table(&TwinCat, &data, &Default::default()).unwrap_err();
        assert_eq!(
            err.to_string(),
            "1501 points, but the table holds at most 1500; choose an interval of 1.001 mm or more (--interval, or compensation: {interval} in a campaign)"
        );
        // 0.33335 mm is 3333.5 steps of 0.1 µm: the points would drift from the list's.
        let data = crate::compensate::testing::straight(0.0, 1.0, 3);
        let settings = Settings {
            interval: Some(0.33335),
            reference: None,
            ..Default::default()
        };
        let err = held_table(&TwinCat, &data, &settings).unwrap_err();
        assert!(matches!(err, Refused::Grid(_)), "{err}");
        // 300 m of error overflows the 32-bit value (2^31 × 0.1 µm ≈ 214.7 m).
        let table = Table {
            kind: AxisKind::Linear,
            positions: vec![0.0, 10.0],
            up: vec![0.0, -3e8],
            down: vec![0.0, 0.0],
            reference: 0.0,
            modulo_deg: None,
            place: Default::default(),
            interpolation: Default::default(),
        };
        assert!(matches!(TwinCat.write(&table, &[]), Err(Refused::Range(_))));
        // Irregular points cannot be written as start and interval.
        let table = Table {
            positions: vec![0.0, 10.0, 25.0],
            up: vec![0.0; 3],
            down: vec![0.0; 3],
            ..table
        };
        assert!(matches!(TwinCat.write(&table, &[]), Err(Refused::Grid(_))));
    }
}
