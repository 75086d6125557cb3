//! `ecmc`: an encoder correction lookup table (LUT) of the EPICS EtherCAT motion
//! controller ecmc (ESS / PSI): one line `position correction` per point, separated by one
//! space, in the axis's engineering units (mm, or degrees on a rotary axis: axcheck assumes
//! the encoder is scaled in them), `#` comment lines at the top, no blank line (the loader
//! rejects a line that is not two numbers, a comment only when `#` is its first character).
//!
//! Sign: ecmc subtracts the table's value, interpolated at the uncorrected encoder position,
//! from the encoder's actual position (`actPos -= scale · LUT(actPos)`, scale 1 by
//! default). Measured without the table, the encoder reads P where the laser reads
//! P + e: the encoder reads e too little, so the value to subtract is −e, the correction
//! (−x̄) itself. CAUTION: the loader's own comment calls the value "the error that should be
//! added"; the code subtracts it. `Cfg.SetAxisEncLookupTableScale(axis,-1.0)` inverts the
//! sign should a version differ: check the actual position with the table enabled and
//! disabled at one point.
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
//! `devEcmcSup/motion/ecmcMotion.h` (the `Cfg.` commands). Not confirmed: the sign on other
//! ecmc versions, and keys for the table in ecmccfg's YAML axis configuration.

use super::{Controller, Directions, Format, Refused, Spacing};
use crate::compensate::Table;
use crate::units::{AxisKind, fmt_fixed};

pub struct Ecmc;

/// Fewest rows ecmc accepts (`ERROR_LOOKUP_TABLE_ERROR` otherwise).
const MIN_ROWS: usize = 3;

impl Controller for Ecmc {
    fn name(&self) -> &'static str {
        "ecmc"
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

    fn write(&self, table: &Table) -> Result<String, Refused> {
        let p = &table.positions;
        if p.len() < MIN_ROWS {
            return Err(too_few(table));
        }
        if p.windows(2).any(|w| w[1] <= w[0]) {
            return Err(Refused::Grid("the positions must increase strictly".into()));
        }
        let per_unit = table.kind.deviation_units_per_position_unit();
        let mut out = header(table);
        for (position, correction) in p.iter().zip(table.mean()) {
            out.push_str(&format!(
                "{} {}\n",
                fmt_fixed(*position, 6),
                fmt_fixed(correction / per_unit, 7)
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

/// The `#` comments: columns, units, sign, backlash, modulo and the lines that load it.
fn header(table: &Table) -> String {
    let unit = table.kind.position_unit();
    let modulo = match (table.kind, table.modulo_deg) {
        (AxisKind::Rotary, Some(revolution)) => format!(
            "# One revolution: looked up at the position modulo {0}, with\n\
             # ecmcConfigOrDie \"Cfg.SetAxisEncLookupTableRange(${{ECMC_AXIS_NO}},{0})\"\n",
            fmt_fixed(revolution, 0)
        ),
        _ => String::new(),
    };
    format!(
        "# ecmc encoder correction table written by axcheck: encoder position, correction ({unit})\n\
         # The value is subtracted from the encoder position: correction = -(actual - target),\n\
         # the mean of both directions (no backlash: the reversal stays).\n\
         {modulo}\
         # Load it (FILE: the path of this file) after the axis's encoder is configured:\n\
         # ecmcConfigOrDie \"Cfg.LoadAxisEncLookupTable(${{ECMC_AXIS_NO}},FILE)\"\n\
         # ecmcConfigOrDie \"Cfg.SetAxisEncLookupTableEnable(${{ECMC_AXIS_NO}},1)\"\n"
    )
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
        let table = held_table(&Ecmc, &data, &Settings::default()).unwrap();
        assert_eq!(table.up, table.down);
        assert_eq!(
            Ecmc.write(&table).unwrap(),
            include_str!("../../../tests/data/compensation/ecmc-linear.lut")
        );
    }

    /// Targets 0, 90, 180, 270, 360°: x̄↑ = 0, 3.6, −7.2, 1.8, 3.6″, x̄↓ = x̄↑ + 3.6″. One
    /// revolution: 0° and 360° hold (0 + 3.6)/2 = 1.8″ ↑, 5.4″ ↓; mean x̄ = 3.6, 5.4, −5.4,
    /// 3.6, 3.6″; the LUT holds −x̄ in degrees: −0.001, −0.0015, 0.0015, −0.001, −0.001.
    #[test]
    fn golden_rotary_modulo() {
        let data = whole_turn_rotary();
        let table = held_table(&Ecmc, &data, &Settings::default()).unwrap();
        assert_eq!(table.modulo_deg, Some(360.0));
        assert_eq!(
            Ecmc.write(&table).unwrap(),
            include_str!("../../../tests/data/compensation/ecmc-rotary-modulo.lut")
        );
    }

    #[test]
    fn refuses_fewer_than_three_rows() {
        let data = axis(AxisKind::Linear, &[0.0, 100.0], 2, |_, _| 1.0);
        let table = held_table(&Ecmc, &data, &Settings::default()).unwrap();
        assert_eq!(
            Ecmc.write(&table).unwrap_err(),
            Refused::Grid(
                "2 points, but an ecmc lookup table needs at least 3: choose an interval of 50.000 mm or less (--interval, or compensation: {interval} in a campaign)"
                    .into()
            )
        );
    }
}
