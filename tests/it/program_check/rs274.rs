//! LinuxCNC's own G-code interpreter, `rs274` (Debian `linuxcnc-uspace`), runs a program
//! with work offsets in its variable file; its canonical calls give the machine positions.
//!
//! What was measured on the installed rs274 (LinuxCNC 2.9.0~pre1, Debian 12), and is relied
//! on here:
//! - `rs274 -g -i INI -v VARFILE PROGRAM` interprets in batch; an error prints its message
//!   and the block to stderr and exits 1 (`Cannot use g53 incremental`).
//! - Moves print in program coordinates: `STRAIGHT_FEED(x, y, z, a, b, c)`; the offsets
//!   print as `SET_G5X_OFFSET(index, x, …)` and `SET_G92_OFFSET(x, …)`; the machine position
//!   is the move plus both offsets (plus the tool length offset). `DWELL(s)` is the dwell.
//! - Variables 5221.. (G54 X, Y, Z, A, B, C) and 5211.. with 5210 = 1 (G92) set offsets. This
//!   build reads a variable file's lengths in inch (a value of 100 printed as 2540 mm): its
//!   `driver.cc` sets `_external_length_units = 0.03937…` unless the INI's `[TRAJ]
//!   LINEAR_UNITS` is `mm`, which it reads only from LinuxCNC commit b27646d4 (2023-10) on.
//!   The runner measures the factor once ([`var_scale`]) and writes lengths divided by it;
//!   it then asserts the offsets rs274 printed are the ones asked for.
//! - `[AXIS_C] WRAPPED_ROTARY = 1` in the `-i` INI makes rs274 unwrap absolute moves as
//!   LinuxCNC does (`Interp::unwrap_rotary`, `src/emc/rs274ngc/interp_find.cc`: the sign of
//!   the value is the direction, its magnitude the position in the turn; values of 360 or
//!   more are an error). The wrapping is rs274's own, not modelled here. With G53 the
//!   value's sign is taken from the block but the magnitude from the value minus the
//!   offsets (`fabs(commanded)`), so `G53 C5` with 107° of offsets ends at 209°: measured.
//!
//! The runner refuses, beyond rs274's own errors: any canonical call it does not know (an
//! arc, a probe, a spindle start); a tool-length change (`USE_TOOL_LENGTH_OFFSET` after the
//! start: G43/G49 may move another axis); a change of a work offset's value or of G92 by the
//! program; feed per revolution or inverse time; a program that does not select mm (G21)
//! itself before its first move; a lathe program that does not state G7 or G8.

use super::machine::{Feed, Refusal, Trace, Tracker};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, OnceLock};

/// The machine rs274 is started as.
#[derive(Debug, Clone)]
pub struct Lcnc {
    /// The tested axis's letter (X, Y, Z, A, B, C).
    pub axis: char,
    /// Its G54 offset (5221..) and G92 offset (5211.., enabled), mm or deg.
    pub g54: f64,
    pub g92: f64,
    /// `[AXIS_<axis>] WRAPPED_ROTARY = 1`.
    pub wrapped: bool,
    /// A lathe: the program must state G7 (diameter) or G8 (radius).
    pub lathe: bool,
}

/// What rs274 did: the trace (machine positions) and the tested axis's offsets it printed
/// at the start.
#[derive(Debug, Clone)]
pub struct Run {
    pub trace: Trace,
    pub g5x: f64,
    pub g92: f64,
}

const AXES: &str = "XYZABCUVW";

fn index(axis: char) -> usize {
    AXES.find(axis).expect("an axis letter of XYZABCUVW")
}

fn is_linear(axis: char) -> bool {
    !"ABC".contains(axis)
}

/// The `rs274` binary, or a failure that says how to get it.
fn binary() -> PathBuf {
    let found = std::env::var_os("PATH").and_then(|paths| {
        std::env::split_paths(&paths)
            .map(|p| p.join("rs274"))
            .find(|p| p.is_file())
    });
    found.unwrap_or_else(|| {
        panic!(
            "rs274 (LinuxCNC's G-code interpreter) is not on PATH: install Debian's \
             linuxcnc-uspace (`apt-get install linuxcnc-uspace`; .ci/test does)"
        )
    })
}

