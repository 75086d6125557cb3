//! The part programs, run through a small interpreter written for these tests
//! ([`interpreter`]): every target is read the right number of times from each direction,
//! after an approach of at least the overrun, dwelling as stated, in machine coordinates
//! whatever the work offset (or in the work offset with `--coordinates work`), on linear,
//! rotary and lathe axes, for every cycle; each control's rules for axis words, rotary
//! starts, travel, machine coordinates and lathes. Golden files per control.

mod interpreter;

use axcheck::evaluate::StandardId;
use axcheck::plan::programs::{self, Coordinates, GcodeSystem, Job};
use axcheck::plan::{self, Axis, Motion, Plan};
use axcheck::simulate::Cycle;
use axcheck::units::{AxisKind, Travel};
use interpreter::Control;

/// The work offset the interpreter applies to moves not in machine coordinates, mm or deg.
const OFFSET: f64 = 107.0;

/// Writes `job`'s program for `control` and runs it: every target read `runs` times each
/// way, after an approach of the overrun or more, dwelling as planned, at the planned
/// feed, and nothing else read; in machine coordinates the positions are the targets
/// whatever the work offset (FANUC's head states the offsets that must be 0, and runs
/// with them 0), in work coordinates the targets plus the offset.
fn check_program(control: &str, job: &Job) {
    let program = programs::find(control).unwrap().write(job).unwrap();
    let plan = job.plan;
    let fanuc_machine = control == "fanuc" && job.coordinates == Coordinates::Machine;
    let lcnc_corrected =
        control == "linuxcnc" && job.coordinates == Coordinates::Machine && job.continuous_rotary();
    let c = Control {
        name: programs::find(control).unwrap().name(),
        axis: job.axis.to_string(),
        offset: if fanuc_machine { 0.0 } else { OFFSET },
        lathe: job.lathe,
        modulo: job.continuous_rotary(),
    };
    if fanuc_machine {
        assert!(program.contains(" MUST BE 0 THE ABSOLUTE"), "{program}");
    }
    // LinuxCNC's correction of what G53 misreads on a wrapped axis (rs274 runs it in
    // program_check; this interpreter has no such defect and skips it).
    assert_eq!(program.contains("#<misread>"), lcnc_corrected, "{program}");
    let m = interpreter::run(&c, &program);
    let context = format!("{control} {:?} {:?}\n{program}", job.coordinates, job.lathe);
    assert_eq!(m.feed, Some(plan.motion.feed), "{context}");
    assert_eq!(
        m.taken.len(),
        2 * plan.runs * plan.targets.len(),
        "{context}"
    );
    let shift = shift(job, &c, &m);
    for &target in &plan.targets {
        for upward in [true, false] {
            let here: Vec<_> = m
                .taken
                .iter()
                .filter(|t| (t.position - shift - target).abs() < 1e-9 && t.upward == upward)
                .collect();
            assert_eq!(here.len(), plan.runs, "target {target} {upward}: {context}");
            for t in here {
                assert!(t.approach >= plan.motion.overrun - 1e-9, "{t:?}: {context}");
                assert_eq!(t.dwell, plan.motion.dwell_s, "{context}");
            }
        }
    }
}

/// Where the program's positions lie from the plan's: the work offset in work
/// coordinates; nothing else, on a continuous rotary axis too (its first move goes to a
/// target's angle within one turn, the position an axis that counts turns reaches).
fn shift(job: &Job, c: &Control, m: &interpreter::Machine) -> f64 {
    let offset = match job.coordinates {
        Coordinates::Machine => 0.0,
        Coordinates::Work => c.offset,
    };
    if job.continuous_rotary() {
        let first = programs::first_position(job.plan);
        assert!((0.0..360.0).contains(&first), "{first}");
        assert_eq!(m.absolute, [first], "one absolute move, to {first}");
    }
    offset
}

fn axis(kind: AxisKind, travel: Travel, continuous: bool) -> Axis {
    Axis {
        kind,
        standard: StandardId::Iso230_2,
        travel,
        continuous,
        measurement_travel: None,
        pitch: Some(5.0),
        scale_pitch: None,
    }
}

fn motion(cycle: Cycle) -> Motion {
    Motion {
        runs: Some(3),
        cycle,
        overrun: 4.0,
        dwell_s: 2.5,
        feed: 1500.0,
    }
}

