//! The part programs, run through a small interpreter written for these tests (absolute and
//! incremental moves, feed, dwell; each control's comments and frame skipped): every target
//! is read the right number of times from each direction, after an approach of at least the
//! overrun, dwelling as stated. Golden files per control.

use axcheck::evaluate::StandardId;
use axcheck::plan::programs::{self, Job};
use axcheck::plan::{self, Axis, Motion, Plan};
use axcheck::simulate::Cycle;
use axcheck::units::{AxisKind, Travel};

/// A reading the program takes: where, coming from which side, after how long a move in
/// that direction, and how long it dwells.
#[derive(Debug, Clone, PartialEq)]
struct Taken {
    position: f64,
    upward: bool,
    approach: f64,
    dwell: f64,
}

/// The machine the interpreter keeps: absolute or incremental, where the axis is, which way
/// it last moved and how far since it last turned.
#[derive(Default)]
struct Machine {
    incremental: bool,
    position: Option<f64>,
    upward: Option<bool>,
    run: f64,
    feed: Option<f64>,
    taken: Vec<Taken>,
}

impl Machine {
    fn go(&mut self, value: f64, incremental: bool) {
        let from = self.position.unwrap_or(0.0);
        let to = if incremental || self.incremental && self.position.is_some() {
            from + value
        } else {
            value
        };
        if self.position.is_some() && (to - from).abs() > 1e-12 {
            let up = to > from;
            if self.upward == Some(up) {
                self.run += (to - from).abs();
            } else {
                self.run = (to - from).abs();
            }
            self.upward = Some(up);
        }
        self.position = Some(to);
    }

    fn dwell(&mut self, seconds: f64) {
        self.taken.push(Taken {
            position: self.position.expect("a dwell after a move"),
            upward: self.upward.expect("a dwell after a move"),
            approach: self.run,
            dwell: seconds,
        });
    }
}

/// The code of a line without its comments, as `control` writes them.
fn code(control: &str, line: &str) -> String {
    let mut out = String::new();
    let mut depth = 0;
    for c in line.chars() {
        match c {
            '(' if control != "heidenhain" && control != "siemens-840d" => depth += 1,
            ')' if depth > 0 => depth -= 1,
            ';' if depth == 0 && control != "fanuc" => break,
            _ if depth == 0 => out.push(c),
            _ => {}
        }
    }
    out.trim().to_string()
}

/// A number after a word's letter(s).
fn value(word: &str, prefix: &str) -> Option<f64> {
    word.strip_prefix(prefix)?
        .trim_start_matches('=')
        .parse()
        .ok()
}

/// Runs a G-code program (FANUC, SINUMERIK, LinuxCNC, TwinCAT) on axis `axis`.
fn g_code(control: &str, program: &str, axis: &str) -> Machine {
    let mut m = Machine::default();
    for line in program.lines() {
        let code = code(control, line);
        let words: Vec<&str> = code.split_whitespace().collect();
        if words.is_empty() || matches!(words[0], "%" | "M30" | "M2") || words[0].starts_with('O') {
            continue;
        }
        if words[0] == "#TIME" {
            m.dwell(words[1].parse().unwrap());
            continue;
        }
        let dwell_word = match control {
            "fanuc" => "X",
            "siemens-840d" => "F",
            "linuxcnc" => "P",
            _ => "X",
        };
        if words.iter().any(|w| matches!(*w, "G04" | "G4")) {
            let t = words
                .iter()
                .find_map(|w| value(w, dwell_word))
                .expect("a dwell time");
            m.dwell(t);
            continue;
        }
        for w in &words {
            match *w {
                "G90" => m.incremental = false,
                "G91" => m.incremental = true,
                _ => {}
            }
        }
        for w in &words {
            if let Some(f) = value(w, "F") {
                m.feed = Some(f);
            }
            if let Some(v) = value(w, axis) {
                m.go(v, false);
            }
        }
    }
    m
}

/// Runs a HEIDENHAIN conversational program: `L X+…`, `L IC-…`, cycle 9's dwell.
fn klartext(program: &str, axis: &str) -> Machine {
    let mut m = Machine::default();
    for (k, line) in program.lines().enumerate() {
        let (number, rest) = line.split_once(' ').unwrap();
        assert_eq!(number, k.to_string(), "blocks numbered from 0");
        let code = code("heidenhain", rest);
        if let Some(t) = code.strip_prefix("CYCL DEF 9.1 DWELL ") {
            m.dwell(t.parse().unwrap());
            continue;
        }
        let Some(words) = code.strip_prefix("L ") else {
            continue;
        };
        for w in words.split_whitespace() {
            if let Some(f) = value(w, "F") {
                m.feed = Some(f);
            } else if let Some(v) = value(w, &format!("I{axis}")) {
                m.go(v, true);
            } else if let Some(v) = value(w, axis) {
                m.go(v, false);
            }
        }
    }
    m
}

