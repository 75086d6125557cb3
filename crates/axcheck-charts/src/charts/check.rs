//! The model-check chart of an axis report's diagnosis section: each statistic measured
//! against the band simulated from the base model, on a scale of its own per row.

use crate::chart_kit::scene::Scene;
use crate::chart_kit::{
    Area, Failed, GUIDE, INK, LEGEND_PX, MUTED, Marker, STRIPE, Style, TICK_PX, draw_marker,
    draw_text, fmt_fixed_for_print, message_chart, render, round_px, row_height, sig_decimals,
    text_style,
};
use crate::charts::diagnosis::look::{
    CHECK_BAND, KIT, MARK_INSIDE, MARK_OUTSIDE, NOTE_PX, OUTSIDE, bold_width, draw_arrow, fill_rect,
};
use crate::lang::Lang;
use crate::words::Words;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, VPos};
use std::sync::LazyLock;

/// Measured statistic against the band simulated from the base model (model check).
#[derive(Debug, Clone, PartialEq)]
pub struct CheckBar {
    pub label: String,
    pub measured: f64,
    pub low: f64,
    pub high: f64,
    pub outside: bool,
    /// The decimals to print the row's numbers with, when they must agree with a table's
    /// (the decision zones: the results table's); else chosen from the numbers.
    pub decimals: Option<usize>,
}

const CHECK_TOP: u32 = 62;
const CHECK_BOTTOM: u32 = 12;

fn check_row_height(rows: usize) -> u32 {
    row_height(rows, &[(12, 36), (30, 28)], 22)
}

/// Height in pixels that fits `bars` rows of [`model_checks`] at 900 px wide.
pub fn model_checks_height(bars: usize) -> u32 {
    let n = bars.clamp(1, 500);
    (CHECK_TOP + CHECK_BOTTOM + n as u32 * check_row_height(n)).max(150)
}

/// Decimals for one row's numbers: its own when it has them; else three significant
/// digits of the band's larger end, and enough to show the band's width to two digits.
pub(crate) fn row_decimals(c: &CheckBar) -> usize {
    if let Some(d) = c.decimals {
        return d;
    }
    let ends = [c.low, c.high].into_iter().filter(|v| v.is_finite());
    let mag = ends.clone().map(f64::abs).fold(0.0, f64::max);
    let mag = if mag > 0.0 { mag } else { c.measured.abs() };
    let by_size = sig_decimals(mag);
    let width = (c.high - c.low).abs();
    let by_width = if width.is_finite() && width > 0.0 {
        (1.0 - width.log10().floor()).clamp(0.0, 9.0) as usize
    } else {
        0
    };
    let d0 = by_size.max(by_width).min(9);
    // Drop decimals that are zero in all of the row's numbers ("0.310 … 0.960" → "0.31 … 0.96").
    let strip = |t: String| {
        if t.contains('.') && !t.contains('e') {
            t.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            t
        }
    };
    let values = [c.low, c.high, c.measured];
    let finite = values.iter().filter(|v| v.is_finite());
    (0..d0)
        .find(|&d| {
            finite
                .clone()
                .all(|v| strip(fmt_fixed_for_print(*v, d)) == strip(fmt_fixed_for_print(*v, d0)))
        })
        .unwrap_or(d0)
}

/// The simulated band as (low, high) in order, if both ends are finite.
fn band_of(c: &CheckBar) -> Option<(f64, f64)> {
    (c.low.is_finite() && c.high.is_finite()).then(|| (c.low.min(c.high), c.low.max(c.high)))
}

/// The band has no width worth scaling (it is drawn as a thin bar).
fn degenerate_band(c: &CheckBar) -> bool {
    band_of(c).is_none_or(|(lo, hi)| {
        // Halves, so that even a band from −MAX to MAX has a finite width.
        let tol = 1e-12 * lo.abs().max(hi.abs()).max(1e-300);
        hi / 2.0 - lo / 2.0 <= tol / 2.0
    })
}