/// Every control's program, for every cycle, in machine and work coordinates: on a linear
/// axis, a continuous rotary one over a turn and over three turns, a rotary one that is
/// not continuous, and on lathes (X in each control's radius or diameter form, every FANUC
/// G-code system; C with its increments); HEIDENHAIN refuses lathes.
#[test]
fn every_program_visits_every_target_as_the_cycle_asks() {
    let cases = [
        (
            axis(AxisKind::Linear, Travel::Range([-200.0, 800.0]), false),
            "X",
        ),
        (axis(AxisKind::Rotary, Travel::Length(360.0), true), "C"),
        (
            axis(AxisKind::Rotary, Travel::Range([0.0, 1080.0]), true),
            "C",
        ),
        (
            axis(AxisKind::Rotary, Travel::Range([0.0, 360.0]), false),
            "A",
        ),
    ];
    let lathes = [
        None,
        Some(GcodeSystem::A),
        Some(GcodeSystem::B),
        Some(GcodeSystem::C),
    ];
    for (a, address) in &cases {
        for cycle in [Cycle::Standard, Cycle::Pilgrim, Cycle::Step] {
            let p = plan::plan(a, &motion(cycle), 7).unwrap();
            for coordinates in [Coordinates::Machine, Coordinates::Work] {
                for lathe in lathes {
                    let address = if lathe.is_some() && *address == "A" {
                        "C"
                    } else {
                        address
                    };
                    for control in programs::names() {
                        let job = Job {
                            coordinates,
                            lathe,
                            ..Job::new(&p, address, "ISO230TEST")
                        };
                        if lathe.is_some() && control == "heidenhain" {
                            assert!(programs::find(control).unwrap().write(&job).is_err());
                            continue;
                        }
                        check_program(control, &job);
                    }
                }
            }
        }
    }
}

/// The plan of the golden programs: targets 10, 55.3 and 100 (mm or deg), two runs,
/// standard cycle, overrun 5, dwell 2 s, feed 1000.
fn golden_plan(kind: AxisKind, continuous: bool) -> Plan {
    let travel = match kind {
        AxisKind::Linear => Travel::Range([0.0, 200.0]),
        AxisKind::Rotary => Travel::Length(360.0),
    };
    let motion = Motion {
        runs: Some(2),
        cycle: Cycle::Standard,
        overrun: 5.0,
        dwell_s: 2.0,
        feed: 1000.0,
    };
    let targets = match kind {
        AxisKind::Linear => vec![10.0, 55.3, 100.0],
        AxisKind::Rotary => vec![0.0, 90.0, 180.0],
    };
    plan::with_targets(&axis(kind, travel, continuous), &motion, targets).unwrap()
}

/// The golden programs: per control, a linear X in machine coordinates (`NAME.EXT`) and
/// in work coordinates (`NAME-work.EXT`), a continuous rotary C over 0°, 90°, 180°
/// (`NAME-rotary.EXT`), and a lathe's X (`NAME-lathe.EXT`, FANUC in G-code system A).
/// `AXCHECK_BLESS=1` writes them anew.
#[test]
fn golden_programs_per_control() {
    let linear = golden_plan(AxisKind::Linear, false);
    let rotary = golden_plan(AxisKind::Rotary, true);
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/programs");
    for control in programs::DIALECTS {
        let cases = [
            ("", Job::new(&linear, "X", "ISO230X")),
            (
                "-work",
                Job {
                    coordinates: Coordinates::Work,
                    ..Job::new(&linear, "X", "ISO230X")
                },
            ),
            ("-rotary", Job::new(&rotary, "C", "ISO230C")),
            (
                "-lathe",
                Job {
                    lathe: Some(GcodeSystem::A),
                    ..Job::new(&linear, "X", "ISO230X")
                },
            ),
        ];
        for (suffix, job) in cases {
            let Ok(program) = control.write(&job) else {
                assert_eq!((control.name(), suffix), ("heidenhain", "-lathe"));
                continue;
            };
            let golden = dir.join(format!(
                "{}{suffix}.{}",
                control.name(),
                control.extension()
            ));
            if std::env::var_os("AXCHECK_BLESS").is_some() {
                std::fs::write(&golden, &program).unwrap();
            }
            let expected = std::fs::read_to_string(&golden).unwrap();
            assert_eq!(program, expected, "{}", golden.display());
        }
    }
}

