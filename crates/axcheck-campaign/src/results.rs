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
use crate::rules::{Severity, Violation};
use crate::safe_text::one_line;
use crate::uncertainty::Uncertainty;
use crate::units::AxisKind;
use std::collections::BTreeMap;
use std::sync::Arc;

pub use crate::campaign::stages::compensate::StatedTableError;

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
    /// A straightness or angular test (ISO 230-1) read, evaluated and judged.
    Other(Box<OtherTested>),
}

/// A straightness or angular test of an axis, evaluated and judged.
#[derive(Debug, Clone)]
pub struct OtherTested {
    pub verdict: Verdict,
    /// What its file was read as (none for a squareness of two tests).
    pub recognised: Option<Recognised>,
    pub test: crate::geometry::TestKind,
    /// ISO 230-1's symbol: `EYX`, `EBX` …
    pub symbol: String,
    /// The readings (dropped by the CI gate once the test is judged).
    pub data: Option<AxisData>,
    pub result: crate::one_file::OtherResult,
    /// U (k = 2) of the result's main value (the straightness, the angular deviation).
    pub uncertainty: crate::geometry::uncertainty::Uncertain,
    pub judgement: Judgement,
    /// An angular test's mean angles, kept when its readings are dropped: a positioning
    /// test of the axis is carried to its tool point through them.
    pub trace: Option<crate::geometry::angular::Trace>,
    /// A squareness's two straightness tests: (symbol, file) each.
    pub sources: Vec<(String, String)>,
    /// Its tolerances as written.
    pub tolerance: Vec<String>,
    /// A straightness test's cross table and the verification of a loaded one.
    pub cross: Option<Box<CrossOutcome>>,
    /// The rules that hold for every measured test (the instrument's calibration).
    pub findings: Vec<Violation>,
}

/// A straightness test's cross table, where its machine names a controller (or why none
/// was written), and the comparison with its prediction where the test re-measures the
/// axis after a cross table was loaded (`compensation.verifies`), or why none was made.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CrossOutcome {
    pub table: Option<Result<crate::compensate::cross::build::CrossCompensation, String>>,
    pub verification: Option<Result<crate::compensate::cross::verify::CrossVerification, String>>,
}

