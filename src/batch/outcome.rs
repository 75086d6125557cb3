//! What a campaign run gives: one [`AxisTest`] per test of each axis, its [`Outcome`]
//! either a file that could not be evaluated (and why) or everything the stages found.
//! An exporter matches the outcome once instead of asking each stage's result whether
//! it is there.

use crate::campaign::{AxisSpec, CampaignInfo, MachineInfo};
use crate::diagnose::cross::OutOfTest;
use crate::evaluate::{Evaluation, StandardId};
use crate::judge::{DecisionRule, Judgement, Verdict};
use crate::measurement::{AxisData, Recognised};
use crate::nde::NdeCorrection;
use crate::rules::{Finding, Severity};
use crate::uncertainty::Uncertainty;
use crate::units::AxisKind;
use std::collections::BTreeMap;
use std::sync::Arc;

/// The result of one test of one axis: one row of the summary.
#[derive(Debug, Clone)]
pub struct AxisTest {
    pub machine: Arc<MachineInfo>,
    pub axis: String,
    /// The axis as the campaign gives it (absent when it could not be read).
    pub spec: Option<Arc<AxisSpec>>,
    /// Measurement file, relative to the campaign's folder, `/`-separated.
    pub file: Option<String>,
    /// Index of this test among the axis's tests (1-based) and their number.
    pub test: usize,
    pub tests: usize,
    pub outcome: Outcome,
}

/// How far a test went.
#[derive(Debug, Clone)]
pub enum Outcome {
    /// Nothing was evaluated: the axis's entry, its spec or its file could not be read,
    /// or the file is not of this axis. The verdict is `error`.
    Unread {
        error: String,
        /// The layout the file was read as, when it was read.
        recognised: Option<Box<Recognised>>,
    },
    /// The file was read and evaluated (boxed: a fleet's results stay small and cheap to
    /// move, whatever a test holds).
    Evaluated(Box<Evaluated>),
}

/// Everything the stages found for a test whose file was read.
#[derive(Debug, Clone)]
pub struct Evaluated {
    // What only some tests have is boxed: a 10 000-axis check holds 10 000 of these.
    pub verdict: Verdict,
    /// Why the parameters could not be judged (limits that cannot apply to the axis);
    /// the verdict is then `error`.
    pub error: Option<String>,
    /// The layout the measurement file was read as and what was assumed or skipped.
    pub recognised: Recognised,
    /// The test conditions taken from the measurement file where the campaign gives
    /// none (e.g. "air temperature, pressure and humidity"; see `AxisSpec::completed_by`).
    pub conditions_from_file: Vec<&'static str>,
    /// The readings (dropped by the CI gate once the test is judged).
    pub data: Option<AxisData>,
    pub evaluation: Evaluation,
    /// The judgement against the limits (absent when they could not apply: `error`).
    pub judgement: Option<Judgement>,
    pub findings: Vec<Finding>,
    pub nde: Option<NdeCorrection>,
    /// The compensation table of the machine's controller and the parameters predicted.
    pub compensation: Option<Box<crate::compensate::Compensation>>,
    /// The re-measurement compared with the prediction of the table it verifies, or why
    /// it cannot be.
    pub verification: Option<Box<Result<crate::verify::Verification, String>>>,
    /// The measurement uncertainty of the parameters (GUM budget, U with k = 2).
    pub uncertainty: Option<Uncertainty>,
    /// Model check and diagnosis, when the run asked for it.
    pub diagnosis: Option<Box<crate::diagnose::Diagnosis>>,
    /// This test predicted by the models of each other diagnosed test of the axis.
    pub out_of_test: Vec<OutOfTest>,
    /// The results the tool that wrote the file printed in it, beside axcheck's.
    pub other_tool: Option<Box<crate::crosscheck::OtherTool>>,
}

impl AxisTest {
    pub fn kind(&self) -> Option<AxisKind> {
        self.spec.as_ref().map(|s| s.raw.kind)
    }

    pub fn standard(&self) -> Option<StandardId> {
        self.spec.as_ref().map(|s| s.standard)
    }

    /// The test's verdict (`error` when it was not evaluated).
    pub fn verdict(&self) -> Verdict {
        match &self.outcome {
            Outcome::Unread { .. } => Verdict::Error,
            Outcome::Evaluated(e) => e.verdict,
        }
    }

    /// Why the test has no verdict on its parameters, when it has none.
    pub fn error(&self) -> Option<&str> {
        match &self.outcome {
            Outcome::Unread { error, .. } => Some(error),
            Outcome::Evaluated(e) => e.error.as_deref(),
        }
    }

