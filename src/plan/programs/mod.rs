//! Part programs that run a plan on a control, one file per control (as the compensation
//! tables are): the same path for every control ([`blocks`]: the steps of the test cycle,
//! each target approached from its direction after the overrun, a dwell at each), written
//! in each control's own syntax for moves, dwell and comments ([`Dialect`]).
//!
//! Linear axes move to absolute positions (G90). Rotary axes move to their start position
//! absolutely and then incrementally (G91 or its equivalent): the sign of each move is its
//! direction whatever the axis's modulo, roll-over or shortest-path setting, which the
//! controls define differently (FANUC parameter 1008, Siemens ACP/ACN and MD30455,
//! HEIDENHAIN M126, LinuxCNC WRAPPED_ROTARY, ISG modulo signs), and positions need not stay
//! within a turn. The comments give every absolute position.

pub mod fanuc;
pub mod heidenhain;
pub mod linuxcnc;
pub mod siemens_840d;
pub mod twincat;

use super::Plan;
use crate::axis_model::Step;
use crate::units::{AxisKind, Direction, fmt_fixed};

/// Why a program cannot be written.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct ProgramError(pub String);

/// One block of the program, before a control's syntax.
#[derive(Debug, Clone, PartialEq)]
pub enum Block {
    /// A move to `position` (absolute, mm or deg), `by` from the position before it.
    Move {
        position: f64,
        by: f64,
        what: Purpose,
    },
    /// The dwell at a target, s.
    Dwell(f64),
}

/// Why the axis moves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Purpose {
    /// To the start, below the first target by the overrun.
    Start,
    /// Beyond a target by the overrun, to reverse.
    Overrun,
    /// To target `target` (1-based, as the data file numbers it), approached in
    /// `direction`, in run `run` (1-based).
    Target {
        target: usize,
        direction: Direction,
        run: usize,
    },
}

impl Purpose {
    /// `T3 up, run 2`, `overrun`, `start`.
    pub fn text(&self) -> String {
        match self {
            Purpose::Start => "start".into(),
            Purpose::Overrun => "overrun".into(),
            Purpose::Target {
                target,
                direction,
                run,
            } => format!("T{target} {}, run {run}", direction.name()),
        }
    }
}

/// The program's path: the plan's steps as moves (to 0.001, the recorded step: every
/// incremental move is exact) and a dwell after each target.
pub fn blocks(plan: &Plan) -> Vec<Block> {
    let steps = plan.test_plan().steps(&plan.targets);
    let mut out = Vec::with_capacity(2 * steps.len());
    let mut at: Option<i64> = None;
    for step in steps {
        let position = (step.position() * 1000.0).round() as i64;
        let by = at.map_or(0, |a| position - a) as f64 / 1000.0;
        let what = match step {
            Step::Move(_) if at.is_none() => Purpose::Start,
            Step::Move(_) => Purpose::Overrun,
            Step::Read {
                target,
                direction,
                run,
                ..
            } => Purpose::Target {
                target: target + 1,
                direction,
                run: run + 1,
            },
        };
        // A move of no length (the start when the path begins there) is not written again.
        if at.is_some() && by == 0.0 && what == Purpose::Overrun {
            continue;
        }
        at = Some(position);
        out.push(Block::Move {
            position: position as f64 / 1000.0,
            by,
            what,
        });
        if matches!(what, Purpose::Target { .. }) && plan.motion.dwell_s > 0.0 {
            out.push(Block::Dwell(plan.motion.dwell_s));
        }
    }
    out
}

/// What a program is written for.
pub struct Job<'a> {
    pub plan: &'a Plan,
    /// The axis's address on the control (`X`, `C`; Siemens and TwinCAT also `X1`).
    pub axis: &'a str,
    /// The program's name (`ISO230X`).
    pub name: &'a str,
}

impl Job<'_> {
    pub fn kind(&self) -> AxisKind {
        self.plan.axis.kind
    }

    /// The lines that describe the plan, for the program's head.
    pub fn description(&self) -> Vec<String> {
        let p = self.plan;
        let unit = p.axis.kind.position_unit();
        let mut out = vec![
            format!(
                "Positioning test of axis {} by axcheck: {}",
                self.axis,
                p.axis.standard.title()
            ),
            format!(
                "{} targets, {} runs, {} cycle, overrun {} {unit}, dwell {} s, feed {} {unit}/min",
                p.targets.len(),
                p.runs,
                p.motion.cycle.name(),
                fmt_fixed(p.motion.overrun, 3),
                fmt_fixed(p.motion.dwell_s, 3),
                fmt_fixed(p.motion.feed, 0)
            ),
            "Targets as the data file numbers them:".to_string(),
        ];
        out.extend(
            p.targets
                .iter()
                .enumerate()
                .map(|(i, t)| format!("T{} = {} {unit}", i + 1, fmt_fixed(*t, 3))),
        );
        if p.axis.kind == AxisKind::Rotary {
            out.push("Rotary axis: after the start every move is incremental, so its sign is its direction whatever the axis's modulo or shortest-path setting".into());
        }
        out.push(
            "Check the axis address, the travel and the feed; run it once without the laser first"
                .into(),
        );
        out
    }
}

