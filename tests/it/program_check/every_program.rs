//! Every program the library writes — each control, a linear and a rotary axis (and a
//! lathe's X where the control has a turning form), every cycle, machine and work
//! coordinates — run by rs274 or the control's checker on machines with work offsets
//! (G54 = 100, G92 = 7 or each control's equivalent) and every rotary-axis setting the
//! control has; the machine positions compared with the plan ([`verify`]).
//!
//! [`write`] is the only place that knows the library's program API: at merge it takes
//! the coordinates and the lathe's form from [`Case`] into the new `Job` fields.

use super::fanuc::{self, Fanuc, GCodeSystem, Rotary};
use super::heidenhain::{self, Heidenhain};
use super::machine::{Expect, Trace, turn, verify};
use super::rs274::{self, Lcnc};
use super::siemens_840d::{self, Modulo, Sinumerik};
use super::twincat::{self, Isg};
use super::{axis, linear_plan, motion, today};
use axcheck::plan::programs::{self, Job};
use axcheck::plan::{self, Plan};
use axcheck::simulate::Cycle;
use axcheck::units::{AxisKind, Travel};
use std::collections::BTreeMap;

/// How the program addresses positions.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Coordinates {
    /// The machine's own coordinates: positions equal the plan's targets.
    Machine,
    /// The active work offset: positions are the targets plus the offsets.
    Work,
}

/// A lathe's turning form, where the control has one.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Lathe {
    Fanuc(GCodeSystem),
    /// SINUMERIK or LinuxCNC: X in diameter or the control's radius mode, stated.
    Stated,
}

/// One program to write and check.
struct Case {
    control: &'static str,
    plan: Plan,
    axis: &'static str,
    coordinates: Coordinates,
    lathe: Option<Lathe>,
}

/// The program the library writes for `case`: its coordinates and, on a lathe, FANUC's
/// G-code system (the other controls take any).
fn write(case: &Case) -> Result<String, String> {
    let job = Job {
        plan: &case.plan,
        axis: case.axis,
        name: "ISO230TEST",
        coordinates: match case.coordinates {
            Coordinates::Machine => programs::Coordinates::Machine,
            Coordinates::Work => programs::Coordinates::Work,
        },
        lathe: case.lathe.map(|l| match l {
            Lathe::Fanuc(GCodeSystem::B) => programs::GcodeSystem::B,
            Lathe::Fanuc(GCodeSystem::C) => programs::GcodeSystem::C,
            Lathe::Fanuc(GCodeSystem::A) | Lathe::Stated => programs::GcodeSystem::A,
        }),
    };
    let control = programs::find(case.control).ok_or("no such control")?;
    control.write(&job).map_err(|e| e.to_string())
}

/// The work offsets every machine carries on the tested axis: 100 + 7.
const OFFSET: f64 = 107.0;

/// How a machine runs a program: its trace, or why it refuses it.
type RunProgram = Box<dyn Fn(&str) -> Result<Trace, String>>;

/// A machine to run a case on: its name, how it runs a program, whether positions compare
/// as angles, the tolerance.
struct Runner {
    name: String,
    run: RunProgram,
    modulo: bool,
    tolerance: f64,
}

fn runner(
    name: String,
    modulo: bool,
    run: impl Fn(&str) -> Result<Trace, String> + 'static,
) -> Runner {
    Runner {
        name,
        run: Box::new(run),
        modulo,
        tolerance: 1e-6,
    }
}

/// The machines a case runs on: each of the control's rotary-axis settings.
fn runners(case: &Case) -> Vec<Runner> {
    let rotary = case.plan.axis.kind == AxisKind::Rotary;
    let letter = case.axis.chars().next().unwrap_or('X');
    match case.control {
        "linuxcnc" => linuxcnc(letter, full_turn(&case.plan), case.lathe.is_some()),
        "fanuc" => fanuc_runners(letter, rotary, case.lathe, case.coordinates),
        "siemens-840d" => siemens(case.axis, rotary, case.lathe.is_some()),
        "heidenhain" => heidenhain_runners(letter, rotary),
        "twincat" => twincat_runners(case.axis, rotary),
        other => panic!("a control without a checker: {other}"),
    }
}

