//! Model checks: statistics of the measurement beside their distribution over tests
//! simulated from the fitted base model with the file's own plan (a parametric
//! bootstrap). A measured value outside the simulated 2.5–97.5 % band is something the
//! standard's model does not explain.

use super::analysis::Analysis;
use super::finding::fmt;
use super::maths::linalg::smooth_trend;
use super::maths::periodogram::{self, Grid, Trend};
use super::maths::stats::quantile_sorted;
use super::model::r4;
use super::options::Options;
use super::prep::Prep;
use crate::axis_model::rng::Rng;
use crate::axis_model::{ErrorModel, Simulation, TestPlan};
use crate::measurement::AxisData;
use rayon::prelude::*;

/// The statistics the model check compares with their simulated distribution.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Statistic {
    R,
    RunMeanSpread,
    Lag1Autocorrelation,
    MaxStudentizedResidual,
    ReversalRange,
    ScatterRatio,
    PeriodogramMaxF,
    TrendLackOfFit,
}

impl Statistic {
    /// Every statistic, in the order of the report's table.
    pub(crate) const ALL: [Statistic; 8] = [
        Statistic::R,
        Statistic::RunMeanSpread,
        Statistic::Lag1Autocorrelation,
        Statistic::MaxStudentizedResidual,
        Statistic::ReversalRange,
        Statistic::ScatterRatio,
        Statistic::PeriodogramMaxF,
        Statistic::TrendLackOfFit,
    ];

    /// Its key in `diagnose --json` and the report.
    pub(crate) fn name(self) -> &'static str {
        match self {
            Statistic::R => "R",
            Statistic::RunMeanSpread => "run_mean_spread",
            Statistic::Lag1Autocorrelation => "lag1_autocorrelation",
            Statistic::MaxStudentizedResidual => "max_studentized_residual",
            Statistic::ReversalRange => "reversal_range",
            Statistic::ScatterRatio => "scatter_ratio_end_to_start",
            Statistic::PeriodogramMaxF => "periodogram_max_f",
            Statistic::TrendLackOfFit => "trend_lack_of_fit_rms",
        }
    }

    /// The statistic whose [`Statistic::name`] is `name`.
    pub(crate) fn named(name: &str) -> Option<Statistic> {
        Statistic::ALL.into_iter().find(|s| s.name() == name)
    }

    fn description(self) -> &'static str {
        match self {
            Statistic::R => {
                "bidirectional repeatability of positioning R = max Ri (ISO 230-2 2.18)"
            }
            Statistic::RunMeanSpread => "range of the run means of the within-cell residuals",
            Statistic::Lag1Autocorrelation => {
                "lag-1 autocorrelation of the within-cell residuals in time order"
            }
            Statistic::MaxStudentizedResidual => {
                "largest |residual| / (s·√((n−1)/n)) over all readings"
            }
            Statistic::ReversalRange => "max Bi − min Bi (reversal value along the axis)",
            Statistic::ScatterRatio => {
                "scatter of the upper half of the travel over that of the lower half"
            }
            Statistic::PeriodogramMaxF => {
                "highest F of the Lomb–Scargle periodogram of the target means"
            }
            Statistic::TrendLackOfFit => {
                "RMS of the bidirectional target means about a cubic trend"
            }
        }
    }
}

/// Human description of the statistic named `name` (empty for another name).
pub(crate) fn describe(name: &str) -> &'static str {
    (Statistic::ALL.iter())
        .find(|s| s.name() == name)
        .map_or("", |s| s.description())
}

/// The value of each [`Statistic`] for one test (NaN where one does not apply).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Statistics([f64; 8]);

impl std::ops::Index<Statistic> for Statistics {
    type Output = f64;
    fn index(&self, s: Statistic) -> &f64 {
        &self.0[s as usize]
    }
}

impl std::ops::IndexMut<Statistic> for Statistics {
    fn index_mut(&mut self, s: Statistic) -> &mut f64 {
        &mut self.0[s as usize]
    }
}

/// The statistics of one test (NaN where one does not apply).
pub(crate) fn statistics(data: &AxisData) -> Statistics {
    statistics_with(data, None)
}

/// [`statistics`], the periodogram's F read after `steps` steps of its refine when given.
fn statistics_with(data: &AxisData, steps: Option<usize>) -> Statistics {
    let layout = Layout::new(data);
    let x: Vec<f64> = layout.prep.rows.iter().map(|r| r.x).collect();
    layout.statistics_with(&x, steps)
}

