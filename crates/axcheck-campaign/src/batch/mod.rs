//! Evaluating a whole campaign: every axis in parallel, each test of each axis read,
//! corrected, rule-checked, evaluated and judged. A broken file or axis fails that axis
//! with its message; the rest of the campaign completes. Then each re-measurement that
//! verifies a table is compared with its prediction ([`verification`]).

mod abbe;
mod cross;
mod other;
mod squareness;
mod tool_point;
pub mod verification;

use crate::results::{AsFound, AxisTest, CampaignResult, Evaluated, Outcome};

use crate::campaign::stages;
use crate::campaign::{AxisSpec, Campaign, MachineInfo};
use crate::diagnose::cross::{OutOfTest, out_of_test};
use crate::evaluate::Evaluation;
use crate::judge::{self, Decision, DecisionRule, Judgement, Spec, Verdict};
use crate::measurement::{AxisData, Recognised};
use crate::rules::{self, Violation};
use crate::uncertainty::Uncertainty;
use rayon::prelude::*;
use std::collections::BTreeMap;
use std::path::{Component, Path};
use std::sync::Arc;

/// Where a campaign's files are read: its folder and its rules.
pub type Files = crate::files::Root;

/// A test's result and, when it verifies a table, what it is compared with.
type Tested = (AxisTest, stages::compensate::Case);

/// Options of a batch run. The axes are evaluated in the caller's rayon pool (the
/// command's one pool, sized by `--jobs`).
#[derive(Debug, Clone, Copy, Default)]
pub struct BatchOptions {
    /// Run the model check and diagnosis of every axis test.
    pub diagnose: bool,
    /// The CI gate: drop each test's readings, per-target statistics and U budgets once
    /// it is evaluated, and compute U only for the tests judged by ISO 14253-1 (the gate
    /// needs only the verdicts; reports need the readings and the budgets). Keeps memory
    /// flat on large fleets.
    pub drop_data: bool,
    /// Compute each test's compensation table where its machine names a controller (with
    /// the diagnosis its warnings need); the CI gate writes no tables and skips them.
    pub compensate: bool,
    /// Note every file read from the campaign's folder with its SHA-256
    /// ([`CampaignResult::inputs`]): `run` records its inputs, the gate need not.
    pub record_inputs: bool,
}

/// Evaluates every axis of `campaign`; `progress` is called once per finished test.
pub fn run(
    campaign: &Campaign,
    options: BatchOptions,
    progress: &(dyn Fn(&AxisTest) + Sync),
) -> CampaignResult {
    // The folder every file read for the campaign must be opened in, resolved once.
    let files = Files::campaign(&campaign.dir, campaign.info.allow_outside_paths);
    let files = match options.record_inputs {
        true => files.recording(),
        false => files,
    };
    let specs = stages::judge::load_specs(campaign, &files);
    let work: Vec<(Arc<MachineInfo>, &crate::campaign::AxisEntry)> = campaign
        .machines
        .iter()
        .flat_map(|m| {
            let info = Arc::new(m.info.clone());
            m.axes.iter().map(move |a| (info.clone(), a))
        })
        .collect();
    let evaluate_all = || -> Vec<Tested> {
        work.par_iter()
            .flat_map_iter(|(machine, entry)| {
                let mut tests = run_axis(campaign, machine, entry, &specs, &files, options);
                for (t, _) in &mut tests {
                    progress(t);
                    // A test carried to its tool point keeps its readings until then.
                    let carried = (t.spec.as_ref()).is_some_and(|s| s.raw.tool_point.is_some());
                    if options.drop_data
                        && let Some(e) = t.evaluated_mut()
                    {
                        if !carried {
                            e.data = None;
                        }
                        // Nor each target's statistics: the gate prints parameters.
                        e.evaluation.targets = Vec::new();
                        // The gate needs U, not each parameter's budget (a third of the
                        // memory of a 10 000-axis check).
                        if let Some(u) = &mut e.uncertainty {
                            u.parameters = Vec::new();
                        }
                    }
                }
                tests
            })
            .collect()
    };
    let mut tested = evaluate_all();
    verification::verify_all(&mut tested);
    cross::verify_all(&mut tested, &files);
    tool_point::carry_all(&mut tested);
    abbe::fit_all(&mut tested);
    let squareness = squareness::evaluate_all(campaign, &tested);
    if options.drop_data {
        for (t, _) in &mut tested {
            t.drop_data();
        }
    }
    tested.extend(squareness.into_iter().map(|t| (t, None)));
    let tests = tested.into_iter().map(|(t, _)| t).collect();
    CampaignResult {
        info: campaign.info.clone(),
        file_name: campaign
            .file
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default(),
        standard: campaign.standard,
        tests,
        inputs: inputs(campaign, &files),
    }
}

