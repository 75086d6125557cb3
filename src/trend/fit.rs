//! The trend of one series: a robust line through its inspections, the date it reaches
//! its limit, and whether people should look at it.

use super::sen;
use super::{Point, Series};
use crate::evaluate::catalogue::{CATALOGUE, Quantity};
use chrono::{Days, NaiveDate};

/// Days per year: dates become years as days / 365.25.
pub const DAYS_PER_YEAR: f64 = 365.25;
/// The interval behind `slope_se` and the significance test: Sen's two-sided 95 %.
pub const ALPHA: f64 = 0.05;
/// The normal quantile z₀.₉₇₅ of that level: slope_se = half-width / z.
pub const Z: f64 = 1.959_963_984_540_054;
/// The share of the limit a significant worsening must surely add within the horizon to
/// raise a flag (see `worsening`).
pub const MATERIAL_SHARE: f64 = 0.10;

/// How far ahead a forecast raises a flag.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Years after the latest inspection (default 2). "Now" is the date of the latest
    /// inspection, not the clock: the trend of a history does not change with the day it
    /// is read.
    pub horizon_years: f64,
}

impl Default for Options {
    fn default() -> Self {
        Options { horizon_years: 2.0 }
    }
}

/// A series' trend. Time t is in years from `origin` (days / 365.25).
#[derive(Debug, Clone, PartialEq)]
pub struct Trend {
    /// The earliest inspection: t = 0.
    pub origin: NaiveDate,
    /// The latest inspection: "now" for the horizon.
    pub latest: NaiveDate,
    /// Theil–Sen slope, unit per year; None with fewer than two distinct dates.
    pub slope_per_year: Option<f64>,
    /// Standard error of the slope: half of Sen's 95 % interval / z₀.₉₇₅; None when the
    /// series is too short for that interval (fewer than 5 distinct dates).
    pub slope_se: Option<f64>,
    /// Sen's 95 % interval of the slope.
    pub slope_interval: Option<(f64, f64)>,
    /// The line's value at `origin`: median of y − slope·t.
    pub intercept: Option<f64>,
    /// The line at each point of the series, in its order (empty without a slope).
    pub fitted: Vec<f64>,
    /// When the line reaches the limit (or, over the limit, since when it is over it).
    pub forecast_date: Option<NaiveDate>,
    /// The earliest of the latest run of inspections over the limit.
    pub over_limit_since: Option<NaiveDate>,
    pub flagged: bool,
    /// Why it is flagged, a sentence for people.
    pub reason: Option<String>,
    /// Median t: the band's pivot.
    pivot: f64,
}

impl Trend {
    /// Years from the origin to `date`.
    pub fn years(&self, date: NaiveDate) -> f64 {
        (date - self.origin).num_days() as f64 / DAYS_PER_YEAR
    }

    /// The fitted line at `date`.
    pub fn value_at(&self, date: NaiveDate) -> Option<f64> {
        Some(self.intercept? + self.slope_per_year? * self.years(date))
    }

    /// The band for charts at `date`: the lines of the interval's two slopes through the
    /// fitted point at the median date, so it shows the slope's uncertainty and widens
    /// towards the forecast. None without an interval.
    pub fn band_at(&self, date: NaiveDate) -> Option<(f64, f64)> {
        let (lo, hi) = self.slope_interval?;
        let pivot_value = self.intercept? + self.slope_per_year? * self.pivot;
        let dt = self.years(date) - self.pivot;
        let (a, b) = (pivot_value + lo * dt, pivot_value + hi * dt);
        Some((a.min(b), a.max(b)))
    }
}

/// Fits `series`: Theil–Sen slope and Sen's interval ([`sen`]), the forecast against the
/// series' limit, and the flag. Values are compared with the limit by magnitude (|B̄| for
/// signed parameters), so a series heads towards its limit when its slope has the sign
/// of its fitted value at the latest inspection.
pub fn fit(series: &Series, options: &Options) -> Trend {
    let mut points: Vec<&Point> = series
        .points
        .iter()
        .filter(|p| p.value.is_finite())
        .collect();
    points.sort_by_key(|p| p.date);
    let origin = points.first().map_or(NaiveDate::MIN, |p| p.date);
    let latest = points.last().map_or(NaiveDate::MIN, |p| p.date);
    let years = |d: NaiveDate| (d - origin).num_days() as f64 / DAYS_PER_YEAR;
    let xy: Vec<(f64, f64)> = points.iter().map(|p| (years(p.date), p.value)).collect();
    let slope = sen::median_sorted(&sen::pairwise_slopes(&xy));
    let intercept =
        slope.and_then(|b| sen::median(&xy.iter().map(|(t, y)| y - b * t).collect::<Vec<_>>()));
    let interval = slope.and(sen::interval(&xy, ALPHA, Z));
    let mut trend = Trend {
        origin,
        latest,
        slope_per_year: slope,
        slope_se: interval.map(|(lo, hi)| (hi - lo) / (2.0 * Z)),
        slope_interval: interval,
        intercept,
        fitted: Vec::new(),
        forecast_date: None,
        over_limit_since: None,
        flagged: false,
        reason: None,
        pivot: sen::median(&xy.iter().map(|p| p.0).collect::<Vec<_>>()).unwrap_or(0.0),
    };
    trend.fitted = match (slope, intercept) {
        (Some(_), Some(_)) => series
            .points
            .iter()
            .filter_map(|p| trend.value_at(p.date))
            .collect(),
        _ => Vec::new(),
    };
    let mut reasons = Vec::new();
    if let Some(limit) = series.limit {
        judge_limit(&mut trend, series, &points, limit, options, &mut reasons);
    }
    if let Some(sentence) = worsening(&trend, series, &points, options) {
        reasons.push(sentence);
    }
    trend.flagged = !reasons.is_empty();
    trend.reason = (!reasons.is_empty()).then(|| reasons.join("; "));
    trend
}

