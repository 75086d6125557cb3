//! The readings of a test as rows for the diagnosis: cell (target, direction), run, time.
//!
//! Time is `time_s` in hours when every reading has one. Without time stamps the readings
//! are placed in the order of the standard test cycle (ISO 230-2 clause 4.3 and Fig. 1:
//! each run goes up through all targets, then down), one run being one unit of time, so
//! rates come out per run.

use crate::measurement::AxisData;
use crate::units::AxisKind;

/// The unit in which time is measured.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TimeUnit {
    /// Hours, from the readings' `time_s`.
    Hours,
    /// Runs of the standard test cycle (no time stamps).
    Runs,
}

impl TimeUnit {
    /// Suffix of rate keys: `h` or `run`.
    pub fn key(self) -> &'static str {
        match self {
            TimeUnit::Hours => "h",
            TimeUnit::Runs => "run",
        }
    }
}

/// One reading.
#[derive(Debug, Clone)]
pub(crate) struct Row {
    /// Index in `AxisData::readings`.
    pub reading: usize,
    /// Target index i (0-based).
    pub i: usize,
    /// Direction index: 0 up, 1 down.
    pub d: usize,
    /// +1 up, −1 down.
    pub sign: f64,
    /// Run index j (0-based).
    pub run: usize,
    /// Time in [`TimeUnit`]s from the start of the test.
    pub t: f64,
    /// Rank of the reading in time (0-based).
    pub order: usize,
    /// Deviation, µm or arcsec.
    pub x: f64,
}

/// A test prepared for the diagnosis.
#[derive(Debug, Clone)]
pub(crate) struct Prep {
    pub kind: AxisKind,
    /// Number of targets m.
    pub m: usize,
    /// Runs per direction n.
    pub n: usize,
    pub positions: Vec<f64>,
    pub rows: Vec<Row>,
    pub time_unit: TimeUnit,
    /// Mean target position (the centre of position-dependent terms).
    pub(crate) pbar: f64,
    /// First and last target.
    pub lo: f64,
    pub hi: f64,
    /// Mean time of the readings.
    pub(crate) tbar: f64,
    /// Time of the first reading: the start of the test, where a warm-up begins.
    pub t0: f64,
    /// Time from the first to the last reading.
    pub(crate) t_span: f64,
    /// What each time term reads per row.
    pub(crate) clocks: Clocks,
    /// The declared thermal origin ([`super::Options::thermal_origin`]).
    pub thermal_origin: Option<f64>,
}

/// What each time term of the model reads per row: the readings' times and runs, or, for
/// a term unrelated to the data ([`super::confirm`]), its own in a random order.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Clocks {
    /// The drift column: time about the mean, t − t̄.
    pub drift: Vec<f64>,
    /// The time in the thermal column (P − P̄)·(t − t̄).
    pub thermal: Vec<f64>,
    /// The time since the start of the test that a warm-up curve reads, t − t0.
    pub warm: Vec<f64>,
    /// The run of each row, for the run effects.
    pub run: Vec<usize>,
}

/// Index of reading (i, d, j) in the standard test cycle with m targets.
pub(crate) fn standard_index(m: usize, i: usize, d: usize, j: usize) -> usize {
    j * 2 * m + if d == 0 { i } else { m + (m - 1 - i) }
}

impl Prep {
    pub fn new(data: &AxisData) -> Prep {
        let m = data.target_count();
        let n = data.runs();
        let has_times = data.has_times() && !data.readings.is_empty();
        let time_unit = if has_times {
            TimeUnit::Hours
        } else {
            TimeUnit::Runs
        };
        let mut rows: Vec<Row> = data
            .readings
            .iter()
            .enumerate()
            .map(|(k, r)| {
                let d = r.direction.index();
                let std_index = standard_index(m, r.target, d, r.run);
                let t = match (time_unit, r.time_s) {
                    (TimeUnit::Hours, Some(s)) => s / 3600.0,
                    _ => std_index as f64 / (2 * m) as f64,
                };
                Row {
                    reading: k,
                    i: r.target,
                    d,
                    sign: r.direction.sign(),
                    run: r.run,
                    t,
                    order: std_index,
                    x: r.deviation,
                }
            })
            .collect();
        // Rank in time; ties broken by the standard cycle's order.
        let mut by_time: Vec<usize> = (0..rows.len()).collect();
        by_time.sort_by(|&a, &b| {
            rows[a]
                .t
                .total_cmp(&rows[b].t)
                .then(rows[a].order.cmp(&rows[b].order))
        });
        for (rank, &k) in by_time.iter().enumerate() {
            rows[k].order = rank;
        }
        let positions = data.targets.clone();
        let pbar = positions.iter().sum::<f64>() / m.max(1) as f64;
        let (lo, hi) = (positions[0], positions[m - 1]);
        let tbar = rows.iter().map(|r| r.t).sum::<f64>() / rows.len().max(1) as f64;
        let (tmin, tmax) = rows
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), r| {
                (a.min(r.t), b.max(r.t))
            });
        let t0 = if tmin.is_finite() { tmin } else { 0.0 };
        let about_mean: Vec<f64> = rows.iter().map(|r| r.t - tbar).collect();
        let clocks = Clocks {
            drift: about_mean.clone(),
            thermal: about_mean,
            warm: rows.iter().map(|r| r.t - t0).collect(),
            run: rows.iter().map(|r| r.run).collect(),
        };
        Prep {
            kind: data.kind,
            m,
            n,
            positions,
            rows,
            time_unit,
            pbar,
            lo,
            hi,
            tbar,
            t0,
            t_span: (tmax - tmin).max(0.0),
            clocks,
            thermal_origin: None,
        }
    }

    /// This test with its time terms reading `clocks`, everything else as it is.
    pub(crate) fn with_clocks(&self, clocks: Clocks) -> Prep {
        Prep {
            clocks,
            ..self.clone()
        }
    }

    /// Number of cells (target, direction).
    pub fn cells(&self) -> usize {
        2 * self.m
    }

    /// Cell of a row.
    pub fn cell(&self, row: &Row) -> usize {
        2 * row.i + row.d
    }

    /// Length of the measurement travel.
    pub fn length(&self) -> f64 {
        self.hi - self.lo
    }

    /// Deviation units per position unit per ppm: a rate of position-proportional error
    /// `g` (deviation per position unit) is `g / ppm_factor()` ppm.
    pub(crate) fn ppm_factor(&self) -> f64 {
        1e-6 * self.kind.deviation_units_per_position_unit()
    }

    /// Per-cell means of `values` over the active rows, with counts.
    pub(crate) fn cell_means(&self, values: &[f64], active: &[bool]) -> (Vec<f64>, Vec<usize>) {
        let mut sum = vec![0.0; self.cells()];
        let mut count = vec![0usize; self.cells()];
        for (k, r) in self.rows.iter().enumerate() {
            if active[k] {
                let c = self.cell(r);
                sum[c] += values[k];
                count[c] += 1;
            }
        }
        let means = sum
            .iter()
            .zip(&count)
            .map(|(s, &c)| if c > 0 { s / c as f64 } else { f64::NAN })
            .collect();
        (means, count)
    }
}
