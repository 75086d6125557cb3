//! The table's rows as the page carries them: [`overview::rows`] by column, each column as
//! compact as the page needs it (summary.md, .csv and .xlsx keep their own forms).
//!
//! - A column of repeated strings (machines, axes, verdicts, lists of rule ids …) is a
//!   [`Dict`]: its distinct values in order of first use and, per row, an index.
//! - A value shown with 2 decimals is its text as a whole number of hundredths (`15.99`
//!   as 1599; page.js writes the text back); the page sorts by it, as shown. A text that
//!   is not a number of hundredths (not finite, too large) stays a string.
//! - A column that most rows leave empty (the compensation, an error) is [`Sparse`]: the
//!   rows that have a value and their values.
//!
//! A row's id (`MACHINE|AXIS|TEST`) is made by the page from its machine, axis and test.

use super::super::overview::{self, HEADLINES};
use serde::Serialize;
use std::collections::HashMap;

/// Distinct values and an index per row.
#[derive(Debug, Serialize)]
pub(crate) struct Dict<T> {
    values: Vec<T>,
    index: Vec<usize>,
}

impl<T: Serialize> Dict<T> {
    fn of(items: impl Iterator<Item = T>) -> Dict<T> {
        let mut values = Vec::new();
        // Keyed by the value's JSON: the values are strings, lists of them and nulls.
        let mut seen: HashMap<String, usize> = HashMap::new();
        let index = items
            .map(|item| {
                let key = serde_json::to_string(&item).unwrap_or_default();
                *seen.entry(key).or_insert_with(|| {
                    values.push(item);
                    values.len() - 1
                })
            })
            .collect();
        Dict { values, index }
    }
}

/// The rows that have a value, and their values.
#[derive(Debug, Serialize)]
pub(crate) struct Sparse<T> {
    rows: Vec<usize>,
    values: Vec<T>,
}

impl<T> Sparse<T> {
    fn of(items: impl Iterator<Item = Option<T>>) -> Sparse<T> {
        let (rows, values) = items
            .enumerate()
            .filter_map(|(k, v)| v.map(|v| (k, v)))
            .unzip();
        Sparse { rows, values }
    }
}

/// A text of 2 decimals as its hundredths, or the text when it is not one.
#[derive(Debug, Serialize)]
#[serde(untagged)]
pub(crate) enum Hundredths {
    Number(i64),
    Text(String),
}

/// `15.99` → 1599, `-0.40` → -40; 2^53 and more (which JavaScript's numbers do not hold
/// exactly) and anything else as text.
pub(crate) fn hundredths(text: &str) -> Hundredths {
    let number = (text.split_once('.'))
        .filter(|&(int, frac)| {
            let digits = int.strip_prefix('-').unwrap_or(int);
            frac.len() == 2
                && !digits.is_empty()
                && (digits == "0" || !digits.starts_with('0'))
                && digits
                    .bytes()
                    .chain(frac.bytes())
                    .all(|b| b.is_ascii_digit())
                && !(int.starts_with('-') && digits == "0" && frac == "00")
        })
        .and_then(|(int, frac)| format!("{int}{frac}").parse::<i64>().ok())
        .filter(|n| n.unsigned_abs() < 1 << 53);
    number.map_or_else(|| Hundredths::Text(text.to_string()), Hundredths::Number)
}

/// A headline column: the parameter's symbol, value and U of each row (null without).
#[derive(Debug, Serialize)]
pub(crate) struct HeadlineColumn {
    symbol: Dict<Option<&'static str>>,
    value: Vec<Option<Hundredths>>,
    #[serde(rename = "U")]
    u: Vec<Option<Hundredths>>,
}

/// The parameter closest to its limit: its symbol, |value| / limit and the rows where
/// that is over 1 (shown in red).
#[derive(Debug, Serialize)]
pub(crate) struct WorstColumn {
    symbol: Dict<Option<String>>,
    ratio: Vec<Option<Hundredths>>,
    over: Vec<usize>,
}

/// The rows by column (see the module docs).
#[derive(Debug, Serialize)]
pub(crate) struct Columns<'a> {
    machine: Dict<&'a str>,
    axis: Dict<String>,
    test: Vec<usize>,
    tests: Vec<usize>,
    kind: Dict<Option<crate::units::AxisKind>>,
    standard: Dict<Option<&'static str>>,
    /// `976.666 mm`: the page sorts by its number.
    travel: Dict<Option<String>>,
    n: Vec<Option<usize>>,
    unit: Dict<Option<&'static str>>,
    values: Vec<(&'static str, HeadlineColumn)>,
    worst: WorstColumn,
    verdict: Dict<crate::judge::Verdict>,
    decision_rule: Dict<Option<&'static str>>,
    rules: Dict<Vec<&'static str>>,
    warnings: Dict<Vec<&'static str>>,
    diagnosis: Dict<Option<Vec<&'static str>>>,
    /// E measured and as predicted with the new table.
    compensation: Sparse<(Hundredths, Hundredths)>,
    trend: Dict<Option<Vec<String>>>,
    error: Sparse<&'a str>,
}