/// The campaign file and every file read beneath its folder, sorted by path.
fn inputs(campaign: &Campaign, files: &Files) -> crate::inputs::Inputs {
    let mut read = files.recorded();
    let name = crate::files::relative_to(&campaign.file, &campaign.dir);
    if let Some(sha256) = &campaign.sha256 {
        read.retain(|f| f.path != name);
        read.push(crate::inputs::InputFile {
            path: name.clone(),
            sha256: sha256.clone(),
        });
        read.sort();
    }
    crate::inputs::Inputs {
        campaign: name,
        files: read,
        ..Default::default()
    }
}

/// Which test of which axis a result belongs to.
#[derive(Clone)]
struct Slot {
    machine: Arc<MachineInfo>,
    axis: String,
    spec: Option<Arc<AxisSpec>>,
    file: Option<String>,
    test: usize,
    tests: usize,
    /// The axis's planned test, read once for its tests.
    planned: Option<Arc<rules::Planned>>,
}

impl Slot {
    /// The test as it stands when `message` stops it before its evaluation.
    fn error(self, message: String) -> AxisTest {
        self.unread(message, None)
    }

    fn unread(self, error: String, recognised: Option<Recognised>) -> AxisTest {
        let recognised = recognised.map(Box::new);
        self.with(Outcome::Unread { error, recognised })
    }

    fn with(self, outcome: Outcome) -> AxisTest {
        AxisTest {
            machine: self.machine,
            axis: self.axis,
            spec: self.spec,
            file: self.file,
            test: self.test,
            tests: self.tests,
            outcome,
        }
    }
}

fn run_axis(
    campaign: &Campaign,
    machine: &Arc<MachineInfo>,
    entry: &crate::campaign::AxisEntry,
    specs: &BTreeMap<String, Result<Arc<Spec>, stages::judge::SpecError>>,
    files: &Files,
    options: BatchOptions,
) -> Vec<Tested> {
    let slot = Slot {
        machine: machine.clone(),
        axis: entry.name.clone(),
        spec: None,
        file: None,
        test: 1,
        tests: 1,
        planned: None,
    };
    let axis = match &entry.spec {
        Ok(axis) => Arc::clone(axis),
        Err(message) => return vec![(slot.error(message.to_string()), None)],
    };
    let slot = Slot {
        spec: Some(axis.clone()),
        planned: axis
            .raw
            .plan
            .as_ref()
            .map(|p| Arc::new(stages::rules::planned(p, axis.raw.kind, files))),
        ..slot
    };
    let paths = match axis.data.resolve(files) {
        Ok(paths) => paths,
        Err(message) => {
            let at = format!("{}:{}", campaign.file.display(), axis.at.line());
            let error = slot.error(format!("{at}: {}: data: {message}", entry.name));
            return vec![(error, None)];
        }
    };
    let spec = match axis.spec.as_ref().map(|name| specs.get(name).cloned()) {
        None => Ok(None),
        Some(Some(Ok(spec))) => Ok(Some(spec)),
        Some(Some(Err(e))) => {
            let (path, line) = axis.at.key("spec");
            Err(format!("{}:{line}: {path}: {e}", campaign.file.display()))
        }
        Some(None) => Err("spec not loaded".to_string()),
    };
    let tests = paths.len();
    // The tests of an axis in parallel too: one axis may have a glob of many files.
    let mut results: Vec<Tested> = paths
        .par_iter()
        .enumerate()
        .map(|(k, path)| {
            let slot = Slot {
                file: Some(relative_name(files.dir(), path)),
                test: k + 1,
                tests,
                ..slot.clone()
            };
            match &spec {
                Err(e) => (slot.error(e.clone()), None),
                Ok(spec) => {
                    let info = &campaign.info;
                    run_test(slot, &axis, spec.as_deref(), info, path, files, options)
                }
            }
        })
        .collect();
    predict_across_tests(&mut results);
    results
}

