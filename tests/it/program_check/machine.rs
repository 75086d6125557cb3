//! The axis every checker drives: where it is in machine coordinates, which way it last
//! moved and how far since it last turned, and what the program read there (a dwell after
//! a move is a reading). The checkers give it machine positions; it keeps the trace the
//! tests compare with the plan ([`verify`]).

use axcheck::plan::Plan;
use axcheck::units::Direction;
use std::fmt;

/// How a move is fed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Feed {
    /// At rapid traverse (G0, or a control's machine-coordinate move that is always rapid).
    Rapid,
    /// At the programmed feed, mm/min or deg/min.
    PerMinute(f64),
}

/// A move of the tested axis: its program line (1-based), the machine position reached
/// (unwrapped: a rotary axis keeps counting past 360°) and its feed.
#[derive(Debug, Clone, PartialEq)]
pub struct Move {
    pub line: usize,
    pub to: f64,
    pub feed: Feed,
}

/// A reading: the dwell at `position` (machine, unwrapped), reached moving `upward`
/// (`None`: the axis had not moved yet) after `approach` of travel in that direction.
#[derive(Debug, Clone, PartialEq)]
pub struct Reading {
    pub line: usize,
    pub position: f64,
    pub upward: Option<bool>,
    pub approach: f64,
    pub dwell_s: f64,
}

/// What a program did: the tested axis's moves and readings, and the blocks that move
/// anything else (another axis, or a tool-length change that may move one).
#[derive(Debug, Clone, Default)]
pub struct Trace {
    pub moves: Vec<Move>,
    pub readings: Vec<Reading>,
    pub others: Vec<String>,
}

/// Why a control refuses a program, or why a checker does: the line (1-based), the block
/// as written and the reason with its source.
#[derive(Debug, Clone, PartialEq)]
pub struct Refusal {
    pub line: usize,
    pub block: String,
    pub why: String,
}

/// `line 12 `G49`: why`; without the line (0) or the block when there is none.
impl fmt::Display for Refusal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line > 0 {
            write!(f, "line {} ", self.line)?;
        }
        if !self.block.is_empty() {
            write!(f, "`{}`: ", self.block)?;
        }
        write!(f, "{}", self.why)
    }
}

/// Builds a [`Refusal`].
pub fn refuse<T>(line: usize, block: &str, why: impl Into<String>) -> Result<T, Refusal> {
    Err(Refusal {
        line,
        block: block.trim().to_string(),
        why: why.into(),
    })
}

/// The tested axis as it moves: position, last direction, travel since the last reversal.
pub struct Tracker {
    position: f64,
    upward: Option<bool>,
    run: f64,
    pub trace: Trace,
}

impl Tracker {
    /// An axis standing at machine position `initial`.
    pub fn new(initial: f64) -> Tracker {
        Tracker {
            position: initial,
            upward: None,
            run: 0.0,
            trace: Trace::default(),
        }
    }

    /// The machine position now (unwrapped).
    pub fn position(&self) -> f64 {
        self.position
    }

    /// Moves to machine position `to`. A move of no length is recorded but changes
    /// neither direction nor the travel since the last reversal.
    pub fn go(&mut self, line: usize, to: f64, feed: Feed) {
        let by = to - self.position;
        if by.abs() > 1e-9 {
            let up = by > 0.0;
            if self.upward == Some(up) {
                self.run += by.abs();
            } else {
                self.run = by.abs();
            }
            self.upward = Some(up);
        }
        self.position = to;
        self.trace.moves.push(Move { line, to, feed });
    }

    /// A dwell of `seconds` where the axis stands: a reading.
    pub fn dwell(&mut self, line: usize, seconds: f64) {
        self.trace.readings.push(Reading {
            line,
            position: self.position,
            upward: self.upward,
            approach: self.run,
            dwell_s: seconds,
        });
    }

    /// A block that moves something other than the tested axis.
    pub fn other(&mut self, line: usize, what: impl Into<String>) {
        self.trace
            .others
            .push(format!("line {line}: {}", what.into()));
    }
}

/// `x` within [0, 360).
pub fn turn(x: f64) -> f64 {
    let r = x.rem_euclid(360.0);
    if (r - 360.0).abs() < 1e-9 { 0.0 } else { r }
}

/// Whether two positions agree to `tolerance`; on a modulo axis, as angles.
pub fn same(a: f64, b: f64, modulo: bool, tolerance: f64) -> bool {
    if modulo {
        let d = (a - b).rem_euclid(360.0);
        d.min(360.0 - d) <= tolerance
    } else {
        (a - b).abs() <= tolerance
    }
}

