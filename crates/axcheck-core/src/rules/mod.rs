//! Test-plan rules: does the measured test follow the standard's plan?
//!
//! One file per rule, its reason beside its check. Each rule has an id, the clause it
//! enforces, a severity and a message that says what to change. Rules count what was
//! measured (targets and runs in the data), not what the campaign claims. Which travel
//! rules apply follows the measured travel: a linear test over ≤ 2000 mm is a clause 4.3.2
//! test (also the working-range test of a longer axis, 4.3.3), a longer one a clause 4.3.3
//! test; rotary tests over ≤ 360° follow 4.3.4, longer ones 4.3.5 (ISO 230-2:1997).

mod data_unit;
mod gost_2_10_runs;
mod gost_2_7_targets;
mod gost_2_8_cardinal;
mod instrument_calibration_due;
mod iso_2_2_measurement_travel;
mod iso_2_2_reversal_room;
mod iso_3_3_thermal;
mod iso_4_2_pitch_alias;
mod iso_4_2_uniform_spacing;
mod iso_4_3_2_runs;
mod iso_4_3_2_targets;
mod iso_4_3_3_runs;
mod iso_4_3_3_spacing;
mod iso_4_3_4_cardinal;
mod iso_4_3_4_runs;
mod iso_4_3_4_targets;
mod iso_4_3_5_range;
mod iso_4_3_5_runs;
mod iso_4_3_5_spacing;
mod iso_7_1_conditions;
mod plan_targets;

use crate::evaluate::StandardId;
use crate::measurement::AxisData;
use crate::units::Travel;
use crate::units::{AxisKind, fmt_position};
use serde::Serialize;

#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    /// The test does not follow the standard: the verdict is `noncompliant`.
    Error,
    /// Worth fixing; the result stands.
    Warning,
}

impl Severity {
    /// `error` or `warning`, as in the JSON outputs.
    pub fn name(self) -> &'static str {
        match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
        }
    }
}

/// A broken rule (a violation of the test plan the standard sets).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Violation {
    pub id: &'static str,
    pub clause: &'static str,
    pub severity: Severity,
    #[serde(serialize_with = "message_text")]
    pub message: Message,
}

/// A finding's message, one allocation shared by the tests that get the same one: a
/// fleet's axes mostly miss the same clause 7.1 conditions, and that 860-byte warning
/// once per axis was 8.6 MB of the CI gate's 65 MB of heap on 10 000 axes.
pub type Message = std::sync::Arc<str>;

fn message_text<S: serde::Serializer>(message: &Message, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(message)
}

/// `message` as the message of rule `id`: the one this thread made last for the rule when
/// the text is the same (tests are judged one after another on each worker), else a new
/// one.
fn shared(id: &'static str, message: String) -> Message {
    use std::cell::RefCell;
    thread_local! {
        static LAST: RefCell<Vec<(&'static str, Message)>> = const { RefCell::new(Vec::new()) };
    }
    LAST.with(|last| {
        let mut last = last.borrow_mut();
        let slot = last.iter().position(|(rule, _)| *rule == id);
        if let Some(k) = slot
            && *last[k].1 == *message
        {
            return last[k].1.clone();
        }
        let made: Message = message.into();
        match slot {
            Some(k) => last[k].1 = made.clone(),
            None => last.push((id, made.clone())),
        }
        made
    })
}

/// Whether `findings` break the test plan: any error does, and a test whose plan is
/// broken is noncompliant whatever its values (warnings are shown, not judged).
pub fn breaks_plan(findings: &[Violation]) -> bool {
    findings.iter().any(|f| f.severity == Severity::Error)
}

/// What the campaign says about the axis, besides its data.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanContext {
    pub kind: AxisKind,
    pub standard: StandardId,
    pub axis_travel: Option<Travel>,
    pub measurement_travel: Option<[f64; 2]>,
    /// Lead-screw or encoder pitch, mm or deg.
    pub pitch: Option<f64>,
    /// The test planned for the axis (`plan:`), to compare the measurement with.
    pub planned: Option<std::sync::Arc<Planned>>,
    /// The clause 7.1 conditions the campaign does not state (`None`: not a campaign's
    /// test, e.g. a plan before the measurement).
    pub unstated: Option<Vec<&'static str>>,
    /// The instrument's stated calibration and the test's date (`None`: not stated).
    pub calibration: Option<CalibrationDue>,
}

