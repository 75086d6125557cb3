//! History rows regrouped as trend series: one per machine, serial, axis and parameter.

use super::Record;
use crate::trend::{Point, Series};
use chrono::NaiveDate;
use std::collections::BTreeMap;

/// Machine id, serial, axis, parameter: a series (a new serial number starts a new one).
type Key<'a> = (&'a str, Option<&'a str>, &'a str, &'a str);

/// One series per (machine, serial, axis, parameter), sorted by that key (no serial first),
/// points in date order. One point per date: when an axis had several tests that day (e.g.
/// a full-travel test beside the working-range test), test 1, the axis's first, counts,
/// as the others follow other plans; when two campaigns measured that test on the same
/// date, the point is their mean. The limit is the latest inspection's; the unit too.
/// Values that are not finite are left out.
pub fn series(records: &[Record]) -> Vec<Series> {
    let mut groups: BTreeMap<Key, BTreeMap<NaiveDate, Vec<&Record>>> = BTreeMap::new();
    for r in records.iter().filter(|r| r.value.is_finite()) {
        let key = (&*r.machine, r.serial.as_deref(), &*r.axis, &*r.parameter);
        groups
            .entry(key)
            .or_default()
            .entry(r.date)
            .or_default()
            .push(r);
    }
    groups
        .into_iter()
        .map(|((machine, serial, axis, parameter), dates)| {
            let inspections: Vec<(NaiveDate, Vec<&Record>)> = dates
                .into_iter()
                .map(|(date, rows)| (date, first_test(rows)))
                .collect();
            let latest = inspections.last().map(|(_, rows)| rows.as_slice());
            Series {
                machine: machine.to_string(),
                serial: serial.map(str::to_string),
                axis: axis.to_string(),
                parameter: parameter.to_string(),
                unit: latest
                    .and_then(|rows| rows.first())
                    .map(|r| r.unit.to_string())
                    .unwrap_or_default(),
                limit: latest.and_then(|rows| rows.iter().find_map(|r| r.limit)),
                points: inspections
                    .iter()
                    .map(|(date, rows)| Point {
                        date: *date,
                        value: rows.iter().map(|r| r.value).sum::<f64>() / rows.len() as f64,
                    })
                    .collect(),
            }
        })
        .collect()
}

/// The rows of the lowest test number, in campaign-name order (deterministic limits).
fn first_test(mut rows: Vec<&Record>) -> Vec<&Record> {
    let first = rows.iter().map(|r| r.test).min().unwrap_or(1);
    rows.retain(|r| r.test == first);
    rows.sort_by(|a, b| a.campaign.cmp(&b.campaign));
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