/// What [`statistics`] needs of a test besides its deviations: the cells, runs and time
/// order of its readings, the trend basis and the periodogram grid of its targets. Tests
/// simulated from one plan share it, so it is built once for all of them.
struct Layout {
    prep: Prep,
    /// Row indices in time order.
    by_order: Vec<usize>,
    /// Per target: whether it lies in the lower half of the travel.
    lower_half: Vec<bool>,
    /// The trend basis (m ≥ 5) and the grid of the periodogram (when applicable).
    trend: Option<Trend>,
    grid: Option<Grid>,
}

impl Layout {
    fn new(data: &AxisData) -> Layout {
        let prep = Prep::new(data);
        let mut by_order: Vec<usize> = (0..prep.rows.len()).collect();
        by_order.sort_by_key(|&k| prep.rows[k].order);
        let mid = (prep.lo + prep.hi) / 2.0;
        let lower_half = prep.positions.iter().map(|p| *p < mid).collect();
        let res = periodogram::resolution(&prep.positions);
        let trend = (prep.m >= 5).then(|| Trend::new(&prep.positions, None));
        let grid = trend
            .as_ref()
            .filter(|_| res.applicable)
            .map(|t| t.grid(1.0 / res.p_max, 1.0 / res.p_min, res.length));
        Layout {
            prep,
            by_order,
            lower_half,
            trend,
            grid,
        }
    }

    /// The statistics of the deviations `x` (one per row), the periodogram's highest F read
    /// after `steps` steps of its refine when given (see [`periodogram::Scanner::max_f`]).
    fn statistics_with(&self, x: &[f64], steps: Option<usize>) -> Statistics {
        let cells = Cells::of(&self.prep, x);
        let mut out = Statistics([f64::NAN; 8]);
        if self.prep.n >= 2 {
            self.within_cells(&cells, &mut out);
        }
        if self.prep.m >= 2 {
            let (lo, hi) = (cells.b.iter())
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, c), v| {
                    (a.min(*v), c.max(*v))
                });
            out[Statistic::ReversalRange] = hi - lo;
        }
        if let Some(trend) = &self.trend {
            let m = self.prep.m;
            let bidir: Vec<f64> = (0..m)
                .map(|i| (cells.means[2 * i] + cells.means[2 * i + 1]) / 2.0)
                .collect();
            let scanner = trend.scanner(&bidir);
            let r = scanner.trend_residuals();
            let dof = scanner.trend_dof();
            if dof > 0.0 {
                out[Statistic::TrendLackOfFit] =
                    (r.iter().map(|v| v * v).sum::<f64>() / dof).sqrt();
            }
            if let Some(grid) = &self.grid {
                out[Statistic::PeriodogramMaxF] = scanner.max_f(grid, steps);
            }
        }
        out
    }

    /// The statistics of the scatter within cells (n ≥ 2): R, the run means' spread, the
    /// lag-1 autocorrelation, the largest studentized residual and the scatter ratio.
    fn within_cells(&self, cells: &Cells, out: &mut Statistics) {
        let prep = &self.prep;
        let (m, n) = (prep.m, prep.n);
        let s: Vec<f64> = (cells.ss.iter())
            .map(|v| (v / (n - 1) as f64).sqrt())
            .collect();
        out[Statistic::R] = (0..m)
            .map(|i| {
                let (su, sd) = (s[2 * i], s[2 * i + 1]);
                (2.0 * su + 2.0 * sd + cells.b[i].abs())
                    .max(4.0 * su)
                    .max(4.0 * sd)
            })
            .fold(f64::NEG_INFINITY, f64::max);
        let mut run_sum = vec![0.0; n];
        for (r, e) in prep.rows.iter().zip(&cells.resid) {
            run_sum[r.run] += e;
        }
        let per = (2 * m) as f64;
        let (lo, hi) = (run_sum.iter()).fold((f64::INFINITY, f64::NEG_INFINITY), |(a, c), v| {
            (a.min(v / per), c.max(v / per))
        });
        out[Statistic::RunMeanSpread] = hi - lo;
        let resid = &cells.resid;
        let den: f64 = self.by_order.iter().map(|&k| resid[k] * resid[k]).sum();
        if den > 0.0 {
            out[Statistic::Lag1Autocorrelation] = (self.by_order.windows(2))
                .map(|w| resid[w[0]] * resid[w[1]])
                .sum::<f64>()
                / den;
        }
        let pooled = cells.ss.iter().sum::<f64>() / (prep.rows.len() - cells.ss.len()) as f64;
        if n >= 3 && pooled > 0.0 {
            let k = (pooled * (n - 1) as f64 / n as f64).sqrt();
            out[Statistic::MaxStudentizedResidual] =
                resid.iter().fold(0.0f64, |a, e| a.max(e.abs() / k));
        }
        if m >= 2 {
            out[Statistic::ScatterRatio] = self.scatter_ratio(&cells.ss);
        }
    }

    /// The scatter of the upper half of the travel over that of the lower half.
    fn scatter_ratio(&self, ss: &[f64]) -> f64 {
        let n = self.prep.n;
        let (mut lo_ss, mut lo_c, mut hi_ss, mut hi_c) = (0.0, 0usize, 0.0, 0usize);
        for (c, v) in ss.iter().enumerate() {
            if self.lower_half[c / 2] {
                lo_ss += v;
                lo_c += n - 1;
            } else {
                hi_ss += v;
                hi_c += n - 1;
            }
        }
        if lo_c > 0 && hi_c > 0 && lo_ss > 0.0 {
            ((hi_ss / hi_c as f64) / (lo_ss / lo_c as f64)).sqrt()
        } else {
            f64::NAN
        }
    }
}