/// Whether the plan's axis is a rotary one of a whole turn (no ends). At merge: the
/// plan's `continuous`.
fn full_turn(plan: &Plan) -> bool {
    plan.axis.continuous
}

/// The ends of the axis's stated travel.
fn ends(plan: &Plan) -> (f64, f64) {
    match plan.axis.travel {
        Travel::Length(l) => (0.0, l),
        Travel::Range([a, b]) => (a, b),
    }
}

/// LinuxCNC: a rotary axis of a whole turn with and without `WRAPPED_ROTARY` (a wrapped
/// axis turns freely; one with ends is not wrapped).
fn linuxcnc(axis: char, full_turn: bool, lathe: bool) -> Vec<Runner> {
    let wraps: &[bool] = if full_turn { &[false, true] } else { &[false] };
    let (g54, g92) = (100.0, 7.0);
    wraps
        .iter()
        .map(|&wrapped| {
            let cfg = Lcnc {
                axis,
                g54,
                g92,
                wrapped,
                lathe,
            };
            let mut r = runner(format!("rs274 wrapped={wrapped}"), wrapped, move |p| {
                let run = rs274::run(p, &cfg).map_err(|e| e.to_string())?;
                let offsets = (run.g5x - cfg.g54).abs() + (run.g92 - cfg.g92).abs();
                if !run.trace.moves.is_empty() && offsets > 1e-4 {
                    return Err(format!(
                        "rs274 moved with G54 {} and G92 {}",
                        run.g5x, run.g92
                    ));
                }
                Ok(run.trace)
            });
            r.tolerance = 0.001;
            r
        })
        .collect()
}

/// FANUC has no machine-coordinate move at feed (G53 is rapid): in machine coordinates
/// the program asks in its head that the axis's G54, EXT and G92 offsets be zero, and
/// runs so here; in work coordinates they are 100 and 7. A rotary axis's machine
/// coordinate is kept within a turn whatever the roll-over (FANUC Power Mate i-D/H
/// Descriptions B-63172EN/01 §7.4, p. 51), so its positions compare as angles.
fn fanuc_runners(
    axis: char,
    rotary: bool,
    lathe: Option<Lathe>,
    coordinates: Coordinates,
) -> Vec<Runner> {
    let (g54, shift) = match coordinates {
        Coordinates::Machine => (0.0, 0.0),
        Coordinates::Work => (100.0, 7.0),
    };
    let modes: Vec<Option<Rotary>> = if rotary {
        vec![
            Some(Rotary::Linear),
            Some(Rotary::RollOver),
            Some(Rotary::SignedDirection),
        ]
    } else {
        vec![None]
    };
    let system = match lathe {
        Some(Lathe::Fanuc(s)) => Some(s),
        _ => None,
    };
    modes
        .into_iter()
        .map(|mode| {
            let m = Fanuc {
                lathe: system,
                axis,
                diameter: system.is_some(),
                work: [g54, 0.0, 0.0, 0.0, 0.0, 0.0],
                active: 0,
                external: 0.0,
                shift,
                rotary: mode,
                initial: 0.0,
            };
            let modulo = mode.is_some();
            runner(format!("FANUC {system:?} {mode:?}"), modulo, move |p| {
                fanuc::run(p, &m).map_err(|e| e.to_string())
            })
        })
        .collect()
}

