//! Inspection trends as the templates show them: `trends.pdf` (every axis of a history,
//! the flagged ones first) and the history section of an axis report. Each series gets a
//! row of formatted numbers and the data of its small chart ([`TrendChart`]).
//!
//! The numbers are those of [`crate::trend::fit()`] (Theil–Sen slope, Sen's 95 % interval,
//! forecast against the latest limit), formatted to the reports' 0.01 µm / 0.01″.

use super::conditions::Row;
use super::{AXIS_NAME, SHORT_NAME, num, short_name};
use crate::charts::trend::TrendChart;
use crate::evaluate::catalogue::CATALOGUE;
use crate::trend::fit::unit_for_people;
use crate::trend::{Series, Trend};
use chrono::{Datelike, Days, NaiveDate};
use serde::Serialize;

/// One series in a table: the parameter, its latest value and limit, the slope and the
/// forecast, and the name of its chart (`/charts/NAME.drawing`) when it has one.
#[derive(Debug, Clone, Serialize)]
pub struct TrendRow {
    pub key: String,
    pub symbol: String,
    pub unit: String,
    pub inspections: usize,
    pub latest: String,
    pub limit: String,
    /// `+1.20 ± 0.31 /year` (± the standard error when there is one).
    pub slope: String,
    /// The forecast date, `over since DATE`, or a dash.
    pub forecast: String,
    pub flagged: bool,
    pub reason: Option<String>,
    pub chart: Option<String>,
}

/// Forecasts further than this after the latest inspection are shown as "not within": a
/// line that flat says the axis is stable, not when it will fail.
pub(crate) const FAR_YEARS: u32 = 50;

/// The axis's series in the catalogue's parameter order (A, A↑, …), unknown keys last.
pub(crate) fn in_parameter_order(pairs: &mut [(&Series, &Trend)]) {
    let rank = |key: &str| {
        CATALOGUE
            .iter()
            .position(|d| d.key.as_str() == key)
            .unwrap_or(usize::MAX)
    };
    pairs.sort_by(|a, b| {
        (rank(&a.0.parameter), &a.0.parameter).cmp(&(rank(&b.0.parameter), &b.0.parameter))
    });
}

/// The table row of one series; `chart` names its chart, if drawn.
pub fn row(series: &Series, trend: &Trend, chart: Option<String>) -> TrendRow {
    let unit = unit_for_people(&series.unit).to_string();
    let slope = match (trend.slope_per_year, trend.slope_se) {
        (Some(b), Some(se)) => format!("{} ± {} {unit}/year", signed(b), num(se)),
        (Some(b), None) => format!("{} {unit}/year", signed(b)),
        _ => "–".into(),
    };
    let far = trend
        .latest
        .checked_add_months(chrono::Months::new(12 * FAR_YEARS));
    let forecast = match (trend.over_limit_since, trend.forecast_date) {
        (Some(since), _) => format!("over since {since}"),
        (None, Some(date)) if far.is_none_or(|far| date > far) => {
            format!("not within {FAR_YEARS} years")
        }
        (None, Some(date)) => date.to_string(),
        (None, None) => "–".into(),
    };
    TrendRow {
        key: series.parameter.clone(),
        symbol: symbol(&series.parameter),
        unit,
        inspections: series.points.len(),
        latest: series.points.last().map_or("–".into(), |p| num(p.value)),
        limit: series.limit.map_or("–".into(), num),
        slope,
        forecast,
        flagged: trend.flagged,
        reason: trend.reason.clone(),
        chart,
    }
}

/// `+1.20`, `−0.35`: slopes always carry their sign.
fn signed(x: f64) -> String {
    let s = num(x);
    if s.starts_with('−') || s == "0.00" {
        s
    } else {
        format!("+{s}")
    }
}

/// The catalogue's symbol for a key (the key itself when unknown).
fn symbol(key: &str) -> String {
    CATALOGUE
        .iter()
        .find(|d| d.key.as_str() == key)
        .map_or(key.to_string(), |d| d.symbol.to_string())
}

/// 2024-07-02 → 2024.5: the date's share of its year.
pub(crate) fn decimal_year(date: NaiveDate) -> f64 {
    let days = if date.leap_year() { 366.0 } else { 365.0 };
    date.year() as f64 + date.ordinal0() as f64 / days
}