/// The deviations by cell (target and direction): means, residuals about them, sums of
/// squares, and the reversal value of each target.
struct Cells {
    means: Vec<f64>,
    resid: Vec<f64>,
    ss: Vec<f64>,
    b: Vec<f64>,
}

impl Cells {
    fn of(prep: &Prep, x: &[f64]) -> Cells {
        let cells = prep.cells();
        let mut sum = vec![0.0; cells];
        let mut count = vec![0usize; cells];
        for (r, v) in prep.rows.iter().zip(x) {
            let c = prep.cell(r);
            sum[c] += v;
            count[c] += 1;
        }
        let means: Vec<f64> = (sum.iter().zip(&count))
            .map(|(s, &c)| if c > 0 { s / c as f64 } else { f64::NAN })
            .collect();
        let resid: Vec<f64> = (prep.rows.iter().zip(x))
            .map(|(r, v)| v - means[prep.cell(r)])
            .collect();
        let mut ss = vec![0.0; cells];
        for (r, e) in prep.rows.iter().zip(&resid) {
            ss[prep.cell(r)] += e * e;
        }
        let b = (0..prep.m)
            .map(|i| means[2 * i] - means[2 * i + 1])
            .collect();
        Cells {
            means,
            resid,
            ss,
            b,
        }
    }
}

/// Tests simulated from a simulation whose plan lists its targets, without building each
/// test's [`AxisData`]: the targets, the schedule, the expected deviation and the scatter
/// of every reading are the same in every test, only the scatter's draws differ. Built
/// only for models without random run offsets and outliers (the base model never has
/// them), and checked against [`Simulation::run`] on the first test.
struct FastSim {
    layout: Layout,
    /// Expected deviation (with the run's fixed offset) per reading, in visit order.
    expected: Vec<f64>,
    /// Scatter σ per reading.
    sigma: Vec<f64>,
    resolution: f64,
}

/// Decimals the simulator keeps (`simulate::DECIMALS`; a difference fails the check in
/// [`FastSim::new`], and the tests then go through [`Simulation::run`]).
const SIM_SCALE: f64 = 1e4;

/// The seed of simulated test `s`.
fn sim_seed(seed: u64, s: usize) -> u64 {
    Rng::new(seed, 0xC4EC + s as u64).next_u64()
}

