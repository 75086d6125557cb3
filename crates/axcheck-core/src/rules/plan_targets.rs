//! `plan-targets`: the test measured is the one planned (a campaign axis's `plan:`).
use super::{Plan, Rule, Severity};
use crate::units::fmt_fixed;

/// ISO 230-2:1997 4.2: the target positions are chosen before the test, and the report
/// gives them. A target skipped, moved or added, or another number of runs, is a test
/// other than the one planned (a typed position, a target the operator left out): each is
/// named, so that it is corrected or accepted knowingly.
pub(crate) const RULE: Rule = Rule {
    id: "plan-targets",
    clause: "ISO 230-2 4.2",
    severity: Severity::Warning,
    checks: "the measured targets and runs are those of the axis's plan (plan: FILE)",
    check,
};

/// Differences listed in full before `… and N more`.
const SHOWN: usize = 5;

fn check(plan: &Plan) -> Option<String> {
    let planned = plan.ctx.planned.as_ref()?;
    let (targets, runs) = match &planned.read {
        Err(e) => return Some(format!("the plan {} cannot be read: {e}", planned.file)),
        Ok(read) => read,
    };
    let mut out = differences(targets, &plan.data.targets, planned.tolerance, plan.unit());
    if *runs != plan.runs {
        out.push(format!("n = {} measured, the plan has {runs}", plan.runs));
    }
    if out.is_empty() {
        return None;
    }
    let more = out.len().saturating_sub(SHOWN);
    out.truncate(SHOWN);
    if more > 0 {
        out.push(format!("and {more} more"));
    }
    Some(format!(
        "against the plan {}: {}",
        planned.file,
        out.join("; ")
    ))
}

/// Each planned target missing or moved beyond `tolerance`, each measured one the plan
/// does not hold.
fn differences(planned: &[f64], measured: &[f64], tolerance: f64, unit: &str) -> Vec<String> {
    let at = |x: f64| format!("{} {unit}", fmt_fixed(x, 3));
    let mut used = vec![false; measured.len()];
    let nearest = |p: f64, used: &[bool]| {
        (0..measured.len())
            .filter(|&k| !used[k])
            .min_by(|&a, &b| (measured[a] - p).abs().total_cmp(&(measured[b] - p).abs()))
    };
    let mut out = Vec::new();
    let mut moved = Vec::new();
    for (i, &p) in planned.iter().enumerate() {
        match nearest(p, &used) {
            Some(k) if (measured[k] - p).abs() <= tolerance => used[k] = true,
            _ => moved.push(i),
        }
    }
    for i in moved {
        let p = planned[i];
        // A measured target nearer this planned one than half its spacing to a neighbour.
        let half = [i.checked_sub(1), Some(i + 1)]
            .into_iter()
            .flatten()
            .filter_map(|j| planned.get(j))
            .map(|q| (q - p).abs() / 2.0)
            .fold(f64::INFINITY, f64::min);
        match nearest(p, &used).filter(|&k| (measured[k] - p).abs() < half) {
            Some(k) => {
                used[k] = true;
                out.push(format!(
                    "T{} planned at {} was measured at {} ({} off, over the tolerance of {})",
                    i + 1,
                    at(p),
                    at(measured[k]),
                    at((measured[k] - p).abs()),
                    at(tolerance)
                ));
            }
            None => out.push(format!("T{} at {} is missing", i + 1, at(p))),
        }
    }
    for (k, &m) in measured.iter().enumerate() {
        if !used[k] {
            out.push(format!("a target at {} is not in the plan", at(m)));
        }
    }
    out
}