/// Where the measured value sits on a row's own scale: the band [low, high] maps to
/// [1/3, 2/3]; values beyond [0, 1] are clipped. None when it cannot be placed.
pub(crate) fn check_position(c: &CheckBar) -> Option<f64> {
    let (lo, hi) = band_of(c)?;
    let m = c.measured;
    if !m.is_finite() {
        return None;
    }
    let tol = 1e-12 * lo.abs().max(hi.abs()).max(1e-300);
    if degenerate_band(c) {
        return Some(if (m - lo).abs() <= tol {
            0.5
        } else if m > lo {
            f64::INFINITY
        } else {
            f64::NEG_INFINITY
        });
    }
    // In halves, so nothing overflows for finite inputs.
    let u = 1.0 / 3.0 + (m / 2.0 - lo / 2.0) / (hi / 2.0 - lo / 2.0) / 3.0;
    Some(if u.is_nan() { 0.5 } else { u })
}

/// What a chart of bands says: its key, headings and empty message.
pub(crate) struct Wording {
    empty: &'static str,
    band_key: &'static str,
    band_head: &'static str,
    band_head_narrow: &'static str,
    measured_head: &'static str,
    inside: &'static str,
    outside: &'static str,
    scale_note: &'static str,
}

/// `keys` (catalogue keys, in the order of [`Wording`]'s fields) in each language, made
/// once (the few strings stay for the life of the process).
fn worded(keys: [&str; 8]) -> Vec<(Lang, Wording)> {
    (Lang::ALL.into_iter())
        .map(|lang| {
            let words = Words::new(lang);
            let t = |k: &str| -> &'static str { words.get(k).leak() };
            let wording = Wording {
                empty: t(keys[0]),
                band_key: t(keys[1]),
                band_head: t(keys[2]),
                band_head_narrow: t(keys[3]),
                measured_head: t(keys[4]),
                inside: t(keys[5]),
                outside: t(keys[6]),
                scale_note: t(keys[7]),
            };
            (lang, wording)
        })
        .collect()
}