/// An axis address the control does not take is refused, naming the control; SINUMERIK
/// writes a name with digits `X1=`.
#[test]
fn an_address_the_control_cannot_take_is_refused() {
    let p = plan::plan(
        &axis(AxisKind::Linear, Travel::Length(500.0), false),
        &Motion::default(),
        1,
    )
    .unwrap();
    let job = Job::new(&p, "X1", "T");
    let fanuc = programs::find("fanuc").unwrap();
    assert_eq!(
        fanuc.write(&job).unwrap_err().to_string(),
        "FANUC addresses an axis by one of the letters X, Y, Z, A, B, C, U, V, W; got `X1` (--axis)"
    );
    let siemens = programs::find("siemens-840d").unwrap().write(&job).unwrap();
    assert!(
        siemens.contains("\nG1 SUPA X1=5.000 F1000.000 ; start at 5.000 mm\n"),
        "{siemens}"
    );
    let twincat = programs::find("twincat").unwrap();
    assert_eq!(
        twincat
            .write(&Job::new(&p, "K1", "T"))
            .unwrap_err()
            .to_string(),
        "The TwinCAT CNC names an axis with A, B, C, U, V, W, X, Y, Z or Q, then letters or digits (X, C, X1); got `K1` (--axis)"
    );
}

/// The axis words of a program: each word that starts with the axis's name, the comments
/// left out.
fn axis_words<'a>(program: &'a str, axis: &str) -> Vec<&'a str> {
    program
        .lines()
        .flat_map(|l| l.split(';').next().unwrap_or("").split_whitespace())
        .filter(|w| w.starts_with(axis))
        .collect()
}

/// TwinCAT (ISG): an axis name of more than one character, or one that ends in a digit,
/// is followed by `=` ("an equals sign must follow axis identifiers that contain more
/// than one character"): `X1=10.000`, never `X110.000`; `C2=0.000`, never `C20.000`.
#[test]
fn twincat_writes_an_equals_sign_after_a_name_of_more_than_one_character() {
    let twincat = programs::find("twincat").unwrap();
    let linear = golden_plan(AxisKind::Linear, false);
    for coordinates in [Coordinates::Machine, Coordinates::Work] {
        let job = Job {
            coordinates,
            ..Job::new(&linear, "X1", "T")
        };
        let program = twincat.write(&job).unwrap();
        let words = axis_words(&program, "X1");
        let moves = programs::blocks(&linear)
            .iter()
            .filter(|b| matches!(b, programs::Block::Move { .. }))
            .count();
        assert_eq!((words.len(), moves), (16, 16), "{program}");
        assert!(words.iter().all(|w| w.starts_with("X1=")), "{words:?}");
        assert!(words.contains(&"X1=10.000") && words.contains(&"X1=55.300"));
    }
    let rotary = golden_plan(AxisKind::Rotary, true);
    let program = twincat.write(&Job::new(&rotary, "C2", "T")).unwrap();
    assert!(
        program.contains("\n#SUPPRESS OFFSETS C2=0.000 ; align at 0.000 deg\n"),
        "{program}"
    );
    assert!(program.contains("\nG01 C2=-5.000 ; start at -5.000 deg\n"));
    assert!(program.contains("\nG01 C2=5.000 ; T1 up, run 1 at 0.000 deg\n"));
    assert!(program.contains("\nG01 C2=-5.000 ; T3 down, run 1 at 180.000 deg\n"));
    assert!(
        axis_words(&program, "C2")
            .iter()
            .all(|w| w.starts_with("C2="))
    );
}

/// The first move of each control's program (the block at or after the first comment of
/// a start or an alignment)
/// and its value: the number after the axis's word.
fn first_move(program: &str, axis: &str) -> (String, f64) {
    let lines: Vec<&str> = program.lines().collect();
    let from = lines
        .iter()
        .position(|l| {
            let l = l.to_lowercase();
            l.contains("start at") || l.contains("align at")
        })
        .expect("a start");
    let word = format!(" {axis}");
    let line = lines[from..]
        .iter()
        .find(|l| l.split(['(', ';']).next().unwrap().contains(&word))
        .expect("a move");
    let at = line.find(&word).unwrap() + word.len();
    let number: String = line[at..]
        .trim_start_matches('=')
        .chars()
        .take_while(|c| c.is_ascii_digit() || matches!(c, '.' | '-' | '+'))
        .collect();
    (line.to_string(), number.parse().unwrap())
}

