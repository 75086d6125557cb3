//! The report's measurement-uncertainty section: the budget over the measurement travel,
//! one row per contributor (GUM: value, distribution, u, sensitivity, c·u, share), u_c
//! and U with k = 2, and what was assumed.

use super::{num, symbol_of};
use crate::charts::check::CheckBar;
use crate::results::AxisTest;
use crate::uncertainty::{BudgetLine, Uncertainty};
use crate::units::fmt_fixed;
use serde::Serialize;

#[derive(Serialize)]
pub(super) struct UncertaintySection<'a> {
    /// `µm` or `arcsec`.
    unit: String,
    /// The length the budget is for, with its unit.
    length: String,
    rows: Vec<BudgetRow>,
    /// A chart of each limited parameter's value against its limit ± U.
    has_decision_chart: bool,
    combined: String,
    expanded: String,
    notes: &'a [String],
}

/// One contributor as text.
#[derive(Serialize)]
struct BudgetRow {
    contributor: String,
    value: String,
    distribution: String,
    u: String,
    sensitivity: String,
    contribution: String,
    share: String,
}

/// Three significant digits, at most six decimals (inputs range from ppm to kPa).
fn sig(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return num(x);
    }
    let decimals = (2 - x.abs().log10().floor() as i32).clamp(0, 6) as usize;
    super::local(&fmt_fixed(x, decimals).replace('-', "−"))
}

/// A budget input's unit as the rest of the report prints it: `um` (the budget's and the
/// JSON's spelling) as `µm`, also in `um/(m·°C)`.
fn budget_unit(unit: &str) -> String {
    match unit.strip_prefix("um") {
        Some(rest) if rest.is_empty() || rest.starts_with('/') => {
            format!("{}{rest}", super::unit("µm"))
        }
        _ => unit.to_string(),
    }
}

impl BudgetRow {
    fn new(l: &BudgetLine) -> BudgetRow {
        let words = crate::words::Words::new(crate::words::numbers());
        BudgetRow {
            contributor: words.get_or(
                &format!("contributor-{}", l.contributor.replace('_', "-")),
                &l.contributor.replace('_', " "),
            ),
            value: format!("{} {}", sig(l.value), budget_unit(l.unit)),
            distribution: words.get_or(
                &format!("distribution-{}", l.distribution.name()),
                l.distribution.name(),
            ),
            u: sig(l.u),
            sensitivity: sig(l.sensitivity),
            contribution: sig(l.contribution),
            share: format!("{} %", super::local(&fmt_fixed(l.share * 100.0, 1))),
        }
    }
}

/// Decimals of the results table's values, limits and U ([`num`]).
const TABLE_DECIMALS: usize = 2;

/// `x` rounded as [`num`] prints it.
fn table_round(x: f64) -> f64 {
    fmt_fixed(x, TABLE_DECIMALS).parse().unwrap_or(x)
}

/// Each limited parameter's |value| against its zone limit ± U (ISO 14253-1): left of the
/// zone conformance is proven, right of it (marked) nonconformance, whatever rule decided.
pub fn decision_bars(t: &AxisTest) -> Vec<CheckBar> {
    let (Some(j), Some(u)) = (
        t.judgement(),
        t.evaluated().and_then(|e| e.uncertainty.as_ref()),
    ) else {
        return Vec::new();
    };
    j.checks
        .iter()
        .filter_map(|c| {
            let expanded = u.expanded_of(c.key)?;
            // The values as the results table prints them (2 decimals), and the zone's ends
            // from those, so that chart and table agree to the last digit.
            let (value, limit, zone) = (
                table_round(c.value.abs()),
                table_round(c.limit),
                table_round(expanded),
            );
            Some(CheckBar {
                label: symbol_of(t, c.key),
                measured: value,
                low: limit - zone,
                high: limit + zone,
                outside: c.value.abs() > c.limit + expanded,
                decimals: Some(TABLE_DECIMALS),
            })
        })
        .collect()
}

pub(super) fn uncertainty_section<'a>(
    t: &AxisTest,
    u: &'a Uncertainty,
    unit: &'static str,
    position_unit: &str,
) -> UncertaintySection<'a> {
    UncertaintySection {
        unit: super::unit(unit),
        length: format!(
            "{} {}",
            super::local(&fmt_fixed(u.budget.length, 3)),
            super::unit(position_unit)
        ),
        rows: u.budget.lines.iter().map(BudgetRow::new).collect(),
        has_decision_chart: !decision_bars(t).is_empty(),
        combined: sig(u.budget.combined),
        expanded: sig(u.budget.expanded),
        notes: &u.notes,
    }
}

#[cfg(test)]
mod tests {
    use super::{budget_unit, sig};

    #[test]
    fn budget_units_print_micrometres() {
        assert_eq!(budget_unit("um"), "µm");
        assert_eq!(budget_unit("um/(m·°C)"), "µm/(m·°C)");
        assert_eq!(budget_unit("ppm"), "ppm");
        assert_eq!(budget_unit("arcsec"), "arcsec");
    }

    #[test]
    fn three_significant_digits() {
        assert_eq!(sig(1.154701), "1.15");
        assert_eq!(sig(0.0004), "0.000400");
        assert_eq!(sig(19.186299), "19.2");
        assert_eq!(sig(1744.2), "1744");
        assert_eq!(sig(-0.05), "−0.0500");
    }
}
