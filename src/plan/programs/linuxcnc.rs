//! `linuxcnc`: an RS274NGC program for LinuxCNC: `%` lines around it, `G17 G21 G40 G49 G54
//! G80 G90 G94` (the set-up LinuxCNC's G-code best practices give, in mm), `G1 X… F…`
//! moves, the dwell `G4 P…` in seconds (fractions allowed), `( )` comments (never starting
//! with MSG, DEBUG, PRINT or LOG, which LinuxCNC acts on), `M2`. Rotary axes: incremental
//! moves (`G91`) after the start: with `WRAPPED_ROTARY = 1` an absolute value's sign is
//! its direction and must stay under 360°, incremental moves are plain.
//!
//! Sources (LinuxCNC/linuxcnc docs and interpreter): `docs/src/gcode/overview.adoc` (`%`,
//! comments, best practices), `g-code.adoc` §G4 (P in seconds), `m-code.adoc` (M2),
//! `src/emc/rs274ngc/interp_find.cc` `unwrap_rotary` (G90 and G53 only). Unconfirmed:
//! nothing in the syntax; the program has not been run on a machine.

use super::{Block, Dialect, Job, ProgramError, g_move, number, one_letter, plain_word};

pub struct LinuxCnc;

impl Dialect for LinuxCnc {
    fn name(&self) -> &'static str {
        "linuxcnc"
    }

    fn extension(&self) -> &'static str {
        "ngc"
    }

    fn address(&self, axis: &str) -> Result<(), ProgramError> {
        one_letter(axis, "LinuxCNC")
    }

    /// A parenthesised comment: parentheses inside would end it early, and none of the
    /// program's comments starts with a word LinuxCNC acts on (MSG, DEBUG, PRINT, LOG).
    fn comment(&self, t: &str) -> String {
        format!("({})", t.replace(['(', ')'], " "))
    }

    fn begin(&self, _job: &Job) -> (Vec<String>, Vec<String>) {
        (
            vec!["%".to_string()],
            vec!["G17 G21 G40 G49 G54 G80 G90 G94".to_string()],
        )
    }

    fn move_to(&self, job: &Job, block: &Block, feed: Option<f64>) -> Vec<String> {
        g_move(self, job, block, feed, "G1 ", plain_word)
    }

    fn dwell(&self, seconds: f64) -> Vec<String> {
        vec![format!("G4 P{}", number(seconds))]
    }

    fn incremental(&self) -> Option<(&'static str, &'static str)> {
        Some(("G91", "G90"))
    }

    fn end(&self, _job: &Job) -> Vec<String> {
        vec!["M2".to_string(), "%".to_string()]
    }

    fn unconfirmed(&self) -> &'static str {
        "none in the syntax; the program has not been run on a machine"
    }
}