impl OtherTested {
    /// The deviation unit of its values: `um` or `arcsec`.
    pub fn unit(&self) -> &'static str {
        match self.test {
            crate::geometry::TestKind::Angular | crate::geometry::TestKind::Squareness => "arcsec",
            _ => "um",
        }
    }

    /// A value's name as reports print it.
    pub fn name(key: crate::param_key::ParamKey) -> &'static str {
        use crate::param_key::ParamKey as K;
        match key {
            K::Straightness => "straightness",
            K::StraightnessLocal => "local straightness",
            K::Angular => "angular deviation",
            K::Squareness => "squareness",
            _ => "",
        }
    }

    /// Each value the test has (of `ParamKey::GEOMETRY`, in its order) with its check,
    /// when a tolerance limited it.
    pub fn values(
        &self,
    ) -> impl Iterator<
        Item = (
            crate::param_key::ParamKey,
            f64,
            Option<&crate::judge::Check>,
        ),
    > {
        (crate::param_key::ParamKey::GEOMETRY.into_iter()).filter_map(move |key| {
            let value = self.result.value(key)?;
            let check = self.judgement.checks.iter().find(|c| c.key == key);
            Some((key, value, check))
        })
    }

    /// U of each judged value, by key.
    pub fn expanded(&self) -> BTreeMap<String, f64> {
        (self.judgement.checks.iter())
            .filter_map(|c| Some((c.key.to_string(), c.expanded_uncertainty?)))
            .collect()
    }
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
    /// The test conditions of ISO 230-2 clause 7.1 stated neither by the campaign nor by
    /// the file, in the clause's order (`crate::campaign::clause7_1`).
    pub unstated: Vec<&'static str>,
    /// The readings (dropped by the CI gate once the test is judged).
    pub data: Option<AxisData>,
    pub evaluation: Evaluation,
    /// The judgement against the limits (absent when they could not apply: `error`).
    pub judgement: Option<Judgement>,
    pub findings: Vec<Violation>,
    pub nde: Option<NdeCorrection>,
    /// The compensation table of the machine's controller and the parameters predicted.
    pub compensation: Option<Box<crate::compensate::Compensation>>,
    /// The re-measurement compared with the prediction of the table it verifies, or why
    /// it cannot be.
    pub verification: Option<Box<Result<crate::verify::Verification, StatedTableError>>>,
    /// The measurement uncertainty of the parameters (GUM budget, U with k = 2).
    pub uncertainty: Option<Uncertainty>,
    /// Model check and diagnosis, when the run asked for it.
    pub diagnosis: Option<Box<crate::diagnose::Diagnosis>>,
    /// This test predicted by the models of each other diagnosed test of the axis.
    pub out_of_test: Vec<OutOfTest>,
    /// The results the tool that wrote the file printed in it, beside axcheck's.
    pub other_tool: Option<Box<crate::crosscheck::OtherTool>>,
    /// The test carried to the tool point (`tool_point:`), or why it could not be.
    pub tool_point: Option<Box<Result<ToolPoint, String>>>,
    /// The fit of the means on the axis's angular tests in the campaign (an Abbe error
    /// read off the beam), where it has any.
    pub abbe: Option<Box<crate::diagnose::abbe::AbbeFit>>,
    /// Where the test verifies a table loaded since a measurement before: that measurement
    /// judged as this test is (the axis as found; this test is the axis as left).
    pub as_found: Option<Box<AsFound>>,
}

/// The measurement before an adjustment of the axis (a table loaded), judged against the
/// same limits, rule and decision rule as the test after it (ISO/IEC 17025:2017 7.8.4.1 d:
/// results before and after an adjustment).
#[derive(Debug, Clone)]
pub struct AsFound {
    /// The file, as the campaign names it (`compensation.verifies.before`).
    pub file: String,
    pub verdict: Verdict,
    /// Why its parameters could not be judged.
    pub error: Option<String>,
    pub evaluation: Evaluation,
    pub judgement: Option<Judgement>,
    pub findings: Vec<Violation>,
    pub uncertainty: Option<Uncertainty>,
}

/// A positioning test carried from the beam to the tool point through its axis's angular
/// tests (Abbe, `geometry::abbe`), evaluated and judged as the measured one.
#[derive(Debug, Clone)]
pub struct ToolPoint {
    /// The offsets across the axis, (letter, mm), in `geometry::abbe`'s order.
    pub offsets_mm: [(char, f64); 2],
    /// The angular tests it is carried through (`EBX`, `ECX`).
    pub rotations: Vec<String>,
    pub evaluation: Evaluation,
    /// Judged against the measured test's limits, with its U.
    pub judgement: Option<Judgement>,
    pub verdict: Verdict,
    pub notes: Vec<String>,
}

impl AxisTest {
    pub fn kind(&self) -> Option<AxisKind> {
        self.spec.as_ref().map(|s| s.raw.kind)
    }

    pub fn standard(&self) -> Option<StandardId> {
        self.spec.as_ref().map(|s| s.standard)
    }

    /// The standard a positioning test is evaluated by; `None` for the other tests (ISO
    /// 230-1's, whatever the campaign's standard).
    pub fn positioning_standard(&self) -> Option<StandardId> {
        self.standard()
            .filter(|_| self.test_kind() == crate::geometry::TestKind::Positioning)
    }

    /// The test's verdict (`error` when it was not evaluated).
    pub fn verdict(&self) -> Verdict {
        match &self.outcome {
            Outcome::Unread { .. } => Verdict::Error,
            Outcome::Evaluated(e) => e.verdict,
            Outcome::Other(o) => o.verdict,
        }
    }

