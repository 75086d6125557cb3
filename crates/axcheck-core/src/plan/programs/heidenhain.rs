//! `heidenhain`: a conversational (Klartext) program for HEIDENHAIN TNC 640 / 620:
//! `0 BEGIN PGM NAME MM`, blocks numbered from 0 without gaps, `L X+… R0 F… M91` moves
//! with the sign always written, the dwell in two blocks (`CYCL DEF 9.0 DWELL TIME`, `CYCL
//! DEF 9.1 DWELL …` in seconds: English dialog; a German control writes `VERWEILZEIT` /
//! `V.ZEIT`), `;` comments in blocks of their own, `END PGM NAME MM`.
//!
//! **Machine coordinates**: `M91` at the end of every absolute L block references its
//! coordinates to the machine datum, for that block only (it takes effect at the block's
//! start); the feed stays the programmed one. The TNC 310 manual adds that in M91 blocks
//! the tool length is not compensated. `--coordinates work` writes the blocks without
//! `M91`, in the active preset.
//!
//! Rotary axes: `L IC±…` incremental moves after the start, as HEIDENHAIN has no absolute
//! move with a direction and M126 (shortest path) would otherwise decide it; a continuous
//! axis first goes to a target's angle within one turn (`C+0.000`), the same position on
//! a modulo display and on one that counts turns, and reaches its start incrementally. Lathes: no program is written (whether
//! the TNC's turning mode, FUNCTION MODE TURN, takes X as a diameter is not confirmed
//! here): the writer refuses.
//!
//! Sources: TNC 320 User's Manual 3/2014 §3.2 (block numbers, BEGIN/END PGM), §6.4 (L, R0,
//! F modal); TNC 640 ISO manual 1/2015 p. 631 (Cycle 9 dwell in s); TNC 620 User's Manual
//! 10/2017 p. 566 (M126); TNC 310 User Manual (286 140) p. 88 and TNC 360 User Manual
//! p. 5-39 (M91: coordinates in a positioning block referenced to the machine datum,
//! effective in that block only; no tool length compensation); the OpenPostProject
//! HEIDENHAIN post (frame, cycle 9 text, signs). Unconfirmed: the cycle text in other
//! dialog languages, whether a `;` comment may follow an L block (so comments have blocks
//! of their own), whether M91 blocks leave out the tool length on TNC 640 / 620 as on TNC
//! 310.

use super::{Block, Dialect, Job, ProgramError, move_note, number, one_letter, word_value};

pub(crate) struct HeidenhainProgram;

/// `+10.000` or `-5.000`.
fn signed(x: f64) -> String {
    let s = number(x);
    if s.starts_with('-') {
        s
    } else {
        format!("+{s}")
    }
}

impl Dialect for HeidenhainProgram {
    fn name(&self) -> &'static str {
        "heidenhain"
    }

    fn extension(&self) -> &'static str {
        "h"
    }

    fn address(&self, job: &Job) -> Result<(), ProgramError> {
        one_letter(job.axis, "HEIDENHAIN")
    }

    fn comment(&self, t: &str) -> String {
        format!(";{t}")
    }

    fn begin(&self, job: &Job) -> (Vec<String>, Vec<String>) {
        (vec![format!("BEGIN PGM {} MM", job.name)], Vec::new())
    }

    fn machine_coordinates(&self, _job: &Job) -> Vec<String> {
        vec!["M91 in every absolute L block references that block to the machine datum".into()]
    }

    fn lathe(&self, _job: &Job) -> Result<Vec<String>, ProgramError> {
        Err(ProgramError(
            "no HEIDENHAIN program is written for a lathe: whether the TNC's turning mode (FUNCTION MODE TURN) programs X as a diameter is not confirmed here; write it by hand, or drop --lathe if the axis moves in milling mode".into(),
        ))
    }

    /// The comment block, then `L X+… [R0 F…] [M91]` or `L IC±…`.
    fn move_to(&self, job: &Job, block: &Block, feed: Option<f64>) -> Vec<String> {
        if !matches!(block, Block::Move { .. }) {
            return Vec::new();
        }
        let (value, incremental) = word_value(job, block);
        let word = if incremental {
            format!("I{}{}", job.axis, signed(value))
        } else {
            format!("{}{}", job.axis, signed(value))
        };
        let mut line = format!("L {word}");
        if let Some(f) = feed {
            line.push_str(&format!(" R0 F{}", number(f)));
        }
        if job.machine() && !incremental {
            line.push_str(" M91");
        }
        vec![move_note(self, job, block), line]
    }

    fn dwell(&self, seconds: f64) -> Vec<String> {
        vec![
            "CYCL DEF 9.0 DWELL TIME".to_string(),
            format!("CYCL DEF 9.1 DWELL {}", number(seconds)),
        ]
    }

    fn incremental(&self, _job: &Job) -> Option<(&'static str, &'static str)> {
        None
    }

    fn end(&self, job: &Job) -> Vec<String> {
        vec![format!("END PGM {} MM", job.name)]
    }

    fn unconfirmed(&self, _job: &Job) -> String {
        "the cycle 9 text in other dialog languages; comments after an L block; whether M91 blocks leave out the tool length on TNC 640".into()
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
