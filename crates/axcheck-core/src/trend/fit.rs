//! The trend of one series: a robust line through its inspections, the date it reaches
//! its limit, and whether people should look at it.

use super::sen;
use super::{Inspection, Series};
use crate::evaluate::catalogue::{CATALOGUE, Quantity};
#[cfg(test)]
use chrono::Datelike;
use chrono::{Days, NaiveDate};

/// Days per year: dates become years as days / 365.25.
pub(crate) const DAYS_PER_YEAR: f64 = 365.25;
/// The interval behind `slope_se` and the significance test: Sen's two-sided 95 %.
pub const ALPHA: f64 = 0.05;
/// The normal quantile z₀.₉₇₅ of that level: slope_se = half-width / z.
pub const Z: f64 = 1.959_963_984_540_054;
/// The share of the limit a significant worsening must surely add within the horizon to
/// raise a flag (see `worsening`).
pub(crate) const MATERIAL_SHARE: f64 = 0.10;

/// How far ahead a forecast raises a flag.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrendOptions {
    /// Years after the latest inspection (default 2). "Now" is the date of the latest
    /// inspection, not the clock: the trend of a history does not change with the day it
    /// is read.
    pub horizon_years: f64,
}

impl Default for TrendOptions {
    fn default() -> Self {
        TrendOptions { horizon_years: 2.0 }
    }
}

impl TrendOptions {
    /// A horizon of `years`, which must be a number of years > 0.
    pub fn with_horizon(years: f64) -> Result<TrendOptions, HorizonError> {
        match years > 0.0 && years.is_finite() {
            true => Ok(TrendOptions {
                horizon_years: years,
            }),
            false => Err(HorizonError { years }),
        }
    }
}

