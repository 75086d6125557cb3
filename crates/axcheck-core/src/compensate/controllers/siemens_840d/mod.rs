//! `siemens-840d`: a SINUMERIK 840D / 840D sl leadscrew and measuring-system error
//! compensation (LEC / MSEC) table, the INI part program `%_N_AX_EEC_INI`: one
//! `$AA_ENC_COMP[0,N,X1]=value` per point N, then `$AA_ENC_COMP_STEP`, `_MIN`, `_MAX`,
//! `_IS_MODULO` and `M17`, in mm (degrees on a rotary axis; inches if MD10240
//! SCALING_SYSTEM_IS_METRIC = 0, which axcheck does not write). The first index is the
//! measuring system: 0 for the first encoder, 1 for an axis closed on a direct (second)
//! measuring system (`--measuring-system 1`, campaign `compensation: {measuring_system: 1}`,
//! or the active table's own). The machine axis is the table's `axis` (`--axis X1`,
//! campaign `compensation: {axis: X1}`); without it the file says `<AXIS?>` and a comment
//! (and the console) asks the user to replace it by the machine axis (X1, Y1, …). Not `AX1`,
//! as before: K3 writes the index `<AXi>`, and `AX1` is the NC's name of machine axis 1
//! (\[recalled\]: machine data archives address axes so; in any case a valid identifier), so
//! an unedited file would load onto the first machine axis. An axis identifier is
//! letters, digits and underscores, the first two letters or underscores, at most 8
//! characters (SINUMERIK 840D Programming Manual Fundamentals, 10.2004, 6FC5298-7AB00-0BP1,
//! §2.2 "Language elements", p. 2-14; SINUMERIK ONE Programming Manual NC programming,
//! 12/2019, 6FC5398-2EP40-0BA0, "Names", p. 383): `<`, `?` and `>` are none of them, and
//! the NC cannot run the line (the alarm it gives was not confirmed). Notes go in the `;`
//! comments.
//!
//! Sign: the NC modifies the actual position value by the table value, and "a positive
//! compensation value causes the corresponding machine axis to move in the negative
//! direction" (K3). The axis must move by the correction c = −x̄ to reach the target, so the
//! value is −c = +x̄ (the mean deviation, error sign), in mm or degrees.
//!
//! Points are equidistant: point N at `MIN + N·STEP`, `MAX = MIN + k·STEP`; linear
//! interpolation between points; below MIN and above MAX the first and last values stay
//! active (not on a modulo table). One table for both directions (direction-dependent LEC
//! exists only through CEC tables): the file holds the mean of ↑ and ↓, and a `;` comment
//! states the mean reversal for MD32450 `$MA_BACKLASH`, positive when the encoder leads
//! the machine part (the normal case, K3): then ↑ approaches stop short and ↓ ones
//! overshoot, so MD32450 = x̄↓ − x̄↑ (inferred from that wording, not confirmed). The NC
//! adds it on one side of a reversal, the table splits it ± half about the mean: a
//! constant apart, which no ISO 230-2 parameter sees. Siemens advises a value of 0 at the
//! reference point (no jump when LEC becomes active after referencing): that is what
//! `--reference` does, and the file says which value it has there. A rotary axis measured
//! over a whole revolution gets a modulo table: `IS_MODULO = 1`, MIN 0, MAX 360, the value at
//! 360° (equal to the one at 0°) written explicitly as Siemens requires.
//!
//! Loading: the table can be written only while MD32700 `$MA_ENC_COMP_ENABLE[0] = 0`: run
//! the INI (copy it into the NC and start it as a part program), then set MD32700 = 1 (which
//! write-protects the table) and POWER ON / NCK reset; the compensation acts once the axis is
//! referenced. Sources: SINUMERIK 840D sl Function Manual Extended Functions, K3
//! Compensation, "Interpolatory compensation / Measuring system error compensation"
//! (6FC5397-1BP40-3BA1, 03/2013, pp. 238–242: sign, table variables, example file,
//! end values, MD38000) and SINUMERIK 808D Function Manual 01/2017 pp. 106–109 (modulo rules,
//! loading with MD32700, at most 200 points on the 808D); SINUMERIK 808D ADVANCED Parameter
//! Manual 08/2013 (6FC5397-8EP40-0BA0), MD32450 BACKLASH (sign).
//!
//! Limits: points are limited by MD38000 `$MA_MM_ENC_COMP_MAX_POINTS` (0 ≤ N ≤ MD38000 − 1),
//! which the machine builder sets per axis; the file states how many it needs. axcheck
//! refuses more than 5000, the upper limit of MD38000 as recalled for the 840D: NOT
//! confirmed (the 840D sl may allow more; the 808D holds 200). Also unconfirmed: the
//! resolution the NC keeps of a value (its internal resolution, MD10200 / MD10210, is not
//! known to the file) and the exact way each HMI version loads the INI file.

