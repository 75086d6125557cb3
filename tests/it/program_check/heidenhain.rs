//! A HEIDENHAIN TNC 640 / 620 conversational (Klartext) program, read strictly: every
//! block numbered, the program framed by BEGIN/END PGM, each block's form checked, the
//! tested axis simulated in machine coordinates through the datum (preset), M91, incremental
//! moves and a rotary axis whose display is reduced to one turn.
//!
//! Rules and their sources:
//! - Blocks are numbered from 0 without gaps; the first is `BEGIN PGM NAME MM`, the last
//!   `END PGM NAME MM` with the same name (TNC 320 User's Manual 3/2014 §3.2). A block is
//!   `;` a comment, `* - …` a structure block, an `L` block, or cycle 9.
//! - `L` takes coordinates written with their sign as the control writes them (`X+10.000`,
//!   incremental `IX-5.000`: unconfirmed whether the TNC loads an unsigned value), `R0`,
//!   `F…` (modal) or `FMAX` (this block only) and M functions; a `; comment` may end the
//!   block (accepted, not confirmed). RL/RR, FAUTO and every other M function are refused.
//! - M91: the coordinates of that block are referenced to the machine datum; effective only
//!   in the block programmed (TNC 310 User's Manual 286 140, §7.3 p. 88; TNC 426B ISO
//!   programming §7.3 p. 122; not read in a TNC 640 manual). M92 is refused (its datum is
//!   the machine tool builder's).
//! - Cycle 9: `CYCL DEF 9.0 DWELL TIME` then `CYCL DEF 9.1 DWELL s` (German dialog
//!   `VERWEILZEIT` / `V.ZEIT`), 0 to 3600 s (TNC 640 User's Manual DIN/ISO 1/2015, p. 631).
//!   The English dialog text is quoted from a post processor: unconfirmed.
//! - A rotary axis whose display is reduced below 360°: without M126 (and without machine
//!   parameter shortestDistance 300401) it traverses the difference between nominal and
//!   actual display (350° → 10° is −340°); with either, the shorter way (TNC 620
//!   Conversational Programming User's Manual 10/2017, p. 566). What the TNC does with an
//!   absolute value outside [0, 360) there is not confirmed: refused.

use super::machine::{Feed, Refusal, Trace, Tracker, number, refuse, turn};

/// The machine the program runs on.
#[derive(Debug, Clone)]
pub struct Heidenhain {
    /// The tested axis's letter.
    pub axis: char,
    /// The active datum (preset) of the tested axis: machine position of its zero.
    pub datum: f64,
    /// `None`: linear, or a rotary axis counting on past 360°. `Some(shortest)`: display
    /// reduced to one turn, with shortestDistance (300401) on or off.
    pub modulo: Option<bool>,
    pub initial: f64,
}

/// The state the program carries from block to block.
#[derive(Default)]
struct State {
    name: Option<String>,
    feed: Option<f64>,
    shortest: bool,
    cycle9: bool,
    ended: bool,
}

/// Runs `program` on `m`: the tested axis's machine positions, or the first refusal.
pub fn run(program: &str, m: &Heidenhain) -> Result<Trace, Refusal> {
    let lines: Vec<&str> = program.lines().collect();
    let mut state = State {
        shortest: m.modulo == Some(true),
        ..State::default()
    };
    let mut axis = Tracker::new(m.initial);
    for (k, &raw) in lines.iter().enumerate() {
        let n = k + 1;
        let (number, rest) = raw.split_once(' ').unwrap_or((raw, ""));
        if number != k.to_string() {
            return refuse(
                n,
                raw,
                format!("block number {number}, expected {k} (numbered from 0 without gaps)"),
            );
        }
        if state.ended {
            return refuse(n, raw, "a block after END PGM");
        }
        let last = k + 1 == lines.len();
        block(
            m,
            &mut state,
            &mut axis,
            (n, raw, k == 0, last),
            rest.trim(),
        )?;
    }
    if !state.ended {
        return refuse(0, "", "no END PGM block");
    }
    Ok(axis.trace)
}