/// +1 when the parameter's magnitude grows with the value, −1 when it grows as the value
/// falls (a negative signed mean): the sign of the line at the latest inspection, else of
/// the latest value, else of the slope.
fn worse_direction(trend: &Trend, points: &[&Point]) -> f64 {
    let level = trend
        .value_at(trend.latest)
        .or_else(|| points.last().map(|p| p.value))
        .unwrap_or(0.0);
    let level = if level == 0.0 {
        trend.slope_per_year.unwrap_or(0.0)
    } else {
        level
    };
    if level < 0.0 { -1.0 } else { 1.0 }
}

/// Over the limit now, or the date the line reaches it: sets the forecast and the
/// over-limit date, and adds the reasons for a flag.
fn judge_limit(
    trend: &mut Trend,
    series: &Series,
    points: &[&Point],
    limit: f64,
    options: &Options,
    reasons: &mut Vec<String>,
) {
    let unit = unit_for_people(&series.unit);
    let over = |p: &&Point| p.value.abs() > limit;
    if points.last().is_some_and(over) {
        let run = points.iter().rev().take_while(|p| over(p)).count();
        let since = points[points.len() - run].date;
        trend.over_limit_since = Some(since);
        trend.forecast_date = Some(since);
        reasons.push(format!("over its limit {limit:.1} {unit} since {since}"));
        return;
    }
    let (Some(slope), Some(now)) = (trend.slope_per_year, trend.value_at(trend.latest)) else {
        return;
    };
    let sign = worse_direction(trend, points);
    if slope * sign <= 0.0 {
        return;
    }
    if now * sign >= limit {
        trend.forecast_date = Some(trend.latest);
        reasons.push(format!(
            "its trend line is past its limit {limit:.1} {unit} at the latest inspection ({})",
            trend.latest
        ));
        return;
    }
    let Some(intercept) = trend.intercept else {
        return;
    };
    let t_cross = (sign * limit - intercept) / slope;
    let days = (t_cross * DAYS_PER_YEAR).round();
    let Some(date) = (days.is_finite() && days >= 0.0 && days < 1e7)
        .then(|| trend.origin.checked_add_days(Days::new(days as u64)))
        .flatten()
    else {
        return;
    };
    trend.forecast_date = Some(date);
    let ahead = (date - trend.latest).num_days() as f64;
    if ahead <= options.horizon_years * DAYS_PER_YEAR {
        let h = options.horizon_years;
        let years = if h == 1.0 { "year" } else { "years" };
        reasons.push(format!(
            "reaches its limit {limit:.1} {unit} around {} (within {h} {years})",
            date.format("%Y-%m")
        ));
    }
}

/// A sentence when the magnitude grows significantly and materially: the 95 % interval
/// of the slope lies wholly on the worsening side (a one-sided test at 2.5 %), and at
/// the interval's nearer end the series would still add [`MATERIAL_SHARE`] of its limit
/// (of its fitted magnitude at the latest inspection when it has no limit) within the
/// horizon. The test alone would flag 2.5 % of stable series, each a few hundredths of a
/// µm per year (3 of 228 in `tests/it/trend.rs`); the materiality keeps the flag for
/// changes that matter. Not for parameters that only locate a band (X̄max, Ā …), whose
/// growth is not a deterioration.
fn worsening(
    trend: &Trend,
    series: &Series,
    points: &[&Point],
    options: &Options,
) -> Option<String> {
    let (lo, hi) = trend.slope_interval?;
    let level_only = CATALOGUE
        .iter()
        .any(|d| d.key == series.parameter && d.quantity == Quantity::Level);
    let sign = worse_direction(trend, points);
    let surely = if sign > 0.0 { lo } else { -hi };
    let reference = series
        .limit
        .or_else(|| trend.value_at(trend.latest).map(f64::abs))?;
    let material = surely * options.horizon_years >= MATERIAL_SHARE * reference;
    if level_only || surely <= 0.0 || !material {
        return None;
    }
    Some(format!(
        "worsening significantly: {:+.2} ± {:.2} {} per year",
        trend.slope_per_year?,
        trend.slope_se?,
        unit_for_people(&series.unit)
    ))
}

/// `um` → `µm`; other units as they are.
pub fn unit_for_people(unit: &str) -> &str {
    match unit {
        "um" => "µm",
        other => other,
    }
}
