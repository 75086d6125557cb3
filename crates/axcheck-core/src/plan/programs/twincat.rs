//! `twincat`: a program for the Beckhoff TwinCAT CNC (TF5200, the ISG kernel's DIN 66025
//! dialect): `% NAME`, `G17 G71 G90 G94 G40` (plane, metric, absolute, mm/min, no radius
//! compensation), the moves, the dwell `#TIME …` in seconds in a block of its own (`G04
//! X…` would need X to be the channel's first main axis), `;` comments, `M30`. Not the
//! TF5100 "NC I" interpreter, whose syntax differs.
//!
//! **Axis words**: an axis name of one letter takes its value directly (`X10.000`); "an
//! equals sign must follow axis identifiers that contain more than one character", which
//! "is necessary especially for axis designations ending with one of the numerals 0–9"
//! (`X1=10.000`, `C2=5.000`; `X110.000` would be an axis X110 or X1 at 10 mm, read
//! wrongly). A name starts with A, B, C, U, V, W, X, Y, Z or Q, then letters or digits.
//!
//! **Machine coordinates**: `#SUPPRESS OFFSETS X…` in every absolute move: "in
//! combination with a motion block" it moves to the programmed position without the
//! active offsets (zero offsets, G92 reference point and additive offsets, position
//! presets, clamping, tool, measuring and manual offsets), non-modal, only in G90 (error
//! 20985), with the active `G01` and feed, which a block of its own sets before it (`G01
//! F…`, as the manual's examples set G and F without a move). `G53` would deselect the
//! zero offsets only (and as P-ZERO-00001 allows), `#MCS ON` needs the "Transformations"
//! licence; `#SUPPRESS OFFSETS` leaves #CS/#ACS transformations active, which the program
//! does not select. A rotary axis's incremental moves (`G91`) carry none: they do not
//! depend on offsets. `--coordinates work` writes `G01 X…` moves in the active offsets.
//!
//! Rotary axes: incremental moves (`G91`) after the start: a modulo axis's sign words
//! (`C+θ`, `C-θ`) and P-CHAN-00346 (always the shortest way) do not decide the direction
//! then; a continuous axis first goes to a target's angle within one turn (`C0.000`),
//! without a sign, so a modulo axis reaches it by the shortest way and one that is not
//! modulo stands at the same position (`C-5.000` would be +5° reached turning negative on
//! a modulo axis); the start follows incrementally. Lathes: `G18` and `G52` (diameter programming
//! deselected, its initial state): X in radius, the slide's position.
//!
//! Sources (Beckhoff Infosys, TF5200 programming manual): "Axis commands" (axis names,
//! the equals sign), "Structure of NC control data" (`%` name, M30), "Block-specific
//! comments", "Dwell time (G04), (#TIME)", "Suppressing offsets (#SUPPRESS OFFSETS)",
//! "Temporary transition to the machine coordinate system (#MCS ON/OFF)", "Zero offsets
//! (G53/G54/...G59)", "Machining time or feedrate (G93/G94/G95/G194)" (a block of G and
//! F), "Programming modulo axes", "Positioning on the shortest way"; TF5200 turning
//! functions "Diameter programming (G51/G52)"; TF5200 diagnosis ID 20985. Unconfirmed:
//! `#SUPPRESS OFFSETS` with a multi-letter axis name (`X1=…`) and after a `G01 F…` block
//! of its own; not run on a control.

use super::{Block, Dialect, Job, ProgramError, g_move, named_word, number};

pub(crate) struct TwinCatProgram;

/// A name of the ISG's reserved first letters, then letters or digits.
fn isg_name(name: &str) -> Result<(), ProgramError> {
    let mut chars = name.chars();
    let ok = chars.next().is_some_and(|c| "ABCUVWXYZQ".contains(c))
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
        && name.len() <= 16;
    if ok {
        Ok(())
    } else {
        Err(ProgramError(format!(
            "The TwinCAT CNC names an axis with A, B, C, U, V, W, X, Y, Z or Q, then letters or digits (X, C, X1); got `{name}` (--axis)"
        )))
    }
}

impl Dialect for TwinCatProgram {
    fn name(&self) -> &'static str {
        "twincat"
    }

    fn extension(&self) -> &'static str {
        "nc"
    }

    fn address(&self, job: &Job) -> Result<(), ProgramError> {
        isg_name(job.axis)
    }

    fn comment(&self, t: &str) -> String {
        format!("; {t}")
    }

    /// The set-up; in machine coordinates `G01 F…` after it, as the moves are
    /// `#SUPPRESS OFFSETS` blocks.
    fn begin(&self, job: &Job) -> (Vec<String>, Vec<String>) {
        let mut setup = vec![
            match job.lathe {
                None => "G17 G71 G90 G94 G40",
                Some(_) => "G18 G71 G90 G94 G40 G52",
            }
            .to_string(),
        ];
        if job.machine() {
            setup.push(format!("G01 F{}", number(job.plan.motion.feed)));
        }
        (vec![format!("% {}", job.name)], setup)
    }

    fn machine_coordinates(&self, _job: &Job) -> Vec<String> {
        vec![
            "#SUPPRESS OFFSETS in every absolute move suppresses the zero, G92, preset, clamping, tool, measuring and manual offsets for that block".into(),
            "It moves at the G01 feed set before it".into(),
        ]
    }

    fn lathe(&self, _job: &Job) -> Result<Vec<String>, ProgramError> {
        Ok(vec!["Lathe: G18 G52, X is programmed in radius (diameter programming deselected), the slide's position".into()])
    }

    /// `#SUPPRESS OFFSETS X…` absolute in machine coordinates (the feed set before it),
    /// `G01 X…` otherwise.
    fn move_to(&self, job: &Job, block: &Block, feed: Option<f64>) -> Vec<String> {
        let machine = job.machine();
        let words = |value: f64, incremental: bool| {
            let word = named_word(job.axis, value);
            if machine && !incremental {
                format!("#SUPPRESS OFFSETS {word}")
            } else {
                format!("G01 {word}")
            }
        };
        g_move(self, job, block, feed.filter(|_| !machine), words)
    }

    fn dwell(&self, seconds: f64) -> Vec<String> {
        vec![format!("#TIME {}", number(seconds))]
    }

    fn incremental(&self, _job: &Job) -> Option<(&'static str, &'static str)> {
        Some(("G91", "G90"))
    }

    fn end(&self, _job: &Job) -> Vec<String> {
        vec!["M30".to_string()]
    }

    fn unconfirmed(&self, job: &Job) -> String {
        if job.machine() {
            "#SUPPRESS OFFSETS with a multi-letter axis name and after a G01 F block of its own; not run on a control".into()
        } else {
            "not run on a control".into()
        }
    }
}