mod read;

use super::controller::{Controller, Directions, Format, ReadAs, Refused, Spacing, Unreadable};
use crate::compensate::table::Table;
use crate::units::{AxisKind, fmt_fixed, fmt_position};

pub(crate) struct Siemens840d;

/// Most points axcheck writes: MD38000's upper limit as recalled (not confirmed).
const MAX_POINTS: usize = 5000;

/// Decimals printed: 1 nm or 1e-6°.
const DECIMALS: usize = 6;

impl Controller for Siemens840d {
    fn name(&self) -> &'static str {
        "siemens-840d"
    }

    fn extension(&self) -> &'static str {
        "ini"
    }

    /// Equidistant points, one table per axis plus MD32450 backlash, modulo tables, values
    /// printed to 1 nm or 1e-6° (0.0036″).
    fn format(&self) -> Format {
        Format {
            spacing: Spacing::Equidistant,
            max_points: MAX_POINTS,
            directions: Directions::Unidirectional { backlash: true },
            modulo: true,
            quantum_um: 1e-3,
            quantum_arcsec: 3.6e-3,
        }
    }

    /// The mean correction and the reversal each rounded to the printed unit, so that the
    /// file's values and its MD32450 figure are exactly the table the prediction applies.
    fn hold(&self, table: Table) -> Result<Table, Refused> {
        let quantum = self.format().quantum(table.kind);
        let round = |v: f64| (v / quantum).round() * quantum;
        let half = round(table.reversal_correction()) / 2.0;
        let mean: Vec<f64> = table.mean().into_iter().map(round).collect();
        Ok(Table {
            up: mean.iter().map(|m| m - half).collect(),
            down: mean.iter().map(|m| m + half).collect(),
            ..table
        })
    }

    /// The table as the NC holds it: the mean correction in both directions (MD32450 is
    /// machine data, not in the file: the active backlash is stated beside the file).
    fn read(&self, text: &str, reading: ReadAs) -> Result<Table, Unreadable> {
        read::read(text, reading)
    }

    fn write(&self, table: &Table, notes: &[String]) -> Result<String, Refused> {
        super::finite(table)?;
        let step = step(table)?;
        let n = table.positions.len();
        let (first, last) = (table.positions[0], table.positions[n - 1]);
        let per_unit = table.kind.deviation_units_per_position_unit();
        let unit = table.kind.position_unit();
        let value = |correction: f64| fmt_fixed(-correction / per_unit, DECIMALS);
        let mean = table.mean();
        let axis = super::axis_name(table)?;
        let e = measuring_system(table);
        let mut out = String::from("%_N_AX_EEC_INI\nCHANDATA(1)\n");
        out.push_str(&header(table, &mean, per_unit));
        out.push_str(&super::commented("; ", notes));
        for (k, c) in mean.iter().enumerate() {
            out.push_str(&format!("$AA_ENC_COMP[{e},{k},{axis}]={}\n", value(*c)));
        }
        let position = |p: f64| fmt_fixed(p, DECIMALS);
        out.push_str(&format!(
            "$AA_ENC_COMP_STEP[{e},{axis}]={} ; {unit}\n",
            position(step)
        ));
        out.push_str(&format!(
            "$AA_ENC_COMP_MIN[{e},{axis}]={}\n",
            position(first)
        ));
        out.push_str(&format!(
            "$AA_ENC_COMP_MAX[{e},{axis}]={}\n",
            position(last)
        ));
        let modulo = u8::from(table.modulo_deg.is_some());
        out.push_str(&format!(
            "$AA_ENC_COMP_IS_MODULO[{e},{axis}]={modulo}\nM17\n"
        ));
        Ok(out)
    }

    fn unnamed_axis(&self, table: &Table) -> Option<String> {
        table.place.axis.is_none().then(|| {
            format!(
                "the file names no machine axis: replace {} in every line by the machine axis name (X1, Y1, ...; the NC cannot run the file as written), or give it with --axis (compensation: {{axis}} in a campaign)",
                super::AXIS_PLACEHOLDER
            )
        })
    }
}