/// A trend horizon that is no number of years > 0.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error("expected a number of years > 0, got {years}")]
pub struct HorizonError {
    pub years: f64,
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
    pub(crate) slope_interval: Option<(f64, f64)>,
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
pub fn fit(series: &Series, options: &TrendOptions) -> Trend {
    let mut points: Vec<&Inspection> = series
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
fn worse_direction(trend: &Trend, points: &[&Inspection]) -> f64 {
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
    points: &[&Inspection],
    limit: f64,
    options: &TrendOptions,
    reasons: &mut Vec<String>,
) {
    let unit = unit_for_people(&series.unit);
    let over = |p: &&Inspection| p.value.abs() > limit;
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
    let Some(date) = (0.0..1e7)
        .contains(&days)
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
    points: &[&Inspection],
    options: &TrendOptions,
) -> Option<String> {
    let (lo, hi) = trend.slope_interval?;
    let level_only = CATALOGUE
        .iter()
        .any(|d| d.key.as_str() == series.parameter && d.quantity == Quantity::Level);
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

#[cfg(test)]
mod tests {
    use super::*;

    fn date(y: i32, m: u32, d: u32) -> NaiveDate {
        NaiveDate::from_ymd_opt(y, m, d).unwrap()
    }

    fn series(key: &str, limit: Option<f64>, points: &[(NaiveDate, f64)]) -> Series {
        Series {
            machine: "M1".into(),
            serial: None,
            axis: "X".into(),
            parameter: key.into(),
            unit: "um".into(),
            limit,
            points: points
                .iter()
                .map(|&(date, value)| Inspection { date, value })
                .collect(),
        }
    }

    /// 2021-01-01 … 2025-01-01: days 0, 365, 730, 1095, 1461.
    fn yearly_2021() -> Vec<NaiveDate> {
        (2021..=2025).map(|y| date(y, 1, 1)).collect()
    }

    /// y = 3 + 0.004·days: 3.0, 4.46, 5.92, 7.38, 8.844.
    fn clean_line(sign: f64) -> Vec<(NaiveDate, f64)> {
        let first = date(2021, 1, 1);
        yearly_2021()
            .into_iter()
            .map(|d| (d, sign * (3.0 + 0.004 * (d - first).num_days() as f64)))
            .collect()
    }

    /// 0.004 µm a day is 1.461 µm a year; the line reaches 10 µm at day 7/0.004 = 1750,
    /// 2025-10-17, 289 days after the latest inspection: within 2 years. All 10 pairwise
    /// slopes are equal, so Sen's interval (n = 5: [min, max]) has no width.
    #[test]
    fn a_clean_line_is_exact_to_the_day() {
        let t = fit(
            &series("A", Some(10.0), &clean_line(1.0)),
            &TrendOptions::default(),
        );
        assert!((t.slope_per_year.unwrap() - 1.461).abs() < 1e-12);
        assert!(t.slope_se.unwrap() < 1e-12);
        assert!((t.intercept.unwrap() - 3.0).abs() < 1e-12);
        assert!((t.fitted[4] - 8.844).abs() < 1e-12);
        assert_eq!(t.forecast_date, Some(date(2025, 10, 17)));
        assert!(t.flagged);
        assert_eq!(
            t.reason.as_deref(),
            Some(
                "reaches its limit 10.0 µm around 2025-10 (within 2 years); \
                 worsening significantly: +1.46 ± 0.00 µm per year"
            )
        );
        // Half a year ahead: the crossing is beyond it, and 1.461 · 0.5 = 0.73 µm is less
        // than 10 % of the limit, so nothing flags it.
        let near = fit(
            &series("A", Some(10.0), &clean_line(1.0)),
            &TrendOptions { horizon_years: 0.5 },
        );
        assert!(!near.flagged);
    }

    /// The same line with the latest inspection 10 µm too high: 6 of the 10 pairwise
    /// slopes are still 1.461 and hold the median; least squares tilts to 3.462 µm/year
    /// (10 · (t₅ − t̄) / Σ(t − t̄)²).
    #[test]
    fn one_odd_inspection_does_not_move_the_slope() {
        let mut points = clean_line(1.0);
        points[4].1 += 10.0;
        let t = fit(&series("A", None, &points), &TrendOptions::default());
        assert!((t.slope_per_year.unwrap() - 1.461).abs() < 1e-12);
        let years: Vec<f64> = points.iter().map(|p| t.years(p.0)).collect();
        let (tm, ym) = (
            years.iter().sum::<f64>() / 5.0,
            points.iter().map(|p| p.1).sum::<f64>() / 5.0,
        );
        let sxy: f64 = years
            .iter()
            .zip(&points)
            .map(|(t, p)| (t - tm) * (p.1 - ym))
            .sum();
        let sxx: f64 = years.iter().map(|t| (t - tm).powi(2)).sum();
        assert!((sxy / sxx - 3.462_368_662_5).abs() < 1e-9);
    }

    /// 5.0, 5.3, 4.8, 5.1, 4.9, 5.2 on 2020…2025-01-01: the 8th of 15 pairwise slopes is
    /// 0.0333 µm/year (0.1 µm over 1096 days), the intercept 5.0; Sen's interval (n = 6:
    /// 2nd and 14th slopes) is −0.200 … +0.299, so no significance; the line would reach
    /// 10 µm after 150 years.
    #[test]
    fn a_stable_series_is_not_flagged() {
        let values = [5.0, 5.3, 4.8, 5.1, 4.9, 5.2];
        let points: Vec<_> = (2020..=2025).map(|y| date(y, 1, 1)).zip(values).collect();
        let t = fit(&series("E", Some(10.0), &points), &TrendOptions::default());
        assert!((t.slope_per_year.unwrap() - 0.1 * 365.25 / 1096.0).abs() < 1e-12);
        assert!((t.intercept.unwrap() - 5.0).abs() < 1e-12);
        let (lo, hi) = t.slope_interval.unwrap();
        assert!((lo + 0.3 * 365.25 / 547.5).abs() < 1e-3 && (hi - 0.2993852459).abs() < 1e-9);
        assert!(t.forecast_date.unwrap().year() > 2160);
        assert!(!t.flagged && t.reason.is_none());
    }

    #[test]
    fn one_inspection_has_no_slope_two_have_no_error() {
        let one = fit(
            &series("B", Some(8.0), &[(date(2024, 5, 1), 3.0)]),
            &TrendOptions::default(),
        );
        assert_eq!(one.slope_per_year, None);
        assert!(one.fitted.is_empty() && one.forecast_date.is_none() && !one.flagged);
        // 3.0 → 4.0 µm over 2024-05-01 … 2025-05-01 (365 days): 365.25/365 µm/year;
        // the line reaches 8 µm at 5 · 365 = 1825 days, 2029-04-30: beyond 2 years.
        let points = [(date(2024, 5, 1), 3.0), (date(2025, 5, 1), 4.0)];
        let two = fit(&series("B", Some(8.0), &points), &TrendOptions::default());
        assert!((two.slope_per_year.unwrap() - 365.25 / 365.0).abs() < 1e-12);
        assert_eq!(two.slope_se, None);
        assert_eq!(two.forecast_date, Some(date(2029, 4, 30)));
        assert!(!two.flagged);
        // Over the limit with one inspection: flagged without a slope.
        let over = fit(
            &series("B", Some(2.0), &[(date(2024, 5, 1), 3.0)]),
            &TrendOptions::default(),
        );
        assert_eq!(
            over.reason.as_deref(),
            Some("over its limit 2.0 µm since 2024-05-01")
        );
    }

    /// 8, 9, 10.5, 11 µm against 10 µm: over since the third inspection.
    #[test]
    fn a_series_over_its_limit_says_since_when() {
        let values = [8.0, 9.0, 10.5, 11.0];
        let points: Vec<_> = (2021..=2024).map(|y| date(y, 6, 1)).zip(values).collect();
        let t = fit(&series("A", Some(10.0), &points), &TrendOptions::default());
        assert_eq!(t.over_limit_since, Some(date(2023, 6, 1)));
        assert_eq!(t.forecast_date, Some(date(2023, 6, 1)));
        assert!(t.flagged);
        assert_eq!(
            t.reason.as_deref(),
            Some("over its limit 10.0 µm since 2023-06-01")
        );
    }

    #[test]
    fn a_decreasing_series_has_no_forecast() {
        let values = [9.0, 8.0, 7.0, 6.0, 5.0];
        let points: Vec<_> = yearly_2021().into_iter().zip(values).collect();
        let t = fit(&series("A", Some(10.0), &points), &TrendOptions::default());
        assert!(t.slope_per_year.unwrap() < -0.99);
        assert_eq!(t.forecast_date, None);
        assert!(!t.flagged);
    }

    /// A signed mean heading down, |B̄| = 3 + 0.004·days: against 8 µm the latest
    /// inspection (8.844) is over, since 2025-01-01; against 9 µm the line gets there at
    /// day 6/0.004 = 1500, 2025-02-09, 39 days after the latest inspection.
    #[test]
    fn a_signed_mean_compares_its_magnitude() {
        let points = clean_line(-1.0);
        let over = fit(
            &series("B_mean", Some(8.0), &points),
            &TrendOptions::default(),
        );
        assert_eq!(over.over_limit_since, Some(date(2025, 1, 1)));
        let t = fit(
            &series("B_mean", Some(9.0), &points),
            &TrendOptions::default(),
        );
        assert!((t.slope_per_year.unwrap() + 1.461).abs() < 1e-12);
        assert_eq!(t.forecast_date, Some(date(2025, 2, 9)));
        assert!(t.reason.unwrap().contains("worsening significantly: -1.46"));
    }

    /// Two inspections on 2020-01-01 (1.0 and 1.4 µm), then 2.0, 3.1, 3.9, 5.2 yearly: the
    /// tied pair gives no slope, 14 remain, median (7th + 8th)/2 = 0.98220 µm/year. The
    /// normal approximation with the tie: Var(S) = (6·5·17 − 2·1·9)/18 = 27.33,
    /// C = 1.96·√27.33 = 10.247, ranks (14 ∓ C)/2 (+1) = 1.877 and 13.123, interpolated:
    /// 0.77563 … 1.12546, SE = 0.34983 / (2·1.96) = 0.089244.
    #[test]
    fn tied_dates_are_left_out_of_the_slopes_and_counted_in_the_variance() {
        let dates = [
            date(2020, 1, 1),
            date(2020, 1, 1),
            date(2021, 1, 1),
            date(2022, 1, 1),
            date(2023, 1, 1),
            date(2024, 1, 1),
        ];
        let values = [1.0, 1.4, 2.0, 3.1, 3.9, 5.2];
        let points: Vec<_> = dates.into_iter().zip(values).collect();
        let t = fit(&series("E", None, &points), &TrendOptions::default());
        assert!((t.slope_per_year.unwrap() - 0.982_198_493_78).abs() < 1e-9);
        let (lo, hi) = t.slope_interval.unwrap();
        assert!((lo - 0.775_634_015_02).abs() < 1e-9 && (hi - 1.125_464_802_56).abs() < 1e-9);
        assert!((t.slope_se.unwrap() - 0.089_244_187_72).abs() < 1e-9);
        // All on one date: no slope at all.
        let same: Vec<_> = values.iter().map(|&v| (date(2020, 1, 1), v)).collect();
        assert_eq!(
            fit(&series("E", None, &same), &TrendOptions::default()).slope_per_year,
            None
        );
    }

    /// The band: the interval's slopes through the line's value at the median date.
    #[test]
    fn the_band_widens_away_from_the_median_date() {
        let values = [5.0, 5.3, 4.8, 5.1, 4.9, 5.2];
        let points: Vec<_> = (2020..=2025).map(|y| date(y, 1, 1)).zip(values).collect();
        let t = fit(&series("E", Some(10.0), &points), &TrendOptions::default());
        let width = |d| {
            let (a, b) = t.band_at(d).unwrap();
            b - a
        };
        assert!(width(date(2022, 7, 2)) < 1e-2);
        assert!(width(date(2027, 1, 1)) > width(date(2025, 1, 1)));
    }
}