    /// Why the test has no verdict on its parameters, when it has none.
    pub fn error(&self) -> Option<&str> {
        match &self.outcome {
            Outcome::Unread { error, .. } => Some(error),
            Outcome::Evaluated(e) => e.error.as_deref(),
            Outcome::Other(_) => None,
        }
    }

    /// What the stages found, when the file was read and evaluated.
    /// A positioning test's: `None` for the other tests ([`Self::other`]).
    pub fn evaluated(&self) -> Option<&Evaluated> {
        match &self.outcome {
            Outcome::Evaluated(e) => Some(e),
            Outcome::Unread { .. } | Outcome::Other(_) => None,
        }
    }

    /// Drops the test's readings (the CI gate, once every pass that needs them is done).
    pub(crate) fn drop_data(&mut self) {
        match &mut self.outcome {
            Outcome::Evaluated(e) => e.data = None,
            Outcome::Other(o) => o.data = None,
            Outcome::Unread { .. } => {}
        }
    }

    pub(crate) fn other_mut(&mut self) -> Option<&mut OtherTested> {
        match &mut self.outcome {
            Outcome::Other(o) => Some(o),
            _ => None,
        }
    }

    pub(crate) fn evaluated_mut(&mut self) -> Option<&mut Evaluated> {
        match &mut self.outcome {
            Outcome::Evaluated(e) => Some(e),
            Outcome::Unread { .. } | Outcome::Other(_) => None,
        }
    }

    /// The axis's name, followed for another laser test by ISO 230-1's symbol: `X`,
    /// `X EYX`.
    pub fn axis_label(&self) -> String {
        if self.test_kind() == crate::geometry::TestKind::Squareness {
            return format!("{} squareness", self.axis);
        }
        match self
            .spec
            .as_ref()
            .and_then(|s| crate::campaign::geometry::symbol(&s.raw))
        {
            Some(symbol) => format!("{} {symbol}", self.axis),
            None => self.axis.clone(),
        }
    }