impl FastSim {
    fn new(sim: &Simulation, seed: u64, strip_times: bool) -> Option<FastSim> {
        let (model, plan) = (&sim.model, &sim.plan);
        if plan.target_list.is_none()
            || model.run_offset_sd != 0.0
            || model.outlier_rate != 0.0
            || !model.outliers.is_empty()
        {
            return None;
        }
        let seed0 = sim_seed(seed, 0);
        let targets = plan.target_positions(seed0);
        let first = sim_test(sim, seed0, strip_times);
        if first.targets != targets || first.run_labels.len() != plan.runs {
            return None;
        }
        let travel = (targets[0], targets[targets.len() - 1]);
        let visits = plan.schedule(&targets);
        if visits.len() != first.readings.len() {
            return None;
        }
        let mut expected = Vec::with_capacity(visits.len());
        let mut sigma = Vec::with_capacity(visits.len());
        for (v, r) in visits.iter().zip(&first.readings) {
            if (r.target, r.direction, r.run) != (v.target, v.direction, v.run) {
                return None;
            }
            let position = targets[v.target];
            let offset = model.run_offsets.get(v.run).copied().unwrap_or(0.0) + 0.0;
            expected
                .push(model.expected(sim.kind, position, v.direction, v.time_s, travel) + offset);
            sigma.push(model.scatter_at(position, travel));
        }
        let fast = FastSim {
            layout: Layout::new(&first),
            expected,
            sigma,
            resolution: model.resolution,
        };
        let same = fast
            .deviations(seed0)
            .iter()
            .zip(&first.readings)
            .all(|(x, r)| x.to_bits() == r.deviation.to_bits());
        same.then_some(fast)
    }

    /// The deviations of the test with `seed`, in reading order (as [`Simulation::run`]
    /// draws and rounds them).
    fn deviations(&self, seed: u64) -> Vec<f64> {
        let mut scatter_rng = Rng::new(seed, 3);
        self.expected
            .iter()
            .zip(&self.sigma)
            .map(|(e, s)| {
                let mut x = *e;
                x += s * scatter_rng.normal();
                if self.resolution > 0.0 {
                    x = (x / self.resolution).round() * self.resolution;
                }
                (x * SIM_SCALE).round() / SIM_SCALE + 0.0
            })
            .collect()
    }
}

/// One simulated test, as the measurement it stands for (without time stamps when it
/// had none).
fn sim_test(sim: &Simulation, seed: u64, strip_times: bool) -> AxisData {
    let mut data = sim.run(seed);
    if strip_times {
        for r in &mut data.readings {
            r.time_s = None;
        }
    }
    data
}

/// One model check.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelCheck {
    pub statistic: String,
    pub measured: f64,
    /// 2.5 % quantile of the simulated distribution.
    pub simulated_low: f64,
    /// 97.5 % quantile.
    pub simulated_high: f64,
    pub outside: bool,
    /// `above` or `below` the band when outside. Below can be telling too: a drift
    /// inflates the base model's scatter, so its simulated target means scatter more
    /// than the measured ones.
    pub side: Option<&'static str>,
}

/// The model checks of `a` against its fitted base model `base` (when the plan can be
/// simulated); a large test gets fewer simulations, and a trend the base model cannot
/// explain gets a note.
pub(crate) fn check_base_model(
    a: &Analysis,
    base: &Simulation,
    simulable: bool,
    options: &Options,
    notes: &mut Vec<String>,
) -> Vec<ModelCheck> {
    if !(a.basis.prep.n >= 2 && simulable && options.simulations > 0) {
        return Vec::new();
    }
    let mut count = options.simulations;
    let budget = 4_000_000 / a.basis.x.len().max(1);
    if count > budget {
        count = budget.max(20);
        notes.push(format!(
            "a large test: {count} Monte-Carlo simulations instead of {}",
            options.simulations
        ));
    }
    let measured = statistics(a.basis.data);
    let checks = run(
        &measured,
        base,
        count,
        options.seed,
        !a.basis.data.has_times(),
    );
    if let Some(c) = checks.iter().find(|c| {
        c.statistic == Statistic::TrendLackOfFit.name()
            && c.measured > c.simulated_high
            && a.periodic.peak.is_none()
    }) {
        let ds = a.basis.units.symbol();
        notes.push(format!(
            "the target means depart from a smooth (cubic) trend more than the scatter explains (RMS {} {ds}, simulated at most {} {ds}): the systematic deviation has structure at the scale of the target spacing — a progressive error of complex shape, or a periodic error the plan cannot resolve or aliases (ISO 230-2 4.2; Hemingray et al. 1971, §4); not one of the named effects",
            fmt(c.measured),
            fmt(c.simulated_high)
        ));
    }
    checks
}