/// The wording of `all` in the language of the document being drawn.
fn in_language(all: &'static [(Lang, Wording)]) -> &'static Wording {
    let lang = crate::words::numbers();
    &all.iter()
        .find(|(l, _)| *l == lang)
        .expect("every language")
        .1
}

/// The model checks of the diagnosis.
static MODEL_CHECKS: LazyLock<Vec<(Lang, Wording)>> = LazyLock::new(|| {
    worded([
        "check-model-empty",
        "check-model-band-key",
        "check-model-band-head",
        "check-model-band-head-narrow",
        "check-model-measured",
        "check-model-measured",
        "check-model-outside",
        "check-model-scale",
    ])
});

/// The decision of each limited parameter (ISO 14253-1): its value against the zone of
/// the limit ± U, where neither conformance nor nonconformance is proven.
static DECISION_ZONES: LazyLock<Vec<(Lang, Wording)>> = LazyLock::new(|| {
    worded([
        "check-decision-empty",
        "check-decision-band-key",
        "check-decision-band-head",
        "check-decision-band-head-narrow",
        "check-decision-value",
        "check-decision-value",
        "check-decision-outside",
        "check-decision-scale",
    ])
});

/// Decision zones: one row per limited parameter, its |value| against the zone limit ± U
/// (left of the zone conformance is proven, right of it nonconformance), drawn as the
/// model checks are. Size the height with [`model_checks_height`].
pub fn decision_zones(bars: &[CheckBar], style: &Style) -> Scene {
    band_rows(bars, style, in_language(&DECISION_ZONES))
}

/// Model checks: one row per statistic. Each row has its own scale: the band simulated from
/// the base model (95 %) is a light grey bar in the middle third, the measured value a marker
/// on that scale (a filled black circle, or a dark red diamond with a bold dark red label when
/// the check is outside); values more than a band width past the band are clipped at the row's
/// end with an arrow. The measured value and the band are printed at the right. A key and the
/// column headings sit above the rows. Size the height with [`model_checks_height`].
pub fn model_checks(bars: &[CheckBar], style: &Style) -> Scene {
    band_rows(bars, style, in_language(&MODEL_CHECKS))
}

/// Rows of a value against a band, each on its own scale, in `words`.
fn band_rows(bars: &[CheckBar], style: &Style, words: &'static Wording) -> Scene {
    if bars.is_empty() {
        return message_chart(style, words.empty);
    }
    let numbers: Vec<(String, String)> = bars.iter().map(row_numbers).collect();
    let positions: Vec<Option<f64>> = bars.iter().map(check_position).collect();
    let clipped = positions.iter().flatten().any(|u| !(0.0..=1.0).contains(u));
    let any_outside = bars.iter().any(|c| c.outside);
    render(style, |root| {
        let layout = Columns::of(root, bars, &numbers, words);
        if bars.len() > 6 {
            draw_stripes(root, &layout, bars.len())?;
        }
        draw_key(root, words, any_outside, clipped)?;
        draw_headings(root, &layout)?;
        for (i, ((c, numbers), pos)) in bars.iter().zip(&numbers).zip(&positions).enumerate() {
            let mid = CHECK_TOP as i32 + ((i as f64 + 0.5) * layout.row_h).round() as i32;
            draw_row_scale(root, &layout, c, *pos, mid)?;
            draw_row_texts(root, &layout, c, numbers, mid)?;
        }
        Ok(())
    })
}

/// A row's measured value and band as printed.
fn row_numbers(c: &CheckBar) -> (String, String) {
    let d = row_decimals(c);
    let band = band_of(c).map_or_else(
        || "n/a".to_string(),
        |(lo, hi)| {
            format!(
                "{} … {}",
                fmt_fixed_for_print(lo, d),
                fmt_fixed_for_print(hi, d)
            )
        },
    );
    (fmt_fixed_for_print(c.measured, d), band)
}

/// Where the columns lie (right edges of the texts, the scale's ends) and the row pitch.
struct Columns {
    words: &'static Wording,
    width: i32,
    band_head: &'static str,
    band_right: i32,
    band_w: i32,
    measured_right: i32,
    measured_w: i32,
    label_right: i32,
    label_w: i32,
    /// The scale's ends, with room for an arrow head at either end.
    sx0: i32,
    sx1: i32,
    row_h: f64,
}

impl Columns {
    fn of(
        root: &Area,
        bars: &[CheckBar],
        numbers: &[(String, String)],
        words: &'static Wording,
    ) -> Columns {
        let (w, h) = root.dim_in_pixel();
        let (wi, hi) = (w as i32, h as i32);
        let band_head = if wi < 600 {
            words.band_head_narrow
        } else {
            words.band_head
        };
        let col_w = |head: &str, texts: &mut dyn Iterator<Item = &String>| {
            texts
                .map(|t| bold_width(t, TICK_PX))
                .fold(KIT.text_width(head, TICK_PX), f64::max)
                .ceil()
                .min(wi as f64 / 3.0) as i32
        };
        let measured_w = col_w(words.measured_head, &mut numbers.iter().map(|p| &p.0));
        let band_w = col_w(band_head, &mut numbers.iter().map(|p| &p.1));
        let band_right = wi - 10;
        let measured_right = band_right - band_w - 26;
        let scale_right = measured_right - measured_w - 26;
        // The labels take what the scale (at least 120 px) leaves, and at least a little.
        let label_w_want = bars
            .iter()
            .map(|c| bold_width(&c.label, TICK_PX))
            .fold(20.0, f64::max)
            .ceil() as i32;
        let avail = scale_right - 10 - 16;
        let label_w = label_w_want.min(avail - 120).max((avail / 3).clamp(20, 60));
        let label_right = 10 + label_w;
        let scale_left = label_right + 16;
        let n = bars.len();
        let avail_h = (hi - CHECK_TOP as i32 - CHECK_BOTTOM as i32).max(n as i32) as f64;
        Columns {
            words,
            width: wi,
            band_head,
            band_right,
            band_w,
            measured_right,
            measured_w,
            label_right,
            label_w,
            sx0: scale_left + 12,
            sx1: (scale_right - 12).max(scale_left + 14),
            row_h: (avail_h / n as f64).min(check_row_height(n) as f64 * 1.25),
        }
    }

    /// The pixel column of `u` on a row's scale (0 … 1).
    fn at(&self, u: f64) -> f64 {
        self.sx0 as f64 + u * (self.sx1 - self.sx0) as f64
    }
}

/// Stripes behind every other row.
fn draw_stripes(root: &Area, layout: &Columns, n: usize) -> Result<(), Failed> {
    let top = CHECK_TOP as i32;
    for i in (1..n).step_by(2) {
        let y0 = top + (i as f64 * layout.row_h).round() as i32;
        let y1 = top + ((i + 1) as f64 * layout.row_h).round() as i32;
        fill_rect(root, (4, y0), (layout.width - 4, y1), STRIPE)?;
    }
    Ok(())
}

/// What a key entry shows.
#[derive(Clone, Copy, PartialEq)]
enum Sample {
    Band,
    Mark((Marker, RGBColor)),
    Arrow,
}

/// The key (row 1): the band, the markers and, when used, the arrow.
fn draw_key(root: &Area, words: &Wording, any_outside: bool, clipped: bool) -> Result<(), Failed> {
    let wi = root.dim_in_pixel().0 as i32;
    let key_y = 14;
    let mut kx = 10;
    let beyond = Words::new(crate::words::numbers()).get("check-beyond");
    let mut key = vec![
        (Sample::Band, words.band_key),
        (Sample::Mark(MARK_INSIDE), words.inside),
    ];
    if any_outside {
        key.push((Sample::Mark(MARK_OUTSIDE), words.outside));
    }
    if clipped {
        key.push((Sample::Arrow, beyond.as_str()));
    }
    for (sample, text) in key {
        if kx + 28 + 40 > wi - 10 {
            break;
        }
        match sample {
            Sample::Band => {
                let (a, b) = ((kx, key_y - 6), (kx + 22, key_y + 6));
                root.draw(&Rectangle::new([a, b], CHECK_BAND.filled()))?;
                root.draw(&Rectangle::new([a, b], MUTED.stroke_width(1)))?;
            }
            Sample::Mark((m, c)) => draw_marker(root, (kx + 11, key_y), m, c)?,
            Sample::Arrow => draw_arrow(root, (kx + 18, key_y), 1, 6, INK)?,
        }
        let text = KIT.fit_text(text, LEGEND_PX, (wi - kx - 38).max(0) as f64);
        if text != "…" {
            let style = text_style(LEGEND_PX, false, INK, HPos::Left, VPos::Center);
            draw_text(root, &text, (kx + 28, key_y), style)?;
        }
        kx += 28 + KIT.text_width(&text, LEGEND_PX).ceil() as i32 + 24;
    }
    Ok(())
}

/// The column headings (row 2) over a rule.
fn draw_headings(root: &Area, layout: &Columns) -> Result<(), Failed> {
    let top = CHECK_TOP as i32;
    let head_y = top - 8;
    let head = |h| text_style(TICK_PX, true, INK, h, VPos::Bottom);
    let measured_at = (layout.measured_right, head_y);
    draw_text(
        root,
        layout.words.measured_head,
        measured_at,
        head(HPos::Right),
    )?;
    let band_at = (layout.band_right, head_y);
    draw_text(root, layout.band_head, band_at, head(HPos::Right))?;
    let scale_note = layout.words.scale_note;
    if KIT.text_width(scale_note, NOTE_PX) <= (layout.sx1 - layout.sx0) as f64 {
        let style = text_style(NOTE_PX, false, MUTED, HPos::Center, VPos::Bottom);
        let at = ((layout.sx0 + layout.sx1) / 2, head_y);
        draw_text(root, scale_note, at, style)?;
    }
    root.draw(&PathElement::new(
        vec![(4, top - 2), (layout.width - 4, top - 2)],
        GUIDE.stroke_width(1),
    ))?;
    Ok(())
}

/// A row's track, band and marker (or arrow when off the scale).
fn draw_row_scale(
    root: &Area,
    layout: &Columns,
    c: &CheckBar,
    pos: Option<f64>,
    mid: i32,
) -> Result<(), Failed> {
    let (sx0, sx1) = (layout.sx0, layout.sx1);
    root.draw(&PathElement::new(
        vec![(sx0, mid), (sx1, mid)],
        GUIDE.stroke_width(1),
    ))?;
    if band_of(c).is_some() {
        let bar_h = ((layout.row_h * 0.42).round() as i32).clamp(4, 16);
        let (b0, b1) = (
            layout.at(1.0 / 3.0).round() as i32,
            layout.at(2.0 / 3.0).round() as i32,
        );
        let (b0, b1) = if degenerate_band(c) {
            ((b0 + b1) / 2 - 1, (b0 + b1) / 2 + 1)
        } else {
            (b0, b1)
        };
        let (a, b) = ((b0, mid - bar_h / 2), (b1, mid - bar_h / 2 + bar_h));
        root.draw(&Rectangle::new([a, b], CHECK_BAND.filled()))?;
        root.draw(&Rectangle::new([a, b], MUTED.stroke_width(1)))?;
    }
    let (marker, color) = if c.outside { MARK_OUTSIDE } else { MARK_INSIDE };
    match pos {
        Some(u) if u < 0.0 => draw_arrow(root, (sx0 - 10, mid), -1, 7, color),
        Some(u) if u > 1.0 => draw_arrow(root, (sx1 + 10, mid), 1, 7, color),
        Some(u) => draw_marker(root, round_px((layout.at(u), mid as f64)), marker, color),
        None => Ok(()),
    }
}

/// A row's label, measured value and band (bold dark red when the check is outside).
fn draw_row_texts(
    root: &Area,
    layout: &Columns,
    c: &CheckBar,
    (measured, band): &(String, String),
    mid: i32,
) -> Result<(), Failed> {
    let (bold, ink) = if c.outside {
        (true, OUTSIDE)
    } else {
        (false, INK)
    };
    let right = |bold, ink| text_style(TICK_PX, bold, ink, HPos::Right, VPos::Center);
    let label = KIT.fit_text(&c.label, TICK_PX, layout.label_w as f64);
    draw_text(root, &label, (layout.label_right, mid), right(bold, ink))?;
    let measured = KIT.fit_text(measured, TICK_PX, layout.measured_w as f64);
    draw_text(
        root,
        &measured,
        (layout.measured_right, mid),
        right(bold, ink),
    )?;
    let band = KIT.fit_text(band, TICK_PX, layout.band_w as f64);
    draw_text(root, &band, (layout.band_right, mid), right(false, INK))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chart_kit::svg_probe::{
        assert_well_formed, degenerate_styles, has_text, text_tag, texts,
    };
    use crate::charts::diagnosis::look::testing::{
        assert_plain_font_sizes, assert_small, circles_in, style,
    };

    // The chart as SVG with an element per outline, as plotters wrote it.
    fn model_checks(bars: &[CheckBar], style: &Style) -> String {
        super::model_checks(bars, style).element_svg()
    }

    fn check(label: &str, measured: f64, low: f64, high: f64, outside: bool) -> CheckBar {
        CheckBar {
            label: label.to_string(),
            measured,
            low,
            high,
            outside,
            decimals: None,
        }
    }

    fn example_checks() -> Vec<CheckBar> {
        vec![
            check("R (max Ri)", 2.31, 1.42, 2.95, false),
            check("run-mean spread", 1.21, 0.31, 0.96, true),
            check("lag-1 autocorrelation", 0.12, -0.27, 0.25, false),
            check("max periodogram power", 0.29, 0.18, 0.41, false),
        ]
    }

    #[test]
    fn model_checks_mark_outside_rows() {
        let st = style(model_checks_height(4));
        let svg = model_checks(&example_checks(), &st);
        assert_well_formed(&svg);
        for want in [
            "R (max Ri)",
            "run-mean spread",
            "lag-1 autocorrelation",
            "max periodogram power",
            "measured",
            "simulated 95 % band",
            "simulated 95 % band (base model)",
            "measured, check outside",
            "2.31",
            "1.42 … 2.95",
            "1.21",
            "0.31 … 0.96",
            "−0.27 … 0.25",
        ] {
            assert!(
                has_text(&svg, want),
                "missing {want:?} in {:?}",
                texts(&svg)
            );
        }
        // Outside: bold dark red label and value; inside: plain.
        for outside in ["run-mean spread", "1.21"] {
            let tag = text_tag(&svg, outside).expect("outside row");
            assert!(
                tag.contains("font-weight=\"bold\"") && tag.contains("#6E1414"),
                "{tag}"
            );
        }
        for inside in ["R (max Ri)", "2.31"] {
            let tag = text_tag(&svg, inside).expect("inside row");
            assert!(!tag.contains("font-weight"), "{tag}");
        }
        // One diamond in the row, one in the key; inside values as black dots (3 + key).
        assert_eq!(
            svg.matches("<polygon opacity=\"1\" fill=\"#6E1414\"")
                .count(),
            2
        );
        assert_eq!(circles_in(&svg, "#1A1A1A"), 4);
        // No value is off the scale: no arrow, no key for it.
        assert!(!has_text(&svg, "beyond the scale"));
    }

    #[test]
    fn model_checks_without_outside_rows_have_no_outside_key() {
        let checks: Vec<CheckBar> = example_checks()
            .into_iter()
            .map(|c| CheckBar {
                outside: false,
                ..c
            })
            .collect();
        let svg = model_checks(&checks, &style(model_checks_height(4)));
        assert!(!has_text(&svg, "measured, check outside"));
        assert!(!svg.contains("#6E1414"));
    }

    #[test]
    fn far_values_are_clipped_with_an_arrow() {
        let checks = [
            check("far above", 50.0, 0.0, 1.0, true),
            check("far below", -50.0, 0.0, 1.0, true),
            check("inside", 0.5, 0.0, 1.0, false),
        ];
        let svg = model_checks(&checks, &style(model_checks_height(3)));
        assert_well_formed(&svg);
        assert!(has_text(&svg, "beyond the scale"));
        assert!(
            has_text(&svg, "50") && has_text(&svg, "−50"),
            "{:?}",
            texts(&svg)
        );
        // Two arrows in the rows (dark red, the checks are outside), one black in the key.
        assert_eq!(
            svg.matches("<polygon opacity=\"1\" fill=\"#6E1414\"")
                .count(),
            2 + 1
        );
        assert_eq!(check_position(&checks[0]), Some(1.0 / 3.0 + 50.0 / 3.0));
    }

    #[test]
    fn check_positions_map_the_band_to_the_middle_third() {
        let at = |m: f64, lo: f64, hi: f64| check_position(&check("", m, lo, hi, false));
        let near = |a: Option<f64>, b: f64| a.is_some_and(|a| (a - b).abs() < 1e-12);
        assert!(near(at(1.0, 1.0, 3.0), 1.0 / 3.0));
        assert!(near(at(3.0, 1.0, 3.0), 2.0 / 3.0));
        assert!(near(at(2.0, 3.0, 1.0), 0.5)); // low and high swapped
        assert!(near(at(-1.0, 1.0, 3.0), 0.0));
        assert!(near(at(5.0, 1.0, 3.0), 1.0));
        // Degenerate bands: on it, or off the scale on the right side.
        assert_eq!(at(2.0, 2.0, 2.0), Some(0.5));
        assert_eq!(at(2.5, 2.0, 2.0), Some(f64::INFINITY));
        assert_eq!(at(1.5, 2.0, 2.0), Some(f64::NEG_INFINITY));
        assert_eq!(at(f64::NAN, 0.0, 1.0), None);
        assert_eq!(at(0.5, f64::NAN, 1.0), None);
        assert!(near(at(0.0, -f64::MAX, f64::MAX), 0.5));
        assert!(at(f64::MAX, -1.0, 1.0).is_some_and(|u| u > 1.0));
    }

    #[test]
    fn model_checks_height_fits_the_rows() {
        assert!(model_checks_height(0) >= 150);
        assert!(model_checks_height(4) < model_checks_height(5));
        assert!(model_checks_height(40) > model_checks_height(12));
        assert!(model_checks_height(usize::MAX) <= 20_000);
        let many: Vec<CheckBar> = (0..40)
            .map(|i| check(&format!("statistic {i}"), i as f64, 0.0, 20.0, i > 30))
            .collect();
        let svg = model_checks(&many, &style(model_checks_height(40)));
        assert_well_formed(&svg);
        assert!(has_text(&svg, "statistic 39"));
    }

    #[test]
    fn font_sizes_are_plain_numbers() {
        assert_plain_font_sizes(&model_checks(&example_checks(), &style(360)));
    }

    #[test]
    fn same_input_gives_same_bytes() {
        assert_eq!(
            model_checks(&example_checks(), &style(360)),
            model_checks(&example_checks(), &style(360))
        );
    }

    #[test]
    fn charts_stay_small() {
        assert_small(&model_checks(&example_checks(), &style(360)));
    }

    #[test]
    fn unicode_and_markup_survive_escaped() {
        let checks = [check("<b>&", 1.0, 0.0, 2.0, true)];
        let svg = model_checks(&checks, &style(model_checks_height(1)));
        assert!(svg.contains("&lt;b&gt;&amp;") && !svg.contains("<b>"));
    }

    #[test]
    fn degenerate_inputs_do_not_panic() {
        let styles = degenerate_styles(style(360));
        let check_cases: Vec<Vec<CheckBar>> = vec![
            Vec::new(),
            vec![check("", 0.0, 0.0, 0.0, false)],
            vec![check("nan", f64::NAN, f64::NAN, f64::NAN, true)],
            vec![check("inf", f64::INFINITY, f64::NEG_INFINITY, 1.0, true)],
            vec![check("huge", 1e300, -1e300, 1e300, false)],
            vec![check("tiny", 1e-300, 0.0, 2e-300, false)],
            vec![check(
                &"a very long statistic name ".repeat(20),
                1.0,
                0.0,
                2.0,
                true,
            )],
            (0..300)
                .map(|i| check("row", i as f64, 0.0, 1.0, i % 3 == 0))
                .collect(),
        ];
        for st in &styles {
            for c in &check_cases {
                assert_well_formed(&model_checks(c, st));
            }
        }
    }

    #[test]
    fn numbers_are_formatted_for_print() {
        let d = |lo, hi, m| row_decimals(&check("", m, lo, hi, false));
        assert_eq!(d(1.42, 2.95, 2.31), 2);
        assert_eq!(d(0.31, 0.96, 1.21), 2);
        assert_eq!(d(0.0, 1.0, 0.5), 1);
        assert_eq!(d(1000.0, 1000.5, 1000.2), 1);
        assert_eq!(d(1000.0, 1000.5, 1000.25), 2);
    }
}
