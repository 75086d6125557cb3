//! Part programs that run a plan on a control, one file per control (as the compensation
//! tables are): the same path for every control ([`blocks`]: the steps of the test cycle,
//! each target approached from its direction after the overrun, a dwell at each), written
//! in each control's own syntax for moves, dwell and comments ([`Dialect`]).
//!
//! - **Only the tested axis moves.** No block addresses another axis, selects or cancels a
//!   tool or its length offset (`G49` is not written: cancelling a length offset may move
//!   the tool axis), nor changes an offset.
//! - **Machine coordinates** by default ([`Coordinates`]): every absolute move is
//!   addressed in the machine's own coordinates by the control's own means that keeps the
//!   programmed feed (LinuxCNC `G53`, SINUMERIK `SUPA`, HEIDENHAIN `M91`, TwinCAT
//!   `#SUPPRESS OFFSETS` in the block; FANUC's `G53` moves at rapid traverse, so its
//!   program selects `G54` and its head states what must be zero). The compensation tables
//!   axcheck writes are in machine positions; with `--coordinates work` the head says that
//!   the active work offset must be added to each table position.
//! - **Rotary axes** move to their first position absolutely and then incrementally (G91
//!   or its equivalent): the sign of each move after the first is its direction whatever
//!   the axis's modulo, roll-over or shortest-path setting, which the controls define
//!   differently (FANUC parameter 1008, Siemens ACP/ACN and MD30455, HEIDENHAIN M126,
//!   LinuxCNC WRAPPED_ROTARY, ISG modulo signs). On a continuous axis (one that turns
//!   freely) the first move goes to a target's angle within one turn, 0 to under 360°
//!   (the first target in that range, [`Purpose::Align`]), and the start below the first
//!   target follows incrementally: an angle within one turn is the same position on an
//!   axis that counts turns (LinuxCNC without WRAPPED_ROTARY, a SINUMERIK or ISG axis that
//!   is not modulo, a TNC that counts) and on a modulo one (LinuxCNC's `unwrap_rotary`,
//!   interp_find.cc, reads a negative value as a direction and its magnitude as the
//!   position; an ISG modulo axis's first sign is a direction; SINUMERIK refuses a modulo
//!   position outside 0…360° when MD30455 bit 0 is 0, alarm 16830, from a third-party
//!   source). A start written as `C355.000` for −5° put the readings of a counting axis a
//!   turn up. Any other axis keeps every move inside its travel ([`check_travel`]), and
//!   its start is its position.
//! - **Lathes** ([`Job::lathe`]): X in radius where the control has a programmable radius
//!   mode (SINUMERIK `DIAMOF`, LinuxCNC `G8`, TwinCAT `G52`), in diameter on FANUC (every X
//!   word twice the slide's position), with FANUC's G-code system A, B or C; HEIDENHAIN
//!   refuses.
//!
//! The comments give every absolute position, unwrapped, as the data file numbers the
//! targets.

pub mod fanuc;
pub mod heidenhain;
pub mod linuxcnc;
pub mod siemens_840d;
pub mod twincat;

use super::Plan;
use crate::axis_model::Step;
use crate::units::{AxisKind, Direction, Travel, fmt_fixed};

/// Why a program cannot be written.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct ProgramError(pub String);

/// One block of the program, before a control's syntax.
#[derive(Debug, Clone, PartialEq)]
pub enum Block {
    /// A move to `position` (mm or deg, as the data file numbers it), `by` from the
    /// position before it; `absolute`: written as a position (every move of an axis that
    /// is not rotary, a rotary axis's first), else as its signed distance.
    Move {
        position: f64,
        by: f64,
        what: Purpose,
        absolute: bool,
    },
    /// The dwell at a target, s.
    Dwell(f64),
}