/// A continuous rotary axis goes first to its first target's angle within one turn (0°),
/// on every control: an axis that counts turns and a modulo, roll-over or shortest-path
/// axis stand there alike (a start at `C355.000` for −5° put a counting axis's readings a
/// turn up); the start at −5° follows incrementally, and the head says so. An axis that
/// is not continuous starts at its position.
#[test]
fn a_rotary_start_lands_where_its_label_says() {
    let rotary = golden_plan(AxisKind::Rotary, true);
    for control in programs::DIALECTS {
        let program = control.write(&Job::new(&rotary, "C", "T")).unwrap();
        let (line, first) = first_move(&program, "C");
        assert_eq!(first, 0.0, "{}: {line}", control.name());
        let lower = program.to_lowercase();
        assert!(lower.contains("align at 0.000 deg"), "{program}");
        assert!(lower.contains("start at -5.000 deg"), "{program}");
        assert!(!lower.contains("355.000"), "{program}");
        assert!(
            lower.contains("the first move goes to 0.000 deg, an angle within one turn"),
            "the head says so: {program}"
        );
    }
    let from_minus_30 = plan::with_targets(
        &axis(AxisKind::Rotary, Travel::Length(360.0), true),
        &Motion::default(),
        vec![-30.0, 60.0, 150.0],
    )
    .unwrap();
    let program = programs::find("linuxcnc").unwrap();
    let text = program.write(&Job::new(&from_minus_30, "C", "T")).unwrap();
    assert_eq!(
        first_move(&text, "C").1,
        60.0,
        "the first target within a turn"
    );
    let tilting = Axis {
        travel: Travel::Range([-90.0, 90.0]),
        ..axis(AxisKind::Rotary, Travel::Length(1.0), false)
    };
    let p = plan::plan(&tilting, &Motion::default(), 1).unwrap();
    assert_eq!(p.measurement_travel, [-80.0, 80.0]);
    let program = programs::find("linuxcnc").unwrap();
    let (line, start) = first_move(&program.write(&Job::new(&p, "A", "T")).unwrap(), "A");
    assert_eq!(
        (start, line.starts_with("G53 G1 A-85.000 F1000.000")),
        (-85.0, true)
    );
}

/// A rotary axis that is not continuous is planned inside its travel as a linear one is
/// (the measurement travel less twice the overrun at each end), and a plan whose moves
/// leave its travel (an old plan file of 0…360° with its overruns at −5° and 365°) is
/// refused by every control, naming the move and the travel.
#[test]
fn a_rotary_axis_that_is_not_continuous_stays_inside_its_travel() {
    let table = axis(AxisKind::Rotary, Travel::Length(360.0), false);
    let p = plan::plan(&table, &Motion::default(), 1).unwrap();
    assert_eq!(p.measurement_travel, [10.0, 350.0]);
    for control in programs::DIALECTS {
        let program = control.write(&Job::new(&p, "C", "T")).unwrap();
        assert!(
            program.to_lowercase().contains("not continuous"),
            "{program}"
        );
    }
    let old = Axis {
        measurement_travel: Some([0.0, 360.0]),
        ..table
    };
    let p = plan::with_targets(
        &old,
        &Motion::default(),
        vec![0.0, 90.0, 180.0, 270.0, 360.0],
    )
    .unwrap();
    for control in programs::DIALECTS {
        assert_eq!(
            control
                .write(&Job::new(&p, "C", "T"))
                .unwrap_err()
                .to_string(),
            "the start move to -5.000 deg leaves the axis travel 0.000 to 360.000 deg of axis C, which is not continuous: mark a rotary axis that turns freely continuous (--continuous, or `continuous: true` in the campaign or the plan file), else plan it again inside its travel",
            "{}",
            control.name()
        );
    }
    let linear = axis(AxisKind::Linear, Travel::Range([0.0, 200.0]), false);
    let p = plan::with_targets(&linear, &Motion::default(), vec![0.0, 100.0, 200.0]).unwrap();
    assert_eq!(
        programs::find("fanuc")
            .unwrap()
            .write(&Job::new(&p, "X", "T"))
            .unwrap_err()
            .to_string(),
        "the start move to -5.000 mm leaves the axis travel 0.000 to 200.000 mm of axis X: plan it again inside the travel"
    );
}