fn block(
    m: &Heidenhain,
    state: &mut State,
    axis: &mut Tracker,
    (n, raw, first, last): (usize, &str, bool, bool),
    rest: &str,
) -> Result<(), Refusal> {
    if first {
        let name = frame(rest, "BEGIN PGM ").ok_or_else(|| Refusal {
            line: n,
            block: raw.into(),
            why: "the first block is BEGIN PGM NAME MM".into(),
        })?;
        state.name = Some(name);
        return Ok(());
    }
    if state.cycle9 && !rest.starts_with("CYCL DEF 9.1 ") {
        return refuse(n, raw, "CYCL DEF 9.0 without its 9.1 block");
    }
    if last {
        return match frame(rest, "END PGM ") {
            Some(name) if Some(&name) == state.name.as_ref() => {
                state.ended = true;
                Ok(())
            }
            _ => refuse(
                n,
                raw,
                "the last block is END PGM with the BEGIN PGM's name and MM",
            ),
        };
    }
    if rest.starts_with(';') || rest.starts_with("* - ") {
        return Ok(());
    }
    if let Some(cycle) = rest.strip_prefix("CYCL DEF 9.") {
        return cycle9(state, axis, (n, raw), cycle);
    }
    match rest.strip_prefix("L ") {
        Some(words) => l_block(m, state, axis, (n, raw), words),
        None => refuse(n, raw, "not a block this check models (L, cycle 9, ;, * -)"),
    }
}

/// `BEGIN PGM NAME MM` → `NAME`.
fn frame(rest: &str, head: &str) -> Option<String> {
    let name = rest.strip_prefix(head)?.strip_suffix(" MM")?;
    let ok = !name.is_empty()
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-');
    ok.then(|| name.to_string())
}

fn cycle9(
    state: &mut State,
    axis: &mut Tracker,
    (n, raw): (usize, &str),
    rest: &str,
) -> Result<(), Refusal> {
    if matches!(rest, "0 DWELL TIME" | "0 VERWEILZEIT") {
        state.cycle9 = true;
        return Ok(());
    }
    let time = rest
        .strip_prefix("1 DWELL ")
        .or_else(|| rest.strip_prefix("1 V.ZEIT "))
        .and_then(number);
    match time {
        Some(t) if state.cycle9 && (0.0..=3600.0).contains(&t.value) => {
            state.cycle9 = false;
            axis.dwell(n, t.value);
            Ok(())
        }
        _ => refuse(
            n,
            raw,
            "CYCL DEF 9.1 DWELL s (0 to 3600) right after CYCL DEF 9.0",
        ),
    }
}

/// An L block's words: the tested axis's target, other axes, R0, F/FMAX, M91/M126/M127.
fn l_block(
    m: &Heidenhain,
    state: &mut State,
    axis: &mut Tracker,
    (n, raw): (usize, &str),
    words: &str,
) -> Result<(), Refusal> {
    let code = words.split(';').next().unwrap_or("");
    let mut target = None;
    let mut rapid = false;
    let mut m91 = false;
    for w in code.split_whitespace() {
        match w {
            "R0" => {}
            "FMAX" => rapid = true,
            "M91" => m91 = true,
            "M126" => state.shortest = true,
            "M127" => state.shortest = m.modulo == Some(true),
            _ if w.starts_with('F') => match number(&w[1..]) {
                Some(f) if !f.signed => state.feed = Some(f.value),
                _ => return refuse(n, raw, format!("`{w}` is not a feed")),
            },
            _ => {
                let (inc, rest) = w.strip_prefix('I').map_or((false, w), |r| (true, r));
                let mut chars = rest.chars();
                let letter = chars.next().filter(|c| "XYZABCUVW".contains(*c));
                let value = number(chars.as_str()).filter(|v| v.signed);
                match (letter, value) {
                    (Some(l), Some(v)) if l == m.axis => target = Some((inc, v.value)),
                    (Some(l), Some(_)) => axis.other(n, format!("moves {l}: `{w}`")),
                    _ => {
                        return refuse(
                            n,
                            raw,
                            format!(
                                "`{w}` is not a word this check models (coordinates carry their sign)"
                            ),
                        );
                    }
                }
            }
        }
    }
    let Some((inc, v)) = target else {
        return Ok(());
    };
    let feed = match (rapid, state.feed) {
        (true, _) => Feed::Rapid,
        (false, Some(f)) => Feed::PerMinute(f),
        (false, None) => return refuse(n, raw, "a move before any feed (F)"),
    };
    let to = destination(m, state.shortest, axis.position(), inc, m91, v)
        .or_else(|e| refuse(n, raw, e))?;
    axis.go(n, to, feed);
    Ok(())
}