/// Why the axis moves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Purpose {
    /// On a continuous rotary axis, first to the angle of a target within one turn, where
    /// an axis that counts turns and a modulo one agree.
    Align,
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
            Purpose::Align => "align".into(),
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
/// incremental move is exact) and a dwell after each target; on a continuous rotary axis
/// led by the move to a target's angle within one turn ([`align_at`]).
pub fn blocks(plan: &Plan) -> Vec<Block> {
    let rotary = plan.axis.kind == AxisKind::Rotary;
    let steps = plan.test_plan().steps(&plan.targets);
    let mut out = Vec::with_capacity(2 * steps.len() + 1);
    let mut at: Option<i64> = None;
    if let Some(align) = align_at(plan) {
        at = Some(milli(align));
        out.push(Block::Move {
            position: align,
            by: 0.0,
            what: Purpose::Align,
            absolute: true,
        });
    }
    let mut started = false;
    for step in steps {
        let position = milli(step.position());
        let by = at.map_or(0, |a| position - a) as f64 / 1000.0;
        let what = match step {
            Step::Move(_) if !started => Purpose::Start,
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
        started = true;
        // A move of no length (the start when the path begins there) is not written again.
        if at.is_some() && by == 0.0 && !matches!(what, Purpose::Target { .. }) {
            continue;
        }
        let absolute = at.is_none() || !rotary;
        at = Some(position);
        out.push(Block::Move {
            position: position as f64 / 1000.0,
            by,
            what,
            absolute,
        });
        if matches!(what, Purpose::Target { .. }) && plan.motion.dwell_s > 0.0 {
            out.push(Block::Dwell(plan.motion.dwell_s));
        }
    }
    out
}

/// A position in thousandths of its unit, the program's step.
fn milli(x: f64) -> i64 {
    (x * 1000.0).round() as i64
}

/// Where a continuous rotary axis goes first: the first target (in the plan's order) at
/// an angle within one turn, 0 to under 360°, where an axis that counts turns and a
/// modulo one stand at the same position; without one, the first target's angle within
/// one turn (a counting axis's readings are then whole turns from the targets, as the
/// head says). `None` on any other axis.
pub(crate) fn align_at(plan: &Plan) -> Option<f64> {
    if plan.axis.kind != AxisKind::Rotary || !plan.axis.continuous {
        return None;
    }
    let in_turn = |t: &&f64| (0.0..360.0).contains(*t);
    let first = plan.targets.iter().find(in_turn).or(plan.targets.first())?;
    Some(milli(*first) as f64 / 1000.0)
}

/// Which coordinates the absolute moves address.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Coordinates {
    /// The machine's own (the compensation tables' positions): by each control's means.
    #[default]
    Machine,
    /// The active work offset, as the shop has it set.
    Work,
}

impl Coordinates {
    /// `machine` or `work`, as `--coordinates` takes it.
    pub fn parse(text: &str) -> Option<Coordinates> {
        match text {
            "machine" => Some(Coordinates::Machine),
            "work" => Some(Coordinates::Work),
            _ => None,
        }
    }
}

/// FANUC's G-code system of a lathe (parameter 3401#6, #7): A, B or C.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum GcodeSystem {
    #[default]
    A,
    B,
    C,
}

impl GcodeSystem {
    /// `a`, `b` or `c`, as `--gcode-system` takes it.
    pub fn parse(text: &str) -> Option<GcodeSystem> {
        match text {
            "a" | "A" => Some(GcodeSystem::A),
            "b" | "B" => Some(GcodeSystem::B),
            "c" | "C" => Some(GcodeSystem::C),
            _ => None,
        }
    }

    pub fn letter(self) -> char {
        match self {
            GcodeSystem::A => 'A',
            GcodeSystem::B => 'B',
            GcodeSystem::C => 'C',
        }
    }
}

/// What a program is written for.
pub struct Job<'a> {
    pub plan: &'a Plan,
    /// The axis's address on the control (`X`, `C`; Siemens and TwinCAT also `X1`).
    pub axis: &'a str,
    /// The program's name (`ISO230X`).
    pub name: &'a str,
    pub coordinates: Coordinates,
    /// `Some`: the machine is a lathe, with FANUC's G-code system (the other controls
    /// ignore it).
    pub lathe: Option<GcodeSystem>,
}

