//! `heidenhain`: a conversational (Klartext) program for HEIDENHAIN TNC 640 / 620:
//! `0 BEGIN PGM NAME MM`, blocks numbered from 0 without gaps, `L X+… R0 F…` moves with the
//! sign always written, the dwell in two blocks (`CYCL DEF 9.0 DWELL TIME`, `CYCL DEF 9.1
//! DWELL …` in seconds: English dialog; a German control writes `VERWEILZEIT` / `V.ZEIT`),
//! `;` comments in blocks of their own, `END PGM NAME MM`. Positions are in the work
//! coordinate system (add M91 for machine coordinates). Rotary axes: `L IC±…` incremental
//! moves after the start, as HEIDENHAIN has no absolute move with a direction and M126
//! (shortest path) would otherwise decide it.
//!
//! Sources: TNC 320 User's Manual 3/2014 §3.2 (block numbers, BEGIN/END PGM), §6.4 (L, R0,
//! F modal); TNC 640 ISO manual 1/2015 p. 631 (Cycle 9 dwell in s); TNC 620 User's Manual
//! 10/2017 p. 566 (M126); the OpenPostProject HEIDENHAIN post (frame, cycle 9 text, signs).
//! Unconfirmed: the cycle text in other dialog languages, whether a `;` comment may follow
//! an L block (so comments have blocks of their own).

use super::{Block, Dialect, Job, ProgramError, is_incremental, number, one_letter};

pub struct Heidenhain;

/// `+10.000` or `-5.000`.
fn signed(x: f64) -> String {
    let s = number(x);
    if s.starts_with('-') {
        s
    } else {
        format!("+{s}")
    }
}

impl Dialect for Heidenhain {
    fn name(&self) -> &'static str {
        "heidenhain"
    }

    fn extension(&self) -> &'static str {
        "h"
    }

    fn address(&self, axis: &str) -> Result<(), ProgramError> {
        one_letter(axis, "HEIDENHAIN")
    }

    fn comment(&self, t: &str) -> String {
        format!(";{t}")
    }

    fn begin(&self, job: &Job) -> (Vec<String>, Vec<String>) {
        (vec![format!("BEGIN PGM {} MM", job.name)], Vec::new())
    }

    fn move_to(&self, job: &Job, block: &Block, feed: Option<f64>) -> Vec<String> {
        let Block::Move { position, by, what } = block else {
            return Vec::new();
        };
        let unit = job.kind().position_unit();
        let note = self.comment(&format!("{} at {} {unit}", what.text(), number(*position)));
        let word = if is_incremental(job, block) {
            format!("I{}{}", job.axis, signed(*by))
        } else {
            format!("{}{}", job.axis, signed(*position))
        };
        let mut line = format!("L {word}");
        if let Some(f) = feed {
            line.push_str(&format!(" R0 F{}", number(f)));
        }
        vec![note, line]
    }

    fn dwell(&self, seconds: f64) -> Vec<String> {
        vec![
            "CYCL DEF 9.0 DWELL TIME".to_string(),
            format!("CYCL DEF 9.1 DWELL {}", number(seconds)),
        ]
    }

    fn incremental(&self) -> Option<(&'static str, &'static str)> {
        None
    }

    fn end(&self, job: &Job) -> Vec<String> {
        vec![format!("END PGM {} MM", job.name)]
    }

    fn unconfirmed(&self) -> &'static str {
        "the cycle 9 text in other dialog languages; comments after an L block"
    }

    /// Every block numbered from 0, as the control numbers them.
    fn write(&self, job: &Job) -> Result<String, ProgramError> {
        let plain = super::assemble(self, job)?;
        let numbered: Vec<String> = plain
            .lines()
            .enumerate()
            .map(|(k, l)| format!("{k} {l}"))
            .collect();
        Ok(numbered.join("\n") + "\n")
    }
}
