//! The part programs `axcheck plan --program CONTROL` writes, run as the controls run
//! them: LinuxCNC's own interpreter (`rs274`, [`rs274`]) with work offsets in its variable
//! file, and for each other control a strict reading written from its programming manual
//! ([`fanuc`], [`siemens_840d`], [`heidenhain`], [`twincat`]; each module cites its sources)
//! that refuses what the control refuses and simulates the tested axis in machine
//! coordinates ([`machine`]). The tests in each module keep the defective lines of the
//! programs of issue 41 as cases the checkers must refuse or show wrong; [`every_program`]
//! runs every program the library writes and compares the machine positions with the plan.

mod every_program;
mod fanuc;
mod heidenhain;
mod machine;
mod rs274;
mod siemens_840d;
mod twincat;

use axcheck::evaluate::StandardId;
use axcheck::plan::{self, Axis, Motion, Plan};
use axcheck::simulate::Cycle;
use axcheck::units::{AxisKind, Travel};

/// An axis of `kind` over `travel`, ISO 230-2.
pub fn axis(kind: AxisKind, travel: Travel) -> Axis {
    Axis {
        kind,
        standard: StandardId::Iso230_2,
        travel,
        measurement_travel: None,
        pitch: Some(5.0),
        scale_pitch: None,
        // A rotary axis of a whole turn turns freely: it is measured over the turn.
        continuous: kind == AxisKind::Rotary
            && match travel {
                Travel::Length(l) => l >= 360.0,
                Travel::Range([a, b]) => b - a >= 360.0,
            },
    }
}

/// The motion every case uses: 2 runs, overrun 4, dwell 2.5 s, feed 1500.
pub fn motion(cycle: Cycle) -> Motion {
    Motion {
        runs: Some(2),
        cycle,
        overrun: 4.0,
        dwell_s: 2.5,
        feed: 1500.0,
    }
}

/// A plan over the given targets.
pub fn plan_at(kind: AxisKind, travel: Travel, cycle: Cycle, targets: &[f64]) -> Plan {
    plan::with_targets(&axis(kind, travel), &motion(cycle), targets.to_vec()).expect("a plan")
}

/// A small plan for the hand-written programs: targets 10 and 50, one run, standard
/// cycle, overrun 4, dwell 2.5 s, feed 1500: start at 6, read 10 and 50 up, overrun to 54,
/// read 50 and 10 down.
pub fn small_plan(kind: AxisKind) -> Plan {
    let m = Motion {
        runs: Some(1),
        ..motion(Cycle::Standard)
    };
    plan::with_targets(
        &axis(kind, Travel::Range([0.0, 400.0])),
        &m,
        vec![10.0, 50.0],
    )
    .expect("a plan")
}

/// The machine expectations: positions equal the plan's targets plus `offset`.
pub fn expect(offset: f64, modulo: bool) -> machine::Expect {
    machine::Expect {
        offset,
        modulo,
        tolerance: 1e-6,
    }
}

/// The linear plan of the program tests: -200 to 800 mm, seed 7.
pub fn linear_plan(cycle: Cycle) -> Plan {
    let a = axis(AxisKind::Linear, Travel::Range([-200.0, 800.0]));
    plan::plan(&a, &motion(cycle), 7).expect("a plan")
}

/// A program as the library wrote it before issue 41 (`tests/data/program_check/today`):
/// `linuxcnc.ngc` and the others for [`linear_plan`] (standard cycle) on X,
/// `linuxcnc-rotary.ngc` for targets 0° and 90° on C (standard cycle, travel −10° to 360°).
pub fn today(file: &str) -> String {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/program_check/today")
        .join(file);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}