/// The chart of one series over its inspections and `horizon_years` beyond the latest.
pub fn chart(series: &Series, trend: &Trend, horizon_years: f64) -> TrendChart {
    let dates: Vec<NaiveDate> = series.points.iter().map(|p| p.date).collect();
    let (Some(&first), Some(&latest)) = (dates.iter().min(), dates.iter().max()) else {
        return TrendChart::default();
    };
    let end = latest
        .checked_add_days(Days::new((horizon_years * 365.25).round().max(0.0) as u64))
        .unwrap_or(latest);
    let year = decimal_year;
    let at = |d: NaiveDate| trend.value_at(d).map(|v| (year(d), v));
    let band = [first, latest, end]
        .into_iter()
        .filter_map(|d| trend.band_at(d).map(|(lo, hi)| (year(d), lo, hi)))
        .collect();
    // A signed parameter (B̄) heads to −limit when its line is below zero.
    let below = trend.value_at(latest).is_some_and(|v| v < 0.0);
    let limit = series.limit.map(|l| if below { -l } else { l });
    let forecast = trend
        .forecast_date
        .filter(|d| *d <= end && trend.over_limit_since.is_none())
        .map(year);
    TrendChart {
        value_label: format!(
            "{} / {}",
            symbol(&series.parameter),
            unit_for_people(&series.unit)
        ),
        points: series
            .points
            .iter()
            .map(|p| (year(p.date), p.value))
            .collect(),
        fitted: at(first).zip(at(latest)).map(|(a, b)| [a, b]),
        ahead: at(latest).zip(at(end)).map(|(a, b)| [a, b]),
        band,
        limit,
        forecast,
        years: (year(first) - 0.25, year(end)),
        flagged: trend.flagged,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trend::{Inspection, TrendOptions, fit};

    fn date(y: i32, m: u32, d: u32) -> NaiveDate {
        NaiveDate::from_ymd_opt(y, m, d).unwrap()
    }

    /// B̄ falls 0.5 µm a year from −1 µm towards its limit of 4 µm (as −4 µm).
    fn falling() -> Series {
        Series {
            machine: "M1".into(),
            serial: None,
            axis: "Y".into(),
            parameter: "B_mean".into(),
            unit: "um".into(),
            limit: Some(4.0),
            points: (0..5)
                .map(|k| Inspection {
                    date: date(2021 + k, 1, 1),
                    value: -1.0 - 0.5 * k as f64,
                })
                .collect(),
        }
    }

    #[test]
    fn decimal_years_count_the_days_of_their_year() {
        assert_eq!(decimal_year(date(2024, 1, 1)), 2024.0);
        // 2024 is a leap year: 1 July is day 182 of 366.
        assert!((decimal_year(date(2024, 7, 1)) - (2024.0 + 182.0 / 366.0)).abs() < 1e-12);
        assert!((decimal_year(date(2023, 7, 2)) - (2023.0 + 182.0 / 365.0)).abs() < 1e-12);
    }

    #[test]
    fn a_falling_signed_parameter_meets_minus_its_limit() {
        let s = falling();
        let t = fit(&s, &TrendOptions::default());
        let c = chart(&s, &t, 2.0);
        assert_eq!(c.limit, Some(-4.0));
        assert_eq!(c.points.len(), 5);
        assert_eq!(c.value_label, "B̄ / µm");
        // Latest −3.0 µm on 2025-01-01; −0.5 µm a year (Theil–Sen over days / 365.25)
        // reaches −4 µm about two years later: within the 2-year horizon, plotted.
        let forecast = c.forecast.expect("forecast within the horizon");
        assert!(forecast > 2026.9 && forecast < 2027.1, "{forecast}");
        let [_, end] = c.ahead.unwrap();
        assert!(
            (end.0 - decimal_year(date(2027, 1, 1))).abs() < 0.01,
            "{end:?}"
        );
        let r = row(&s, &t, Some("h0".into()));
        assert_eq!(r.symbol, "B̄");
        assert_eq!(r.latest, "−3.00");
        assert_eq!(r.limit, "4.00");
        assert!(r.slope.starts_with("−0.50"), "{}", r.slope);
        assert!(r.forecast.starts_with("2026-12") || r.forecast.starts_with("2027-01"));
    }

    #[test]
    fn slopes_carry_their_sign() {
        assert_eq!(signed(1.234), "+1.23");
        assert_eq!(signed(-0.5), "−0.50");
        assert_eq!(signed(-0.001), "0.00");
    }
}

/// The distinct inspection dates of these series, in order.
fn inspection_dates<'a>(series: impl Iterator<Item = &'a Series>) -> Vec<NaiveDate> {
    let mut dates: Vec<NaiveDate> = series
        .flat_map(|s| s.points.iter().map(|p| p.date))
        .collect();
    dates.sort();
    dates.dedup();
    dates
}