fn run(control: &str, program: &str, axis: &str) -> Machine {
    if control == "heidenhain" {
        klartext(program, axis)
    } else {
        g_code(control, program, axis)
    }
}

/// Every target read `runs` times each way, after an approach of the overrun or more,
/// dwelling as planned, at the planned feed, and nothing else read.
fn check_program(control: &str, plan: &Plan, axis: &str) {
    let job = Job {
        plan,
        axis,
        name: "ISO230TEST",
    };
    let program = programs::find(control).unwrap().write(&job).unwrap();
    let m = run(control, &program, axis);
    assert_eq!(m.feed, Some(plan.motion.feed), "{control}");
    assert_eq!(
        m.taken.len(),
        2 * plan.runs * plan.targets.len(),
        "{control}\n{program}"
    );
    for &target in &plan.targets {
        for upward in [true, false] {
            let here: Vec<&Taken> = m
                .taken
                .iter()
                .filter(|t| (t.position - target).abs() < 1e-9 && t.upward == upward)
                .collect();
            assert_eq!(
                here.len(),
                plan.runs,
                "{control}: target {target} {upward}\n{program}"
            );
            for t in here {
                assert!(t.approach >= plan.motion.overrun - 1e-9, "{control}: {t:?}");
                assert_eq!(t.dwell, plan.motion.dwell_s, "{control}");
            }
        }
    }
}

fn axis(kind: AxisKind, travel: Travel) -> Axis {
    Axis {
        kind,
        standard: StandardId::Iso230_2,
        travel,
        measurement_travel: None,
        pitch: Some(5.0),
        scale_pitch: None,
    }
}

/// Each control's program, for every cycle, on a linear axis and on a rotary one over a
/// whole turn (moves incremental there) and over three turns.
#[test]
fn every_program_visits_every_target_as_the_cycle_asks() {
    let cases = [
        (axis(AxisKind::Linear, Travel::Range([-200.0, 800.0])), "X"),
        (axis(AxisKind::Rotary, Travel::Length(360.0)), "C"),
        (axis(AxisKind::Rotary, Travel::Range([0.0, 1080.0])), "C"),
    ];
    for (a, address) in &cases {
        for cycle in [Cycle::Standard, Cycle::Pilgrim, Cycle::Step] {
            let motion = Motion {
                runs: Some(3),
                cycle,
                overrun: 4.0,
                dwell_s: 2.5,
                feed: 1500.0,
            };
            let p = plan::plan(a, &motion, 7).unwrap();
            for control in programs::names() {
                check_program(control, &p, address);
            }
        }
    }
}

/// The golden programs: three targets (10, 55.3 and 100 mm), two runs, standard cycle,
/// overrun 5 mm, dwell 2 s, feed 1000 mm/min.
#[test]
fn golden_programs_per_control() {
    let a = Axis {
        measurement_travel: None,
        ..axis(AxisKind::Linear, Travel::Range([0.0, 200.0]))
    };
    let motion = Motion {
        runs: Some(2),
        cycle: Cycle::Standard,
        overrun: 5.0,
        dwell_s: 2.0,
        feed: 1000.0,
    };
    let p = plan::with_targets(&a, &motion, vec![10.0, 55.3, 100.0]).unwrap();
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/programs");
    for control in programs::DIALECTS {
        let job = Job {
            plan: &p,
            axis: "X",
            name: "ISO230X",
        };
        let program = control.write(&job).unwrap();
        let golden = dir.join(format!("{}.{}", control.name(), control.extension()));
        if std::env::var_os("AXCHECK_BLESS").is_some() {
            std::fs::write(&golden, &program).unwrap();
        }
        let expected = std::fs::read_to_string(&golden).unwrap();
        assert_eq!(program, expected, "{}", golden.display());
    }
}

/// An axis address the control does not take is refused, naming the control.
#[test]
fn an_address_the_control_cannot_take_is_refused() {
    let p = plan::plan(
        &axis(AxisKind::Linear, Travel::Length(500.0)),
        &Motion::default(),
        1,
    )
    .unwrap();
    let job = Job {
        plan: &p,
        axis: "X1",
        name: "T",
    };
    let fanuc = programs::find("fanuc").unwrap();
    assert_eq!(
        fanuc.write(&job).unwrap_err().to_string(),
        "FANUC addresses an axis by one of the letters X, Y, Z, A, B, C, U, V, W; got `X1` (--axis)"
    );
    let siemens = programs::find("siemens-840d").unwrap().write(&job).unwrap();
    assert!(
        siemens.contains("\nG1 X1=5.000 F1000.000 ; start at 5.000 mm\n"),
        "{siemens}"
    );
}