/// The measuring system's index: 0 (the first encoder) unless the table's place says.
fn measuring_system(table: &Table) -> u8 {
    table.place.measuring_system.unwrap_or(0)
}

/// The interval of an equidistant table of at least two points, printable exactly (the NC
/// computes the points from MIN and STEP), within MD38000's limit.
fn step(table: &Table) -> Result<f64, Refused> {
    let p = &table.positions;
    if p.len() < 2 {
        return Err(Refused::Grid(
            "an LEC table needs at least 2 points (MIN, MAX and STEP)".into(),
        ));
    }
    if p.len() > MAX_POINTS {
        return Err(Refused::Grid(format!(
            "{} points, but MD38000 allows at most {MAX_POINTS}",
            p.len()
        )));
    }
    let step = p[1] - p[0];
    let tolerance = 1e-9 * step.abs().max(1.0);
    if step <= 0.0 || p.windows(2).any(|w| (w[1] - w[0] - step).abs() > tolerance) {
        return Err(Refused::Grid(
            "LEC points must be equidistant and increasing (MIN + N·STEP)".into(),
        ));
    }
    let scale = 10f64.powi(DECIMALS as i32);
    if ((step * scale).round() / scale - step).abs() > tolerance {
        let unit = table.kind.position_unit();
        return Err(Refused::Grid(format!(
            "the interval {step} {unit} is not a whole number of 0.000001 {unit}: the NC places the points at MIN + N·STEP"
        )));
    }
    Ok(step)
}

/// The `;` comments: what the file is, the axis to name, units and sign, the reference
/// point, MD38000 and the MD32450 backlash.
fn header(table: &Table, mean: &[f64], per_unit: f64) -> String {
    let unit = table.kind.position_unit();
    let axis = match table.kind {
        AxisKind::Linear => "linear axis",
        AxisKind::Rotary if table.modulo_deg.is_some() => "rotary axis, one revolution (modulo)",
        AxisKind::Rotary => "rotary axis",
    };
    let backlash = -table.reversal_correction() / per_unit;
    let e = measuring_system(table);
    format!(
        "; LEC table written by axcheck, {axis}, measuring system {} ([{e},...])\n\
         {}\
         ; Values in {unit}: the mean deviation x-bar (actual - target) of both directions;\n\
         ; the NC subtracts them (a positive value moves the axis negative).\n\
         {}\
         ; Needs MD38000 $MA_MM_ENC_COMP_MAX_POINTS[{e}] >= {}; load with MD32700 $MA_ENC_COMP_ENABLE[{e}]=0, then set it to 1.\n\
         ; MD32450 $MA_BACKLASH[{e}]={} ; mean reversal, {unit} (positive: the encoder leads the machine part)\n",
        e + 1,
        match table.place.axis {
            None => format!(
                "; Replace {} by the machine axis name (X1, Y1, ...) in every line before loading: the NC cannot run it as written.\n",
                super::AXIS_PLACEHOLDER
            ),
            Some(_) => String::new(),
        },
        reference(table, mean, per_unit),
        table.positions.len(),
        fmt_fixed(backlash, DECIMALS),
    )
}