/// The instrument's calibration as stated, against the test's date; dates as
/// `YYYY-MM-DD`, which compare as text.
#[derive(Debug, Clone, PartialEq)]
pub struct CalibrationDue {
    /// The instrument's name and serial as stated (`None`: no instrument is stated).
    pub instrument: Option<String>,
    pub certificate: Option<String>,
    pub calibrated_on: Option<String>,
    pub due: Option<String>,
    pub test_date: Option<String>,
    /// The campaign is a calibration certificate (`campaign.certificate`): the traceability
    /// must be shown, so an unstated certificate or due date is a breach too.
    pub certifying: bool,
}

/// A planned test as the rules compare it: its targets (mm or deg) and runs, or why its
/// file could not be read.
#[derive(Debug, Clone, PartialEq)]
pub struct Planned {
    /// The plan file as the campaign names it.
    pub file: String,
    pub read: Result<(Vec<f64>, usize), PlanUnread>,
    /// How far a measured target may lie from its planned position, mm or deg.
    pub tolerance: f64,
}

/// Why a planned test cannot be compared.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PlanUnread {
    /// The file cannot be had or read as a plan: the reason as the file layer gives it
    /// (a path refused, a file missing, a key at a line).
    #[error("{0}")]
    File(String),
    #[error("it plans a {planned} axis, this one is {measured}")]
    Kind {
        planned: AxisKind,
        measured: AxisKind,
    },
}

/// A test-plan rule: what it is called and enforces, and its check.
#[derive(Debug, Clone, Copy)]
pub struct Rule {
    pub id: &'static str,
    pub clause: &'static str,
    pub severity: Severity,
    /// What the rule checks, in a few words (the README's rule table).
    pub checks: &'static str,
    /// The message when the plan breaks the rule; `None` when it holds or does not apply.
    check: fn(&Plan) -> Option<String>,
}

impl Rule {
    /// The finding for `plan`, if the rule is broken.
    fn apply(&self, plan: &Plan) -> Option<Violation> {
        (self.check)(plan).map(|message| Violation {
            id: self.id,
            clause: self.clause,
            severity: self.severity,
            message: shared(self.id, message),
        })
    }
}

/// Every rule, in the order their findings are reported.
pub const RULES: &[Rule] = &[
    iso_4_3_2_targets::RULE,
    iso_4_3_2_runs::RULE,
    iso_4_3_3_spacing::RULE,
    iso_4_3_3_runs::RULE,
    iso_4_3_4_targets::RULE,
    iso_4_3_4_cardinal::RULE,
    iso_4_3_4_runs::RULE,
    iso_4_3_5_spacing::RULE,
    iso_4_3_5_runs::RULE,
    iso_4_3_5_range::RULE,
    gost_2_7_targets::RULE,
    gost_2_8_cardinal::RULE,
    gost_2_10_runs::RULE,
    iso_2_2_measurement_travel::RULE,
    iso_2_2_reversal_room::RULE,
    iso_4_2_uniform_spacing::RULE,
    iso_4_2_pitch_alias::RULE,
    iso_3_3_thermal::RULE,
    data_unit::RULE,
    plan_targets::RULE,
    iso_7_1_conditions::RULE,
    instrument_calibration_due::RULE,
];

/// Checks the plan of one test.
pub fn check(ctx: &PlanContext, data: &AxisData) -> Vec<Violation> {
    let plan = Plan::new(ctx, data);
    RULES.iter().filter_map(|rule| rule.apply(&plan)).collect()
}