/// A control's syntax: its own words for the program's frame, moves, dwell and comments;
/// the program is assembled from them ([`Dialect::write`]).
pub trait Dialect: Sync {
    /// The name users give (`--program NAME`).
    fn name(&self) -> &'static str;
    /// The program file's extension.
    fn extension(&self) -> &'static str;
    /// The axis address as the control takes it, or why not.
    fn address(&self, axis: &str) -> Result<(), ProgramError>;
    /// A comment line.
    fn comment(&self, text: &str) -> String;
    /// The program's first lines (before the description) and the modal set-up after it.
    fn begin(&self, job: &Job) -> (Vec<String>, Vec<String>);
    /// The move of `block` (a [`Block::Move`]): absolute, or incremental on a rotary axis
    /// after the start; `feed` on the first move only (every control keeps it).
    fn move_to(&self, job: &Job, block: &Block, feed: Option<f64>) -> Vec<String>;
    /// The dwell, s.
    fn dwell(&self, seconds: f64) -> Vec<String>;
    /// The lines that switch to incremental moves and back, for a rotary axis (`None`: the
    /// control marks each move incremental itself).
    fn incremental(&self) -> Option<(&'static str, &'static str)>;
    /// The program's last lines.
    fn end(&self, job: &Job) -> Vec<String>;
    /// What is not confirmed about this control's syntax, for the program's head.
    fn unconfirmed(&self) -> &'static str;

    /// The whole program.
    fn write(&self, job: &Job) -> Result<String, ProgramError> {
        assemble(self, job)
    }
}

/// The program of `job` in `d`'s words: its frame, the description as comments, the
/// set-up, the moves and dwells, the end.
pub fn assemble<D: Dialect + ?Sized>(d: &D, job: &Job) -> Result<String, ProgramError> {
    d.address(job.axis)?;
    let (first, setup) = d.begin(job);
    let mut lines = first;
    lines.extend(job.description().iter().map(|t| d.comment(t)));
    lines.push(d.comment(&format!("Not confirmed: {}", d.unconfirmed())));
    lines.extend(setup);
    let rotary = job.kind() == AxisKind::Rotary;
    for (k, block) in blocks(job.plan).iter().enumerate() {
        match block {
            Block::Move { .. } => {
                let feed = (k == 0).then_some(job.plan.motion.feed);
                lines.extend(d.move_to(job, block, feed));
                if k == 0
                    && rotary
                    && let Some((on, _)) = d.incremental()
                {
                    lines.push(on.to_string());
                }
            }
            Block::Dwell(s) => lines.extend(d.dwell(*s)),
        }
    }
    if rotary && let Some((_, off)) = d.incremental() {
        lines.push(off.to_string());
    }
    lines.extend(d.end(job));
    Ok(lines.join("\n") + "\n")
}

/// A G-code move block: `prefix` (`G1 `), the axis word `word(axis, value)` (the absolute
/// position, or on a rotary axis after the start the signed move), ` F…` with the first
/// move, and a comment with the target's number and absolute position.
pub fn g_move<D: Dialect + ?Sized>(
    d: &D,
    job: &Job,
    block: &Block,
    feed: Option<f64>,
    prefix: &str,
    word: fn(&str, f64) -> String,
) -> Vec<String> {
    let Block::Move { position, by, what } = block else {
        return Vec::new();
    };
    let value = if is_incremental(job, block) {
        *by
    } else {
        *position
    };
    let mut line = format!("{prefix}{}", word(job.axis, value));
    if let Some(f) = feed {
        line.push_str(&format!(" F{}", number(f)));
    }
    let unit = job.kind().position_unit();
    let note = d.comment(&format!("{} at {} {unit}", what.text(), number(*position)));
    vec![format!("{line} {note}")]
}

/// `X10.000`: the axis letter and the number.
pub fn plain_word(axis: &str, value: f64) -> String {
    format!("{axis}{}", number(value))
}

/// Whether a move of a program for `job` is written incrementally: on a rotary axis, all
/// but the start.
pub fn is_incremental(job: &Job, block: &Block) -> bool {
    job.kind() == AxisKind::Rotary
        && !matches!(
            block,
            Block::Move {
                what: Purpose::Start,
                ..
            }
        )
}

/// Every control, by name.
pub const DIALECTS: &[&dyn Dialect] = &[
    &fanuc::Fanuc,
    &siemens_840d::Siemens840d,
    &heidenhain::Heidenhain,
    &linuxcnc::LinuxCnc,
    &twincat::TwinCat,
];

/// The control called `name`.
pub fn find(name: &str) -> Option<&'static dyn Dialect> {
    DIALECTS.iter().copied().find(|d| d.name() == name)
}

/// The controls' names, for messages.
pub fn names() -> Vec<&'static str> {
    DIALECTS.iter().map(|d| d.name()).collect()
}

/// `name` is one letter of the axis words most controls take.
pub fn one_letter(name: &str, control: &str) -> Result<(), ProgramError> {
    let ok = name.len() == 1 && "XYZABCUVW".contains(name);
    if ok {
        Ok(())
    } else {
        Err(ProgramError(format!(
            "{control} addresses an axis by one of the letters X, Y, Z, A, B, C, U, V, W; got `{name}` (--axis)"
        )))
    }
}

/// `name` is a letter, then letters or digits (`X`, `X1`, `C2`).
pub fn identifier(name: &str, control: &str) -> Result<(), ProgramError> {
    let mut chars = name.chars();
    let ok = chars.next().is_some_and(|c| c.is_ascii_uppercase())
        && chars.all(|c| c.is_ascii_alphanumeric())
        && name.len() <= 8;
    if ok {
        Ok(())
    } else {
        Err(ProgramError(format!(
            "{control} needs an axis name of an upper-case letter and letters or digits (X, C, X1); got `{name}` (--axis)"
        )))
    }
}

/// A position or distance to 0.001, with a decimal point always.
pub fn number(x: f64) -> String {
    fmt_fixed(x, 3)
}