/// Tests of an axis that predict each one of them: all the others up to this many, else
/// the nearest in the axis's file order. Every test predicted by every other grew with the
/// square of the files: one axis of 1 500 files took 41 s, 5.3 GB and a 1.6 GB
/// `results.json`; bounded, the work and the output grow with the files.
pub(crate) const MAX_PREDICTORS: usize = 8;

/// The tests (0-based) that predict test `k` of `n`: every other one when there are at
/// most [`MAX_PREDICTORS`] others, else the [`MAX_PREDICTORS`] nearest in order (half
/// before and half after, shifted at the ends).
pub(crate) fn predictors(k: usize, n: usize) -> impl Iterator<Item = usize> {
    let (start, end) = if n <= MAX_PREDICTORS + 1 {
        (0, n)
    } else {
        let start = k
            .saturating_sub(MAX_PREDICTORS / 2)
            .min(n - MAX_PREDICTORS - 1);
        (start, start + MAX_PREDICTORS + 1)
    };
    (start..end).filter(move |&j| j != k)
}

/// Each diagnosed test of an axis predicted by the models of the others
/// ([`predictors`]; fit on one test, predict the other): [`crate::diagnose::cross`].
fn predict_across_tests(tested: &mut [Tested]) {
    let tests: Vec<&AxisTest> = tested.iter().map(|(t, _)| t).collect();
    let predictions: Vec<Vec<OutOfTest>> = tests
        .par_iter()
        .enumerate()
        .map(|(k, target)| {
            let Some(data) = target.evaluated().and_then(|e| e.data.as_ref()) else {
                return Vec::new();
            };
            predictors(k, tests.len())
                .map(|j| tests[j])
                .filter_map(|from| {
                    let diagnosis = from.evaluated()?.diagnosis.as_ref()?;
                    out_of_test(diagnosis, from.test, from.file.clone(), data)
                })
                .collect()
        })
        .collect();
    for ((test, _), p) in tested.iter_mut().zip(predictions) {
        if let Some(e) = test.evaluated_mut() {
            e.out_of_test = p;
        }
    }
}

/// `path` relative to the campaign folder with `/` separators (stable across systems).
fn relative_name(base: &Path, path: &Path) -> String {
    let rel = path.strip_prefix(base).unwrap_or(path);
    rel.components()
        .filter(|c| !matches!(c, Component::CurDir))
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect::<Vec<_>>()
        .join("/")
}

