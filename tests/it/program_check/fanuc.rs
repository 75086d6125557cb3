//! A FANUC Series 0i / 30i program, read as the control reads it, strictly: each block
//! tokenized, words the check does not model refused, the tested axis simulated in machine
//! coordinates through work offsets, G53, incremental moves, a rotary axis's roll-over,
//! diameter programming and the lathe G-code systems A, B and C.
//!
//! Rules and their sources:
//! - Words: an address letter and a number; a comment in parentheses, not nested, closed
//!   in its block; `;` is the end-of-block code, not a comment; `%` alone on the first and
//!   last line; `O` with up to 4 digits only in the program's first block.
//! - A position without a decimal point is a count of least input increments (`X10` is
//!   0.010 mm with parameter 3401#0 DPI = 0): refused. `G04 X` in seconds needs the point,
//!   `G04 P` in ms may not have one; the dwell block carries nothing else; seconds only in
//!   feed-per-minute mode (in G95/G99 it counts spindle revolutions). SINUMERIK
//!   802D sl/840D sl ISO Milling (PGM) 04.07, §3.3.1 (the FANUC-compatible dialect).
//! - `G53` is one-shot, absolute only, and moves at rapid traverse (same manual, §3.1.1):
//!   accepted, recorded as a rapid move. Unconfirmed: whether a 30i option moves G53 at
//!   feed.
//! - Milling: `G90`/`G91` absolute/incremental, `G94` feed per minute, `G20` (inch) and
//!   `G95` refused, `G49` refused (the tool-length vector is cancelled on the next move of
//!   the tool axis: FANUC 0i-MB Operator's Manual B-63844EN/02 §14.1.2), `G92`, `G52`,
//!   `G10`, `G28` refused (they change offsets or move elsewhere).
//! - Lathe, G-code system A: absolute and incremental are told by the address (X/U, Z/W,
//!   Y/V, C/H), not by G90/G91 (FANUC Series 16i/18i Descriptions B-63522EN/02 §8.1,
//!   p. 109): `G91` does not exist and is refused; `G90` (outer diameter cutting cycle) and
//!   `G94` (end face turning cycle) are cycles and refused; `G98` is feed per minute, `G99`
//!   per revolution. Systems B and C: `G90`/`G91`, `G94`/`G95`; the cycles are `G77`/`G79`
//!   (B) and `G20`/`G24` (C, where inch/mm are `G70`/`G71`). The code table is quoted from a
//!   copy of the FANUC 30i lathe G-code list (cncschool.pl, "GE Fanuc 30i lathe system
//!   code B"), not from a FANUC manual: unconfirmed for system C.
//! - Diameter programming (parameter 1006#3 DIA): X and U are diameters, absolute and
//!   incremental (FANUC Power Mate 0 Operator's Manual B-63444EN/01 §8.4, p. 75): the slide
//!   moves half.
//! - Rotary axis roll-over (1008#0 ROA): an absolute target is taken modulo 360; with
//!   1008#1 RAB = 0 the axis takes the shorter way; with the rotary axis control function
//!   the sign of the value is the direction and its magnitude the target (FANUC 0i-MB
//!   Operator's Manual B-63534EN/02 §20.2.1, §20.2.2). Incremental moves are moves.
//! - Each of feed mode, units, absolute/incremental (mill, B, C) and G00/G01 is set by a
//!   parameter at power-on, so a move before the program set it is refused.

use super::machine::{Feed, Refusal, Trace, Tracker, number, refuse, turn};

/// The lathe G-code systems (parameter 3401#6 GSB, #7 GSC).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GCodeSystem {
    A,
    B,
    C,
}

/// How a rotary axis takes an absolute target.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Rotary {
    /// No roll-over: positions count on past 360°, like a linear axis.
    Linear,
    /// Roll-over, the shorter way (1008#0 ROA = 1, #1 RAB = 0).
    RollOver,
    /// Roll-over with the rotary axis control function: sign = direction.
    SignedDirection,
}