fn siemens(axis: &str, rotary: bool, lathe: bool) -> Vec<Runner> {
    let mut settings: Vec<(Option<Modulo>, bool)> = Vec::new();
    if rotary {
        settings.push((None, false));
        for (wrap_values, shortest) in [(false, false), (true, false), (true, true)] {
            settings.push((
                Some(Modulo {
                    wrap_values,
                    shortest,
                }),
                false,
            ));
        }
    } else if lathe {
        settings.extend([(None, false), (None, true)]);
    } else {
        settings.push((None, false));
    }
    settings
        .into_iter()
        .map(|(modulo, diamon)| {
            let m = Sinumerik {
                channel: vec![axis.to_string(), "Y".into(), "Z".into()],
                axis: axis.to_string(),
                base: 100.0,
                settable: [7.0, 0.0, 0.0, 0.0],
                active: Some(0),
                external: 0.0,
                modulo,
                transverse: lathe,
                diamon,
                initial: 0.0,
            };
            runner(
                format!("SINUMERIK {modulo:?} DIAMON at start {diamon}"),
                modulo.is_some(),
                move |p| siemens_840d::run(p, &m).map_err(|e| e.to_string()),
            )
        })
        .collect()
}

fn heidenhain_runners(axis: char, rotary: bool) -> Vec<Runner> {
    let modes: &[Option<bool>] = if rotary {
        &[None, Some(false), Some(true)]
    } else {
        &[None]
    };
    modes
        .iter()
        .map(|&modulo| {
            let m = Heidenhain {
                axis,
                datum: OFFSET,
                modulo,
                initial: 0.0,
            };
            runner(
                format!("TNC one-turn display {modulo:?}"),
                modulo.is_some(),
                move |p| heidenhain::run(p, &m).map_err(|e| e.to_string()),
            )
        })
        .collect()
}

fn twincat_runners(axis: &str, rotary: bool) -> Vec<Runner> {
    let modes: &[bool] = if rotary { &[false, true] } else { &[false] };
    modes
        .iter()
        .map(|&modulo| {
            let first = if axis.starts_with('X') { axis } else { "X" };
            let mut channel = vec![first.to_string(), "Y".into(), "Z".into()];
            if !channel.iter().any(|a| a == axis) {
                channel.push(axis.to_string());
            }
            let m = Isg {
                channel,
                axis: axis.to_string(),
                zero: [0.0, OFFSET, 0.0, 0.0, 0.0, 0.0, 0.0],
                active: 1,
                modulo,
                initial: 0.0,
            };
            runner(format!("ISG modulo={modulo}"), modulo, move |p| {
                twincat::run(p, &m).map_err(|e| e.to_string())
            })
        })
        .collect()
}

/// Every case: each control, each axis it takes, each cycle, both coordinate modes.
fn cases() -> Vec<Case> {
    let linear = axis(AxisKind::Linear, Travel::Range([-200.0, 800.0]));
    let rotary = axis(AxisKind::Rotary, Travel::Length(360.0));
    let part_turn = axis(AxisKind::Rotary, Travel::Range([10.0, 300.0]));
    let lathe_x = axis(AxisKind::Linear, Travel::Range([0.0, 300.0]));
    let mut shapes: Vec<(&'static str, &'static str, &plan::Axis, Option<Lathe>)> = Vec::new();
    for control in programs::names() {
        shapes.push((control, "X", &linear, None));
        shapes.push((control, "C", &rotary, None));
        shapes.push((control, "C", &part_turn, None));
    }
    shapes.push(("siemens-840d", "X1", &linear, None));
    shapes.push(("twincat", "X1", &linear, None));
    shapes.push(("twincat", "C2", &rotary, None));
    for system in [GCodeSystem::A, GCodeSystem::B, GCodeSystem::C] {
        shapes.push(("fanuc", "X", &lathe_x, Some(Lathe::Fanuc(system))));
    }
    shapes.push(("siemens-840d", "X", &lathe_x, Some(Lathe::Stated)));
    shapes.push(("linuxcnc", "X", &lathe_x, Some(Lathe::Stated)));
    let mut out = Vec::new();
    for (control, address, a, lathe) in shapes {
        for cycle in [Cycle::Standard, Cycle::Step, Cycle::Pilgrim] {
            for coordinates in [Coordinates::Machine, Coordinates::Work] {
                out.push(Case {
                    control,
                    plan: plan::plan(a, &motion(cycle), 7).expect("a plan"),
                    axis: address,
                    coordinates,
                    lathe,
                });
            }
        }
    }
    out
}