/// The value at the reference point, which Siemens advises to be 0 (no jump when LEC
/// becomes active after referencing).
fn reference(table: &Table, mean: &[f64], per_unit: f64) -> String {
    let unit = table.kind.position_unit();
    let at = fmt_position(table.reference);
    let value = fmt_fixed(
        -crate::compensate::linear(&table.positions, mean, table.reference) / per_unit,
        DECIMALS,
    );
    if value == fmt_fixed(0.0, DECIMALS) {
        format!("; Value 0 at the reference point {at} {unit}, as Siemens advises.\n")
    } else {
        format!(
            "; Value {value} {unit} at {at} {unit}: Siemens advises 0 at the reference point (--reference, or compensation: {{reference}} in a campaign).\n"
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compensate::testing::{irregular_linear, whole_turn_rotary};
    use crate::compensate::{Settings, held_table};

    /// `--interval 25 --reference 50`: the grid 0, 25, 50, 75, 100 mm. x̄↑ interpolated
    /// there: 0; 3·25/30 = 2.5; 3 − 4·20/40 = 1; −1 + 3·5/30 = −0.5; 2. x̄↓ = x̄↑ + 2, so the
    /// mean x̄ = 1, 3.5, 2, 0.5, 3 µm. Zero at the reference 50 mm: minus 2 µm gives −1, 1.5,
    /// 0, −1.5, 1 µm; Siemens stores +x̄ (−correction): −0.001, 0.0015, 0, −0.0015, 0.001 mm.
    /// Reversal: c↓ − c↑ = x̄↑ − x̄↓ = −2 µm, so MD32450 = x̄↓ − x̄↑ = +0.002 mm.
    #[test]
    fn golden_linear_resampled_with_reference() {
        let settings = Settings {
            interval: Some(25.0),
            reference: Some(50.0),
            ..Default::default()
        };
        let table = held_table(&Siemens840d, &irregular_linear(), &settings).unwrap();
        assert_eq!(table.positions, [0.0, 25.0, 50.0, 75.0, 100.0]);
        assert_eq!(
            Siemens840d.write(&table, &[]).unwrap(),
            include_str!("../../../../../../tests/data/compensation/siemens-840d-linear.ini")
        );
    }

    /// Targets 0, 90, 180, 270, 360°: x̄↑ = 0, 3.6, −7.2, 1.8, 3.6″ and x̄↓ = x̄↑ + 3.6″.
    /// A whole revolution: a modulo table every 90° (the mean spacing), 0° and 360° one
    /// position holding (0 + 3.6)/2 = 1.8″ ↑ and 5.4″ ↓. Mean x̄ = 3.6, 5.4, −5.4, 3.6, 3.6″
    /// = 0.001, 0.0015, −0.0015, 0.001, 0.001°; MD32450 = x̄↓ − x̄↑ = 3.6″ = 0.001°. No
    /// --reference: the value at 0° is 0.001°, and the file says so.
    #[test]
    fn golden_rotary_modulo() {
        let data = whole_turn_rotary();
        let table = held_table(&Siemens840d, &data, &Settings::default()).unwrap();
        assert_eq!(table.modulo_deg, Some(360.0));
        assert_eq!(
            Siemens840d.write(&table, &[]).unwrap(),
            include_str!(
                "../../../../../../tests/data/compensation/siemens-840d-rotary-modulo.ini"
            )
        );
    }

    #[test]
    fn refuses_too_many_points_and_uneven_ones() {
        let data = crate::compensate::testing::straight(0.0, 100.0, 2);
        let settings = Settings {
            interval: Some(0.01),
            reference: None,
            ..Default::default()
        };
        let err = held_table(&Siemens840d, &data, &settings).unwrap_err();
        assert_eq!(
            err.to_string(),
            "10001 points, but the table holds at most 5000; choose an interval of 0.021 mm or more (--interval, or compensation: {interval} in a campaign)"
        );
        let uneven = Table {
            kind: AxisKind::Linear,
            positions: vec![0.0, 10.0, 25.0],
            up: vec![0.0; 3],
            down: vec![0.0; 3],
            reference: 0.0,
            modulo_deg: None,
            place: Default::default(),
            interpolation: Default::default(),
        };
        assert!(matches!(
            Siemens840d.write(&uneven, &[]),
            Err(Refused::Grid(_))
        ));
    }
}