    /// The unit its deviations are printed in: `µm` or `″` (an angular test's arcsec on a
    /// linear axis); empty when the axis is unknown.
    pub fn deviation_symbol(&self) -> &'static str {
        match self.test_kind() {
            crate::geometry::TestKind::Angular | crate::geometry::TestKind::Squareness => {
                crate::units::AxisKind::Rotary.deviation_symbol()
            }
            _ => self.kind().map_or("", |k| k.deviation_symbol()),
        }
    }

    /// The unit of its deviations as files write it: `um` or `arcsec`.
    pub fn deviation_unit(&self) -> Option<&'static str> {
        match self.test_kind() {
            crate::geometry::TestKind::Angular | crate::geometry::TestKind::Squareness => {
                Some("arcsec")
            }
            _ => self.kind().map(|k| k.deviation_unit()),
        }
    }

    /// A straightness or angular test evaluated and judged.
    pub fn other(&self) -> Option<&OtherTested> {
        match &self.outcome {
            Outcome::Other(o) => Some(o),
            _ => None,
        }
    }

    /// Which laser test this is: positioning unless the axis entry says otherwise (or
    /// it is a machine's squareness pair).
    pub fn test_kind(&self) -> crate::geometry::TestKind {
        match (self.other(), &self.spec) {
            (Some(o), _) => o.test,
            (None, Some(s)) => s.raw.test,
            (None, None) => Default::default(),
        }
    }

    /// The layout the file was read as, when it was read.
    pub fn recognised(&self) -> Option<&Recognised> {
        match &self.outcome {
            Outcome::Unread { recognised, .. } => recognised.as_deref(),
            Outcome::Evaluated(e) => Some(&e.recognised),
            Outcome::Other(o) => o.recognised.as_ref(),
        }
    }

    /// The judgement against the limits, when the test was judged.
    pub fn judgement(&self) -> Option<&crate::judge::Judgement> {
        match &self.outcome {
            Outcome::Evaluated(e) => e.judgement.as_ref(),
            Outcome::Other(o) => Some(&o.judgement),
            Outcome::Unread { .. } => None,
        }
    }

    /// The checks whose U is over half the limit or over the value (none when the test
    /// was not judged or its U not computed: `check` computes U only for ISO 14253-1).
    pub fn large_uncertainty(&self) -> Vec<crate::judge::LargeUncertainty> {
        if let Some(o) = self.other() {
            return o.judgement.large_uncertainty(&o.expanded());
        }
        let e = self.evaluated();
        match (self.judgement(), e.and_then(|e| e.uncertainty.as_ref())) {
            (Some(j), Some(u)) => j.large_uncertainty(&u.expanded),
            _ => Vec::new(),
        }
    }

    /// The checks whose decision is inconclusive (the measurement's U straddles the
    /// limit, ISO 14253-1): none when the test was not judged.
    pub fn inconclusive(&self) -> impl Iterator<Item = &crate::judge::Check> {
        self.judgement().into_iter().flat_map(|j| j.inconclusive())
    }

    /// The test-plan findings (none when the file was not read).
    pub fn findings(&self) -> &[Violation] {
        match &self.outcome {
            Outcome::Evaluated(e) => &e.findings,
            Outcome::Other(o) => &o.findings,
            Outcome::Unread { .. } => &[],
        }
    }

    /// `VMC-07 X`, `VMC-07 X (2/3)` or, for another laser test, `VMC-07 X EYX`, on one line whatever the names hold: hidden
    /// characters, line breaks and tabs as escapes ([`crate::safe_text::one_line`]).
    pub fn label(&self) -> String {
        let axis_label = self.axis_label();
        let (id, axis) = (one_line(&self.machine.id), one_line(&axis_label));
        if self.tests > 1 {
            format!("{id} {axis} ({}/{})", self.test, self.tests)
        } else {
            format!("{id} {axis}")
        }
    }

    /// The test-plan rules of severity error the test breaks (they make it noncompliant).
    pub fn broken_rules(&self) -> impl Iterator<Item = &Violation> {
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
        self.judgement().is_none_or(|j| j.limits.is_empty())
    }
}

/// Tests named one by one under a caveat before `… and N more`.
pub(crate) const CAVEAT_TESTS: usize = 20;

/// A whole campaign's results.
#[derive(Debug, Clone)]
pub struct CampaignResult {
    pub info: CampaignInfo,
    /// The campaign file's name (not its full path: outputs stay the same across checkouts).
    pub file_name: String,
    pub standard: StandardId,
    pub tests: Vec<AxisTest>,
    /// What the run read and how it was run (`results.json` `inputs`): the files read
    /// from the campaign's folder when the batch recorded them, the rest set by the run.
    pub inputs: crate::inputs::Inputs,
}