impl<'a> Job<'a> {
    /// A job in machine coordinates on a machine that is not a lathe.
    pub fn new(plan: &'a Plan, axis: &'a str, name: &'a str) -> Job<'a> {
        Job {
            plan,
            axis,
            name,
            coordinates: Coordinates::Machine,
            lathe: None,
        }
    }

    pub fn kind(&self) -> AxisKind {
        self.plan.axis.kind
    }

    /// A rotary axis that turns freely: its start is written within one turn.
    pub fn continuous_rotary(&self) -> bool {
        self.kind() == AxisKind::Rotary && self.plan.axis.continuous
    }

    /// Whether absolute moves carry the control's machine-coordinate word.
    pub fn machine(&self) -> bool {
        self.coordinates == Coordinates::Machine
    }

    /// The lines that describe the plan, for the program's head: `means` is how the
    /// control addresses machine coordinates, `lathe` how it programs X on a lathe.
    pub fn description(&self, means: &[String], lathe: &[String]) -> Vec<String> {
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
        match self.coordinates {
            Coordinates::Machine => out.extend(means.iter().enumerate().map(|(k, m)| match k {
                0 => format!("Machine coordinates: {m}"),
                _ => m.clone(),
            })),
            Coordinates::Work => out.extend(work_note(self.axis)),
        }
        out.extend(lathe.iter().cloned());
        out.extend(self.rotary_notes());
        out.push(format!(
            "Only axis {} moves: no block changes a tool, a tool length or an offset",
            self.axis
        ));
        out.push(
            "Check the axis address, the travel and the feed; run it once without the laser first"
                .into(),
        );
        out
    }

    /// How a rotary axis's moves are written, for the head.
    fn rotary_notes(&self) -> Vec<String> {
        if self.kind() != AxisKind::Rotary {
            return Vec::new();
        }
        let mut out = vec!["Rotary axis: after the first move every move is incremental, so its sign is its direction whatever the axis's modulo or shortest-path setting".to_string()];
        if let Some(align) = align_at(self.plan) {
            out.push(format!(
                "The axis is continuous, it turns freely: the first move goes to {} deg, an angle within one turn, where an axis that counts turns and a modulo, roll-over or shortest-path axis agree; the start follows incrementally",
                number(within_turn(align))
            ));
            if within_turn(align) != align {
                out.push(format!(
                    "No target lies within 0 to 360 deg: on an axis that counts turns the positions read are {} deg from the targets' numbers",
                    number(within_turn(align) - align)
                ));
            }
            out.push("The comments give the positions as the data file numbers the targets".into());
        } else {
            let [a, b] = travel_ends(self.plan.axis.travel);
            out.push(format!(
                "The axis is not continuous: every move stays inside its travel {} to {} deg",
                number(a),
                number(b)
            ));
        }
        out
    }
}

/// The head's note on work coordinates (and the console's).
pub fn work_note(axis: &str) -> [String; 2] {
    [
        "Work coordinates, as --coordinates work asks: every position is in the active work offset"
            .into(),
        format!(
            "The compensation tables axcheck writes are in machine positions: add the active work offset of axis {axis} to each table position"
        ),
    ]
}

/// A control's syntax: its own words for the program's frame, moves, dwell and comments;
/// the program is assembled from them ([`Dialect::write`]).
pub trait Dialect: Sync {
    /// The name users give (`--program NAME`).
    fn name(&self) -> &'static str;
    /// The program file's extension.
    fn extension(&self) -> &'static str;
    /// The axis address as the control takes it on the job's machine, or why not.
    fn address(&self, job: &Job) -> Result<(), ProgramError>;
    /// A comment line.
    fn comment(&self, text: &str) -> String;
    /// The program's first lines (before the description) and the modal set-up after it.
    fn begin(&self, job: &Job) -> (Vec<String>, Vec<String>);
    /// How the program addresses machine coordinates, for the head (a line each).
    fn machine_coordinates(&self, job: &Job) -> Vec<String>;
    /// How X is programmed on a lathe, for the head, or why no lathe program is written.
    fn lathe(&self, job: &Job) -> Result<Vec<String>, ProgramError>;
    /// The move of `block` (a [`Block::Move`]): absolute, or incremental on a rotary axis
    /// after the start; `feed` on the first move only (every control keeps it).
    fn move_to(&self, job: &Job, block: &Block, feed: Option<f64>) -> Vec<String>;
    /// The dwell, s.
    fn dwell(&self, seconds: f64) -> Vec<String>;
    /// The lines that switch to incremental moves and back, for a rotary axis (`None`: the
    /// control marks each move incremental itself).
    fn incremental(&self, job: &Job) -> Option<(&'static str, &'static str)>;
    /// The program's last lines.
    fn end(&self, job: &Job) -> Vec<String>;
    /// What is not confirmed about this control's syntax, for the program's head.
    fn unconfirmed(&self, job: &Job) -> String;