/// The chart drawn for a row, by name.
pub(crate) type NamedChart = (String, TrendChart);

/// An axis report's history section: the axis's series over the history's inspections.
#[derive(Debug, Serialize)]
pub struct HistorySection {
    pub first: String,
    pub last: String,
    pub inspections: usize,
    pub horizon_years: String,
    pub flagged: usize,
    pub rows: Vec<TrendRow>,
}

/// Most charts in an axis report's history section (three to a row).
pub(crate) const AXIS_REPORT_CHARTS: usize = 6;
/// What an axis report charts when no parameter has a limit or a flag.
const HEADLINE: [&str; 3] = ["E", "R", "B"];

/// The section for one axis's series (None without any): every series in the table, a
/// chart for the flagged ones and those with a limit (else E, R and B), at most
/// [`AXIS_REPORT_CHARTS`], named `history-K`.
pub fn history_section(
    pairs: &[(Series, Trend)],
    horizon_years: f64,
) -> Option<(HistorySection, Vec<NamedChart>)> {
    let mut pairs: Vec<(&Series, &Trend)> = pairs.iter().map(|(s, t)| (s, t)).collect();
    in_parameter_order(&mut pairs);
    let dates = inspection_dates(pairs.iter().map(|(s, _)| *s));
    let (first, last) = (*dates.first()?, *dates.last()?);
    let charted = charted_parameters(&pairs);
    let mut charts = Vec::new();
    let mut rows = Vec::new();
    for &(s, t) in &pairs {
        let name = charted.contains(&s.parameter.as_str()).then(|| {
            let name = format!("history-{}", charts.len());
            charts.push((name.clone(), chart(s, t, horizon_years)));
            name
        });
        rows.push(row(s, t, name));
    }
    let section = HistorySection {
        first: first.to_string(),
        last: last.to_string(),
        inspections: dates.len(),
        horizon_years: crate::units::fmt_position(horizon_years),
        flagged: rows.iter().filter(|r| r.flagged).count(),
        rows,
    };
    Some((section, charts))
}

/// The parameters an axis report charts: the flagged ones, then those with a limit, at
/// most [`AXIS_REPORT_CHARTS`]; E, R and B when none is flagged or limited.
fn charted_parameters<'a>(pairs: &[(&'a Series, &Trend)]) -> Vec<&'a str> {
    let flagged = pairs.iter().filter(|(_, t)| t.flagged);
    let limited = pairs
        .iter()
        .filter(|(s, t)| !t.flagged && s.limit.is_some());
    let mut keys: Vec<&str> = flagged
        .chain(limited)
        .map(|(s, _)| s.parameter.as_str())
        .collect();
    if keys.is_empty() {
        keys = HEADLINE.to_vec();
    }
    keys.truncate(AXIS_REPORT_CHARTS);
    keys
}

/// A flagged series in the campaign summary.
#[derive(Debug, Serialize)]
pub struct FlaggedRow {
    pub machine: String,
    pub axis: String,
    pub row: TrendRow,
}

/// The campaign summary's trends: the flagged series of the run's axes.
#[derive(Debug, Serialize)]
pub struct TrendsSummary {
    pub first: String,
    pub last: String,
    pub horizon_years: String,
    pub series: usize,
    pub flagged: Vec<FlaggedRow>,
}

/// The summary's trends from every series of the run's axes.
pub fn trends_summary<'a>(
    pairs: impl IntoIterator<Item = &'a (Series, Trend)>,
    horizon_years: f64,
) -> Option<TrendsSummary> {
    let pairs: Vec<&(Series, Trend)> = pairs.into_iter().collect();
    let dates = inspection_dates(pairs.iter().map(|(s, _)| s));
    let (first, last) = (dates.first()?, dates.last()?);
    let flagged = pairs
        .iter()
        .filter(|(_, t)| t.flagged)
        .map(|(s, t)| FlaggedRow {
            machine: s.machine.clone(),
            axis: s.axis.clone(),
            row: row(s, t, None),
        })
        .collect();
    Some(TrendsSummary {
        first: first.to_string(),
        last: last.to_string(),
        horizon_years: crate::units::fmt_position(horizon_years),
        series: pairs.len(),
        flagged,
    })
}