impl CampaignResult {
    /// The certificate `t`'s report is part of: its machine's, else the campaign's.
    pub fn certificate_of<'a>(
        &'a self,
        t: &'a AxisTest,
    ) -> Option<&'a crate::campaign::certificate::CertificateRaw> {
        (t.machine.certificate.as_ref()).or(self.info.certificate.as_ref())
    }

    /// The number of `t`'s report when the campaign is a certificate
    /// (`campaign.certificate`; see [`crate::campaign::certificate`]).
    pub fn report_number(&self, t: &AxisTest) -> Option<String> {
        use crate::geometry::TestKind;
        let certificate = self.certificate_of(t)?;
        // A positioning test is `P`; another its ISO 230-1 symbol (a squareness `SQ`), or
        // its kind where the symbol is not known (a file that could not be read).
        let symbol = match t.test_kind() {
            TestKind::Positioning => None,
            TestKind::Squareness => Some("SQ".to_string()),
            kind => (t.other().map(|o| o.symbol.clone()))
                .or_else(|| crate::campaign::geometry::symbol(&t.spec.as_ref()?.raw))
                .filter(|s| !s.is_empty())
                .or_else(|| Some(kind.key().to_string())),
        };
        let id = crate::campaign::certificate::ReportId {
            machine: &t.machine.id,
            axis: &t.axis,
            symbol: symbol.as_deref(),
            test: t.test,
            tests: t.tests,
        };
        Some(certificate.report_number(&id))
    }

    /// Number of tests per verdict.
    pub fn counts(&self) -> BTreeMap<Verdict, usize> {
        let mut counts = BTreeMap::from([
            (Verdict::Pass, 0),
            (Verdict::Fail, 0),
            (Verdict::Noncompliant, 0),
            (Verdict::Error, 0),
            (Verdict::Inconclusive, 0),
            (Verdict::NotJudged, 0),
        ]);
        for t in &self.tests {
            *counts.entry(t.verdict()).or_default() += 1;
        }
        counts
    }

    /// Whether a test was judged by ISO 14253-1 (then `inconclusive` is a possible verdict).
    pub fn uses_uncertainty_rule(&self) -> bool {
        self.tests.iter().any(|t| {
            t.judgement()
                .is_some_and(|j| j.rule == DecisionRule::Iso14253_1)
        })
    }

    /// `16 pass, 2 fail, 1 noncompliant, 0 error` (and `, 1 inconclusive` when a test was
    /// judged by ISO 14253-1, `, 1 not judged` when a test had no limit).
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
        let unjudged = c[&Verdict::NotJudged];
        if unjudged > 0 {
            let allowed = match self.info.unjudged_allowed() {
                true => " (allowed by the campaign)",
                false => "",
            };
            text.push_str(&format!(", {unjudged} not judged{allowed}"));
        }
        text
    }

    /// What the verdicts rest on that a reader must know, a line each, for the console,
    /// `summary.md` and the summary PDF: tests judged by example limits (`example:
    /// true`), clause 7.1 conditions not stated, uncertainties too large for their verdict.
    pub fn caveats(&self) -> Vec<String> {
        self.caveats_labelled(AxisTest::label)
    }

    /// [`Self::caveats`] with each test named by `label` (a report shortens long names).
    pub fn caveats_labelled(&self, label: impl Fn(&AxisTest) -> String) -> Vec<String> {
        let mut lines = Vec::new();
        let example: Vec<&AxisTest> = (self.tests.iter())
            .filter(|t| t.judgement().is_some_and(|j| j.limits.example))
            .collect();
        if !example.is_empty() {
            let mut specs: Vec<&str> = (example.iter())
                .filter_map(|t| t.judgement()?.limits.spec.as_deref())
                .map(|s| s.split(" (").next().unwrap_or(s))
                .collect();
            specs.sort_unstable();
            specs.dedup();
            lines.push(format!(
                "Example limits, not from a standard: {} of {} tests judged by spec {}",
                example.len(),
                self.tests.len(),
                specs.join(", ")
            ));
        }
        lines.extend(self.large_uncertainty_lines(&label));
        lines.extend(self.tool_point_lines(&label));
        lines.extend(self.abbe_lines(&label));
        let unstated: Vec<usize> = (self.tests.iter())
            .filter_map(|t| t.evaluated().map(|e| e.unstated.len()))
            .filter(|n| *n > 0)
            .collect();
        if !unstated.is_empty() {
            lines.push(format!(
                "Test conditions not stated (ISO 230-2 7.1): {} items over {} of {} tests (each report lists them)",
                unstated.iter().sum::<usize>(),
                unstated.len(),
                self.tests.len()
            ));
        }
        lines
    }

    /// The positioning tests whose verdict at the tool point is not the measured one (a
    /// pitch or yaw large enough to change it, Abbe), or that could not be carried there.
    fn tool_point_lines(&self, label: &impl Fn(&AxisTest) -> String) -> Vec<String> {
        let mut lines = Vec::new();
        for t in &self.tests {
            let Some(carried) = t.evaluated().and_then(|e| e.tool_point.as_deref()) else {
                continue;
            };
            match carried {
                Ok(p) if p.verdict != t.verdict() => lines.push(format!(
                    "Verdict changes at the tool point (Abbe, through {}): {} is {} at the beam, {} at the tool point",
                    p.rotations.join(" and "),
                    label(t),
                    t.verdict().words(),
                    p.verdict.words()
                )),
                Ok(_) => {}
                Err(why) => lines.push(format!("Not carried to the tool point: {}: {why}", label(t))),
            }
        }
        lines
    }

    /// The positioning tests whose means follow the axis's pitch or yaw (an Abbe error).
    fn abbe_lines(&self, label: &impl Fn(&AxisTest) -> String) -> Vec<String> {
        let found = (self.tests.iter())
            .filter_map(|t| Some((t, t.evaluated()?.abbe.as_deref()?)))
            .filter(|(_, a)| a.found);
        found
            .map(|(t, a)| {
                let levers: Vec<String> = (a.levers.iter())
                    .filter(|l| matches!((l.offset_mm, l.u_mm), (Some(o), Some(u)) if o.abs() >= 3.0 * u))
                    .filter_map(|l| {
                        Some(format!(
                            "{} as a lever of {} ± {} mm along {}",
                            l.symbol,
                            crate::units::fmt_fixed(l.offset_mm?, 0),
                            crate::units::fmt_fixed(l.u_mm?, 0),
                            l.along
                        ))
                    })
                    .collect();
                format!(
                    "Abbe error: {}'s positioning error follows {} (the beam off the line the axis positions on): its E depends on where the beam is; `tool_point:` judges it at the tool",
                    label(t),
                    levers.join(" and ")
                )
            })
            .collect()
    }

    /// The tests whose U is large against a limit or a value: a line saying how many,
    /// then one per test (at most [`CAVEAT_TESTS`]).
    fn large_uncertainty_lines(&self, label: &impl Fn(&AxisTest) -> String) -> Vec<String> {
        let flagged: Vec<(&AxisTest, Vec<crate::judge::LargeUncertainty>)> = (self.tests.iter())
            .map(|t| (t, t.large_uncertainty()))
            .filter(|(_, l)| !l.is_empty())
            .collect();
        if flagged.is_empty() {
            return Vec::new();
        }
        let mut lines = vec![format!(
            "Uncertainty large for the verdict (U over half its limit or over the value): {} of {} tests",
            flagged.len(),
            self.tests.len()
        )];
        for (t, large) in flagged.iter().take(CAVEAT_TESTS) {
            let unit = t.deviation_symbol();
            // The first in the standard's order (A before E, M …), and how many more.
            let Some(worst) = large.first() else {
                continue;
            };
            let more = match large.len() - 1 {
                0 => String::new(),
                1 => " (and 1 more parameter)".to_string(),
                n => format!(" (and {n} more parameters)"),
            };
            let (label, verdict) = (label(t), t.verdict().words());
            lines.push(format!(
                "  {label} ({verdict}): {}{more}",
                worst.text(2, unit)
            ));
        }
        if flagged.len() > CAVEAT_TESTS {
            lines.push(format!("  … and {} more", flagged.len() - CAVEAT_TESTS));
        }
        lines
    }

    /// True when the CI gate passes: every test passes, or is not judged and the campaign
    /// allows that (`unjudged: allowed`).
    pub fn passes_gate(&self) -> bool {
        let allowed = self.info.unjudged_allowed();
        (self.tests.iter()).all(|t| match t.verdict() {
            Verdict::Pass => true,
            Verdict::NotJudged => allowed,
            _ => false,
        })
    }
}
