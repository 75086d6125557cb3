//! The trends as `trend --json` and as CSV: one entry (row) per series, in the order given.

use super::{Inspection, Series, Trend};
use crate::evaluate::catalogue::CATALOGUE;
use chrono::NaiveDate;
use serde::Serialize;

/// One series and its trend, with the keys of issue 16 (plus `serial` and `symbol`).
#[derive(Debug, Serialize)]
pub(crate) struct AxisTrend<'a> {
    pub machine: &'a str,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub serial: Option<&'a str>,
    pub axis: &'a str,
    pub parameter: &'a str,
    /// Symbol for people (`B̄`), when the parameter is in the catalogue.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub symbol: Option<&'static str>,
    pub unit: &'a str,
    pub limit: Option<f64>,
    pub points: &'a [Inspection],
    pub slope_per_year: Option<f64>,
    pub slope_se: Option<f64>,
    pub forecast_date: Option<NaiveDate>,
    pub flagged: bool,
    pub reason: Option<&'a str>,
}

impl<'a> AxisTrend<'a> {
    pub fn new(series: &'a Series, trend: &'a Trend) -> AxisTrend<'a> {
        AxisTrend {
            machine: &series.machine,
            serial: series.serial.as_deref(),
            axis: &series.axis,
            parameter: &series.parameter,
            symbol: symbol(&series.parameter),
            unit: &series.unit,
            limit: series.limit,
            points: &series.points,
            slope_per_year: trend.slope_per_year,
            slope_se: trend.slope_se,
            forecast_date: trend.forecast_date,
            flagged: trend.flagged,
            reason: trend.reason.as_deref(),
        }
    }
}

/// The catalogue's symbol for a parameter key.
fn symbol(key: &str) -> Option<&'static str> {
    CATALOGUE
        .iter()
        .find(|d| d.key.as_str() == key)
        .map(|d| d.symbol)
}

/// The JSON document of `trend --json`, pretty-printed: `{"axes": [...]}`.
pub fn json<'a>(trends: impl IntoIterator<Item = (&'a Series, &'a Trend)>) -> String {
    let mut out = Vec::new();
    write_json(trends, &mut out).expect("a trend view serialises");
    String::from_utf8(out).expect("serde_json writes UTF-8")
}

/// [`json`] written to `out` as it is made: a history of 10 000 axes gives 130 MB of JSON,
/// which is never held whole.
pub fn write_json<'a>(
    trends: impl IntoIterator<Item = (&'a Series, &'a Trend)>,
    out: impl std::io::Write,
) -> serde_json::Result<()> {
    /// The axes, each made when it is written.
    struct Axes<I>(std::cell::RefCell<Option<I>>);
    impl<'a, I: Iterator<Item = (&'a Series, &'a Trend)>> Serialize for Axes<I> {
        fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            let items = self.0.borrow_mut().take().into_iter().flatten();
            s.collect_seq(items.map(|(series, trend)| AxisTrend::new(series, trend)))
        }
    }
    #[derive(Serialize)]
    struct Document<I: Serialize> {
        axes: I,
    }
    let axes = Axes(std::cell::RefCell::new(Some(trends.into_iter())));
    serde_json::to_writer_pretty(out, &Document { axes })
}

/// The CSV columns, in order.
pub(crate) const CSV_COLUMNS: [&str; 16] = [
    "machine",
    "serial",
    "axis",
    "parameter",
    "unit",
    "limit",
    "points",
    "first_date",
    "first_value",
    "last_date",
    "last_value",
    "slope_per_year",
    "slope_se",
    "forecast_date",
    "flagged",
    "reason",
];

/// The trends as CSV (RFC 4180 quoting, numbers in shortest round-trip form, empty
/// cells for absent values): one row per series, its points as count, first and last.
pub fn csv<'a>(trends: impl IntoIterator<Item = (&'a Series, &'a Trend)>) -> String {
    let mut out = CSV_COLUMNS.join(",");
    out.push('\n');
    for (series, trend) in trends {
        out.push_str(&csv_row(series, trend).join(","));
        out.push('\n');
    }
    out
}

fn csv_row(series: &Series, trend: &Trend) -> Vec<String> {
    let number = |x: Option<f64>| {
        x.filter(|x| x.is_finite())
            .map_or(String::new(), |x| x.to_string())
    };
    let date = |d: Option<NaiveDate>| d.map_or(String::new(), |d| d.to_string());
    let first = series.points.iter().min_by_key(|p| p.date);
    let last = series.points.iter().max_by_key(|p| p.date);
    vec![
        quote(&series.machine),
        quote(series.serial.as_deref().unwrap_or("")),
        quote(&series.axis),
        quote(&series.parameter),
        quote(&series.unit),
        number(series.limit),
        series.points.len().to_string(),
        date(first.map(|p| p.date)),
        number(first.map(|p| p.value)),
        date(last.map(|p| p.date)),
        number(last.map(|p| p.value)),
        number(trend.slope_per_year),
        number(trend.slope_se),
        date(trend.forecast_date),
        trend.flagged.to_string(),
        quote(trend.reason.as_deref().unwrap_or("")),
    ]
}

/// A text field: RFC 4180 quoting, neutralised against formulas and hidden characters.
fn quote(s: &str) -> String {
    crate::safe_text::csv_text(s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trend::{TrendOptions, fit};

    fn example() -> Series {
        let date = |y| NaiveDate::from_ymd_opt(y, 1, 1).unwrap();
        Series {
            machine: "M1".into(),
            serial: Some("S-7".into()),
            axis: "X".into(),
            parameter: "B_mean".into(),
            unit: "um".into(),
            limit: Some(2.0),
            points: vec![
                Inspection {
                    date: date(2023),
                    value: 1.0,
                },
                Inspection {
                    date: date(2024),
                    value: 2.5,
                },
            ],
        }
    }

    #[test]
    fn json_has_the_issues_keys() {
        let series = example();
        let trend = fit(&series, &TrendOptions::default());
        let value: serde_json::Value = serde_json::from_str(&json([(&series, &trend)])).unwrap();
        let axis = &value["axes"][0];
        let keys: Vec<&str> = axis
            .as_object()
            .unwrap()
            .keys()
            .map(String::as_str)
            .collect();
        assert_eq!(
            keys,
            [
                "machine",
                "serial",
                "axis",
                "parameter",
                "symbol",
                "unit",
                "limit",
                "points",
                "slope_per_year",
                "slope_se",
                "forecast_date",
                "flagged",
                "reason"
            ]
        );
        assert_eq!(axis["symbol"], "B̄");
        assert_eq!(axis["points"][1]["date"], "2024-01-01");
        assert_eq!(axis["slope_se"], serde_json::Value::Null);
        assert_eq!(axis["forecast_date"], "2024-01-01");
        assert_eq!(axis["reason"], "over its limit 2.0 µm since 2024-01-01");
    }

    #[test]
    fn csv_has_one_row_per_series() {
        let series = example();
        let trend = fit(&series, &TrendOptions::default());
        let text = csv([(&series, &trend)]);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], CSV_COLUMNS.join(","));
        assert_eq!(
            lines[1],
            format!(
                "M1,S-7,X,B_mean,um,2,2,2023-01-01,1,2024-01-01,2.5,{},,2024-01-01,true,\
                 over its limit 2.0 µm since 2024-01-01",
                1.5 * 365.25 / 365.0
            )
        );
    }
}
