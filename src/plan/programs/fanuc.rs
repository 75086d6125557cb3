//! `fanuc`: a part program for FANUC Series 0i / 30i: `%`, `O1000 (name)`, `G17 G21 G40 G49
//! G80 G90 G94`, `G01 X… F…` moves with a decimal point always (without one, and with
//! parameter 3401#0 = 0, `X10` is 0.010 mm), the dwell `G04 X…` in seconds in a block of
//! its own (G94 active), comments in parentheses in upper case with letters, digits and
//! `. , = _ -` only, `M30`, `%`. Rotary axes: incremental moves (`G91`) after the start, so
//! the roll-over parameters (1008#0 ROA, #1 RAB) do not decide the direction.
//!
//! Sources: the FANUC-compatible ISO dialect of SINUMERIK (ISO Milling 04.07 §3.3.1, the
//! G04 rules: X with a decimal point in s, P in ms); FANUC 0i-MB Operator's Manual
//! B-63534EN/02 §20.2 (roll-over); the Autodesk FANUC post (frame, comment characters,
//! forced decimals). Unconfirmed: the parameter numbers 3401#0 and 3405#1, the program
//! number's range on each machine.

use super::{Block, Dialect, Job, ProgramError, Purpose, g_move, number, one_letter, plain_word};

pub struct Fanuc;

/// The comment's text as FANUC takes it: upper case, letters, digits and `. , = _ -`.
fn text(s: &str) -> String {
    s.to_uppercase()
        .replace('↑', "UP")
        .replace('↓', "DOWN")
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

impl Dialect for Fanuc {
    fn name(&self) -> &'static str {
        "fanuc"
    }

    fn extension(&self) -> &'static str {
        "nc"
    }

    fn address(&self, axis: &str) -> Result<(), ProgramError> {
        one_letter(axis, "FANUC")
    }

    fn comment(&self, t: &str) -> String {
        format!("({})", text(t))
    }

    fn begin(&self, job: &Job) -> (Vec<String>, Vec<String>) {
        let first = vec!["%".to_string(), format!("O1000 ({})", text(job.name))];
        (first, vec!["G17 G21 G40 G49 G80 G90 G94".to_string()])
    }

    /// The start in `G90 G01` (set again, as the program may follow another); the others
    /// modal.
    fn move_to(&self, job: &Job, block: &Block, feed: Option<f64>) -> Vec<String> {
        let start = matches!(
            block,
            Block::Move {
                what: Purpose::Start,
                ..
            }
        );
        let prefix = if start { "G90 G01 " } else { "" };
        g_move(self, job, block, feed, prefix, plain_word)
    }

    fn dwell(&self, seconds: f64) -> Vec<String> {
        vec![format!("G04 X{}", number(seconds))]
    }

    fn incremental(&self) -> Option<(&'static str, &'static str)> {
        Some(("G91", "G90"))
    }

    fn end(&self, _job: &Job) -> Vec<String> {
        vec!["M30".to_string(), "%".to_string()]
    }

    fn unconfirmed(&self) -> &'static str {
        "G04 X with a decimal point in seconds (parameter 3405), the program number O1000"
    }
}