/// The first problems of one run, or nothing when it runs the plan.
fn check(case: &Case, program: &str, r: &Runner) -> Option<String> {
    let offset = match case.coordinates {
        Coordinates::Machine => 0.0,
        Coordinates::Work => OFFSET,
    };
    let expect = Expect {
        offset,
        modulo: r.modulo,
        tolerance: r.tolerance,
    };
    let problems = match (r.run)(program) {
        Ok(trace) => {
            let mut found = verify(&case.plan, &trace, &expect);
            found.extend(outside_travel(&case.plan, &trace, &expect));
            found
        }
        Err(refusal) => vec![format!("refused: {refusal}")],
    };
    (!problems.is_empty()).then(|| {
        let shown: Vec<&str> = problems.iter().take(2).map(String::as_str).collect();
        format!(
            "{} --axis {} {:?} {:?} {} {:?} {:?} on {}: {} problem(s): {}",
            case.control,
            case.axis,
            case.plan.axis.kind,
            case.plan.axis.travel,
            case.plan.motion.cycle.name(),
            case.coordinates,
            case.lathe,
            r.name,
            problems.len(),
            shown.join(" | ")
        )
    })
}

/// The moves beyond the axis's stated travel (shifted by the expected offset), unless the
/// axis is a rotary one of a whole turn (it has no ends).
fn outside_travel(plan: &Plan, trace: &Trace, expect: &Expect) -> Vec<String> {
    let (lo, hi) = ends(plan);
    if full_turn(plan) {
        return Vec::new();
    }
    let angles = expect.modulo && lo >= 0.0 && hi <= 360.0;
    trace
        .moves
        .iter()
        .filter(|m| {
            let at = m.to - expect.offset;
            let at = if angles { turn(at) } else { at };
            at < lo - expect.tolerance || at > hi + expect.tolerance
        })
        .map(|m| {
            format!(
                "line {}: moves to {:.4}, outside the travel [{lo}, {hi}]",
                m.line, m.to
            )
        })
        .collect()
}

/// Each plan target reached in machine coordinates (or work coordinates plus the offsets),
/// exactly n times from each side, after at least the overrun, with the dwell, at the
/// plan's feed, nothing else moved — by every program on every machine setting.
/// (Before issue 41 was closed: a continuous rotary axis that counts past 360° read every
/// target a turn up from its start `C355.000`, 30 of 252 runs.)
#[test]
fn every_program_reaches_every_target_in_machine_coordinates() {
    let mut failures = Vec::new();
    let mut tally: BTreeMap<&str, [usize; 2]> = BTreeMap::new();
    for case in cases() {
        let program = match write(&case) {
            Ok(p) => p,
            Err(e) => {
                failures.push(format!(
                    "{} --axis {}: not written: {e}",
                    case.control, case.axis
                ));
                continue;
            }
        };
        for r in runners(&case) {
            let found = check(&case, &program, &r);
            let t = tally.entry(case.control).or_default();
            t[0] += 1;
            t[1] += usize::from(found.is_some());
            failures.extend(found);
        }
    }
    let summary: Vec<String> = tally
        .iter()
        .map(|(control, [runs, failed])| format!("{control}: {failed} of {runs}"))
        .collect();
    assert!(
        failures.is_empty(),
        "runs that do not run the plan, per control: {}\n{}",
        summary.join(", "),
        failures.join("\n")
    );
}

