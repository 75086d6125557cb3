//! `siemens-840d`: a main program for SINUMERIK 840D sl in Siemens mode: a `;` comment
//! naming the file `_N_NAME_MPF`, `G17 G71 G90 G94 G40 G500 G60` (plane, metric, absolute,
//! mm/min, no radius compensation, no settable frame, exact stop), `G1 X… F…` moves, the
//! dwell `G4 F…` in seconds in a block of its own, `;` comments, `M30`. An axis name with
//! digits (`X1`) is written `X1=…`; a part program usually addresses the channel axis
//! (`X`), machine axes only in special cases. Rotary axes: incremental moves (`G91`) after
//! the start, so MD30455 (how G90 moves a modulo axis) does not decide the direction.
//!
//! Sources: SINUMERIK ONE NC Programming 12/2019 (program names, `;` comments, machine
//! axes); 808D Programming 05/2012 p. 26 (ACP/ACN); 840D sl Axes and spindles 06/2019
//! R2 §7.2 (MD30455); the Autodesk 840D post (`G4 F` seconds, frame). Unconfirmed: `G4 F`
//! is quoted from secondary sources; `G500` is a zero offset only if its frame is zero.

use super::{Block, Dialect, Job, ProgramError, g_move, identifier, number};

pub struct Siemens840d;

/// `X10.000` or, for a name with digits, `X1=10.000`.
fn word(axis: &str, value: f64) -> String {
    if axis.len() == 1 {
        format!("{axis}{}", number(value))
    } else {
        format!("{axis}={}", number(value))
    }
}

impl Dialect for Siemens840d {
    fn name(&self) -> &'static str {
        "siemens-840d"
    }

    fn extension(&self) -> &'static str {
        "mpf"
    }

    fn address(&self, axis: &str) -> Result<(), ProgramError> {
        identifier(axis, "SINUMERIK")
    }

    fn comment(&self, t: &str) -> String {
        format!("; {t}")
    }

    fn begin(&self, job: &Job) -> (Vec<String>, Vec<String>) {
        let first = vec![format!("; %_N_{}_MPF", job.name)];
        (first, vec!["G17 G71 G90 G94 G40 G500 G60".to_string()])
    }

    fn move_to(&self, job: &Job, block: &Block, feed: Option<f64>) -> Vec<String> {
        g_move(self, job, block, feed, "G1 ", word)
    }

    fn dwell(&self, seconds: f64) -> Vec<String> {
        vec![format!("G4 F{}", number(seconds))]
    }

    fn incremental(&self) -> Option<(&'static str, &'static str)> {
        Some(("G91", "G90"))
    }

    fn end(&self, _job: &Job) -> Vec<String> {
        vec!["M30".to_string()]
    }

    fn unconfirmed(&self) -> &'static str {
        "G4 F in seconds (secondary sources); G500 as no offset depends on its frame"
    }
}
