//! What the report templates show, as typed views serialised to the virtual file
//! `/data.json`: every number already formatted, every label in words. The templates only
//! lay out; they compute nothing and evaluate no user text.
//!
//! [`axis`] is the test report of one axis (ISO 230-2 clause 7), [`conditions`] its test
//! conditions (clause 7.1), [`compensation`] its compensation table and the parameters
//! predicted with it, [`summary`](mod@summary) the campaign summary ([`inputs`]: the files its run
//! read, with their SHA-256); [`axis_chart`] gives the
//! data of the figures of ISO 230-2 Fig. 2a/2b.

mod as_found;
mod axis;
pub mod certificate;
mod compensation;
mod conditions;
pub mod diagnosis;
pub mod inputs;
mod other;
mod other_tool;
mod summary;
mod tool_point;
pub mod trends;
mod uncertainty;

pub use axis::{AxisReport, axis_report};
pub use compensation::{compensation_chart, verification_chart};
pub use other::{chart as other_chart, other_report};
pub use summary::{Summary, summary};
pub use uncertainty::decision_bars;

use super::charts::{AxisChart, DirectionSeries, Span};
use crate::evaluate::{Approach, DirectionResult, Evaluation, ParamKey, StandardId};
use crate::results::{AxisTest, CampaignResult};
use crate::units::{AxisKind, Direction, fmt_fixed, fmt_position};
use serde::Serialize;

/// Deviation values in reports: 2 decimals (0.01 µm / 0.01″), with a typographic minus.
/// In the language of the document being built ([`crate::words::Words::scope`]).
pub fn num(x: f64) -> String {
    local(&fmt_fixed(x, 2).replace('-', "−"))
}

/// A number written with a decimal point, in the form of the document's language
/// ([`crate::words::numbers`]: a decimal comma in Russian).
pub(crate) fn local(text: &str) -> String {
    crate::words::numbers().number(text)
}

/// [`num`], or a dash for a value that does not apply.
fn opt(x: Option<f64>) -> String {
    x.map_or("–".into(), num)
}

/// A unit symbol in the language of the document being built (`мм`, `мкм` in Russian).
pub(crate) fn unit(symbol: &str) -> String {
    crate::words::Words::new(crate::words::numbers()).unit(symbol)
}

/// A position with its unit: `250.5 mm`, `90°`.
fn pos(kind: AxisKind, x: f64) -> String {
    match kind {
        AxisKind::Linear => format!(
            "{} {}",
            local(&fmt_position(x).replace('-', "−")),
            unit("mm")
        ),
        AxisKind::Rotary => format!("{}°", local(&fmt_position(x).replace('-', "−"))),
    }
}

/// The symbol of the scatter estimate: S in ISO 230-2 and GOST 27843, σ in the NMTBA and
/// VDI 3441 definitions.
fn s_symbol(standard: Option<StandardId>) -> &'static str {
    match standard {
        Some(StandardId::Vdi3441 | StandardId::Nmtba) => "σ",
        _ => "S",
    }
}

/// The symbol of parameter `key` in the test's standard (the key itself when it does not
/// apply): what the reports, the summary and the page label a limit's check with.
pub fn symbol_of(t: &AxisTest, key: ParamKey) -> String {
    t.evaluated()
        .map(|e| &e.evaluation)
        .and_then(|e| e.parameter(key))
        .map_or(key.to_string(), |p| p.symbol().to_string())
}

/// Longest name, in characters, that a heading, a table cell or a footer shows whole:
/// longer ones are shortened there ([`short_name`]) and printed whole once (the axis
/// report's facts, the summary's title).
const SHORT_NAME: usize = 60;

/// Longest axis name shown whole in a heading or a fact.
const AXIS_NAME: usize = 40;

/// `name` shortened to at most `max` characters with an ellipsis, cut before a character
/// (never between a letter and its combining marks): where a 10 000-character name would
/// fill the page, a table column or the footer.
pub fn short_name(name: &str, max: usize) -> String {
    use unicode_properties::{GeneralCategoryGroup, UnicodeGeneralCategory};
    if name.chars().count() <= max {
        return name.to_string();
    }
    let mut end = 0;
    for (n, (i, c)) in name.char_indices().enumerate() {
        let mark = c.general_category_group() == GeneralCategoryGroup::Mark;
        if n >= max.saturating_sub(1) && !mark {
            break;
        }
        end = i + c.len_utf8();
    }
    format!("{}…", name[..end].trim_end())
}

/// The campaign header both templates show (absent items as empty strings).
#[derive(Serialize)]
pub struct CampaignHeader<'a> {
    name: &'a str,
    site: &'a str,
    purpose: &'a str,
    /// In the form of the document's language ([`crate::words::numbers`]).
    date: String,
    inspector: &'a str,
    file: &'a str,
    standard: String,
}

