//! `fanuc`: a part program for FANUC Series 0i / 30i: `%`, `O1000 (name)`, the modal set-up
//! (milling: `G17 G21 G40 G80 G90 G94`), `G01 X… F…` moves with a decimal point always
//! (without one, and with parameter 3401#0 = 0, `X10` is 0.010 mm), the dwell `G04 X…` in
//! seconds in a block of its own, comments in parentheses in upper case with letters,
//! digits and `. , = _ -` only, `M30`, `%`. Rotary axes: incremental moves after the start,
//! so the roll-over parameters (1008#0 ROA, #1 RAB) do not decide the direction; a
//! continuous axis first goes to a target's angle within one turn (`C0.000`), the same
//! position with roll-over and without, and reaches its start incrementally.
//!
//! **Machine coordinates.** FANUC's `G53` is a one-shot selection that moves at rapid
//! traverse, not at the programmed feed (SINUMERIK ISO Milling 04.07 §3.1.1, describing
//! the FANUC-compatible dialect: "the tool moves to that position in rapid traverse"); no
//! source found here gives a FANUC form of `G53` at feed. So the program selects `G54`
//! and its head states what must be zero: the G54 and external (EXT) offsets of the axis,
//! any `G52` or `G92` shift of it, and any tool offset acting on it (checked on the
//! position display: absolute position equals machine position). Not written: `G49` (a
//! length-offset cancel may move the tool axis) nor any tool call. `--coordinates work`
//! leaves the active work offset as it is.
//!
//! **Lathes** (G-code system A, B or C, parameter 3401#6/#7): system A has no `G90`/`G91`
//! (`G90` and `G94` are its turning cycles): positions are absolute addresses (X, Z, C),
//! increments are U, W and H (C's), feed per minute is `G98`; systems B and C have `G90`/
//! `G91` and `G94` for feed per minute (their cycles are G77/G79 and G20/G24), and system
//! C's metric input is `G71` (its `G21` is a threading cycle). X is programmed in
//! diameter (parameter 1006#3 DIA = 1, the lathe's usual setting): every X word is twice
//! the slide's position, and the head says so.
//!
//! Sources: the FANUC-compatible ISO dialect of SINUMERIK (ISO Milling 04.07 §3.1.1 G53 at
//! rapid traverse, §3.3.1 the G04 rules: X with a decimal point in s, P in ms); FANUC 0i-MB
//! Operator's Manual B-63534EN/02 §20.2 (roll-over); the HSMWorks/Autodesk FANUC turning
//! post (G-code system A: `G98`, no `G90`/`G91`; comment characters, forced decimals).
//! Unconfirmed: the parameter numbers 3401#0, 3405#1 and 1006#3; the lathe G-code tables
//! are quoted from secondary sources; no FANUC form of G53 at feed; the program number's
//! range on each machine.

use super::{
    Block, Dialect, GcodeSystem, Job, ProgramError, g_move, is_first, number, one_letter,
    plain_word,
};
use crate::units::AxisKind;

pub(crate) struct FanucProgram;