/// The machine the program runs on.
#[derive(Debug, Clone)]
pub struct Fanuc {
    /// `None`: a machining centre; otherwise a lathe in this G-code system.
    pub lathe: Option<GCodeSystem>,
    /// The tested axis's (absolute) address: X, Y, Z, A, B, C.
    pub axis: char,
    /// X in diameter (1006#3 DIA = 1): X and U words are twice the slide's travel.
    pub diameter: bool,
    /// The work zero offsets G54..G59 of the tested axis (slide units: radius on a lathe).
    pub work: [f64; 6],
    /// The work offset active at the start (0 = G54).
    pub active: usize,
    /// The external work zero offset and a G92/G50 shift left by an earlier program.
    pub external: f64,
    pub shift: f64,
    /// `None`: a linear axis.
    pub rotary: Option<Rotary>,
    /// Machine position at the start.
    pub initial: f64,
}

/// A word: its address letter, its text and number.
#[derive(Debug, Clone)]
struct Word {
    letter: char,
    text: String,
    value: f64,
    point: bool,
}

/// What a G code does, in the system in use.
#[derive(Debug, Clone, Copy, PartialEq)]
enum G {
    Rapid,
    Feed,
    Dwell,
    Ignore,
    Metric,
    Absolute,
    Incremental,
    PerMinute,
    Machine,
    Work(usize),
}

/// The blocks of a program: code without comments, per line.
fn blocks(program: &str) -> Result<Vec<(usize, String, String)>, Refusal> {
    let lines: Vec<&str> = program.lines().collect();
    let mut out = Vec::new();
    for (k, raw) in lines.iter().enumerate() {
        let n = k + 1;
        let line = raw.trim();
        if line.is_empty() {
            continue;
        }
        if line == "%" {
            if k != 0 && k + 1 != lines.len() {
                return refuse(n, line, "`%` only on the first and last line");
            }
            continue;
        }
        out.push((n, line.to_string(), strip_comment(n, line)?));
    }
    Ok(out)
}

/// The block without its comment (parentheses, not nested, closed in the block).
fn strip_comment(n: usize, line: &str) -> Result<String, Refusal> {
    let mut code = String::new();
    let mut open = false;
    for c in line.chars() {
        match (c, open) {
            ('(', true) => return refuse(n, line, "a comment inside a comment"),
            ('(', false) => open = true,
            (')', true) => open = false,
            (')', false) => return refuse(n, line, "`)` without `(`"),
            (';', false) => {
                return refuse(n, line, "`;` is FANUC's end-of-block code, not a comment");
            }
            (_, true) => {}
            (_, false) => code.push(c),
        }
    }
    if open {
        return refuse(n, line, "a comment not closed in its block");
    }
    Ok(code)
}

/// The words of a block: address letters (upper case) each followed by a number.
fn words(n: usize, line: &str, code: &str) -> Result<Vec<Word>, Refusal> {
    let chars: Vec<char> = code.chars().filter(|c| !c.is_whitespace()).collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let letter = chars[i];
        if !letter.is_ascii_uppercase() {
            return refuse(n, line, format!("`{letter}` is not an address letter"));
        }
        let start = i + 1;
        i = start;
        while i < chars.len() && (chars[i].is_ascii_digit() || "+-.".contains(chars[i])) {
            i += 1;
        }
        let text: String = chars[start..i].iter().collect();
        let Some(num) = number(&text) else {
            return refuse(n, line, format!("`{letter}` without a number"));
        };
        out.push(Word {
            letter,
            text: format!("{letter}{text}"),
            value: num.value,
            point: num.point,
        });
    }
    Ok(out)
}