/// What a program must have done for a plan: each target's machine position is the plan's
/// target plus `offset` (0 when the program addresses machine coordinates), compared as
/// angles on a `modulo` axis, to `tolerance`.
#[derive(Debug, Clone, Copy)]
pub struct Expect {
    pub offset: f64,
    pub modulo: bool,
    pub tolerance: f64,
}

/// The plan's readings in order: target index, its position, direction.
fn planned(plan: &Plan) -> Vec<(usize, f64, Direction)> {
    use axcheck::axis_model::Step;
    plan.test_plan()
        .steps(&plan.targets)
        .into_iter()
        .filter_map(|s| match s {
            Step::Read {
                position,
                target,
                direction,
                ..
            } => Some((target, position, direction)),
            Step::Move(_) => None,
        })
        .collect()
}

/// Everything in `trace` that the plan does not ask for: readings out of order, off their
/// target, from the wrong side, after too short an approach or with another dwell; a
/// target not read exactly n times from each side; a move not at the plan's feed; anything
/// else moved. Empty when the program runs the plan.
pub fn verify(plan: &Plan, trace: &Trace, expect: &Expect) -> Vec<String> {
    let want = planned(plan);
    let mut problems = Vec::new();
    if trace.readings.len() != want.len() {
        problems.push(format!(
            "{} readings, the plan has {}",
            trace.readings.len(),
            want.len()
        ));
    }
    let mut hits = vec![[0usize; 2]; plan.targets.len()];
    for (r, &(target, position, direction)) in trace.readings.iter().zip(&want) {
        let at = position + expect.offset;
        let up = direction == Direction::Up;
        let mut wrong = Vec::new();
        if !same(r.position, at, expect.modulo, expect.tolerance) {
            let (got, want) = if expect.modulo {
                (turn(r.position), turn(at))
            } else {
                (r.position, at)
            };
            wrong.push(format!("at {got:.4} instead of {want:.4}"));
        }
        if r.upward != Some(up) {
            wrong.push(format!("approached {:?} instead of up = {up}", r.upward));
        }
        if r.approach < plan.motion.overrun - 1e-6 {
            wrong.push(format!(
                "approach {:.4} < overrun {}",
                r.approach, plan.motion.overrun
            ));
        }
        if (r.dwell_s - plan.motion.dwell_s).abs() > 1e-9 {
            wrong.push(format!("dwell {} s", r.dwell_s));
        }
        if wrong.is_empty() {
            hits[target][direction.index()] += 1;
        } else {
            problems.push(format!(
                "line {}: T{} {}: {}",
                r.line,
                target + 1,
                direction.name(),
                wrong.join(", ")
            ));
        }
    }
    for (k, h) in hits.iter().enumerate() {
        if h[0] != plan.runs || h[1] != plan.runs {
            problems.push(format!(
                "T{} reached {}× up and {}× down as planned, not {}×",
                k + 1,
                h[0],
                h[1],
                plan.runs
            ));
        }
    }
    problems.extend(feed_problems(plan, trace));
    problems.extend(trace.others.iter().cloned());
    problems
}

/// The moves not made at the plan's feed.
fn feed_problems(plan: &Plan, trace: &Trace) -> Vec<String> {
    trace
        .moves
        .iter()
        .filter(|m| match m.feed {
            Feed::Rapid => true,
            Feed::PerMinute(f) => (f - plan.motion.feed).abs() > 1e-9,
        })
        .map(|m| {
            format!(
                "line {}: moves at {:?}, not F{}",
                m.line, m.feed, plan.motion.feed
            )
        })
        .collect()
}

/// A number as the G-code dialects write it: a sign, digits, at most one decimal point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Number {
    pub value: f64,
    /// Whether it was written with a decimal point (FANUC reads `X10` as 10 increments).
    pub point: bool,
    /// Whether it was written with a sign.
    pub signed: bool,
}

/// Reads `text` as a whole [`Number`], or `None`.
pub fn number(text: &str) -> Option<Number> {
    let body = text.strip_prefix(['+', '-']).unwrap_or(text);
    let digits = body.chars().filter(|c| c.is_ascii_digit()).count();
    let points = body.matches('.').count();
    let ok = digits > 0 && points <= 1 && body.chars().all(|c| c.is_ascii_digit() || c == '.');
    if !ok {
        return None;
    }
    Some(Number {
        value: text.parse().ok()?,
        point: points == 1,
        signed: body.len() != text.len(),
    })
}