/// Only the tested axis moves: no `G49` (a length-offset cancel may move Z), no `G43`,
/// no tool call, no `G54` on LinuxCNC (G53 needs none), nor a word of another axis (the
/// interpreter refuses any word it does not know).
#[test]
fn only_the_tested_axis_moves() {
    let linear = golden_plan(AxisKind::Linear, false);
    for control in programs::DIALECTS {
        for coordinates in [Coordinates::Machine, Coordinates::Work] {
            let job = Job {
                coordinates,
                ..Job::new(&linear, "Z", "T")
            };
            let program = control.write(&job).unwrap();
            for line in program.lines() {
                let code = line.split(['(', ';']).next().unwrap();
                for word in code.split_whitespace() {
                    let tool_call = word.starts_with("TOOL")
                        || word.starts_with('T')
                            && word[1..].starts_with(|c: char| c.is_ascii_digit());
                    let length = matches!(word, "G49" | "G43" | "G44" | "M6" | "M06" | "D0");
                    assert!(
                        !tool_call && !length,
                        "{}: `{word}` in `{line}`",
                        control.name()
                    );
                }
            }
            assert!(!(control.name() == "linuxcnc" && program.contains("G54")));
            assert!(program.contains("Only axis Z moves") || program.contains("ONLY AXIS Z MOVES"));
        }
    }
}

/// Every absolute move is in machine coordinates by default, by each control's own means
/// that keeps the feed: LinuxCNC `G53`, SINUMERIK `SUPA`, HEIDENHAIN `M91`, TwinCAT
/// `#SUPPRESS OFFSETS` in the block (and never in an incremental one); FANUC selects G54
/// and its head states the offsets that must be 0. With `--coordinates work` none is
/// written and the head says the tables need the work offset added.
#[test]
fn absolute_moves_are_in_machine_coordinates_by_default() {
    let linear = golden_plan(AxisKind::Linear, false);
    let rotary = golden_plan(AxisKind::Rotary, true);
    let marks = [
        ("linuxcnc", "G53 G1 "),
        ("siemens-840d", "G1 SUPA "),
        ("heidenhain", " M91"),
        ("twincat", "#SUPPRESS OFFSETS "),
    ];
    for (name, mark) in marks {
        let control = programs::find(name).unwrap();
        for (p, axis) in [(&linear, "X"), (&rotary, "C")] {
            let program = control.write(&Job::new(p, axis, "T")).unwrap();
            let moves: Vec<&str> = program
                .lines()
                .filter(|l| {
                    let code = l.split(['(', ';']).next().unwrap();
                    code.contains(&format!(" {axis}")) || code.contains(&format!(" I{axis}"))
                })
                .filter(|l| !l.contains("#TIME") && !l.contains("G4"))
                .collect();
            let absolute = match axis {
                "X" => moves.len(),
                _ => 1,
            };
            for (k, line) in moves.iter().enumerate() {
                assert_eq!(
                    line.contains(mark),
                    k < absolute,
                    "{name}: {line}\n{program}"
                );
            }
            assert!(program.contains("Machine coordinates: "), "{program}");
            let work = Job {
                coordinates: Coordinates::Work,
                ..Job::new(p, axis, "T")
            };
            let program = control.write(&work).unwrap();
            let code: Vec<&str> = program
                .lines()
                .map(|l| l.split(['(', ';']).next().unwrap())
                .collect();
            assert!(!code.iter().any(|c| c.contains(mark)), "{program}");
            assert!(
                program.contains("The compensation tables axcheck writes are in machine positions: add the active work offset of axis"),
                "{program}"
            );
        }
    }
    let fanuc = programs::find("fanuc").unwrap();
    let program = fanuc.write(&Job::new(&linear, "X", "T")).unwrap();
    assert!(
        program.contains("\nG17 G21 G40 G80 G90 G94 G54\n"),
        "{program}"
    );
    assert!(program.contains("\n(MACHINE COORDINATES G53 IS NOT USED, AS FANUC MOVES G53 BLOCKS AT RAPID TRAVERSE, G54 IS SELECTED)\n(THE G54 AND EXTERNAL EXT OFFSETS OF AXIS X, ANY G52 OR G92 SHIFT OF IT AND ANY TOOL OFFSET ACTING ON IT MUST BE 0 THE ABSOLUTE POSITION DISPLAY THEN EQUALS THE MACHINE POSITION)\n"), "{program}");
    assert!(!program.lines().any(|l| l.starts_with("G53")), "{program}");
    let work = fanuc
        .write(&Job {
            coordinates: Coordinates::Work,
            ..Job::new(&linear, "X", "T")
        })
        .unwrap();
    assert!(work.contains("\nG17 G21 G40 G80 G90 G94\n") && !work.contains("G54"));
}