/// The rules that hold for every test an instrument measures, whatever its plan's standard:
/// those of a straightness or angular test (ISO 230-1), whose plans ISO 230-2's rules do
/// not judge.
pub fn check_instrument(ctx: &PlanContext, data: &AxisData) -> Vec<Violation> {
    let plan = Plan::new(ctx, data);
    instrument_calibration_due::RULE
        .apply(&plan)
        .into_iter()
        .collect()
}

const EPS: f64 = 1e-9;

/// Linear tests over at most this measured travel follow clause 4.3.2.
pub(crate) const LINEAR_SHORT_MM: f64 = 2000.0;
/// Rotary tests over at most this measured travel follow clause 4.3.4.
pub(crate) const ROTARY_SHORT_DEG: f64 = 360.0;

/// The ISO 230-2 clause whose plan a test follows, by axis kind and measured travel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum IsoPlan {
    /// Linear, up to 2000 mm.
    Clause4_3_2,
    /// Linear, over 2000 mm.
    Clause4_3_3,
    /// Rotary, up to 360°.
    Clause4_3_4,
    /// Rotary, over 360°.
    Clause4_3_5,
}

/// One test as the rules see it: the campaign's context and the measured figures.
struct Plan<'a> {
    ctx: &'a PlanContext,
    data: &'a AxisData,
    /// m: targets measured.
    targets: usize,
    /// n: approaches per direction.
    runs: usize,
    /// First and last target.
    first: f64,
    last: f64,
    /// Measurement travel, last − first.
    travel: f64,
}

impl<'a> Plan<'a> {
    fn new(ctx: &'a PlanContext, data: &'a AxisData) -> Plan<'a> {
        let (first, last) = data.measurement_travel();
        Plan {
            ctx,
            data,
            targets: data.target_count(),
            runs: data.runs(),
            first,
            last,
            travel: last - first,
        }
    }

    fn gost(&self) -> bool {
        self.ctx.standard == StandardId::Gost27843
    }

    /// The ISO clause the test follows; `None` for a GOST 27843 test.
    fn iso_plan(&self) -> Option<IsoPlan> {
        if self.gost() {
            return None;
        }
        Some(match self.ctx.kind {
            AxisKind::Linear if self.travel <= LINEAR_SHORT_MM + EPS => IsoPlan::Clause4_3_2,
            AxisKind::Linear => IsoPlan::Clause4_3_3,
            AxisKind::Rotary if self.travel <= ROTARY_SHORT_DEG + EPS => IsoPlan::Clause4_3_4,
            AxisKind::Rotary => IsoPlan::Clause4_3_5,
        })
    }

    /// Position unit for messages: `mm` or `deg`.
    fn unit(&self) -> &'static str {
        self.ctx.kind.position_unit()
    }

    /// A position with its unit: `10 mm` or `40°`.
    fn at(&self, x: f64) -> String {
        match self.ctx.kind {
            AxisKind::Linear => format!("{} mm", fmt_position(x)),
            AxisKind::Rotary => format!("{}°", fmt_position(x)),
        }
    }

    /// Intervals between neighbouring targets.
    fn gaps(&self) -> Vec<f64> {
        self.data.targets.windows(2).map(|w| w[1] - w[0]).collect()
    }

    /// ISO 230-2 4.3.4 / GOST 27843 2.8: the principal positions 0°, 90°, 180° and 270°
    /// (in every turn of the travel) that are not targets, or `None` when all are.
    fn missing_cardinal_positions(&self) -> Option<String> {
        let mut missing = Vec::new();
        for base in [0.0, 90.0, 180.0, 270.0] {
            // Every turn of the travel that holds this angle.
            let mut k = ((self.first - base) / 360.0).ceil();
            while base + 360.0 * k <= self.last + EPS {
                let angle = base + 360.0 * k;
                if !self.data.targets.iter().any(|t| (t - angle).abs() <= 1e-6) {
                    missing.push(fmt_position(angle));
                }
                k += 1.0;
            }
        }
        (!missing.is_empty()).then(|| {
            format!(
                "the principal positions {}° are not targets; include 0°, 90°, 180° and 270° where inside the travel",
                missing.join("°, ")
            )
        })
    }
}