pub(crate) fn columns<'a>(rows: &'a [overview::Row<'a>]) -> Columns<'a> {
    let values = (HEADLINES.iter())
        .map(|&(key, _)| {
            let of = |r: &'a overview::Row<'a>| r.values.get(key);
            let column = HeadlineColumn {
                symbol: Dict::of(rows.iter().map(|r| of(r).map(|h| h.symbol))),
                value: (rows.iter())
                    .map(|r| of(r).map(|h| hundredths(&h.text)))
                    .collect(),
                u: (rows.iter())
                    .map(|r| of(r).and_then(|h| h.u_text.as_deref()).map(hundredths))
                    .collect(),
            };
            (key, column)
        })
        .collect();
    let worst = WorstColumn {
        symbol: Dict::of(
            rows.iter()
                .map(|r| r.worst.as_ref().map(|w| w.symbol.clone())),
        ),
        ratio: (rows.iter())
            .map(|r| r.worst.as_ref().map(|w| hundredths(&worst_ratio_text(w))))
            .collect(),
        over: (rows.iter().enumerate())
            .filter(|(_, r)| r.worst.as_ref().is_some_and(|w| w.ratio > 1.0))
            .map(|(k, _)| k)
            .collect(),
    };
    Columns {
        machine: Dict::of(rows.iter().map(|r| r.machine)),
        axis: Dict::of(rows.iter().map(|r| r.axis.clone())),
        test: rows.iter().map(|r| r.test).collect(),
        tests: rows.iter().map(|r| r.tests).collect(),
        kind: Dict::of(rows.iter().map(|r| r.kind)),
        standard: Dict::of(rows.iter().map(|r| r.standard)),
        travel: Dict::of(rows.iter().map(|r| r.travel_text.clone())),
        n: rows.iter().map(|r| r.n).collect(),
        unit: Dict::of(rows.iter().map(|r| r.unit)),
        values,
        worst,
        verdict: Dict::of(rows.iter().map(|r| r.verdict)),
        decision_rule: Dict::of(rows.iter().map(|r| r.decision_rule)),
        rules: Dict::of(rows.iter().map(|r| r.rules.clone())),
        warnings: Dict::of(rows.iter().map(|r| r.warnings.clone())),
        diagnosis: Dict::of(rows.iter().map(|r| r.diagnosis.clone())),
        compensation: Sparse::of(rows.iter().map(|r| {
            (r.compensation.as_ref()).and_then(|c| {
                let (measured, predicted) = c.text.split_once(" → ")?;
                Some((hundredths(measured), hundredths(predicted)))
            })
        })),
        trend: Dict::of(rows.iter().map(|r| r.trend.clone())),
        error: Sparse::of(rows.iter().map(|r| r.error)),
    }
}

/// The ratio's text in `R 0.73`: what follows the symbol.
fn worst_ratio_text(w: &overview::Worst) -> String {
    let text = w.text.strip_prefix(&w.symbol).unwrap_or(&w.text);
    text.trim_start().to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hundredths_are_the_texts_number_or_the_text() {
        let number = |t: &str| match hundredths(t) {
            Hundredths::Number(n) => Some(n),
            Hundredths::Text(_) => None,
        };
        assert_eq!(number("15.99"), Some(1599));
        assert_eq!(number("0.00"), Some(0));
        assert_eq!(number("0.07"), Some(7));
        assert_eq!(number("-0.40"), Some(-40));
        assert_eq!(number("-12.30"), Some(-1230));
        assert_eq!(number("90071992547409.91"), Some((1 << 53) - 1));
        assert_eq!(number("90071992547409.92"), None);
        for text in [
            "NaN", "inf", "-0.00", "1.5", "01.00", "1.000", ".50", "-.50", "1e3.00",
        ] {
            assert_eq!(number(text), None, "{text}");
        }
    }

    #[test]
    fn a_dict_keeps_first_use_order() {
        let d = Dict::of(["b", "a", "b", "c", "a"].into_iter());
        assert_eq!(d.values, ["b", "a", "c"]);
        assert_eq!(d.index, [0, 1, 0, 2, 1]);
        let s = Sparse::of([None, Some(3), None, Some(4)].into_iter());
        assert_eq!((s.rows, s.values), (vec![1, 3], vec![3, 4]));
    }
}