    /// What the stages found, when the file was read and evaluated.
    pub fn evaluated(&self) -> Option<&Evaluated> {
        match &self.outcome {
            Outcome::Unread { .. } => None,
            Outcome::Evaluated(e) => Some(e),
        }
    }

    pub fn evaluated_mut(&mut self) -> Option<&mut Evaluated> {
        match &mut self.outcome {
            Outcome::Unread { .. } => None,
            Outcome::Evaluated(e) => Some(e),
        }
    }

    /// The layout the file was read as, when it was read.
    pub fn recognised(&self) -> Option<&Recognised> {
        match &self.outcome {
            Outcome::Unread { recognised, .. } => recognised.as_deref(),
            Outcome::Evaluated(e) => Some(&e.recognised),
        }
    }

    /// The checks whose decision is inconclusive (the measurement's U straddles the
    /// limit, ISO 14253-1): none when the test was not judged.
    pub fn inconclusive(&self) -> impl Iterator<Item = &crate::judge::Check> {
        self.evaluated()
            .and_then(|e| e.judgement.as_ref())
            .into_iter()
            .flat_map(|j| j.inconclusive())
    }

    /// The test-plan findings (none when the file was not read).
    pub fn findings(&self) -> &[Finding] {
        self.evaluated().map_or(&[], |e| &e.findings)
    }

    /// `VMC-07 X` or `VMC-07 X (2/3)`.
    pub fn label(&self) -> String {
        if self.tests > 1 {
            format!(
                "{} {} ({}/{})",
                self.machine.id, self.axis, self.test, self.tests
            )
        } else {
            format!("{} {}", self.machine.id, self.axis)
        }
    }

    /// The test-plan rules of severity error the test breaks (they make it noncompliant).
    pub fn broken_rules(&self) -> impl Iterator<Item = &Finding> {
        (self.findings().iter()).filter(|f| f.severity == Severity::Error)
    }

    /// [`Self::broken_rules`] as `id (clause): message; …`.
    pub fn broken_rules_text(&self) -> String {
        self.broken_rules()
            .map(|f| format!("{} ({}): {}", f.id, f.clause, f.message))
            .collect::<Vec<_>>()
            .join("; ")
    }

    /// True when no tolerance applied to this test.
    pub fn no_tolerance(&self) -> bool {
        (self.evaluated().and_then(|e| e.judgement.as_ref())).is_none_or(|j| j.limits.is_empty())
    }
}

/// A whole campaign's results.
#[derive(Debug, Clone)]
pub struct CampaignResult {
    pub info: CampaignInfo,
    /// The campaign file's name (not its full path: outputs stay the same across checkouts).
    pub file_name: String,
    pub standard: StandardId,
    pub tests: Vec<AxisTest>,
}

impl CampaignResult {
    /// Number of tests per verdict.
    pub fn counts(&self) -> BTreeMap<Verdict, usize> {
        let mut counts = BTreeMap::from([
            (Verdict::Pass, 0),
            (Verdict::Fail, 0),
            (Verdict::Noncompliant, 0),
            (Verdict::Error, 0),
            (Verdict::Inconclusive, 0),
        ]);
        for t in &self.tests {
            *counts.entry(t.verdict()).or_default() += 1;
        }
        counts
    }

    /// Whether a test was judged by ISO 14253-1 (then `inconclusive` is a possible verdict).
    pub fn uses_uncertainty_rule(&self) -> bool {
        self.tests.iter().any(|t| {
            (t.evaluated().and_then(|e| e.judgement.as_ref()))
                .is_some_and(|j| j.rule == DecisionRule::Iso14253_1)
        })
    }

    /// `16 pass, 2 fail, 1 noncompliant, 0 error` (and `, 1 inconclusive` when a test was
    /// judged by ISO 14253-1).
    pub fn counts_text(&self) -> String {
        let c = self.counts();
        let mut text = format!(
            "{} pass, {} fail, {} noncompliant, {} error",
            c[&Verdict::Pass],
            c[&Verdict::Fail],
            c[&Verdict::Noncompliant],
            c[&Verdict::Error]
        );
        if self.uses_uncertainty_rule() {
            text.push_str(&format!(", {} inconclusive", c[&Verdict::Inconclusive]));
        }
        text
    }

    /// True when every test passes.
    pub fn all_pass(&self) -> bool {
        self.tests.iter().all(|t| t.verdict() == Verdict::Pass)
    }
}