impl Fanuc {
    /// What G code `code` does here, or why it is refused.
    fn g(&self, code: f64) -> Result<G, String> {
        use GCodeSystem::*;
        let whole = code.fract() == 0.0;
        let c = code as u32;
        let sys = self.lathe;
        Ok(match (c, sys) {
            _ if !whole => return Err(format!("G{code} is not modelled")),
            (0, _) => G::Rapid,
            (1, _) => G::Feed,
            (4, _) => G::Dwell,
            (17..=19, _) | (40, _) | (80, _) => G::Ignore,
            (21, None | Some(A | B)) | (71, Some(C)) => G::Metric,
            (20, None | Some(A | B)) | (70, Some(C)) => return Err("inch input".into()),
            (53, _) => G::Machine,
            (54..=59, _) => G::Work((c - 54) as usize),
            (49, _) => {
                return Err("G49 cancels the tool length offset: the tool axis moves on its next move (B-63844EN/02 §14.1.2)".into());
            }
            (90, Some(A)) => {
                return Err("G90 is the outer diameter cutting cycle in G code system A".into());
            }
            (94, Some(A)) => {
                return Err("G94 is the end face turning cycle in G code system A".into());
            }
            (91, Some(A)) => {
                return Err("G91 does not exist in G code system A (U/W are incremental)".into());
            }
            (98, Some(A)) => G::PerMinute,
            (99, Some(A)) | (95, None | Some(B | C)) => {
                return Err("feed per revolution: the plan's feed is per minute".into());
            }
            (90, _) => G::Absolute,
            (91, _) => G::Incremental,
            (94, None | Some(B | C)) => G::PerMinute,
            (98 | 99, None | Some(B | C)) => G::Ignore,
            (77 | 79, Some(B)) | (20 | 24, Some(C)) => {
                return Err(format!("G{c} is a turning cycle in this G code system"));
            }
            _ => return Err(format!("G{c} is not modelled by this check")),
        })
    }

    /// The incremental address of the tested axis in G-code system A.
    fn incremental_letter(&self) -> Option<char> {
        match (self.lathe, self.axis) {
            (Some(GCodeSystem::A), 'X') => Some('U'),
            (Some(GCodeSystem::A), 'Z') => Some('W'),
            (Some(GCodeSystem::A), 'Y') => Some('V'),
            (Some(GCodeSystem::A), 'C') => Some('H'),
            _ => None,
        }
    }

    /// The slide's travel for a value of the tested axis.
    fn slide(&self, value: f64) -> f64 {
        if self.diameter && self.axis == 'X' {
            value / 2.0
        } else {
            value
        }
    }
}

/// The modal state as the program set it (`None`: left to a parameter).
#[derive(Default)]
struct Modal {
    motion: Option<bool>,
    incremental: Option<bool>,
    per_minute: bool,
    metric: bool,
    feed: Option<f64>,
    ended: bool,
}

/// Runs `program` on `m`: the tested axis's machine positions, or the first refusal.
pub fn run(program: &str, m: &Fanuc) -> Result<Trace, Refusal> {
    let mut state = Modal {
        incremental: m.lathe.filter(|s| *s == GCodeSystem::A).map(|_| false),
        ..Modal::default()
    };
    let mut work = m.active;
    let mut axis = Tracker::new(m.initial);
    for (k, (n, line, code)) in blocks(program)?.into_iter().enumerate() {
        if state.ended {
            return refuse(n, &line, "a block after the program's end");
        }
        let ws = words(n, &line, &code)?;
        block(m, &mut state, &mut work, &mut axis, (n, &line, k == 0), &ws)?;
    }
    if !state.ended {
        return refuse(0, "", "no M30 or M02 at the end");
    }
    Ok(axis.trace)
}