/// The comment's text as FANUC takes it: upper case, letters, digits and `. , = _ -` (a
/// semicolon a comma, any other character a space).
fn text(s: &str) -> String {
    s.to_uppercase()
        .replace('↑', "UP")
        .replace('↓', "DOWN")
        .replace(';', ",")
        .chars()
        .map(|c| match c {
            'A'..='Z' | '0'..='9' | ' ' | '.' | ',' | '=' | '_' | '-' => c,
            _ => ' ',
        })
        .collect::<String>()
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

/// Whether the job's words are those of lathe G-code system A (no G90/G91).
fn system_a(job: &Job) -> bool {
    job.lathe == Some(GcodeSystem::A)
}

/// Whether the axis's words are diameters: X on a lathe.
fn diameter(job: &Job) -> bool {
    job.lathe.is_some() && job.axis == "X"
}

/// The set-up block: plane, metric input, no radius compensation, absolute, feed per
/// minute in the G-code system's words, and G54 in machine coordinates.
fn setup(job: &Job) -> String {
    let mut words: Vec<&str> = match job.lathe {
        None => vec!["G17", "G21", "G40", "G80", "G90", "G94"],
        Some(GcodeSystem::A) => vec!["G18", "G21", "G40", "G98"],
        Some(GcodeSystem::B) => vec!["G18", "G21", "G40", "G90", "G94"],
        Some(GcodeSystem::C) => vec!["G18", "G71", "G40", "G90", "G94"],
    };
    if job.machine() {
        words.push("G54");
    }
    words.join(" ")
}

impl Dialect for FanucProgram {
    fn name(&self) -> &'static str {
        "fanuc"
    }

    fn extension(&self) -> &'static str {
        "nc"
    }

    /// One letter; on a lathe in system A not U, V, W (X, Y, Z's increments), and a rotary
    /// axis only as C (its increment H).
    fn address(&self, job: &Job) -> Result<(), ProgramError> {
        one_letter(job.axis, "FANUC")?;
        if system_a(job) && "UVW".contains(job.axis) {
            return Err(ProgramError(format!(
                "in FANUC lathe G-code system A, `{}` is an incremental address (U, V, W are X, Y, Z's increments); name the axis X, Y, Z or C (--axis), or give --gcode-system b or c",
                job.axis
            )));
        }
        if system_a(job) && job.kind() == AxisKind::Rotary && job.axis != "C" {
            return Err(ProgramError(format!(
                "FANUC lathe G-code system A writes a rotary axis's increments with H, C's incremental address; got the rotary axis `{}` (--axis): give --gcode-system b or c",
                job.axis
            )));
        }
        Ok(())
    }

    fn comment(&self, t: &str) -> String {
        format!("({})", text(t))
    }

    fn begin(&self, job: &Job) -> (Vec<String>, Vec<String>) {
        let first = vec!["%".to_string(), format!("O1000 ({})", text(job.name))];
        (first, vec![setup(job)])
    }

    fn machine_coordinates(&self, job: &Job) -> Vec<String> {
        vec![
            "G53 is not used, as FANUC moves G53 blocks at rapid traverse; G54 is selected".into(),
            format!(
                "The G54 and external EXT offsets of axis {}, any G52 or G92 shift of it and any tool offset acting on it must be 0: the absolute position display then equals the machine position",
                job.axis
            ),
        ]
    }

    fn lathe(&self, job: &Job) -> Result<Vec<String>, ProgramError> {
        let system = job.lathe.unwrap_or_default();
        let words = match system {
            GcodeSystem::A => {
                "feed per minute G98; positions as absolute X, Z, C words and increments as U, W, H words, as the system has no codes for absolute and incremental mode"
            }
            GcodeSystem::B | GcodeSystem::C => {
                "G94 feed per minute, G90 absolute and G91 incremental"
            }
        };
        let x = if diameter(job) {
            "X is programmed in diameter, parameter 1006 bit 3 DIA = 1: every X word is twice the slide's position, the comments give the slide's position"
        } else {
            "Only X is programmed in diameter; this axis's words are its positions"
        };
        Ok(vec![
            format!("Lathe, G-code system {}: {words}", system.letter()),
            x.to_string(),
        ])
    }

    /// The start with `G90 G01` (set again, as the program may follow another; `G01` alone
    /// in system A), the others modal; in system A a rotary axis's increments are H words.
    fn move_to(&self, job: &Job, block: &Block, feed: Option<f64>) -> Vec<String> {
        let start = is_first(block);
        let scale = if diameter(job) { 2.0 } else { 1.0 };
        let words = |value: f64, incremental: bool| {
            let axis = if incremental && system_a(job) {
                "H"
            } else {
                job.axis
            };
            let word = plain_word(axis, scale * value);
            match (start, system_a(job)) {
                (true, true) => format!("G01 {word}"),
                (true, false) => format!("G90 G01 {word}"),
                (false, _) => word,
            }
        };
        g_move(self, job, block, feed, words)
    }

    fn dwell(&self, seconds: f64) -> Vec<String> {
        vec![format!("G04 X{}", number(seconds))]
    }

    fn incremental(&self, job: &Job) -> Option<(&'static str, &'static str)> {
        (!system_a(job)).then_some(("G91", "G90"))
    }

    fn end(&self, _job: &Job) -> Vec<String> {
        vec!["M30".to_string(), "%".to_string()]
    }

    fn unconfirmed(&self, job: &Job) -> String {
        let mut out = "G04 X with a decimal point in seconds, parameter 3405; the program number O1000; a G53 at feed on any model".to_string();
        if job.lathe.is_some() {
            out.push_str("; the lathe G-code system's words, from secondary sources");
        }
        out
    }
}
