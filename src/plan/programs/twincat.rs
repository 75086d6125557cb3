//! `twincat`: a program for the Beckhoff TwinCAT CNC (TF5200, the ISG kernel's DIN 66025
//! dialect): `% NAME`, `G17 G71 G90 G94 G40 G53` (plane, metric, absolute, mm/min, no
//! radius compensation, no zero offset), `G01 X… F…` moves, the dwell `#TIME …` in seconds
//! in a block of its own (`G04 X…` would need X to be the channel's first main axis), `;`
//! comments, `M30`. Rotary axes: incremental moves (`G91`) after the start: a modulo axis's
//! sign words (`C+θ`, `C-θ`) and P-CHAN-00346 (always the shortest way) do not decide the
//! direction then. Not the TF5100 "NC I" interpreter, whose syntax differs.
//!
//! Sources (Beckhoff Infosys, TF5200 programming manual): "Structure of NC control data"
//! (`%` name, M30), "Block-specific comments", "Dwell time (G04), (#TIME)", "Programming
//! modulo axes", "Zero offsets" (G53 as deselection depends on P-ZERO-00001). Unconfirmed:
//! the program has not been run on a control.

use super::{Block, Dialect, Job, ProgramError, g_move, identifier, number, plain_word};

pub struct TwinCat;

impl Dialect for TwinCat {
    fn name(&self) -> &'static str {
        "twincat"
    }

    fn extension(&self) -> &'static str {
        "nc"
    }

    fn address(&self, axis: &str) -> Result<(), ProgramError> {
        identifier(axis, "The TwinCAT CNC")
    }

    fn comment(&self, t: &str) -> String {
        format!("; {t}")
    }

    fn begin(&self, job: &Job) -> (Vec<String>, Vec<String>) {
        (
            vec![format!("% {}", job.name)],
            vec!["G17 G71 G90 G94 G40 G53".to_string()],
        )
    }

    fn move_to(&self, job: &Job, block: &Block, feed: Option<f64>) -> Vec<String> {
        g_move(self, job, block, feed, "G01 ", plain_word)
    }

    fn dwell(&self, seconds: f64) -> Vec<String> {
        vec![format!("#TIME {}", number(seconds))]
    }

    fn incremental(&self) -> Option<(&'static str, &'static str)> {
        Some(("G91", "G90"))
    }

    fn end(&self, _job: &Job) -> Vec<String> {
        vec!["M30".to_string()]
    }

    fn unconfirmed(&self) -> &'static str {
        "G53 as no zero offset depends on P-ZERO-00001; not run on a control"
    }
}