/// One test of an axis, stage by stage: read, the file's own conditions, NDE, the plan
/// rules, the evaluation, U, the verdict, the diagnosis and the compensation.
/// `campaign`: its decision rule (the axis's own and then its spec's come first) and its
/// date (clause 7.1). `files`: where the data and table files are opened.
fn run_test(
    slot: Slot,
    axis: &AxisSpec,
    spec: Option<&Spec>,
    campaign: &crate::campaign::CampaignInfo,
    path: &Path,
    files: &Files,
    options: BatchOptions,
) -> Tested {
    let (data, recognised) = match read_stage(&slot, axis, path, files) {
        Ok(read) => read,
        Err(test) => return (*test, None),
    };
    if other::is_other(axis) {
        let controller = (slot.machine.controller.as_deref()).filter(|_| options.compensate);
        let cross = cross::table(controller, axis, &data, files);
        return (
            other::run(slot, axis, campaign, (data, recognised), cross),
            None,
        );
    }
    // The tool's own results are of the readings as the file holds them (before NDE).
    let other_tool = (recognised.reported.as_ref()).map(|r| crate::crosscheck::compare(r, &data));
    // The file's own conditions (a Renishaw ENVIRONMENT) fill what the campaign leaves out.
    let completed = (recognised.info.as_ref())
        .and_then(|info| axis.completed_by(info))
        .map(|(spec, taken)| (Arc::new(spec), taken));
    let from_file = completed.as_ref().map_or(Vec::new(), |(_, t)| t.clone());
    let spec_arc = completed.map(|(s, _)| s);
    let axis: &AxisSpec = spec_arc.as_deref().unwrap_or(axis);
    let (data, nde) = stages::nde::apply(axis, data);
    let judging = Judging {
        slot: &slot,
        axis,
        spec,
        campaign,
        options,
    };
    let judged = judging.judge(&recognised, &data, nde.as_ref());
    let diagnosis_of = || crate::diagnose::diagnose(&data, &stages::diagnose::options(axis));
    let diagnosis = options.diagnose.then(diagnosis_of);
    let controller = (slot.machine.controller.as_deref()).filter(|_| options.compensate);
    let (compensation, verify_case) = stages::compensate::for_test(
        controller,
        axis,
        &data,
        files,
        diagnosis.as_ref(),
        diagnosis_of,
    );
    let as_found = (verify_case.as_ref())
        .and_then(|c| c.as_ref().ok())
        .map(|c| Box::new(judging.as_found(c)));
    let mut slot = slot;
    if let Some(spec) = spec_arc {
        slot.spec = Some(spec);
    }
    let JudgedReadings {
        verdict,
        error,
        unstated,
        evaluation,
        judgement,
        findings,
        uncertainty,
    } = judged;
    let test = slot.with(Outcome::Evaluated(Box::new(Evaluated {
        verdict,
        error,
        recognised,
        conditions_from_file: from_file,
        unstated,
        data: Some(data),
        evaluation,
        judgement,
        findings,
        nde,
        compensation: compensation.map(Box::new),
        verification: None,
        uncertainty,
        diagnosis: diagnosis.map(Box::new),
        out_of_test: Vec::new(),
        other_tool: other_tool.map(Box::new),
        tool_point: None,
        abbe: None,
        as_found,
    })));
    (test, verify_case)
}

/// What a test's readings are judged with: its axis, limits, campaign and run.
struct Judging<'a> {
    slot: &'a Slot,
    axis: &'a AxisSpec,
    spec: Option<&'a Spec>,
    campaign: &'a crate::campaign::CampaignInfo,
    options: BatchOptions,
}

/// Readings checked against the plan's rules, evaluated, given U and judged.
struct JudgedReadings {
    verdict: Verdict,
    error: Option<String>,
    unstated: Vec<&'static str>,
    evaluation: Evaluation,
    judgement: Option<Judgement>,
    findings: Vec<Violation>,
    uncertainty: Option<Uncertainty>,
}