/// One block: its G codes, then a dwell or a move.
fn block(
    m: &Fanuc,
    state: &mut Modal,
    work: &mut usize,
    axis: &mut Tracker,
    (n, line, first): (usize, &str, bool),
    ws: &[Word],
) -> Result<(), Refusal> {
    let mut machine = false;
    let mut dwell = false;
    for (i, w) in ws.iter().enumerate() {
        match w.letter {
            'O' if !(first && i == 0 && w.text.len() <= 5 && !w.point) => {
                return refuse(
                    n,
                    line,
                    "`O` (up to 4 digits) only first in the first block",
                );
            }
            'N' if !(i == 0 && !w.point && w.value >= 1.0 && w.text.len() <= 6) => {
                return refuse(n, line, "`N` (up to 5 digits) only first in a block");
            }
            'G' => match m.g(w.value).or_else(|e| refuse(n, line, e))? {
                G::Rapid => state.motion = Some(false),
                G::Feed => state.motion = Some(true),
                G::Dwell => dwell = true,
                G::Metric => state.metric = true,
                G::Absolute => state.incremental = Some(false),
                G::Incremental => state.incremental = Some(true),
                G::PerMinute => state.per_minute = true,
                G::Machine => machine = true,
                G::Work(k) => *work = k,
                G::Ignore => {}
            },
            'M' if matches!(w.text.as_str(), "M2" | "M02" | "M30") => state.ended = true,
            'M' => return refuse(n, line, format!("`{}` is not modelled", w.text)),
            'F' => state.feed = Some(w.value),
            _ => {}
        }
    }
    if dwell {
        return dwell_block(state, axis, (n, line), ws);
    }
    motion(m, state, *work, axis, (n, line, machine), ws)
}

/// `G04 X…` (s, with the point), `G04 U…` (lathe), `G04 P…` (ms, without), alone.
fn dwell_block(
    state: &Modal,
    axis: &mut Tracker,
    (n, line): (usize, &str),
    ws: &[Word],
) -> Result<(), Refusal> {
    let rest: Vec<&Word> = ws
        .iter()
        .filter(|w| !matches!(w.letter, 'G' | 'N'))
        .collect();
    if ws.iter().filter(|w| w.letter == 'G').count() != 1 || rest.len() != 1 {
        return refuse(n, line, "the dwell block carries G04 and its time only");
    }
    if !state.per_minute {
        return refuse(
            n,
            line,
            "a dwell in seconds needs feed per minute set (G94/G98)",
        );
    }
    let t = rest[0];
    let seconds = match t.letter {
        'X' | 'U' if t.point => t.value,
        'X' | 'U' => return refuse(n, line, "G04 X without a decimal point counts increments"),
        'P' if !t.point => t.value / 1000.0,
        'P' => return refuse(n, line, "G04 P takes milliseconds without a decimal point"),
        _ => return refuse(n, line, "G04 takes X, U or P"),
    };
    axis.dwell(n, seconds);
    Ok(())
}

/// The axis words of a block: the tested axis's target (absolute, incremental or
/// machine), other axes refused, then the move.
fn motion(
    m: &Fanuc,
    state: &Modal,
    work: usize,
    axis: &mut Tracker,
    (n, line, machine): (usize, &str, bool),
    ws: &[Word],
) -> Result<(), Refusal> {
    let inc_letter = m.incremental_letter();
    let mut target: Option<(f64, bool)> = None;
    for w in ws {
        let ours = w.letter == m.axis || Some(w.letter) == inc_letter;
        match w.letter {
            'O' | 'N' | 'G' | 'M' | 'F' => continue,
            _ if !ours && "XYZABCUVWH".contains(w.letter) => {
                axis.other(n, format!("moves {}", w.text));
                continue;
            }
            _ if !ours => return refuse(n, line, format!("`{}` is not modelled", w.text)),
            _ => {}
        }
        if !w.point {
            return refuse(
                n,
                line,
                format!(
                    "`{}` without a decimal point is {} least input increments (3401#0 DPI = 0)",
                    w.text,
                    w.text[1..].trim_start_matches('+')
                ),
            );
        }
        target = Some((m.slide(w.value), Some(w.letter) == inc_letter));
    }
    let Some((value, by_address)) = target else {
        if machine {
            return refuse(n, line, "G53 without the axis");
        }
        return Ok(());
    };
    let incremental = by_address || state.incremental == Some(true);
    if state.incremental.is_none() && !by_address {
        return refuse(n, line, "a move before G90/G91 is set");
    }
    if machine && incremental {
        return refuse(n, line, "G53 takes absolute values only");
    }
    let feed = feed(state, machine).or_else(|e| refuse(n, line, e))?;
    let offset = m.work[work] + m.external + m.shift;
    let to = if incremental {
        axis.position() + value
    } else if machine {
        absolute(m, axis.position(), value, 0.0)
    } else {
        absolute(m, axis.position(), value, offset)
    };
    axis.go(n, to, feed);
    Ok(())
}