/// Today's linear programs (kept in `tests/data/program_check/today`, as the library wrote
/// them before issue 41) as they should be, by a small edit: no G49, and for LinuxCNC `G53`
/// in every motion block, SINUMERIK `SUPA` in place of G500, HEIDENHAIN `M91` in every L
/// block (TwinCAT's G53 head already deselects the zero offset); FANUC, which has no
/// machine-coordinate move at feed, in work coordinates. The checks pass on them: they fail
/// the programs of today for what the programs do, not for what the checks cannot read.
#[test]
fn corrected_linear_programs_pass_every_check() {
    let mut failures = Vec::new();
    for control in programs::DIALECTS {
        let coordinates = if control.name() == "fanuc" {
            Coordinates::Work
        } else {
            Coordinates::Machine
        };
        let case = Case {
            control: control.name(),
            plan: linear_plan(Cycle::Standard),
            axis: "X",
            coordinates,
            lathe: None,
        };
        let file = format!("{}.{}", control.name(), control.extension());
        let program = corrected(control.name(), &today(&file));
        for r in runners(&case) {
            failures.extend(check(&case, &program, &r));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The edit of [`corrected_linear_programs_pass_every_check`].
fn corrected(control: &str, program: &str) -> String {
    let program = program.replace(" G49", "");
    match control {
        "linuxcnc" => program.replace("\nG1 ", "\nG53 G1 "),
        "siemens-840d" => program
            .replace(" G500", "")
            .replace("\nG1 X", "\nG1 SUPA X"),
        "heidenhain" => program
            .lines()
            .map(|l| {
                if l.contains(" L X") {
                    format!("{l} M91\n")
                } else {
                    format!("{l}\n")
                }
            })
            .collect(),
        _ => program,
    }
}

/// LinuxCNC's G53 on a `WRAPPED_ROTARY` axis reads a position below the offsets wrong
/// (`unwrap_rotary` takes the magnitude of the value less the offsets): `G53 G1 C0` with
/// 107° of offsets ends at 214°, measured by rs274. The program for a continuous axis in
/// machine coordinates reads where the axis went and moves back by the difference: with
/// the offsets, wrapped or counting, its first target is read at 0° (the whole program on
/// every setting: every_program_reaches_every_target_in_machine_coordinates).
#[test]
fn lcnc_full_turn_corrects_what_g53_misreads() {
    let with_offsets = |wrapped| Lcnc {
        axis: 'C',
        g54: 100.0,
        g92: 7.0,
        wrapped,
        lathe: false,
    };
    let bare = "%\nG21 G90 G94\nG53 G1 C0 F1000\nM2\n%\n";
    let trace = rs274::run(bare, &with_offsets(true))
        .expect("rs274 runs it")
        .trace;
    assert!(
        (trace.moves[0].to - 214.0).abs() < 1e-6,
        "{:?}",
        trace.moves
    );
    let rotary = axis(AxisKind::Rotary, Travel::Length(360.0));
    let case = Case {
        control: "linuxcnc",
        plan: plan::plan(&rotary, &motion(Cycle::Standard), 7).expect("a plan"),
        axis: "C",
        coordinates: Coordinates::Machine,
        lathe: None,
    };
    let program = write(&case).expect("a program");
    assert!(
        program.contains(
            "\n#<misread> = [#5425 + #[5206 + 20 * #5220] + #5216 * #5210 + #5406 - 0.000]\n"
        ),
        "{program}"
    );
    for wrapped in [false, true] {
        let trace = rs274::run(&program, &with_offsets(wrapped))
            .expect("it runs")
            .trace;
        let after_first: Vec<f64> = trace.moves.iter().take(2).map(|m| m.to).collect();
        let start = -case.plan.motion.overrun;
        let expected = if wrapped { [214.0, 0.0] } else { [0.0, start] };
        assert_eq!(after_first.len(), 2);
        for (got, want) in after_first.iter().zip(expected) {
            assert!(
                (got - want).abs() < 1e-6,
                "wrapped {wrapped}: {after_first:?}"
            );
        }
    }
}