/// Lathes: FANUC in G-code system A has no G90, G91 or G94 word and feeds per minute
/// with G98, its X words are diameters (twice the slide's position) and its head says so;
/// system B and C keep G90/G91 and G94 (C with G71 for metric); SINUMERIK `DIAMOF`,
/// LinuxCNC `G8`, TwinCAT `G52` program X in radius; HEIDENHAIN refuses.
#[test]
fn lathe_programs_write_x_as_each_control_programs_it() {
    let linear = golden_plan(AxisKind::Linear, false);
    let rotary = golden_plan(AxisKind::Rotary, true);
    let lathe = |p, axis, system| Job {
        lathe: Some(system),
        ..Job::new(p, axis, "T")
    };
    let fanuc = programs::find("fanuc").unwrap();
    for (p, axis) in [(&linear, "X"), (&rotary, "C")] {
        let program = fanuc.write(&lathe(p, axis, GcodeSystem::A)).unwrap();
        let words: Vec<&str> = program
            .lines()
            .flat_map(|l| l.split('(').next().unwrap().split_whitespace())
            .collect();
        for word in ["G90", "G91", "G94"] {
            assert!(!words.contains(&word), "{word}: {program}");
        }
        assert!(program.contains("\nG18 G21 G40 G98 G54\n"), "{program}");
        assert!(program.contains("G-CODE SYSTEM A"), "{program}");
    }
    let x = fanuc.write(&lathe(&linear, "X", GcodeSystem::A)).unwrap();
    assert!(
        x.contains(
            "\nG01 X10.000 F1000.000 (START AT 5.000 MM)\nX20.000 (T1 UP, RUN 1 AT 10.000 MM)\n"
        ),
        "{x}"
    );
    assert!(x.contains("X IS PROGRAMMED IN DIAMETER"), "{x}");
    let c = fanuc.write(&lathe(&rotary, "C", GcodeSystem::A)).unwrap();
    assert!(
        c.contains(
            "\nG01 C0.000 F1000.000 (ALIGN AT 0.000 DEG)\nH-5.000 (START AT -5.000 DEG)\nH5.000 (T1 UP, RUN 1 AT 0.000 DEG)\n"
        ),
        "{c}"
    );
    let b = fanuc.write(&lathe(&linear, "X", GcodeSystem::B)).unwrap();
    assert!(b.contains("\nG18 G21 G40 G90 G94 G54\n") && b.contains("\nG90 G01 X10.000 F1000.000"));
    let c = fanuc.write(&lathe(&linear, "X", GcodeSystem::C)).unwrap();
    assert!(c.contains("\nG18 G71 G40 G90 G94 G54\n"), "{c}");
    let refused = fanuc
        .write(&lathe(&linear, "U", GcodeSystem::A))
        .unwrap_err();
    assert!(
        refused
            .to_string()
            .contains("`U` is an incremental address"),
        "{refused}"
    );
    let radius = [
        (
            "siemens-840d",
            "G18 G71 G90 G94 G40 G60 DIAMOF",
            "G1 SUPA X5.000 F1000.000",
        ),
        (
            "linuxcnc",
            "G18 G8 G21 G40 G80 G90 G94",
            "G53 G1 X5.000 F1000.000",
        ),
        (
            "twincat",
            "G18 G71 G90 G94 G40 G52",
            "#SUPPRESS OFFSETS X5.000",
        ),
    ];
    for (name, setup, start) in radius {
        let program = programs::find(name)
            .unwrap()
            .write(&lathe(&linear, "X", GcodeSystem::A))
            .unwrap();
        assert!(program.contains(&format!("\n{setup}\n")), "{program}");
        assert!(program.contains(&format!("\n{start} ")), "{program}");
        assert!(program.contains("X is programmed in radius"), "{program}");
    }
    let heidenhain = programs::find("heidenhain").unwrap();
    assert_eq!(
        heidenhain
            .write(&lathe(&linear, "X", GcodeSystem::A))
            .unwrap_err()
            .to_string(),
        "no HEIDENHAIN program is written for a lathe: whether the TNC's turning mode (FUNCTION MODE TURN) programs X as a diameter is not confirmed here; write it by hand, or drop --lathe if the axis moves in milling mode"
    );
}