    /// The whole program.
    fn write(&self, job: &Job) -> Result<String, ProgramError> {
        assemble(self, job)
    }
}

/// The program of `job` in `d`'s words: its frame, the description as comments, the
/// set-up, the moves and dwells, the end; refused where the control cannot take the axis
/// or the machine, or a move leaves the travel of an axis that is not continuous.
pub(crate) fn assemble<D: Dialect + ?Sized>(d: &D, job: &Job) -> Result<String, ProgramError> {
    d.address(job)?;
    let lathe = job
        .lathe
        .map(|_| d.lathe(job))
        .transpose()?
        .unwrap_or_default();
    check_travel(job)?;
    let (first, setup) = d.begin(job);
    let mut lines = first;
    let means = d.machine_coordinates(job);
    let head = job.description(&means, &lathe);
    lines.extend(head.iter().map(|t| d.comment(t)));
    lines.push(d.comment(&format!("Not confirmed: {}", d.unconfirmed(job))));
    lines.extend(setup);
    let rotary = job.kind() == AxisKind::Rotary;
    for (k, block) in blocks(job.plan).iter().enumerate() {
        match block {
            Block::Move { .. } => {
                let feed = (k == 0).then_some(job.plan.motion.feed);
                lines.extend(d.move_to(job, block, feed));
                if k == 0
                    && rotary
                    && let Some((on, _)) = d.incremental(job)
                {
                    lines.push(on.to_string());
                }
            }
            Block::Dwell(s) => lines.extend(d.dwell(*s)),
        }
    }
    if rotary && let Some((_, off)) = d.incremental(job) {
        lines.push(off.to_string());
    }
    lines.extend(d.end(job));
    Ok(lines.join("\n") + "\n")
}

/// The ends of a travel, mm or deg.
pub(crate) fn travel_ends(travel: Travel) -> [f64; 2] {
    match travel {
        Travel::Length(l) => [0.0, l],
        Travel::Range(r) => r,
    }
}

/// Every move of an axis that is not continuous lies inside its axis travel; else the
/// first that leaves it is named, with the travel.
pub(crate) fn check_travel(job: &Job) -> Result<(), ProgramError> {
    if job.continuous_rotary() {
        return Ok(());
    }
    let [a, b] = travel_ends(job.plan.axis.travel);
    let unit = job.kind().position_unit();
    for block in blocks(job.plan) {
        let Block::Move { position, what, .. } = block else {
            continue;
        };
        if position < a - 1e-9 || position > b + 1e-9 {
            let hint = match job.kind() {
                AxisKind::Rotary => {
                    ", which is not continuous: mark a rotary axis that turns freely continuous (--continuous, or `continuous: true` in the campaign or the plan file), else plan it again inside its travel"
                }
                AxisKind::Linear => ": plan it again inside the travel",
            };
            return Err(ProgramError(format!(
                "the {} move to {} {unit} leaves the axis travel {} to {} {unit} of axis {}{hint}",
                what.text(),
                number(position),
                number(a),
                number(b),
                job.axis
            )));
        }
    }
    Ok(())
}

/// The program's first position, mm or deg: the start, or on a continuous rotary axis
/// the angle it aligns at ([`align_at`]).
pub fn first_position(plan: &Plan) -> f64 {
    match blocks(plan).first() {
        Some(Block::Move { position, .. }) => *position,
        _ => 0.0,
    }
}

/// An angle within one turn, 0 to under 360° (to 0.001°, exactly).
pub(crate) fn within_turn(deg: f64) -> f64 {
    let milli = (deg * 1000.0).round() as i64;
    milli.rem_euclid(360_000) as f64 / 1000.0
}

/// What a move block programs: the value of its axis word and whether it is incremental.
/// Absolute: the position (on a continuous rotary axis, within one turn); incremental (a
/// rotary axis after its first move): the signed move.
pub(crate) fn word_value(job: &Job, block: &Block) -> (f64, bool) {
    let Block::Move { position, by, .. } = block else {
        return (0.0, false);
    };
    if is_incremental(block) {
        (*by, true)
    } else if job.continuous_rotary() {
        (within_turn(*position), false)
    } else {
        (*position, false)
    }
}

/// The comment of a move: why, and its absolute position (unwrapped).
pub(crate) fn move_note<D: Dialect + ?Sized>(d: &D, job: &Job, block: &Block) -> String {
    let Block::Move { position, what, .. } = block else {
        return String::new();
    };
    let unit = job.kind().position_unit();
    d.comment(&format!("{} at {} {unit}", what.text(), number(*position)))
}

/// A G-code move block: `words(value, incremental)` (the block's words for the value of
/// [`word_value`]), ` F…` with the first move, and the move's comment.
pub(crate) fn g_move<D: Dialect + ?Sized>(
    d: &D,
    job: &Job,
    block: &Block,
    feed: Option<f64>,
    words: impl Fn(f64, bool) -> String,
) -> Vec<String> {
    if !matches!(block, Block::Move { .. }) {
        return Vec::new();
    }
    let (value, incremental) = word_value(job, block);
    let mut line = words(value, incremental);
    if let Some(f) = feed {
        line.push_str(&format!(" F{}", number(f)));
    }
    vec![format!("{line} {}", move_note(d, job, block))]
}

/// `X10.000`: the axis letter and the number.
pub(crate) fn plain_word(axis: &str, value: f64) -> String {
    format!("{axis}{}", number(value))
}

/// `X10.000`, or for a name of more than one character `X1=10.000` (SINUMERIK, and ISG:
/// "an equals sign must follow axis identifiers that contain more than one character").
pub(crate) fn named_word(axis: &str, value: f64) -> String {
    if axis.len() == 1 {
        plain_word(axis, value)
    } else {
        format!("{axis}={}", number(value))
    }
}

/// Whether the move is the program's first (the start, or on a continuous rotary axis
/// the alignment before it).
pub(crate) fn is_first(block: &Block) -> bool {
    matches!(
        block,
        Block::Move {
            what: Purpose::Start | Purpose::Align,
            absolute: true,
            ..
        }
    )
}

/// Whether a move is written incrementally: on a rotary axis, all but the first.
pub(crate) fn is_incremental(block: &Block) -> bool {
    matches!(
        block,
        Block::Move {
            absolute: false,
            ..
        }
    )
}

/// Every control, by name.
pub const DIALECTS: &[&dyn Dialect] = &[
    &fanuc::FanucProgram,
    &siemens_840d::Siemens840dProgram,
    &heidenhain::HeidenhainProgram,
    &linuxcnc::LinuxCncProgram,
    &twincat::TwinCatProgram,
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
pub(crate) fn one_letter(name: &str, control: &str) -> Result<(), ProgramError> {
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