/// Simulates `count` tests of `sim` (seeds from `seed`) and compares them with the
/// measured statistics; `strip_times` removes the simulated time stamps when the
/// measurement had none, so both are analysed alike.
pub(crate) fn run(
    measured: &Statistics,
    sim: &Simulation,
    count: usize,
    seed: u64,
    strip_times: bool,
) -> Vec<ModelCheck> {
    if count == 0 {
        return Vec::new();
    }
    let fast = FastSim::new(sim, seed, strip_times);
    // Test `s`'s statistics, the periodogram's F bounded after `steps` of its refine.
    let simulate = |s: usize, steps: Option<usize>| match &fast {
        Some(fast) => (fast.layout).statistics_with(&fast.deviations(sim_seed(seed, s)), steps),
        None => statistics_with(&sim_test(sim, sim_seed(seed, s), strip_times), steps),
    };
    let mut sims: Vec<Statistics> = (0..count)
        .into_par_iter()
        .map(|s| simulate(s, Some(periodogram::PARTIAL_STEPS)))
        .collect();
    let periodogram = Statistic::PeriodogramMaxF;
    if measured[periodogram].is_finite() {
        let exact = |s: usize| simulate(s, None)[periodogram];
        let bounds: Vec<f64> = sims.iter().map(|v| v[periodogram]).collect();
        for (s, v) in refined_at_band(&bounds, exact) {
            sims[s][periodogram] = v;
        }
    }
    let mut out = Vec::new();
    for k in Statistic::ALL {
        if !measured[k].is_finite() {
            continue;
        }
        let mut values: Vec<f64> = sims.iter().map(|s| s[k]).collect();
        values.retain(|v| v.is_finite());
        values.sort_by(f64::total_cmp);
        let low = quantile_sorted(&values, BAND[0]);
        let high = quantile_sorted(&values, BAND[1]);
        if !(low.is_finite() && high.is_finite()) {
            continue;
        }
        out.push(ModelCheck {
            statistic: k.name().to_string(),
            measured: measured[k],
            simulated_low: low,
            simulated_high: high,
            outside: measured[k] < low || measured[k] > high,
            side: if measured[k] > high {
                Some("above")
            } else if measured[k] < low {
                Some("below")
            } else {
                None
            },
        });
    }
    out
}

/// The simulated band's quantiles.
const BAND: [f64; 2] = [0.025, 0.975];

/// The simulated tests whose periodogram F the band needs exactly, with that F: `bounds`
/// are each test's F after [`periodogram::PARTIAL_STEPS`] steps of the refine, which the
/// full refine (`exact`) moves by less than [`periodogram::PARTIAL_REL`] of itself. Only
/// the values at the band's ranks enter it, so a test is refined fully when it may hold
/// such a rank: until every test at those ranks is exact and no other test's interval
/// holds their values, the band is the one of the full refine of every test, to the bit.
/// Most tests then keep the bound (and skip 29 of the refine's 43 fits; about 13 of 200
/// tests were refined fully on an axis of 1 500 files): a model check's 200
/// simulated periodograms were 40 % of the diagnosis of a 15-target plan.
fn refined_at_band(bounds: &[f64], exact: impl Fn(usize) -> f64) -> Vec<(usize, f64)> {
    let mut value: Vec<f64> = bounds.to_vec();
    let mut known = vec![false; bounds.len()];
    // Tests whose F is not finite are left out of the band; refined, they are known.
    for (s, v) in bounds.iter().enumerate() {
        if !v.is_finite() {
            value[s] = exact(s);
            known[s] = true;
        }
    }
    let interval = |v: f64| {
        let margin = v.abs() * periodogram::PARTIAL_REL;
        (v - margin, v + margin)
    };
    loop {
        let mut order: Vec<usize> = (0..value.len()).filter(|&s| value[s].is_finite()).collect();
        order.sort_by(|&x, &y| value[x].total_cmp(&value[y]));
        let ranks = band_ranks(order.len());
        let mut todo: Vec<usize> = Vec::new();
        for &r in &ranks {
            let s = order[r];
            if !known[s] {
                todo.push(s);
                continue;
            }
            let v = value[s];
            todo.extend((0..value.len()).filter(|&t| {
                let (lo, hi) = interval(value[t]);
                !known[t] && lo <= v && v <= hi
            }));
        }
        if todo.is_empty() {
            break;
        }
        todo.sort_unstable();
        todo.dedup();
        for s in todo {
            value[s] = exact(s);
            known[s] = true;
        }
    }
    (0..value.len())
        .filter(|&s| known[s])
        .map(|s| (s, value[s]))
        .collect()
}

