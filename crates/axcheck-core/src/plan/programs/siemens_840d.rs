//! `siemens-840d`: a main program for SINUMERIK 840D sl in Siemens mode: a `;` comment
//! naming the file `_N_NAME_MPF`, `G17 G71 G90 G94 G40 G60` (plane, metric, absolute,
//! mm/min, no radius compensation, exact stop), `G1 SUPA X… F…` moves, the dwell `G4 F…`
//! in seconds in a block of its own, `;` comments, `M30`. An axis name of more than one
//! character (`X1`) is written `X1=…`; a part program usually addresses the channel axis
//! (`X`), machine axes only in special cases.
//!
//! **Machine coordinates**: `SUPA` in every absolute block suppresses, for that block,
//! the zero offsets: the settable (G54 …) and programmable frames and the base frames
//! (the 828D function manual: SUPA, G153 and G53 make the WCS, SZS "and possibly the BZS"
//! jump); the motion keeps `G1` and its feed. No `G500` is needed. `SUPA` leaves an
//! active tool offset in place unless MD10760 `G53_TOOLCORR` = 1, so the head asks that
//! none acts on the axis. The incremental moves of a rotary axis (`G91`) carry none: they
//! do not depend on offsets. `--coordinates work` writes the moves without `SUPA`, in the
//! active frames.
//!
//! Rotary axes: incremental moves (`G91`) after the start, so MD30455 (how G90 moves a
//! modulo axis) does not decide the direction; a continuous axis first goes to a target's
//! angle within one turn (`C0.000`), the same position on a modulo axis and on one that
//! is not, and reaches its start incrementally: a modulo axis with MD30455 bit 0 = 0
//! refuses a position outside 0…360° (alarm 16830, third-party source). Lathes: `G18` and `DIAMOF`, so X is
//! programmed in radius, the slide's position (many turning machines start in `DIAMON`).
//!
//! Sources: SINUMERIK ONE NC Programming 12/2019 (program names, `;` comments, machine
//! axes); SINUMERIK 840D sl/828D Fundamentals Programming Manual 10/2015
//! (6FC5398-1BP40-5BA3) chapter 9 "Geometry settings" (G53, G153, SUPA, G500; DIAMON,
//! DIAMOF); SINUMERIK ISO Milling 04.07 §3.1.1 (G53/G153/SUPA: non-modal suppression of
//! the zero offsets, the tool offsets kept while `$MN_G53_TOOLCORR` = 0); SINUMERIK 828D
//! Basic Functions, Function Manual 09/2011 (6FC5397-0BP40-2BA0) K2 §10.5 p. 741 (frame
//! suppression by SUPA, G153, G53; MD24020); 808D Programming 05/2012 p. 26 (ACP/ACN);
//! 840D sl Axes and spindles 06/2019 R2 §7.2 (MD30455); the Autodesk 840D post (`G4 F`
//! seconds, frame). Unconfirmed: `G4 F` is quoted from secondary sources; which offsets
//! beyond the frames SUPA suppresses (DRF, external zero offset, PRESET: the Fundamentals
//! manual's list, not seen here); alarm 16830 from a third-party source.

use super::{Block, Dialect, Job, ProgramError, g_move, identifier, named_word, number};

pub(crate) struct Siemens840dProgram;

impl Dialect for Siemens840dProgram {
    fn name(&self) -> &'static str {
        "siemens-840d"
    }

    fn extension(&self) -> &'static str {
        "mpf"
    }

    fn address(&self, job: &Job) -> Result<(), ProgramError> {
        identifier(job.axis, "SINUMERIK")
    }

    fn comment(&self, t: &str) -> String {
        format!("; {t}")
    }

    fn begin(&self, job: &Job) -> (Vec<String>, Vec<String>) {
        let first = vec![format!("; %_N_{}_MPF", job.name)];
        let setup = match job.lathe {
            None => "G17 G71 G90 G94 G40 G60",
            Some(_) => "G18 G71 G90 G94 G40 G60 DIAMOF",
        };
        (first, vec![setup.to_string()])
    }

    fn machine_coordinates(&self, job: &Job) -> Vec<String> {
        vec![
            "SUPA in every absolute block suppresses the zero offsets and frames (settable, programmable, base) for that block".into(),
            format!(
                "No tool offset may act on axis {}: SUPA keeps it unless MD10760 G53_TOOLCORR = 1",
                job.axis
            ),
        ]
    }

    fn lathe(&self, _job: &Job) -> Result<Vec<String>, ProgramError> {
        Ok(vec![
            "Lathe: G18 DIAMOF, X is programmed in radius, the slide's position".into(),
        ])
    }

    /// `G1 SUPA X…` absolute in machine coordinates, `G1 X…` otherwise.
    fn move_to(&self, job: &Job, block: &Block, feed: Option<f64>) -> Vec<String> {
        let words = |value: f64, incremental: bool| {
            let supa = if job.machine() && !incremental {
                "SUPA "
            } else {
                ""
            };
            format!("G1 {supa}{}", named_word(job.axis, value))
        };
        g_move(self, job, block, feed, words)
    }

    fn dwell(&self, seconds: f64) -> Vec<String> {
        vec![format!("G4 F{}", number(seconds))]
    }

    fn incremental(&self, _job: &Job) -> Option<(&'static str, &'static str)> {
        Some(("G91", "G90"))
    }

    fn end(&self, _job: &Job) -> Vec<String> {
        vec!["M30".to_string()]
    }

    fn unconfirmed(&self, _job: &Job) -> String {
        "G4 F in seconds (secondary sources); whether SUPA also suppresses DRF, external and PRESET offsets".into()
    }
}
