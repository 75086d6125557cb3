//! The file's test plan as a simulator plan, and the fitted models as simulations.
//!
//! The plan: the file's targets and runs; the cycle is the one whose order of approaches
//! the readings follow (in time order when time stamps exist); feed, dwell and overrun are
//! fitted to the time stamps (time of each reading = distance·s + overrun moves·s·o +
//! readings·dwell + t₀, least squares), or the simulator's defaults without them.

use super::maths::linalg::least_squares;
use crate::axis_model::{Cycle, TestPlan};
use crate::measurement::AxisData;

/// A guessed plan with what was guessed.
pub(crate) struct PlanGuess {
    pub plan: TestPlan,
    pub notes: Vec<String>,
    /// Whether the targets survive the simulator's rounding to 0.001 as distinct values.
    pub(crate) simulable: bool,
}

fn plan_with(data: &AxisData, cycle: Cycle, feed: f64, dwell: f64, overrun: f64) -> TestPlan {
    TestPlan {
        targets: None,
        target_list: Some(data.targets.clone()),
        runs: data.runs(),
        cycle,
        feed_per_min: feed,
        dwell_s: dwell,
        overrun,
    }
}

/// Guesses the plan of `data`.
pub(crate) fn guess_plan(data: &AxisData) -> PlanGuess {
    let mut notes = Vec::new();
    let unit = data.kind.position_unit();
    // Readings in time order when every one has a time stamp, else in file order.
    let mut order: Vec<usize> = (0..data.readings.len()).collect();
    if data.has_times() {
        order.sort_by(|&a, &b| {
            data.readings[a]
                .time_s
                .unwrap_or(0.0)
                .total_cmp(&data.readings[b].time_s.unwrap_or(0.0))
                .then(a.cmp(&b))
        });
    }
    let keys: Vec<(usize, usize, usize)> = order
        .iter()
        .map(|&k| {
            let r = &data.readings[k];
            (r.target, r.direction.index(), r.run)
        })
        .collect();
    let mut cycle = None;
    for c in [Cycle::Standard, Cycle::Pilgrim, Cycle::Step] {
        let visits = plan_with(data, c, 1000.0, 4.0, 5.0).schedule(&data.targets);
        if visits.len() == keys.len()
            && visits
                .iter()
                .zip(&keys)
                .all(|(v, k)| (v.target, v.direction.index(), v.run) == *k)
        {
            cycle = Some(c);
            break;
        }
    }
    let cycle = cycle.unwrap_or_else(|| {
        notes.push(
            "the order of the readings follows none of the standard, step and pilgrim cycles: the plan of the models uses the standard cycle"
                .to_string(),
        );
        Cycle::Standard
    });
    let (mut feed, mut dwell, mut overrun) = (1000.0, 4.0, 5.0);
    if data.has_times() {
        match fit_timing(data, cycle) {
            Some((f, d, o, rms)) => {
                feed = f;
                dwell = d;
                overrun = o;
                let span = data
                    .readings
                    .iter()
                    .filter_map(|r| r.time_s)
                    .fold(0.0f64, f64::max);
                if rms > 0.05 * span.max(1e-9) {
                    notes.push(format!(
                        "the time stamps do not follow one feed and dwell (RMS misfit {rms:.1} s): the models' plan approximates them"
                    ));
                }
            }
            None => notes.push(
                "feed and dwell could not be fitted to the time stamps: the models' plan uses the simulator's defaults".to_string(),
            ),
        }
    } else {
        notes.push(format!(
            "no time stamps: the models' plan uses the simulator's default timing (feed 1000 {unit}/min, dwell 4 s, overrun 5 {unit})"
        ));
    }
    let rounded: Vec<f64> = data
        .targets
        .iter()
        .map(|x| (x * 1000.0).round() / 1000.0)
        .collect();
    let simulable =
        rounded.windows(2).all(|w| w[1] > w[0]) && rounded.iter().all(|x| x.is_finite());
    if !simulable {
        notes.push(
            "targets closer than 0.001 cannot be simulated (the simulator rounds targets to 0.001): no Monte-Carlo checks".to_string(),
        );
    }
    PlanGuess {
        // A feed that rounds to nothing would not make a valid plan.
        plan: if r4(feed) > 0.0 {
            plan_with(data, cycle, r4(feed), r4(dwell), r4(overrun))
        } else {
            plan_with(data, cycle, 1000.0, r4(dwell), r4(overrun))
        },
        notes,
        simulable,
    }
}

/// Fits (feed, dwell, overrun, RMS misfit in s) to the time stamps for `cycle`.
fn fit_timing(data: &AxisData, cycle: Cycle) -> Option<(f64, f64, f64, f64)> {
    let targets = &data.targets;
    // Unit feed (1 position unit per second), no dwell: times are distances.
    let d0 = plan_with(data, cycle, 60.0, 0.0, 0.0).schedule(targets);
    let d1 = plan_with(data, cycle, 60.0, 0.0, 1.0).schedule(targets);
    let key = |t: usize, d: usize, j: usize| (t * 2 + d) * data.runs() + j;
    let mut time = vec![f64::NAN; targets.len() * 2 * data.runs()];
    for r in &data.readings {
        time[key(r.target, r.direction.index(), r.run)] = r.time_s?;
    }
    let y: Vec<f64> = d0
        .iter()
        .map(|v| time[key(v.target, v.direction.index(), v.run)])
        .collect();
    if y.iter().any(|v| !v.is_finite()) || y.len() < 4 {
        return None;
    }
    let dist: Vec<f64> = d0.iter().map(|v| v.time_s).collect();
    let over: Vec<f64> = d0
        .iter()
        .zip(&d1)
        .map(|(a, b)| b.time_s - a.time_s)
        .collect();
    let reads: Vec<f64> = (1..=d0.len()).map(|k| k as f64).collect();
    let one = vec![1.0; d0.len()];
    let solve = |cols: Vec<Vec<f64>>| least_squares(&cols, &y);
    let full = solve(vec![dist.clone(), over.clone(), reads.clone(), one.clone()]);
    let (s, so, dwell) = (full.coef[0], full.coef[1], full.coef[2]);
    let n = y.len() as f64;
    if s > 0.0 && so >= 0.0 && dwell >= 0.0 && full.kept[0] {
        let rms = (full.rss / n).sqrt();
        return Some((60.0 / s, dwell, so / s, rms));
    }
    // Fall back: no overrun term (overrun 0), then no dwell.
    let two = solve(vec![dist.clone(), reads, one.clone()]);
    if two.coef[0] > 0.0 && two.coef[1] >= 0.0 && two.kept[0] {
        return Some((60.0 / two.coef[0], two.coef[1], 0.0, (two.rss / n).sqrt()));
    }
    let one_fit = solve(vec![dist, one]);
    if one_fit.coef[0] > 0.0 && one_fit.kept[0] {
        return Some((60.0 / one_fit.coef[0], 0.0, 0.0, (one_fit.rss / n).sqrt()));
    }
    None
}

/// Rounds to 4 decimals (what the measurement files carry), without −0.
pub(crate) fn r4(x: f64) -> f64 {
    if x.is_finite() {
        (x * 1e4).round() / 1e4 + 0.0
    } else {
        0.0
    }
}
