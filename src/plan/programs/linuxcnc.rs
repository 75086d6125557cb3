//! `linuxcnc`: an RS274NGC program for LinuxCNC: `%` lines around it, `G17 G21 G40 G80 G90
//! G94` (plane, mm, no cutter compensation, no canned cycle, absolute, per minute; no `G49`,
//! whose length-offset cancel may move Z, and no `G54`: the moves need no work offset),
//! `G53 G1 X… F…` moves, the dwell `G4 P…` in seconds (fractions allowed), `( )` comments
//! (never starting with MSG, DEBUG, PRINT or LOG, which LinuxCNC acts on), `M2`.
//!
//! **Machine coordinates**: `G53` in every absolute motion block: for that block the
//! interpreter takes the value as a machine position, less the G5x origin, the G92 offset
//! and the tool offset (`find_ends`), at the active `G1` feed. LinuxCNC refuses `G53` in
//! `G91` ("Cannot use g53 incremental", `check_g_codes`), so a rotary axis's incremental
//! moves carry none; they do not depend on offsets. `--coordinates work` writes the moves
//! without `G53`, in the active G5x and G92 offsets.
//!
//! Rotary axes: incremental moves (`G91`) after the start. With `WRAPPED_ROTARY = 1`,
//! `unwrap_rotary` reads an absolute value's sign as the direction and its magnitude as
//! the position (under 360°, in G90 and G53 alike), so a continuous axis's start is
//! written within one turn (`C355.000` for −5°, reached turning positive); incremental
//! moves are plain. Lathes: `G18 G8`: X in radius (G8), the slide's position, whatever
//! `G7` a lathe's start-up code selects.
//!
//! Sources (LinuxCNC/linuxcnc): `docs/src/gcode/overview.adoc` (`%`, comments, best
//! practices), `docs/src/gcode/g-code.adoc` (§G4 P in seconds, §G7/§G8 lathe diameter and
//! radius mode, §G53 machine coordinates, one block only, with G0 or G1), `m-code.adoc`
//! (M2), `src/emc/rs274ngc/interp_find.cc` (`find_ends` for G53, `unwrap_rotary`),
//! `interp_check.cc` (`check_g_codes`: no G53 in G91); the NIST RS274NGC Interpreter
//! version 3 §3.5.12 (G53). Unconfirmed: nothing in the syntax (rs274, LinuxCNC's own
//! interpreter, runs these programs in the tests); not run on a machine here.

use super::{Block, Dialect, Job, ProgramError, g_move, number, one_letter, plain_word};

pub struct LinuxCnc;

impl Dialect for LinuxCnc {
    fn name(&self) -> &'static str {
        "linuxcnc"
    }

    fn extension(&self) -> &'static str {
        "ngc"
    }

    fn address(&self, job: &Job) -> Result<(), ProgramError> {
        one_letter(job.axis, "LinuxCNC")
    }

    /// A parenthesised comment: parentheses inside would end it early, and none of the
    /// program's comments starts with a word LinuxCNC acts on (MSG, DEBUG, PRINT, LOG).
    fn comment(&self, t: &str) -> String {
        format!("({})", t.replace(['(', ')'], " "))
    }

    fn begin(&self, job: &Job) -> (Vec<String>, Vec<String>) {
        let setup = match job.lathe {
            None => "G17 G21 G40 G80 G90 G94",
            Some(_) => "G18 G8 G21 G40 G80 G90 G94",
        };
        (vec!["%".to_string()], vec![setup.to_string()])
    }

    fn machine_coordinates(&self, _job: &Job) -> Vec<String> {
        vec![
            "G53 in every absolute move suspends the G5x, G92 and tool offsets for that block".into(),
            "LinuxCNC refuses G53 in G91, so the incremental moves carry none; they do not depend on offsets".into(),
        ]
    }

    fn lathe(&self, _job: &Job) -> Result<Vec<String>, ProgramError> {
        Ok(vec![
            "Lathe: G18 G8, X is programmed in radius, the slide's position".into(),
        ])
    }

    /// `G53 G1 X…` absolute in machine coordinates, `G1 X…` otherwise.
    fn move_to(&self, job: &Job, block: &Block, feed: Option<f64>) -> Vec<String> {
        let words = |value: f64, incremental: bool| {
            let g53 = if job.machine() && !incremental {
                "G53 "
            } else {
                ""
            };
            format!("{g53}G1 {}", plain_word(job.axis, value))
        };
        g_move(self, job, block, feed, words)
    }

    fn dwell(&self, seconds: f64) -> Vec<String> {
        vec![format!("G4 P{}", number(seconds))]
    }

    fn incremental(&self, _job: &Job) -> Option<(&'static str, &'static str)> {
        Some(("G91", "G90"))
    }

    fn end(&self, _job: &Job) -> Vec<String> {
        vec!["M2".to_string(), "%".to_string()]
    }

    fn unconfirmed(&self, _job: &Job) -> String {
        "none in the syntax; the program has not been run on a machine".into()
    }
}