impl Judging<'_> {
    /// `data` (read as `recognised`, NDE-corrected by `nde`) judged as this test is.
    fn judge(
        &self,
        recognised: &Recognised,
        data: &AxisData,
        nde: Option<&crate::nde::NdeCorrection>,
    ) -> JudgedReadings {
        let (axis, campaign) = (self.axis, self.campaign);
        let unstated =
            stages::rules::unstated(axis, &self.slot.machine, campaign, recognised, data);
        let mut context = stages::rules::context(axis);
        context.planned = self.slot.planned.clone();
        context.unstated = Some(unstated.clone());
        context.calibration =
            stages::rules::calibration(axis, &self.slot.machine, campaign, recognised);
        let findings = rules::check(&context, data);
        let evaluation = stages::evaluate::evaluate(axis, data);
        let rule = stages::judge::decision_rule(axis, self.spec, campaign.decision_rule);
        // The gate computes what it prints: U only where the decision rule judges with it.
        let uncertainty =
            (!self.options.drop_data || rule == DecisionRule::Iso14253_1).then(|| {
                let setup = stages::uncertainty::setup(axis, data, nde);
                crate::uncertainty::evaluate(&setup, &evaluation)
            });
        let judged = Judged {
            evaluation: &evaluation,
            findings: &findings,
            uncertainty: uncertainty.as_ref(),
            rule,
        };
        let (verdict, error, judgement) = judge_stage(axis, self.spec, data, &judged);
        JudgedReadings {
            verdict,
            error,
            unstated,
            evaluation,
            judgement,
            findings,
            uncertainty,
        }
    }

    /// The measurement before the table this test verifies, judged as the test is: the
    /// axis as found (ISO/IEC 17025:2017 7.8.4.1 d), the test being the axis as left.
    fn as_found(&self, case: &stages::compensate::VerifyCase) -> AsFound {
        let j = self.judge(
            &case.before_recognised,
            &case.before,
            case.before_nde.as_ref(),
        );
        AsFound {
            file: case.before_file.clone(),
            verdict: j.verdict,
            error: j.error,
            evaluation: j.evaluation,
            judgement: j.judgement,
            findings: j.findings,
            uncertainty: j.uncertainty,
        }
    }
}

/// The file read, and of the axis kind the campaign declares; else the test's error.
fn read_stage(
    slot: &Slot,
    axis: &AxisSpec,
    path: &Path,
    files: &Files,
) -> Result<(AxisData, Recognised), Box<AxisTest>> {
    let (data, recognised) = match stages::read::read(axis, path, files) {
        Ok(read) => (read.data, read.recognised),
        Err(e) => return Err(Box::new(slot.clone().error(e.to_string()))),
    };
    if data.kind != axis.raw.kind {
        let message = format!(
            "{}: the file holds a {} axis (target_{}) but the campaign declares axis `{}` {}",
            path.display(),
            data.kind,
            data.kind.position_unit(),
            slot.axis,
            axis.raw.kind
        );
        return Err(Box::new(slot.clone().unread(message, Some(recognised))));
    }
    Ok((data, recognised))
}

/// What a test is judged on.
struct Judged<'a> {
    evaluation: &'a Evaluation,
    findings: &'a [Violation],
    uncertainty: Option<&'a Uncertainty>,
    rule: DecisionRule,
}

/// The verdict, or the error of limits that cannot apply, and the judgement.
fn judge_stage(
    axis: &AxisSpec,
    spec: Option<&Spec>,
    data: &AxisData,
    judged: &Judged,
) -> (Verdict, Option<String>, Option<Judgement>) {
    match stages::judge::limits(axis, spec, data) {
        Err(e) => (Verdict::Error, Some(e.to_string()), None),
        Ok(limits) => {
            let decision = Decision {
                rule: judged.rule,
                expanded: judged.uncertainty.map(|u| &u.expanded),
            };
            let judgement = judge::judge(judged.evaluation, limits, &decision);
            let plan_broken = crate::rules::breaks_plan(judged.findings);
            (judgement.verdict(plan_broken), None, Some(judgement))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn few_tests_are_predicted_by_all_others_many_by_their_neighbours() {
        let all = |k, n| predictors(k, n).collect::<Vec<_>>();
        assert_eq!(all(1, 3), [0, 2]);
        assert_eq!(all(4, 9), [0, 1, 2, 3, 5, 6, 7, 8]);
        assert_eq!(all(0, 1500), [1, 2, 3, 4, 5, 6, 7, 8]);
        assert_eq!(all(700, 1500), [696, 697, 698, 699, 701, 702, 703, 704]);
        assert_eq!(
            all(1499, 1500),
            [1491, 1492, 1493, 1494, 1495, 1496, 1497, 1498]
        );
    }
}
