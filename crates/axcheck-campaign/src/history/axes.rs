//! The trends of one run's axes, fitted over the whole history: what the axis reports'
//! history sections and the campaign summary's list of flagged axes show.

use super::Record;
use crate::trend::{self, Series, Trend};
use rayon::prelude::*;
use std::collections::{BTreeMap, BTreeSet};

/// Machine id, serial, axis: whose series these are (a new serial starts new series).
pub type AxisKey = (String, Option<String>, String);

/// Every series of the run's axes with its trend, by axis.
#[derive(Debug, Default)]
pub struct AxisTrends {
    pub options: trend::TrendOptions,
    by_axis: BTreeMap<AxisKey, Vec<(Series, Trend)>>,
}

impl AxisTrends {
    /// The series of the axes that have rows in `run`, fitted with `options`, from the
    /// history's rows that `feed` passes in batches (file by file from the store, so that
    /// only the run's axes are kept, never the whole history).
    pub fn of_run<E>(
        run: &[Record],
        options: trend::TrendOptions,
        feed: impl FnOnce(&mut dyn FnMut(Vec<Record>)) -> Result<(), E>,
    ) -> Result<AxisTrends, E> {
        let wanted: BTreeSet<AxisKey> = run.iter().map(axis_key).collect();
        let mut builder = super::SeriesBuilder::default();
        feed(&mut |rows| builder.add(rows.into_iter().filter(|r| wanted.contains(&axis_key(r)))))?;
        Ok(AxisTrends::fitted(builder.finish(), options))
    }

    /// The series fitted, by axis.
    pub fn fitted(series: Vec<Series>, options: trend::TrendOptions) -> AxisTrends {
        let fitted: Vec<(Series, Trend)> = series
            .into_par_iter()
            .map(|s| {
                let t = trend::fit(&s, &options);
                (s, t)
            })
            .collect();
        let mut by_axis: BTreeMap<AxisKey, Vec<(Series, Trend)>> = BTreeMap::new();
        for (s, t) in fitted {
            let k = (s.machine.clone(), s.serial.clone(), s.axis.clone());
            by_axis.entry(k).or_default().push((s, t));
        }
        AxisTrends { options, by_axis }
    }

    /// The series of one axis, in the history's parameter order; empty when it has none.
    pub fn axis(&self, machine: &str, serial: Option<&str>, axis: &str) -> &[(Series, Trend)] {
        let k = (
            machine.to_string(),
            serial.map(str::to_string),
            axis.to_string(),
        );
        self.by_axis.get(&k).map_or(&[], Vec::as_slice)
    }

    /// Every series, by machine, serial, axis and parameter.
    pub fn all(&self) -> impl Iterator<Item = &(Series, Trend)> {
        self.by_axis.values().flatten()
    }

    /// Every flagged series, by machine, serial, axis and parameter.
    pub fn flagged(&self) -> impl Iterator<Item = &(Series, Trend)> {
        self.by_axis.values().flatten().filter(|(_, t)| t.flagged)
    }

    /// The inspection dates of the history behind these trends, first and last.
    pub fn dates(&self) -> Option<(chrono::NaiveDate, chrono::NaiveDate)> {
        let points = self.by_axis.values().flatten().flat_map(|(s, _)| &s.points);
        let first = points.clone().map(|p| p.date).min()?;
        Some((first, points.map(|p| p.date).max()?))
    }
}

/// Whose series a record belongs to.
pub fn axis_key(r: &Record) -> AxisKey {
    (
        r.machine.to_string(),
        r.serial.as_deref().map(str::to_string),
        r.axis.to_string(),
    )
}
