//! `linuxcnc`: a joint compensation file of type 1 (`[JOINT_n] COMP_FILE = …`,
//! `COMP_FILE_TYPE = 1`): one line per point, `nominal forward_trim reverse_trim`, in the
//! joint's units (mm, or degrees on a rotary joint), three numbers and nothing else (the
//! loader stops at the first line that is not three numbers: no header, no comment).
//!
//! LinuxCNC adds the trim to the commanded joint position, interpolating linearly between
//! points on the commanded position and holding the end values beyond them, the forward
//! trim when moving in the positive direction (LinuxCNC source: `src/emc/motion/control.c`,
//! `compute_screw_comp`; the file read by `usrmotLoadComp` in `usrmotintf.cc`): so the
//! trim is the correction, −x̄↑ forward and −x̄↓ reverse. Nominal positions must increase
//! strictly; at most 256 points per joint (`EMCMOT_COMP_SIZE`). With a table, `BACKLASH`
//! is not used: the reversal is in the two columns.

use super::{Controller, Directions, Format, Refused, Spacing};
use crate::compensate::Table;
use crate::units::{AxisKind, fmt_fixed};

pub struct LinuxCnc;

/// Points per joint the motion controller holds (`EMCMOT_COMP_SIZE`).
const MAX_POINTS: usize = 256;

impl Controller for LinuxCnc {
    fn name(&self) -> &'static str {
        "linuxcnc"
    }

    fn extension(&self) -> &'static str {
        "txt"
    }

    /// Any increasing list of up to 256 points, forward and reverse trims, no wrap (a
    /// rotary joint's table covers the positions the joint takes); the file prints 0.1 nm
    /// or 1e-7°.
    fn format(&self) -> Format {
        Format {
            spacing: Spacing::Free,
            max_points: MAX_POINTS,
            directions: Directions::Bidirectional,
            modulo: false,
            quantum_um: 1e-4,
            quantum_arcsec: 3.6e-4,
        }
    }

    fn write(&self, table: &Table) -> Result<String, Refused> {
        if table.positions.windows(2).any(|w| w[1] <= w[0]) {
            return Err(Refused::Grid("the positions must increase strictly".into()));
        }
        // Corrections in µm or arcsec, the file in mm or degrees.
        let per_unit = match table.kind {
            AxisKind::Linear => 1000.0,
            AxisKind::Rotary => 3600.0,
        };
        let mut out = String::new();
        for ((p, u), d) in table.positions.iter().zip(&table.up).zip(&table.down) {
            out.push_str(&format!(
                "{} {} {}\n",
                fmt_fixed(*p, 6),
                fmt_fixed(u / per_unit, 7),
                fmt_fixed(d / per_unit, 7)
            ));
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compensate::testing::{axis, irregular_linear};
    use crate::compensate::{Settings, held_table};
    use crate::units::Direction;

    /// Targets 0, 30, 70, 100 mm; x̄↑ = 0, 3, −1, 2 µm; x̄↓ = x̄↑ + 2 µm; every 25 mm with
    /// the reference at 50 mm. Corrections −x̄↑ on the grid: 0, −2.5, −1, 0.5, −2 µm; zero at
    /// 50 adds 1: trims ↑ 1, −1.5, 0, 1.5, −1 µm and ↓ two less, written in mm.
    #[test]
    fn golden_type_1_file_by_hand() {
        let data = irregular_linear();
        let settings = Settings {
            interval: Some(25.0),
            reference: Some(50.0),
            ..Default::default()
        };
        let table = held_table(&LinuxCnc, &data, &settings).unwrap();
        assert_eq!(
            LinuxCnc.write(&table).unwrap(),
            include_str!("../../../tests/data/compensation/linuxcnc-linear.txt")
        );
        // A rotary joint in degrees: x̄↑ = −3.6″, 7.2″ → trims 0.001°, −0.002°.
        let rotary = axis(AxisKind::Rotary, &[0.0, 90.0], 2, |p, d| match d {
            Direction::Up if p == 0.0 => -3.6,
            Direction::Up => 7.2,
            Direction::Down => 0.0,
        });
        let table = held_table(&LinuxCnc, &rotary, &Settings::default()).unwrap();
        assert_eq!(
            LinuxCnc.write(&table).unwrap(),
            "0.000000 0.0010000 0.0000000\n90.000000 -0.0020000 0.0000000\n"
        );
    }

    #[test]
    fn refuses_what_a_joint_cannot_hold() {
        let data = crate::compensate::testing::straight(0.0, 1.0, MAX_POINTS + 1);
        let err = crate::compensate::held_table(&LinuxCnc, &data, &Default::default())
            .unwrap_err()
            .to_string();
        assert_eq!(
            err,
            "257 points, but the table holds at most 256; choose an interval of 1.004 mm or more (--interval, or compensation: {interval} in a campaign)"
        );
    }
}