/// The feed of a move, or why it has none the program set.
fn feed(state: &Modal, machine: bool) -> Result<Feed, String> {
    if !state.metric {
        return Err("a move before G21 (mm) is set".into());
    }
    match (state.motion, machine) {
        (_, true) | (Some(false), _) => Ok(Feed::Rapid),
        (None, _) => Err("a move before G00/G01 is set".into()),
        (Some(true), _) if !state.per_minute => Err("a feed move before G94/G98".into()),
        (Some(true), _) => state
            .feed
            .map(Feed::PerMinute)
            .ok_or_else(|| "a feed move before F".to_string()),
    }
}

/// The machine position an absolute `value` takes the axis to from `at`, with `offset`
/// from work to machine coordinates.
fn absolute(m: &Fanuc, at: f64, value: f64, offset: f64) -> f64 {
    let here = at - offset;
    match m.rotary {
        None | Some(Rotary::Linear) => value + offset,
        Some(Rotary::RollOver) => {
            let mut by = turn(value) - turn(here);
            if by > 180.0 {
                by -= 360.0;
            } else if by <= -180.0 {
                by += 360.0;
            }
            at + by
        }
        Some(Rotary::SignedDirection) => {
            let by = turn(value.abs() - here);
            if value.is_sign_negative() && by > 0.0 {
                at + by - 360.0
            } else {
                at + by
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::machine::{turn, verify};
    use super::super::{expect, small_plan};
    use super::*;
    use axcheck::units::AxisKind;

    /// A machining centre with G54 = 100 mm and a 7 mm G92 shift on the tested axis.
    fn mill(axis: char) -> Fanuc {
        Fanuc {
            lathe: None,
            axis,
            diameter: false,
            work: [100.0, 0.0, 0.0, 0.0, 0.0, 0.0],
            active: 0,
            external: 0.0,
            shift: 7.0,
            rotary: None,
            initial: 0.0,
        }
    }

    /// The small plan (targets 10 and 50) in work coordinates at feed, no G49.
    const GOOD: &str = "%\nO1000 (TEST)\nG17 G21 G40 G80 G90 G94\nG01 X6.000 F1500.\nX10.000 (T1 UP)\nG04 X2.500\nX50.000\nG04 P2500\nX54.000\nX50.000\nG04 X2.500\nX10.000\nG04 X2.500\nM30\n%\n";

    #[test]
    fn a_program_in_work_coordinates_reaches_the_targets_plus_the_offsets() {
        let plan = small_plan(AxisKind::Linear);
        let trace = run(GOOD, &mill('X')).unwrap();
        assert_eq!(
            verify(&plan, &trace, &expect(107.0, false)),
            Vec::<String>::new()
        );
        let shifted = verify(&plan, &trace, &expect(0.0, false));
        assert!(
            shifted[0].contains("at 117.0000 instead of 10.0000"),
            "{shifted:?}"
        );
    }

    #[test]
    fn g53_moves_in_machine_coordinates_but_at_rapid_traverse() {
        let program = GOOD
            .replace("G01 X6.000", "G53 X6.000")
            .replace("\nX", "\nG53 X");
        let trace = run(&program, &mill('X')).unwrap();
        let problems = verify(&small_plan(AxisKind::Linear), &trace, &expect(0.0, false));
        assert_eq!(problems.len(), 6, "{problems:?}");
        assert!(
            problems.iter().all(|p| p.contains("moves at Rapid")),
            "{problems:?}"
        );
    }

    /// Today's head (`G17 G21 G40 G49 G80 G90 G94`): G49 may move the tool axis.
    #[test]
    fn g49_is_refused() {
        let program = GOOD.replace("G40 G80", "G40 G49 G80");
        let e = run(&program, &mill('X')).unwrap_err();
        assert_eq!(e.line, 3);
        assert!(e.why.contains("G49 cancels the tool length offset"), "{e}");
    }

    #[test]
    fn a_position_without_a_decimal_point_is_refused() {
        let e = run(&GOOD.replace("X10.000 (T1 UP)", "X10"), &mill('X')).unwrap_err();
        assert!(
            e.why
                .contains("`X10` without a decimal point is 10 least input increments"),
            "{e}"
        );
        let e = run(&GOOD.replace("G04 P2500", "G04 P2500.0"), &mill('X')).unwrap_err();
        assert!(
            e.why.contains("milliseconds without a decimal point"),
            "{e}"
        );
        let e = run(&GOOD.replace("G04 P2500", "G04 X2500 Y1."), &mill('X')).unwrap_err();
        assert!(e.why.contains("G04 and its time only"), "{e}");
    }

    /// The FANUC program of today on a lathe in G-code system A: G90 and G94 are cycles
    /// there and G91 does not exist (the rotary program's `G91`).
    #[test]
    fn a_lathe_in_g_code_system_a_refuses_g90_g91_and_g94() {
        let lathe = Fanuc {
            lathe: Some(GCodeSystem::A),
            diameter: true,
            ..mill('X')
        };
        for (line, why) in [
            (
                "G90 G01 X5.000 F1000.000 (START AT 5.000 MM)",
                "outer diameter cutting cycle",
            ),
            ("G91", "G91 does not exist in G code system A"),
            ("G17 G21 G40 G80 G94", "end face turning cycle"),
        ] {
            let program = format!("%\nO1000\nG21 G98\n{line}\nM30\n%\n");
            let e = run(&program, &lathe).unwrap_err();
            assert_eq!((e.line, e.block.as_str()), (4, line));
            assert!(e.why.contains(why), "{e}");
        }
        let diameter = "%\nO1000\nG18 G21 G98\nG01 U12.000 F1500.\nX20.000\nG04 U2.500\nM30\n%\n";
        let trace = run(diameter, &lathe).unwrap();
        assert_eq!(trace.readings[0].position, 10.0 + 100.0 + 7.0);
        assert_eq!(trace.moves[0].to, 6.0);
    }

    /// G-code systems B and C take G90/G91/G94; C's cycles are G20/G24 and mm is G71.
    #[test]
    fn lathe_systems_b_and_c() {
        let b = Fanuc {
            lathe: Some(GCodeSystem::B),
            ..mill('Z')
        };
        let program = "O1000\nG21 G90 G94\nG01 Z6.000 F1500.\nG04 X2.500\nM30\n";
        assert_eq!(run(program, &b).unwrap().readings[0].position, 113.0);
        let c = Fanuc {
            lathe: Some(GCodeSystem::C),
            ..b
        };
        let e = run(program, &c).unwrap_err();
        assert!(e.why.contains("G21 is not modelled"), "{e}");
        let e = run(&program.replace("G21", "G71 G20"), &c).unwrap_err();
        assert!(e.why.contains("G20 is a turning cycle"), "{e}");
        assert!(run(&program.replace("G21", "G71"), &c).is_ok());
    }

    /// Today's rotary start `G90 G01 C-5.000`: with the rotary axis control function the
    /// sign is the direction, so the axis stands at +5° and every later (incremental)
    /// target is 10° from its label; with plain roll-over it is −5° ≡ 355°.
    #[test]
    fn a_first_absolute_c_minus_5_lands_at_plus_5_with_rotary_axis_control() {
        let program = "O1000\nG21 G90 G94\nG90 G01 C-5.000 F1500.\nG91\nC5.000\nG04 X2.500\nM30\n";
        let rotary = |r| Fanuc {
            rotary: Some(r),
            work: [0.0; 6],
            shift: 0.0,
            ..mill('C')
        };
        let signed = run(program, &rotary(Rotary::SignedDirection)).unwrap();
        assert_eq!(turn(signed.moves[0].to), 5.0);
        assert_eq!(turn(signed.readings[0].position), 10.0);
        let shorter = run(program, &rotary(Rotary::RollOver)).unwrap();
        assert_eq!(turn(shorter.readings[0].position), 0.0);
    }
}