impl<'a> CampaignHeader<'a> {
    pub fn new(result: &'a CampaignResult) -> CampaignHeader<'a> {
        let info = &result.info;
        CampaignHeader {
            name: &info.name,
            site: info.site.as_deref().unwrap_or_default(),
            purpose: info.purpose.as_deref().unwrap_or_default(),
            date: crate::words::numbers().date(info.date.as_deref().unwrap_or_default()),
            inspector: info.inspector.as_deref().unwrap_or_default(),
            file: &result.file_name,
            standard: crate::words::Words::new(crate::words::numbers()).standard(result.standard),
        }
    }
}

/// The campaign's name as the axis reports' headings and the footers show it: longer
/// names shortened ([`short_name`]); the summary's title prints it whole.
pub(crate) fn campaign_short(result: &CampaignResult) -> String {
    short_name(&result.info.name, 2 * SHORT_NAME)
}

/// A test's label (`MACHINE AXIS`) with each name shortened ([`short_name`]).
pub(crate) fn short_label(t: &AxisTest) -> String {
    let (m, a) = (
        short_name(&t.machine.id, SHORT_NAME),
        short_name(&t.axis_label(), AXIS_NAME),
    );
    if t.tests > 1 {
        format!("{m} {a} ({}/{})", t.test, t.tests)
    } else {
        format!("{m} {a}")
    }
}

/// A key of the JSON (`slope_um_per_m`, `systematic_per_target`) in words for a customer:
/// underscores as spaces, and from the first unit on the unit in brackets with its first
/// `per` as a slash (`slope (µm/m)`, `growth (µm/m per run)`).
pub(crate) fn key_words(key: &str) -> String {
    let words: Vec<&str> = key.split('_').collect();
    let unit = |w: &str| matches!(w, "um" | "arcsec" | "mm" | "deg" | "ppm" | "pct");
    let Some(i) = words.iter().skip(1).position(|w| unit(w)).map(|i| i + 1) else {
        return words.join(" ");
    };
    let spelled: Vec<&str> = (words[i..].iter())
        .map(|w| match *w {
            "um" => "µm",
            "deg" => "°",
            "pct" => "%",
            other => other,
        })
        .collect();
    let unit = spelled.join(" ").replacen(" per ", "/", 1);
    format!("{} ({unit})", words[..i].join(" "))
}

/// The version that made the report, for its footer.
fn generator() -> String {
    format!("axcheck {}", env!("CARGO_PKG_VERSION"))
}

/// The chart data of an evaluation (ISO 230-2 Fig. 2a/2b): the bidirectional chart, and
/// the range parameters (A, E, M and their ↑/↓ forms) to mark on the bidirectional,
/// ↑ and ↓ charts.
pub fn axis_chart(e: &Evaluation) -> (AxisChart, Vec<Span>, Vec<Span>) {
    let series = |d: Direction| {
        let r: Vec<&DirectionResult> = e.targets.iter().map(|t| t.direction(d)).collect();
        let all = |f: &dyn Fn(&DirectionResult) -> Option<f64>| {
            r.iter().map(|x| f(x)).collect::<Option<Vec<f64>>>()
        };
        DirectionSeries {
            mean: r.iter().map(|x| x.mean).collect(),
            upper: all(&|x| x.upper),
            lower: all(&|x| x.lower),
            deviations: r.iter().map(|x| x.deviations.clone()).collect(),
        }
    };
    let spans = |approach: Approach| -> Vec<Span> {
        e.parameters
            .iter()
            .filter(|p| p.def.approach == approach)
            .filter_map(|p| {
                p.span.map(|(upper, lower)| Span {
                    label: p.symbol().to_string(),
                    upper,
                    lower,
                })
            })
            .collect()
    };
    // The labels in the language of the document being built ([`crate::words::numbers`]).
    let words = crate::words::Words::new(crate::words::numbers());
    let (pos_unit, dev_unit) = match e.kind {
        AxisKind::Linear => ("mm", "µm"),
        AxisKind::Rotary => ("°", "arcsec"),
    };
    let chart = AxisChart {
        positions: e.targets.iter().map(|t| t.position).collect(),
        position_label: words.args("chart-target-position", &[("unit", &words.unit(pos_unit))]),
        deviation_label: words.args(
            "chart-positional-deviation",
            &[("unit", &words.unit(dev_unit))],
        ),
        up: series(Direction::Up),
        down: series(Direction::Down),
        mean: e.targets.iter().map(|t| t.mean).collect(),
        band_label: format!("X̄ ± {}{}", e.coverage_factor, s_symbol(Some(e.standard))),
        spans: spans(Approach::Both),
    };
    (chart, spans(Approach::Up), spans(Approach::Down))
}

#[cfg(test)]
mod tests {
    use super::{key_words, short_name};

    #[test]
    fn long_names_are_shortened_with_an_ellipsis() {
        assert_eq!(short_name("VMC-07", 60), "VMC-07");
        let long = "Fräszentrum-".repeat(900);
        let short = short_name(&long, 60);
        assert_eq!(short.chars().count(), 60);
        assert!(short.ends_with('…') && long.starts_with(short.trim_end_matches('…')));
        // A combining mark stays with its letter.
        let marked = "X\u{304}".repeat(40);
        let short = short_name(&marked, 9);
        assert!(short.ends_with("X\u{304}…"), "{short:?}");
    }

    #[test]
    fn keys_read_as_words() {
        assert_eq!(key_words("slope_um_per_m"), "slope (µm/m)");
        assert_eq!(key_words("reversal_start_um"), "reversal start (µm)");
        assert_eq!(key_words("systematic_per_target"), "systematic per target");
        assert_eq!(key_words("shape"), "shape");
        assert_eq!(
            key_words("growth_se_um_per_m_per_run"),
            "growth se (µm/m per run)"
        );
        assert_eq!(key_words("offset_run1_um"), "offset run1 (µm)");
        assert_eq!(key_words("origin_mm"), "origin (mm)");
    }
}
