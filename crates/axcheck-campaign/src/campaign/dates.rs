//! Dates of a campaign (`campaign.date`, an instrument's calibration, a certificate's
//! issue): written YYYY-MM-DD and a day of the calendar.

use crate::yaml::describe;
use serde::de::Error as _;
use serde::{Deserialize, Deserializer};
use serde_norway::Value;

/// A date written YYYY-MM-DD (text, as YAML reads `2026-11-20`) that is a day of the
/// calendar: `2026-02-30` is refused here, not by the history after the outputs.
pub(crate) fn iso_date<'de, D: Deserializer<'de>>(
    deserializer: D,
) -> Result<Option<String>, D::Error> {
    let value = Value::deserialize(deserializer)?;
    match value.as_str() {
        _ if value.is_null() => Ok(None),
        Some(date) if is_iso_date(date) => match calendar_day(date) {
            Ok(()) => Ok(Some(date.to_string())),
            Err(why) => Err(D::Error::custom(why)),
        },
        _ => Err(D::Error::custom(format!(
            "expected a date YYYY-MM-DD, got {}",
            describe(&value)
        ))),
    }
}

pub(crate) fn is_iso_date(s: &str) -> bool {
    let b = s.as_bytes();
    b.len() == 10
        && b[4] == b'-'
        && b[7] == b'-'
        && b.iter()
            .enumerate()
            .all(|(k, c)| k == 4 || k == 7 || c.is_ascii_digit())
        && matches!(s[5..7].parse::<u32>(), Ok(1..=12))
        && matches!(s[8..10].parse::<u32>(), Ok(1..=31))
}

/// `Err` naming the month's last day when the day of `date` (YYYY-MM-DD, month 1–12) is
/// past it.
fn calendar_day(date: &str) -> Result<(), String> {
    use chrono::{Datelike, NaiveDate};
    if NaiveDate::parse_from_str(date, "%Y-%m-%d").is_ok() {
        return Ok(());
    }
    let first = NaiveDate::parse_from_str(&format!("{}-01", &date[..7]), "%Y-%m-%d");
    let last = first.ok().and_then(|f| {
        let next = f.checked_add_months(chrono::Months::new(1))?;
        next.pred_opt()
    });
    Err(match last {
        Some(last) => format!(
            "`{date}` is not a day of the calendar: {} has {} days; write the test's real date",
            last.format("%B %Y"),
            last.day()
        ),
        None => format!("`{date}` is not a day of the calendar; write the test's real date"),
    })
}