/// The machine position an L block's coordinate takes the axis to.
fn destination(
    m: &Heidenhain,
    shortest: bool,
    at: f64,
    inc: bool,
    m91: bool,
    v: f64,
) -> Result<f64, String> {
    if inc {
        return Ok(at + v);
    }
    let datum = if m91 { 0.0 } else { m.datum };
    if m.modulo.is_none() {
        return Ok(v + datum);
    }
    if !(0.0..360.0).contains(&v) {
        return Err(format!(
            "{v} outside [0, 360) on an axis whose display is one turn: not confirmed what the TNC does"
        ));
    }
    let here = turn(at - datum);
    let by = v - here;
    Ok(at
        + if shortest && by > 180.0 {
            by - 360.0
        } else if shortest && by < -180.0 {
            by + 360.0
        } else {
            by
        })
}

#[cfg(test)]
mod tests {
    use super::super::machine::verify;
    use super::super::{expect, small_plan};
    use super::*;
    use axcheck::units::AxisKind;

    /// The small plan with M91 in every L block (machine datum).
    const M91: &str = "0 BEGIN PGM TEST MM\n1 ;start\n2 L X+6.000 R0 F1500 M91\n3 L X+10.000 M91 ; T1 up\n4 CYCL DEF 9.0 DWELL TIME\n5 CYCL DEF 9.1 DWELL 2.500\n6 L X+50.000 M91\n7 CYCL DEF 9.0 DWELL TIME\n8 CYCL DEF 9.1 DWELL 2.5\n9 L X+54.000 M91\n10 L X+50.000 M91\n11 CYCL DEF 9.0 VERWEILZEIT\n12 CYCL DEF 9.1 V.ZEIT 2.500\n13 * - down\n14 L IX-40.000\n15 CYCL DEF 9.0 DWELL TIME\n16 CYCL DEF 9.1 DWELL 2.500\n17 END PGM TEST MM\n";

    fn tnc(axis: char) -> Heidenhain {
        Heidenhain {
            axis,
            datum: 107.0,
            modulo: None,
            initial: 0.0,
        }
    }

    #[test]
    fn m91_moves_in_machine_coordinates() {
        let trace = run(M91, &tnc('X')).unwrap();
        assert_eq!(
            verify(&small_plan(AxisKind::Linear), &trace, &expect(0.0, false)),
            Vec::<String>::new()
        );
        let work = run(&M91.replace(" M91", ""), &tnc('X')).unwrap();
        assert_eq!(work.readings[0].position, 117.0);
    }

    #[test]
    fn the_frame_and_the_numbering_are_checked() {
        let gap = M91.replace("5 CYCL DEF 9.1", "6 CYCL DEF 9.1");
        let e = run(&gap, &tnc('X')).unwrap_err();
        assert!(e.why.contains("block number 6, expected 5"), "{e}");
        let name = M91.replace("END PGM TEST MM", "END PGM OTHER MM");
        assert!(run(&name, &tnc('X')).unwrap_err().why.contains("END PGM"));
        let alone = M91.replace("4 CYCL DEF 9.0 DWELL TIME", "4 ;no cycle");
        assert!(
            run(&alone, &tnc('X'))
                .unwrap_err()
                .why
                .contains("right after CYCL DEF 9.0")
        );
        let unsigned = M91.replace("X+6.000", "X6.000");
        assert!(
            run(&unsigned, &tnc('X'))
                .unwrap_err()
                .why
                .contains("carry their sign")
        );
        let rl = M91.replace("R0", "RL");
        assert!(run(&rl, &tnc('X')).is_err());
    }

    /// Today's rotary start `L C-5.000` on an axis whose display is one turn: what the TNC
    /// makes of it is not confirmed, so it is refused; `C+355.000` is not.
    #[test]
    fn a_negative_absolute_angle_on_a_one_turn_axis_is_refused() {
        let program = "0 BEGIN PGM T MM\n1 L C-5.000 R0 F1500\n2 L IC+5.000\n3 CYCL DEF 9.0 DWELL TIME\n4 CYCL DEF 9.1 DWELL 2.5\n5 END PGM T MM\n";
        let m = Heidenhain {
            datum: 0.0,
            modulo: Some(false),
            ..tnc('C')
        };
        let e = run(program, &m).unwrap_err();
        assert_eq!(e.line, 2);
        let trace = run(&program.replace("C-5.000", "C+355.000"), &m).unwrap();
        assert_eq!(trace.readings[0].position, 360.0);
        let shortest = Heidenhain {
            modulo: Some(true),
            ..m
        };
        let trace = run(&program.replace("C-5.000", "C+355.000"), &shortest).unwrap();
        assert_eq!(trace.readings[0].position, 0.0);
    }
}