/// A fresh folder for one run (rs274 rewrites its variable file at exit).
fn scratch() -> PathBuf {
    static COUNT: AtomicUsize = AtomicUsize::new(0);
    let n = COUNT.fetch_add(1, Ordering::SeqCst);
    let dir = std::env::temp_dir().join(format!("axcheck-rs274-{}-{n}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a scratch folder");
    dir
}

fn ini(cfg: &Lcnc) -> String {
    let mut text = "[TRAJ]\nLINEAR_UNITS = mm\nANGULAR_UNITS = degree\n".to_string();
    if cfg.wrapped {
        text.push_str(&format!("[AXIS_{}]\nWRAPPED_ROTARY = 1\n", cfg.axis));
    }
    text
}

/// The variable file: G54 selected (5220 = 1), G92 enabled (5210 = 1); lengths divided
/// by `scale` (what this rs274 multiplies a file's lengths by).
fn var_file(axis: char, g54: f64, g92: f64, scale: f64) -> String {
    let k = index(axis);
    let unit = if is_linear(axis) { scale } else { 1.0 };
    let mut rows = [
        (5210, 1.0),
        (5211 + k, g92 / unit),
        (5220, 1.0),
        (5221 + k, g54 / unit),
    ];
    rows.sort_by_key(|r| r.0);
    rows.iter()
        .map(|(n, v)| format!("{n}\t{v:.12}\n"))
        .collect()
}

/// Runs rs274 on `program` in `dir`; its stdout, or why it failed.
fn interpret(dir: &Path, cfg: &Lcnc, var: &str, program: &str) -> Result<String, String> {
    std::fs::write(dir.join("machine.ini"), ini(cfg)).expect("the INI");
    std::fs::write(dir.join("machine.var"), var).expect("the variable file");
    std::fs::write(dir.join("program.ngc"), program).expect("the program");
    // Two rs274 at once die of SIGBUS here (measured): the tests' threads take turns.
    static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let out = Command::new(binary())
        .current_dir(dir)
        .args([
            "-g",
            "-i",
            "machine.ini",
            "-v",
            "machine.var",
            "program.ngc",
        ])
        .output()
        .expect("rs274 runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    let noise: Vec<&str> = stderr
        .lines()
        .filter(|l| !l.trim().is_empty() && l.trim() != "executing")
        .collect();
    if !out.status.success() || !noise.is_empty() {
        return Err(format!("rs274 ({}): {}", out.status, noise.join(" | ")));
    }
    Ok(String::from_utf8_lossy(&out.stdout).into_owned())
}

/// What this rs274 multiplies a variable file's lengths by (25.4 or 1): measured once.
fn var_scale() -> f64 {
    static SCALE: OnceLock<f64> = OnceLock::new();
    *SCALE.get_or_init(|| {
        let cfg = Lcnc {
            axis: 'X',
            g54: 0.0,
            g92: 0.0,
            wrapped: false,
            lathe: false,
        };
        let dir = scratch();
        let out = interpret(&dir, &cfg, &var_file('X', 1.0, 0.0, 1.0), "G21\nM2\n")
            .expect("rs274 runs an empty program");
        let _ = std::fs::remove_dir_all(&dir);
        let first = out
            .lines()
            .find_map(|l| call(l).filter(|(n, _)| n == "SET_G5X_OFFSET"))
            .expect("rs274 prints the G54 offset");
        numbers(&first.1)[1]
    })
}

/// `   26 N..... STRAIGHT_FEED(5.0000, 0.0000)` → (`STRAIGHT_FEED`, `5.0000, 0.0000`).
fn call(line: &str) -> Option<(String, String)> {
    let rest = line.trim_start().split_once(' ')?.1.trim_start();
    let rest = rest.strip_prefix("N.....").unwrap_or(rest).trim();
    let (name, args) = rest.split_once('(')?;
    Some((name.to_string(), args.strip_suffix(')')?.to_string()))
}

/// The numbers of a call's arguments (commas and spaces between).
fn numbers(args: &str) -> Vec<f64> {
    args.split([',', ' '])
        .filter_map(|t| t.trim().parse().ok())
        .collect()
}

/// Runs `program` on rs274 as `cfg` says; the tested axis's machine positions, or why
/// rs274 or the runner refuses it.
pub fn run(program: &str, cfg: &Lcnc) -> Result<Run, Refusal> {
    let scale = var_scale();
    let dir = scratch();
    let out = interpret(
        &dir,
        cfg,
        &var_file(cfg.axis, cfg.g54, cfg.g92, scale),
        program,
    );
    let _ = std::fs::remove_dir_all(&dir);
    let out = out.map_err(|why| Refusal {
        line: 0,
        block: String::new(),
        why,
    })?;
    if cfg.lathe && !states_lathe_mode(program) {
        return Err(refusal(
            0,
            "a lathe program must state G7 (diameter) or G8 (radius)",
        ));
    }
    Canon::new(cfg.axis).read(&out)
}

/// Whether the program has a G7 or G8 word outside comments before its first move.
fn states_lathe_mode(program: &str) -> bool {
    for line in program.lines() {
        let mut code = String::new();
        let mut depth = 0;
        for c in line.chars() {
            match c {
                '(' => depth += 1,
                ')' if depth > 0 => depth -= 1,
                ';' if depth == 0 => break,
                _ if depth == 0 => code.push(c.to_ascii_uppercase()),
                _ => {}
            }
        }
        let words: Vec<&str> = code.split_whitespace().collect();
        if words
            .iter()
            .any(|w| matches!(*w, "G7" | "G07" | "G8" | "G08"))
        {
            return true;
        }
        if words
            .iter()
            .any(|w| matches!(*w, "G1" | "G01" | "G0" | "G00"))
        {
            return false;
        }
    }
    false
}

fn refusal(line: usize, why: impl Into<String>) -> Refusal {
    Refusal {
        line,
        block: String::new(),
        why: why.into(),
    }
}

/// The canonical calls read in order: units, offsets, feed, moves and dwells.
struct Canon {
    axis: usize,
    mm_per_unit: f64,
    g5x: [f64; 9],
    g5x_index: i64,
    g92: [f64; 9],
    tool: [f64; 9],
    feed: f64,
    machine: [f64; 9],
    started: bool,
    mm_selected: bool,
    ended: bool,
    first: Option<(f64, f64)>,
    tracker: Tracker,
}

/// Calls that neither move nor change what the positions mean.
const QUIET: &[&str] = &[
    "COMMENT",
    "SELECT_PLANE",
    "SET_XY_ROTATION",
    "SET_FEED_REFERENCE",
    "SET_NAIVECAM_TOLERANCE",
    "SET_MOTION_CONTROL_MODE",
    "STOP_SPINDLE_TURNING",
    "SET_SPINDLE_MODE",
    "PROGRAM_STOP",
    "FINISH",
];

impl Canon {
    fn new(axis: char) -> Canon {
        Canon {
            axis: index(axis),
            mm_per_unit: 1.0,
            g5x: [0.0; 9],
            g5x_index: 1,
            g92: [0.0; 9],
            tool: [0.0; 9],
            feed: 0.0,
            machine: [0.0; 9],
            started: false,
            mm_selected: false,
            ended: false,
            first: None,
            tracker: Tracker::new(0.0),
        }
    }

    fn read(mut self, out: &str) -> Result<Run, Refusal> {
        for (k, line) in out.lines().enumerate() {
            let Some((name, args)) = call(line) else {
                continue;
            };
            self.call(k + 1, &name, &args).map_err(|why| Refusal {
                line: 0,
                block: format!("rs274 output: {}", line.trim()),
                why,
            })?;
        }
        let (g5x, g92) = self.first.unwrap_or((0.0, 0.0));
        Ok(Run {
            trace: self.tracker.trace,
            g5x,
            g92,
        })
    }

    /// Values of a 6- or 9-axis call in mm (lengths) or degrees.
    fn scaled(&self, values: &[f64]) -> [f64; 9] {
        let mut out = [0.0; 9];
        for (k, v) in values.iter().take(9).enumerate() {
            out[k] = if "ABC".contains(&AXES[k..=k]) {
                *v
            } else {
                v * self.mm_per_unit
            };
        }
        out
    }

    fn call(&mut self, line: usize, name: &str, args: &str) -> Result<(), String> {
        let v = numbers(args);
        match name {
            "USE_LENGTH_UNITS" => self.units(args),
            "ON_RESET" => {
                self.started = true;
                Ok(())
            }
            "SET_G5X_OFFSET" => self.set_g5x(&v),
            "SET_G92_OFFSET" => self.set_g92(&v),
            "USE_TOOL_LENGTH_OFFSET" => {
                if self.started && !self.ended {
                    return Err("the program changes the tool length offset (G43/G49): another axis may move".into());
                }
                self.tool = self.scaled(&v);
                Ok(())
            }
            "SET_FEED_RATE" => {
                self.feed = v.first().copied().unwrap_or(0.0);
                Ok(())
            }
            "SET_FEED_MODE" => match v.get(1).copied() {
                Some(m) if m != 0.0 => Err("not feed per minute".into()),
                _ => Ok(()),
            },
            "STRAIGHT_FEED" | "STRAIGHT_TRAVERSE" => self.motion(line, name, &v),
            "DWELL" => {
                self.tracker.dwell(line, v.first().copied().unwrap_or(0.0));
                Ok(())
            }
            "PROGRAM_END" => {
                self.ended = true;
                Ok(())
            }
            _ if QUIET.contains(&name) => Ok(()),
            _ => Err(format!(
                "a canonical call this check does not model ({name})"
            )),
        }
    }

    fn units(&mut self, args: &str) -> Result<(), String> {
        self.mm_per_unit = if args.contains("INCHES") { 25.4 } else { 1.0 };
        if self.started && args.contains("MM") {
            self.mm_selected = true;
        }
        Ok(())
    }

    fn set_g5x(&mut self, v: &[f64]) -> Result<(), String> {
        let index = v.first().copied().unwrap_or(1.0) as i64;
        let values = self.scaled(v.get(1..).unwrap_or(&[]));
        let changed = (values[self.axis] - self.g5x[self.axis]).abs() > 1e-9;
        if self.started && !self.ended && index == self.g5x_index && changed {
            return Err("the program changes a work offset's value (G10)".into());
        }
        self.g5x = values;
        self.g5x_index = index;
        Ok(())
    }

    fn set_g92(&mut self, v: &[f64]) -> Result<(), String> {
        let values = self.scaled(v);
        if self.started && !self.ended {
            return Err("the program changes the G92 offset".into());
        }
        self.g92 = values;
        Ok(())
    }

    fn motion(&mut self, line: usize, name: &str, v: &[f64]) -> Result<(), String> {
        if !self.mm_selected {
            return Err("a move before the program selects mm (G21)".into());
        }
        self.first
            .get_or_insert((self.g5x[self.axis], self.g92[self.axis]));
        let p = self.scaled(v);
        let mut machine = [0.0; 9];
        for k in 0..v.len().min(9) {
            machine[k] = p[k] + self.g5x[k] + self.g92[k] + self.tool[k];
            if k != self.axis && (machine[k] - self.machine[k]).abs() > 1e-9 {
                self.tracker.other(
                    line,
                    format!("{name} moves {} to {:.4}", &AXES[k..=k], machine[k]),
                );
            }
        }
        self.machine = machine;
        let feed = if name == "STRAIGHT_TRAVERSE" {
            Feed::Rapid
        } else {
            Feed::PerMinute(
                self.feed
                    * if self.axis < 3 || self.axis > 5 {
                        self.mm_per_unit
                    } else {
                        1.0
                    },
            )
        };
        self.tracker.go(line, machine[self.axis], feed);
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::super::machine::{turn, verify};
    use super::super::{expect, linear_plan, plan_at, small_plan, today};
    use super::*;
    use axcheck::simulate::Cycle;
    use axcheck::units::{AxisKind, Travel};

    fn lcnc(axis: char) -> Lcnc {
        Lcnc {
            axis,
            g54: 100.0,
            g92: 7.0,
            wrapped: false,
            lathe: false,
        }
    }

    /// The small plan with G53 in every motion block.
    const G53: &str = "%\n(machine coordinates)\nG17 G21 G40 G80 G90 G94\nG53 G1 X6.000 F1500.000\nG53 G1 X10.000\nG4 P2.500\nG53 G1 X50.000 (T2 up)\nG4 P2.500\nG53 G1 X54.000\nG53 G1 X50.000\nG4 P2.500\nG53 G1 X10.000\nG4 P2.500\nM2\n%\n";

    /// The acceptance test's setting: G54 = 100 mm, G92 = 7 mm; the machine positions of a
    /// G53 program equal the plan's targets.
    #[test]
    fn g53_reaches_the_targets_in_machine_coordinates_with_g54_and_g92_set() {
        let run = run(G53, &lcnc('X')).unwrap();
        assert_eq!((run.g5x, run.g92), (100.0, 7.0));
        let plan = small_plan(AxisKind::Linear);
        assert_eq!(
            verify(&plan, &run.trace, &expect(0.0, false)),
            Vec::<String>::new()
        );
    }

    /// Today's head `G17 G21 G40 G49 G54 G80 G90 G94`: G49 is a tool-length change.
    #[test]
    fn g49_is_refused() {
        let program = today("linuxcnc.ngc");
        assert!(
            program.contains("\nG17 G21 G40 G49 G54 G80 G90 G94\n"),
            "{program}"
        );
        let e = run(&program, &lcnc('X')).unwrap_err();
        assert!(
            e.why.contains("changes the tool length offset (G43/G49)"),
            "{e}"
        );
    }

    /// Today's program (its G49 taken out) moves in G54 + G92: every reading 107 mm off.
    #[test]
    fn todays_program_moves_in_the_work_offset() {
        let plan = linear_plan(Cycle::Standard);
        let program = today("linuxcnc.ngc").replace(" G49", "");
        let run = run(&program, &lcnc('X')).unwrap();
        let in_work = verify(&plan, &run.trace, &expect(107.0, false));
        assert_eq!(in_work, Vec::<String>::new());
        let problems = verify(&plan, &run.trace, &expect(0.0, false));
        let t1 = plan.targets[0];
        let first = format!("at {:.4} instead of {t1:.4}", t1 + 107.0);
        assert!(problems[0].contains(&first), "{problems:?}");
    }

    /// Today's rotary start `G1 C-4.000` with WRAPPED_ROTARY: rs274 takes it as 4° reached
    /// turning negative; every later incremental target is 8° from its label.
    #[test]
    fn a_first_absolute_c_minus_4_lands_at_plus_4_on_a_wrapped_axis() {
        let plan = plan_at(
            AxisKind::Rotary,
            Travel::Range([-10.0, 360.0]),
            Cycle::Standard,
            &[0.0, 90.0],
        );
        let program = today("linuxcnc-rotary.ngc").replace(" G49", "");
        assert!(program.contains("\nG1 C-4.000 F1500.000 "), "{program}");
        let cfg = Lcnc {
            g54: 0.0,
            g92: 0.0,
            wrapped: true,
            ..lcnc('C')
        };
        let wrapped = run(&program, &cfg).unwrap();
        assert_eq!(turn(wrapped.trace.moves[0].to), 4.0);
        assert_eq!(turn(wrapped.trace.readings[0].position), 8.0);
        assert!(!verify(&plan, &wrapped.trace, &expect(0.0, true)).is_empty());
        let plain = run(
            &program,
            &Lcnc {
                wrapped: false,
                ..cfg
            },
        )
        .unwrap();
        assert_eq!(
            verify(&plan, &plain.trace, &expect(0.0, false)),
            Vec::<String>::new()
        );
    }

    /// A finding for the writer: with offsets on a wrapped axis, rs274 unwraps a G53 value
    /// from |value − offsets| with the value's sign, so `G53 C5` with 107° of offsets ends at
    /// 209°, not 5°; `G53 C355` ends at 355°.
    #[test]
    fn g53_on_a_wrapped_axis_with_offsets_misses_below_the_offsets() {
        let cfg = Lcnc {
            wrapped: true,
            ..lcnc('C')
        };
        let program = "G21 G90 G94\nG53 G1 C5.000 F1500\nG4 P1\nG53 G1 C355.000\nG4 P1\nM2\n";
        let run = run(program, &cfg).unwrap();
        let at: Vec<f64> = run
            .trace
            .readings
            .iter()
            .map(|r| turn(r.position))
            .collect();
        assert_eq!(at, [209.0, 355.0]);
    }

    #[test]
    fn a_program_that_does_not_select_mm_is_refused() {
        let e = run(&G53.replace("G21 ", ""), &lcnc('X')).unwrap_err();
        assert!(e.why.contains("before the program selects mm (G21)"), "{e}");
        let e = run(
            &G53.replace(
                "G4 P2.500\nG53 G1 X50.000 (T2 up)",
                "G4 P2.500\nG91 G53 G1 X50.000",
            ),
            &lcnc('X'),
        )
        .unwrap_err();
        assert!(e.why.contains("Cannot use g53 incremental"), "{e}");
    }
}