/// `trends.pdf`: the axes of a history, flagged first, each with a chart per parameter.
#[derive(Debug, Serialize)]
pub struct TrendsDocument {
    pub title: String,
    pub history: String,
    pub first: String,
    pub last: String,
    pub inspections: usize,
    pub horizon_years: String,
    pub series: usize,
    pub(crate) flagged_series: usize,
    pub(crate) flagged_axes: usize,
    pub axes: Vec<AxisTrendRows>,
    /// Axes left out of the document (their rows are in `trends.csv`), and how many of
    /// them are flagged (none unless more than [`TRENDS_PDF_AXES`] are).
    pub(crate) omitted_axes: usize,
    pub(crate) omitted_flagged_axes: usize,
    pub table: String,
}

/// One axis in `trends.pdf`: its names whole, and shortened for its heading (a
/// 10 000-character machine name filled the page and ran over the footer) with the long
/// ones printed whole once below its table (`full_names`).
#[derive(Debug, Serialize)]
pub struct AxisTrendRows {
    pub machine: String,
    pub serial: Option<String>,
    pub axis: String,
    pub(crate) machine_short: String,
    pub(crate) serial_short: Option<String>,
    pub(crate) axis_short: String,
    full_names: Vec<Row>,
    pub flagged: bool,
    pub rows: Vec<TrendRow>,
}

impl AxisTrendRows {
    fn new(machine: &str, serial: Option<&str>, axis: &str, rows: Vec<TrendRow>) -> AxisTrendRows {
        let long = |name: &str, max: usize| (name.chars().count() > max).then(|| name.to_string());
        AxisTrendRows {
            machine_short: short_name(machine, SHORT_NAME),
            serial_short: serial.map(|s| short_name(s, AXIS_NAME)),
            axis_short: short_name(axis, AXIS_NAME),
            full_names: Row::present([
                ("Machine, in full", long(machine, SHORT_NAME)),
                ("Serial, in full", serial.and_then(|s| long(s, AXIS_NAME))),
                ("Axis, in full", long(axis, AXIS_NAME)),
            ]),
            machine: machine.to_string(),
            serial: serial.map(str::to_string),
            axis: axis.to_string(),
            flagged: rows.iter().any(|r| r.flagged),
            rows,
        }
    }
}

/// Most axes `trends.pdf` charts (one page each at most); the rest are counted and are in
/// `trends.csv`. The flagged axes come first, so they are left out last.
pub(crate) const TRENDS_PDF_AXES: usize = 200;

/// The document for `pairs` (series with their trends, any order): axes flagged first,
/// then by machine, serial and axis; charts named `t-K`.
pub fn trends_document(
    history: &str,
    pairs: &[(&Series, &Trend)],
    horizon_years: f64,
    table: &str,
) -> (TrendsDocument, Vec<NamedChart>) {
    type Key<'k> = (&'k str, Option<&'k str>, &'k str);
    let mut by_axis: std::collections::BTreeMap<Key, Vec<(&Series, &Trend)>> = Default::default();
    for &(s, t) in pairs {
        let key = (s.machine.as_str(), s.serial.as_deref(), s.axis.as_str());
        by_axis.entry(key).or_default().push((s, t));
    }
    let mut axes: Vec<_> = by_axis.into_iter().collect();
    axes.sort_by_key(|(_, v)| !v.iter().any(|(_, t)| t.flagged));
    let dates = inspection_dates(pairs.iter().map(|(s, _)| *s));
    let flagged_axes = axes
        .iter()
        .filter(|(_, v)| v.iter().any(|(_, t)| t.flagged))
        .count();
    let mut charts = Vec::new();
    let mut views = Vec::new();
    for ((machine, serial, axis), mut series) in axes.iter().take(TRENDS_PDF_AXES).cloned() {
        in_parameter_order(&mut series);
        let rows = series
            .iter()
            .map(|(s, t)| {
                let name = format!("t-{}", charts.len());
                charts.push((name.clone(), chart(s, t, horizon_years)));
                row(s, t, Some(name))
            })
            .collect::<Vec<_>>();
        views.push(AxisTrendRows::new(machine, serial, axis, rows));
    }
    let document = TrendsDocument {
        title: "Inspection trends".into(),
        history: history.to_string(),
        first: dates.first().map_or(String::new(), NaiveDate::to_string),
        last: dates.last().map_or(String::new(), NaiveDate::to_string),
        inspections: dates.len(),
        horizon_years: crate::units::fmt_position(horizon_years),
        series: pairs.len(),
        flagged_series: pairs.iter().filter(|(_, t)| t.flagged).count(),
        flagged_axes,
        omitted_axes: axes.len().saturating_sub(TRENDS_PDF_AXES),
        omitted_flagged_axes: flagged_axes.saturating_sub(TRENDS_PDF_AXES),
        axes: views,
        table: table.to_string(),
    };
    (document, charts)
}