/// The ranks of `len` sorted values that [`quantile_sorted`] reads for the band.
fn band_ranks(len: usize) -> Vec<usize> {
    if len == 0 {
        return Vec::new();
    }
    let mut ranks: Vec<usize> = BAND
        .iter()
        .flat_map(|q| {
            let h = (len - 1) as f64 * q;
            [h.floor() as usize, h.ceil() as usize]
        })
        .collect();
    ranks.dedup();
    ranks
}

/// The base model (the standard's assumptions) fitted to the raw readings: smooth
/// systematic deviation, one reversal value, white scatter, nothing in time.
pub(crate) fn base_model(a: &Analysis, plan: &TestPlan, seed: u64) -> Simulation {
    let (p, m) = (&a.basis.prep, a.basis.prep.m);
    let all = vec![true; a.basis.x.len()];
    let (raw_means, _) = p.cell_means(&a.basis.x, &all);
    let raw_bidir: Vec<f64> = (0..m)
        .map(|i| (raw_means[2 * i] + raw_means[2 * i + 1]) / 2.0)
        .collect();
    let raw_b: Vec<f64> = (0..m)
        .map(|i| raw_means[2 * i] - raw_means[2 * i + 1])
        .collect();
    let trend = smooth_trend(&p.positions, &raw_bidir);
    let raw_sigma = if p.n >= 2 {
        let ss: f64 = p
            .rows
            .iter()
            .zip(&a.basis.x)
            .map(|(r, v)| (v - raw_means[p.cell(r)]).powi(2))
            .sum();
        (ss / (a.basis.x.len() - p.cells()) as f64).sqrt()
    } else {
        0.0
    };
    Simulation {
        kind: a.basis.data.kind,
        seed,
        description: Some(
            "base model fitted by axcheck diagnose: smooth systematic deviation, one reversal value, white scatter, nothing in time"
                .to_string(),
        ),
        model: ErrorModel {
            shape: p
                .positions
                .iter()
                .zip(&trend)
                .map(|(p, t)| [*p, r4(*t)])
                .collect(),
            reversal: r4(raw_b.iter().sum::<f64>() / m as f64),
            scatter: r4(raw_sigma),
            ..ErrorModel::default()
        },
        plan: plan.clone(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::axis_model::{Cycle, ErrorModel, PeriodicTerm, TestPlan};
    use crate::units::AxisKind;

    fn simulation(cycle: Cycle, model: ErrorModel) -> Simulation {
        // Uneven targets, fine enough for the periodogram (m = 21, spacing ≈ 5).
        let targets = (0..21)
            .map(|i| i as f64 * 5.0 + 0.37 * ((i * 7 % 5) as f64))
            .collect();
        Simulation {
            kind: AxisKind::Linear,
            seed: 0,
            description: None,
            model,
            plan: TestPlan {
                targets: None,
                target_list: Some(targets),
                runs: 5,
                cycle,
                feed_per_min: 1000.0,
                dwell_s: 4.0,
                overrun: 5.0,
            },
        }
    }

    fn base_like() -> ErrorModel {
        ErrorModel {
            shape: vec![[0.0, 0.3], [50.0, -1.2], [101.0, 0.8]],
            periodic: vec![PeriodicTerm {
                pitch: 12.5,
                amplitude: 0.4,
                phase_deg: 20.0,
            }],
            reversal: 2.5,
            reversal_end: Some(3.5),
            scatter: 0.5,
            scatter_end: Some(0.9),
            ..ErrorModel::default()
        }
    }

    /// The shortcut gives, to the bit, the statistics of the tests [`Simulation::run`]
    /// simulates.
    #[test]
    fn fast_tests_are_the_simulators_tests() {
        let quantised = ErrorModel {
            resolution: 0.1,
            run_offsets: vec![0.0, 0.5, -0.3, 0.2, -0.1],
            ..base_like()
        };
        for model in [base_like(), quantised] {
            for cycle in [Cycle::Standard, Cycle::Pilgrim, Cycle::Step] {
                for strip in [false, true] {
                    let sim = simulation(cycle, model.clone());
                    let fast = FastSim::new(&sim, 7, strip).expect("the shortcut applies");
                    assert!(fast.layout.grid.is_some());
                    for s in 0..12 {
                        let seed = sim_seed(7, s);
                        let a = fast.layout.statistics_with(&fast.deviations(seed), None);
                        let b = statistics(&sim_test(&sim, seed, strip));
                        let bits = |v: Statistics| v.0.map(f64::to_bits);
                        assert_eq!(bits(a), bits(b), "{cycle:?} strip {strip} test {s}");
                    }
                }
            }
        }
    }

    /// The periodogram's F read after [`periodogram::PARTIAL_STEPS`] steps of the refine
    /// lies within a fiftieth of [`periodogram::PARTIAL_REL`] of the fully refined F, on
    /// 3 600 simulated tests of three cycles, with and without a periodic error (the
    /// worst was 6.1·10⁻⁴).
    #[test]
    fn the_partial_refine_is_within_its_bound() {
        let flat = ErrorModel {
            periodic: Vec::new(),
            ..base_like()
        };
        let mut worst = 0.0f64;
        for model in [base_like(), flat] {
            for cycle in [Cycle::Standard, Cycle::Pilgrim, Cycle::Step] {
                let fast = FastSim::new(&simulation(cycle, model.clone()), 11, false).unwrap();
                for s in 0..600 {
                    let x = fast.deviations(sim_seed(11, s));
                    let p = Statistic::PeriodogramMaxF;
                    let bound = fast
                        .layout
                        .statistics_with(&x, Some(periodogram::PARTIAL_STEPS))[p];
                    let full = fast.layout.statistics_with(&x, None)[p];
                    worst = worst.max((full - bound).abs() / bound);
                }
            }
        }
        assert!(worst <= periodogram::PARTIAL_REL / 50.0, "worst {worst:e}");
    }

    /// The band of the model checks, every simulated test's periodogram refined fully,
    /// to the bit.
    #[test]
    fn the_band_is_the_band_of_full_refines() {
        for cycle in [Cycle::Standard, Cycle::Pilgrim] {
            let sim = simulation(cycle, base_like());
            let fast = FastSim::new(&sim, 3, false).unwrap();
            let measured = fast
                .layout
                .statistics_with(&fast.deviations(sim_seed(99, 0)), None);
            let checks = run(&measured, &sim, 200, 3, false);
            let p = Statistic::PeriodogramMaxF;
            let mut full: Vec<f64> = (0..200)
                .map(|s| {
                    fast.layout
                        .statistics_with(&fast.deviations(sim_seed(3, s)), None)[p]
                })
                .collect();
            full.sort_by(f64::total_cmp);
            let check = checks.iter().find(|c| c.statistic == p.name()).unwrap();
            let low = quantile_sorted(&full, BAND[0]);
            let high = quantile_sorted(&full, BAND[1]);
            assert_eq!(check.simulated_low.to_bits(), low.to_bits(), "{cycle:?}");
            assert_eq!(check.simulated_high.to_bits(), high.to_bits(), "{cycle:?}");
        }
    }

    /// Values crowded about the band's ranks, each exact value anywhere within the bound's
    /// interval: the band from the refined tests is the band of all exact values.
    #[test]
    fn refining_at_the_band_finds_its_ranks() {
        let mut rng = Rng::new(5, 1);
        for case in 0..300 {
            let count = 40 + case % 170;
            // Few distinct levels, so that many intervals overlap.
            let bounds: Vec<f64> = (0..count)
                .map(|_| 1.0 + (rng.uniform() * 8.0).floor() * 2e-5)
                .collect();
            let exact: Vec<f64> = (bounds.iter())
                .map(|b| b * (1.0 + (rng.uniform() - 0.5) * periodogram::PARTIAL_REL))
                .collect();
            let mut values = bounds.clone();
            for (s, v) in refined_at_band(&bounds, |s| exact[s]) {
                values[s] = v;
            }
            values.sort_by(f64::total_cmp);
            let mut all = exact.clone();
            all.sort_by(f64::total_cmp);
            for q in BAND {
                assert_eq!(
                    quantile_sorted(&values, q),
                    quantile_sorted(&all, q),
                    "{case}"
                );
            }
        }
    }

    #[test]
    fn random_terms_take_the_simulator() {
        for model in [
            ErrorModel {
                run_offset_sd: 0.3,
                ..base_like()
            },
            ErrorModel {
                outlier_rate: 0.01,
                outlier_size: 5.0,
                ..base_like()
            },
        ] {
            assert!(FastSim::new(&simulation(Cycle::Standard, model), 7, false).is_none());
        }
    }
}
