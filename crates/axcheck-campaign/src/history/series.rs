//! History rows regrouped as trend series: one per machine, serial, axis and parameter.

use super::Record;
use super::record::SharedText;
use crate::trend::{Inspection, Series};
use chrono::NaiveDate;
use std::collections::{BTreeMap, BTreeSet};

/// Machine id, serial, axis, parameter: a series (a new serial number starts a new one).
type Key = (SharedText, Option<SharedText>, SharedText, SharedText);

/// What a point needs of one row: the rows of one inspection date are averaged over the
/// axis's first test, in the order of their campaigns' names. Texts are numbers into the
/// builder's tables: a row is 48 bytes, and ten yearly inspections of 10 000 axes (1.1
/// million rows) take about 50 MB.
struct Row {
    series: u32,
    date: NaiveDate,
    test: u32,
    campaign: u32,
    unit: u32,
    value: f64,
    limit: Option<f64>,
}

/// The series of a history built row by row, keeping of each row only what its point
/// needs (the history need not be held whole).
#[derive(Default)]
pub struct SeriesBuilder {
    /// Every series' key and its number (in the order first seen).
    keys: BTreeMap<Key, u32>,
    campaigns: Interned,
    units: Interned,
    rows: Vec<Row>,
    dates: BTreeSet<NaiveDate>,
    count: usize,
}

/// Texts by number (few distinct ones: the campaigns, the units).
#[derive(Default)]
struct Interned {
    numbers: BTreeMap<SharedText, u32>,
    texts: Vec<SharedText>,
}

impl Interned {
    fn number(&mut self, text: SharedText) -> u32 {
        if let Some(&k) = self.numbers.get(&text) {
            return k;
        }
        let k = self.texts.len() as u32;
        self.texts.push(text.clone());
        self.numbers.insert(text, k);
        k
    }
}

impl SeriesBuilder {
    /// Adds the rows of a history (rows whose value is not finite are left out).
    pub fn add(&mut self, records: impl IntoIterator<Item = Record>) {
        for r in records {
            self.count += 1;
            self.dates.insert(r.date);
            if !r.value.is_finite() {
                continue;
            }
            let next = self.keys.len() as u32;
            let key = (r.machine, r.serial, r.axis, r.parameter);
            let series = *self.keys.entry(key).or_insert(next);
            self.rows.push(Row {
                series,
                date: r.date,
                test: r.test,
                campaign: self.campaigns.number(r.campaign),
                unit: self.units.number(r.unit),
                value: r.value,
                limit: r.limit,
            });
        }
    }

    /// Rows added.
    pub fn rows(&self) -> usize {
        self.count
    }

    /// The rows' distinct dates, in order.
    pub fn dates(&self) -> Vec<NaiveDate> {
        self.dates.iter().copied().collect()
    }

    /// The series, by machine, serial, axis and parameter.
    pub fn finish(mut self) -> Vec<Series> {
        // Each series' place in key order; the rows of a series and date keep their order.
        let mut rank = vec![0u32; self.keys.len()];
        for (place, &k) in self.keys.values().enumerate() {
            rank[k as usize] = place as u32;
        }
        self.rows.sort_by_key(|r| (rank[r.series as usize], r.date));
        let mut rows = self.rows.as_slice();
        let mut out = Vec::with_capacity(self.keys.len());
        for (machine, serial, axis, parameter) in self.keys.into_keys() {
            let n = rows.partition_point(|r| r.series == rows[0].series);
            let (mine, rest) = rows.split_at(n);
            rows = rest;
            out.push(series_of(
                mine,
                (machine, serial, axis, parameter),
                &self.campaigns,
                &self.units,
            ));
        }
        out
    }
}

/// One series from its rows (sorted by date).
fn series_of(rows: &[Row], key: Key, campaigns: &Interned, units: &Interned) -> Series {
    let (machine, serial, axis, parameter) = key;
    let mut inspections: Vec<(NaiveDate, Vec<&Row>)> = Vec::new();
    for date_rows in rows.chunk_by(|a, b| a.date == b.date) {
        let rows = first_test(date_rows.iter().collect(), campaigns);
        inspections.push((date_rows[0].date, rows));
    }
    let latest = inspections.last().map(|(_, rows)| rows.as_slice());
    Series {
        machine: machine.to_string(),
        serial: serial.as_deref().map(str::to_string),
        axis: axis.to_string(),
        parameter: parameter.to_string(),
        unit: (latest.and_then(|rows| rows.first()))
            .map(|r| units.texts[r.unit as usize].to_string())
            .unwrap_or_default(),
        limit: latest.and_then(|rows| rows.iter().find_map(|r| r.limit)),
        points: (inspections.iter())
            .map(|(date, rows)| Inspection {
                date: *date,
                value: rows.iter().map(|r| r.value).sum::<f64>() / rows.len() as f64,
            })
            .collect(),
    }
}

/// The trend series of a history's rows: one per machine (and serial), axis and
/// parameter, a point per inspection date.
pub fn series(records: &[Record]) -> Vec<Series> {
    let mut builder = SeriesBuilder::default();
    builder.add(records.iter().cloned());
    builder.finish()
}

/// The rows of the axis's first test at one date, in the order of their campaigns' names.
fn first_test<'a>(mut rows: Vec<&'a Row>, campaigns: &Interned) -> Vec<&'a Row> {
    let first = rows.iter().map(|r| r.test).min().unwrap_or(1);
    rows.retain(|r| r.test == first);
    let name = |r: &Row| &campaigns.texts[r.campaign as usize];
    rows.sort_by(|a, b| name(a).cmp(name(b)));
    rows
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::history::SCHEMA_VERSION;

    fn row(date: &str, serial: Option<&str>, test: u32, value: f64, limit: f64) -> Record {
        Record {
            schema_version: SCHEMA_VERSION,
            campaign: format!("plant {date}").into(),
            date: NaiveDate::parse_from_str(date, "%Y-%m-%d").unwrap(),
            machine: "VMC-07".into(),
            serial: serial.map(Into::into),
            axis: "X".into(),
            test,
            kind: "linear".into(),
            standard: "iso230-2".into(),
            verdict: "pass".into(),
            parameter: "E".into(),
            unit: "um".into(),
            value,
            limit: Some(limit),
            uncertainty: None,
            effects: "".into(),
        }
    }

    #[test]
    fn points_follow_dates_first_test_and_latest_limit() {
        let rows = [
            row("2025-11-20", Some("A"), 1, 5.0, 20.0),
            row("2024-11-20", Some("A"), 2, 9.0, 18.0),
            row("2024-11-20", Some("A"), 1, 4.0, 18.0),
            row("2026-11-20", Some("B"), 1, 2.0, 22.0),
        ];
        let series = series(&rows);
        assert_eq!(series.len(), 2, "a new serial starts a new series");
        let a = &series[0];
        assert_eq!(a.serial.as_deref(), Some("A"));
        let values: Vec<f64> = a.points.iter().map(|p| p.value).collect();
        assert_eq!(values, [4.0, 5.0]);
        assert_eq!(a.limit, Some(20.0));
        assert_eq!(series[1].points.len(), 1);
    }

    #[test]
    fn two_campaigns_on_one_date_are_averaged() {
        let mut other = row("2024-11-20", None, 1, 6.0, 18.0);
        other.campaign = "another".into();
        let rows = [row("2024-11-20", None, 1, 4.0, 18.0), other];
        assert_eq!(series(&rows)[0].points[0].value, 5.0);
    }
}
