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
//! the position (under 360°, in G90 and G53 alike), so a continuous axis first goes
//! to a target's angle within one turn (`C0.000`), the same position wrapped or counting
//! turns, and reaches its start incrementally; incremental moves are plain. With G53,
//! `find_ends` passes `unwrap_rotary` the value less the offsets and `unwrap_rotary`
//! takes its magnitude (`fabs`): below the offsets a wrapped axis goes to the wrong angle
//! (`G53 C0` with 107° of offsets ends at 214°, measured with rs274). A continuous axis's
//! program in machine coordinates therefore reads, after its first move, the machine
//! position the interpreter reached (numbered parameters: the current position and the
//! offsets, `docs/src/gcode/overview.adoc` §Numbered Parameters) and moves back by the
//! difference, which is 0 on an axis that counts turns ([`misread_correction`]). Lathes: `G18 G8`: X in radius (G8), the slide's position, whatever
//! `G7` a lathe's start-up code selects.
//!
//! Sources (LinuxCNC/linuxcnc): `docs/src/gcode/overview.adoc` (`%`, comments, best
//! practices), `docs/src/gcode/g-code.adoc` (§G4 P in seconds, §G7/§G8 lathe diameter and
//! radius mode, §G53 machine coordinates, one block only, with G0 or G1), `m-code.adoc`
//! (M2), `src/emc/rs274ngc/interp_find.cc` (`find_ends` for G53, `unwrap_rotary`),
//! `interp_check.cc` (`check_g_codes`: no G53 in G91); the NIST RS274NGC Interpreter
//! version 3 §3.5.12 (G53). Unconfirmed: nothing in the syntax (rs274, LinuxCNC's own
//! interpreter, runs these programs in the tests); not run on a machine here.

use super::{
    Block, Dialect, Job, ProgramError, g_move, is_first, number, one_letter, plain_word, word_value,
};

pub(crate) struct LinuxCncProgram;

impl Dialect for LinuxCncProgram {
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

    fn machine_coordinates(&self, job: &Job) -> Vec<String> {
        let mut out = vec![
            "G53 in every absolute move suspends the G5x, G92 and tool offsets for that block".into(),
            "LinuxCNC refuses G53 in G91, so the incremental moves carry none; they do not depend on offsets".into(),
        ];
        if corrected(job) {
            out.push(format!(
                "With WRAPPED_ROTARY, LinuxCNC's G53 turns {} to the wrong angle below its offsets: after the first move the program reads where the axis went and moves back by the difference, 0 on an axis that counts turns",
                job.axis
            ));
        }
        out
    }

    fn lathe(&self, _job: &Job) -> Result<Vec<String>, ProgramError> {
        Ok(vec![
            "Lathe: G18 G8, X is programmed in radius, the slide's position".into(),
        ])
    }

    /// `G53 G1 X…` absolute in machine coordinates, `G1 X…` otherwise; on a continuous
    /// rotary axis the first move is followed by its correction ([`misread_correction`]).
    fn move_to(&self, job: &Job, block: &Block, feed: Option<f64>) -> Vec<String> {
        let words = |value: f64, incremental: bool| {
            let g53 = if job.machine() && !incremental {
                "G53 "
            } else {
                ""
            };
            format!("{g53}G1 {}", plain_word(job.axis, value))
        };
        let mut lines = g_move(self, job, block, feed, words);
        if is_first(block) && corrected(job) {
            let (value, _) = word_value(job, block);
            lines.extend(misread_correction(job.axis, value));
        }
        lines
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

/// Whether the first move is followed by its correction: a continuous rotary axis in
/// machine coordinates (`G53` on a wrapped axis misreads a position below the offsets).
fn corrected(job: &Job) -> bool {
    job.continuous_rotary() && job.machine()
}

/// After `G53 G1 C{value}`: the machine position the interpreter reached (the current
/// position `#5420 + k` in the program's coordinates plus the active G5x origin `#[5201 +
/// k + 20 × #5220]`, the G92 offset `#[5211 + k]` where applied (`#5210`) and the tool
/// offset `#[5401 + k]`; LinuxCNC `docs/src/gcode/overview.adoc`, §Numbered Parameters)
/// less `value`, and an incremental move back by it when it is not 0. On an axis that
/// counts turns the difference is 0; on a `WRAPPED_ROTARY` axis below its offsets it is
/// what `unwrap_rotary`'s `fabs` added (214° for `C0` with 107° of offsets, measured).
fn misread_correction(axis: &str, value: f64) -> Vec<String> {
    let k = "XYZABCUVW".find(axis).unwrap_or(0);
    vec![
        format!(
            "#<misread> = [#{} + #[{} + 20 * #5220] + #{} * #5210 + #{} - {}]",
            5420 + k,
            5201 + k,
            5211 + k,
            5401 + k,
            number(value)
        ),
        "O101 if [ABS[#<misread>] GT 0.0005]".into(),
        format!(
            "G91 G1 {axis}[0 - #<misread>] (back to {} deg: G53 on a WRAPPED_ROTARY axis below its offsets)",
            number(value)
        ),
        "G90".into(),
        "O101 endif".into(),
    ]
}
