//! The look of the ISO 230-2 axis charts, which the tolerance usage, compensation,
//! verification and trend charts borrow: tones, strokes, markers, dash patterns, how text is
//! measured, numbers and ranges, and the panel (axes with a zero line) a chart is drawn in.
//! Chosen for charts about 900 px wide shown about 16 cm wide.

use crate::chart_kit::{
    Area, AxesSpec, Chart, Conventions, DASHED, DOWN, Failed, INK, MUTED, Marker, Px, SOLID,
    Stroke, UP, build_axes, extent, fmt_fixed_for_print, padded_range, sig_decimals,
};
use plotters::prelude::*;

// ---------------------------------------------------------------------------------------------
// Look

pub(crate) const UP_LIGHT: RGBColor = RGBColor(0x5F, 0x7F, 0xB0);
pub(crate) const DOWN_LIGHT: RGBColor = RGBColor(0xBE, 0x62, 0x62);

/// Text size of the span labels, in SVG pixels (the `font-size` written into the SVG).
pub(super) const SPAN_PX: f64 = 14.0;

/// Dash patterns in pixels: on, off, on, off …
pub(crate) const DASHED_THIN: &[f64] = &[6.0, 4.0];
const DASH_DOT: &[f64] = &[9.0, 3.5, 2.0, 3.5];

/// How these charts measure text (see [`Conventions`]).
pub(crate) const KIT: Conventions = Conventions {
    narrow_superscripts: false,
};

pub(super) const MEAN_UP: Stroke = Stroke::new(UP, 2, SOLID);
pub(super) const MEAN_DOWN: Stroke = Stroke::new(DOWN, 2, DASHED);
pub(super) const LIMIT_UP: Stroke = Stroke::new(UP_LIGHT, 1, SOLID);
pub(super) const LIMIT_DOWN: Stroke = Stroke::new(DOWN_LIGHT, 1, DASHED_THIN);
pub(super) const MEAN_BIDIR: Stroke = Stroke::new(INK, 1, DASH_DOT);
pub(super) const MARK_MEAN_UP: (Marker, RGBColor) = (Marker::Dot(4), UP);
pub(super) const MARK_MEAN_DOWN: (Marker, RGBColor) = (Marker::Triangle(5), DOWN);
pub(super) const MARK_READ_UP: (Marker, RGBColor) = (Marker::Dot(2), UP_LIGHT);
pub(super) const MARK_READ_DOWN: (Marker, RGBColor) = (Marker::TriangleOutline(3), DOWN_LIGHT);

// ---------------------------------------------------------------------------------------------
// Numbers

/// Three significant digits, at most nine decimals.
pub(super) fn fmt_sig(v: f64) -> String {
    fmt_fixed_for_print(v, sig_decimals(v))
}

/// The x range: the targets with 4 % to spare; a single target gets a window around it.
pub(super) fn x_range(positions: &[f64]) -> Option<(f64, f64)> {
    padded_range(positions.iter().copied(), 0.04)
}

/// The y range: every value and zero, padded by 8 %.
pub(crate) fn y_range(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
    let (lo, hi) = extent(values.into_iter().chain([0.0]))?;
    let span = hi - lo;
    // Zero is inside, so only data that is all (practically) zero has no extent.
    let (lo, hi) = if span < 1e-9 {
        (lo - 1.0, hi + 1.0)
    } else {
        (lo - span * 0.08, hi + span * 0.08)
    };
    (lo.is_finite() && hi.is_finite() && hi > lo).then_some((lo, hi))
}

// ---------------------------------------------------------------------------------------------
// Drawing primitives (in backend pixels, on the root area)

pub(crate) fn to_px(c: (i32, i32)) -> Px {
    (c.0 as f64, c.1 as f64)
}

// ---------------------------------------------------------------------------------------------
// Panels

/// Builds one panel's chart with grid, ticks, frame and zero line.
pub(crate) fn build_panel<'a>(
    area: &'a Area,
    frame: &AxesSpec,
    y_label_w: u32,
) -> Result<Chart<'a>, Failed> {
    let chart = build_axes(area, frame, y_label_w)?;

    // The zero line.
    // (`area` draws in its own pixels; the chart reports backend pixels.)
    let (bx, by) = area.get_base_pixel();
    let (xr, _) = chart.plotting_area().get_pixel_range();
    let (l, r) = (xr.start - bx, xr.end - 1 - bx);
    let zero = chart.backend_coord(&(frame.x.0, 0.0)).1 - by;
    area.draw(&PathElement::new(
        vec![(l, zero), (r, zero)],
        MUTED.stroke_width(1),
    ))?;
    Ok(chart)
}

/// Pixel points of a per-target curve (non-finite values are skipped).
pub fn curve(chart: &Chart, positions: &[f64], values: &[f64]) -> Vec<Px> {
    positions
        .iter()
        .zip(values)
        .filter(|(x, v)| x.is_finite() && v.is_finite())
        .map(|(x, v)| to_px(chart.backend_coord(&(*x, *v))))
        .collect()
}

#[cfg(test)]
pub(crate) mod testing {
    //! What the tests of the ISO 230-2 charts (and of the tolerance usage) share.

    use super::super::axis_chart::{AxisChart, DirectionSeries, Span};
    use crate::chart_kit::Style;
    use crate::chart_kit::svg_probe::attr_values;

    pub(crate) fn style() -> Style {
        Style {
            width_px: 900,
            height_px: 420,
        }
    }

    /// The ISO 230-2 Table 2 example: 11 targets, n = 5, k = 2.
    pub(crate) fn iso_example() -> AxisChart {
        let positions = vec![
            6.711, 175.077, 340.251, 509.912, 674.140, 843.192, 1009.475, 1175.001, 1342.648,
            1510.000, 1750.920,
        ];
        let up = [
            -1.60, -0.70, -0.34, -0.94, -2.16, -3.34, -4.14, -4.28, -4.10, -3.72, -3.96,
        ];
        let down = [
            2.26, 3.42, 3.42, 2.78, 1.44, 0.24, -0.60, -0.62, -0.20, -0.30, -0.48,
        ];
        let s_up = [
            0.35, 0.42, 0.50, 0.30, 0.62, 0.55, 0.70, 0.65, 0.50, 0.45, 0.75,
        ];
        let s_down = [
            0.60, 0.45, 0.30, 0.52, 0.40, 0.66, 0.38, 0.71, 0.55, 0.48, 0.35,
        ];
        let offsets = [-1.2, -0.4, 0.3, 0.5, 0.8];
        let series = |m: &[f64], s: &[f64]| DirectionSeries {
            mean: m.to_vec(),
            upper: Some(m.iter().zip(s).map(|(a, b)| a + 2.0 * b).collect()),
            lower: Some(m.iter().zip(s).map(|(a, b)| a - 2.0 * b).collect()),
            deviations: m
                .iter()
                .zip(s)
                .map(|(a, b)| offsets.iter().map(|o| a + o * b).collect())
                .collect(),
        };
        AxisChart {
            mean: up.iter().zip(&down).map(|(a, b)| (a + b) / 2.0).collect(),
            positions,
            position_label: "Target position Pi / mm".to_string(),
            deviation_label: "Positional deviation / µm".to_string(),
            up: series(&up, &s_up),
            down: series(&down, &s_down),
            band_label: "X̄ ± 2S".to_string(),
            spans: vec![
                span("A", 4.01, -5.58),
                span("E", 3.42, -4.28),
                span("M", 1.54, -2.45),
            ],
        }
    }

    pub(crate) fn span(label: &str, upper: f64, lower: f64) -> Span {
        Span {
            label: label.to_string(),
            upper,
            lower,
        }
    }

    /// An axis measured once per target (n = 1): no limit curves.
    pub(crate) fn single_run(targets: usize) -> AxisChart {
        let positions: Vec<f64> = (0..targets).map(|i| 20.0 + 100.0 * i as f64).collect();
        let up: Vec<f64> = (0..targets).map(|i| (i as f64 * 0.4).sin() * 3.0).collect();
        let down: Vec<f64> = up.iter().map(|v| v + 2.0).collect();
        let series = |m: &[f64]| DirectionSeries {
            mean: m.to_vec(),
            upper: None,
            lower: None,
            deviations: m.iter().map(|v| vec![*v]).collect(),
        };
        AxisChart {
            mean: up.iter().zip(&down).map(|(a, b)| (a + b) / 2.0).collect(),
            positions,
            position_label: "Target position Pi / mm".to_string(),
            deviation_label: "Positional deviation / µm".to_string(),
            up: series(&up),
            down: series(&down),
            band_label: "X̄ ± 3S".to_string(),
            spans: Vec::new(),
        }
    }

    /// Degenerate and hostile charts: empty, one or two targets, flat, tiny, ragged, huge,
    /// far out, with many spans.
    pub(crate) fn degenerate_cases() -> Vec<AxisChart> {
        let flat = |v: f64| DirectionSeries {
            mean: vec![v; 3],
            upper: Some(vec![v; 3]),
            lower: Some(vec![v; 3]),
            deviations: vec![vec![v; 2]; 3],
        };
        let mut cases = vec![
            AxisChart::default(),
            single_run(1),
            single_run(2),
            AxisChart {
                positions: vec![5.0; 3],
                up: flat(0.0),
                down: flat(0.0),
                mean: vec![0.0; 3],
                ..AxisChart::default()
            },
            AxisChart {
                positions: vec![0.0, 1.0, 2.0],
                up: flat(7.25),
                down: flat(7.25),
                spans: vec![span("A", 7.25, 7.25)],
                ..AxisChart::default()
            },
            AxisChart {
                positions: vec![0.0, 1e-12, 2e-12],
                up: flat(1e-300),
                down: flat(-1e-300),
                ..AxisChart::default()
            },
            AxisChart {
                positions: vec![1.0, 2.0, 3.0],
                up: flat(1e-6),
                down: flat(1.000001e-6),
                ..AxisChart::default()
            },
        ];
        // Ragged and hostile data: lengths that disagree, non-finite values, huge values.
        let mut ragged = iso_example();
        ragged.up.mean.truncate(4);
        ragged.down.upper = Some(vec![1.0]);
        ragged.down.deviations.push(vec![f64::NAN, f64::INFINITY]);
        ragged.mean = vec![f64::NAN, 2.0, f64::NEG_INFINITY];
        ragged.spans.push(span("Z", f64::INFINITY, 0.0));
        ragged.spans.push(span("W", -1.0, 2.0));
        cases.push(ragged);
        let mut huge = iso_example();
        huge.up.mean[0] = 1e300;
        huge.down.mean[0] = -1e300;
        cases.push(huge);
        let mut far = iso_example();
        far.positions = vec![-1e300, 1e300];
        cases.push(far);
        let mut many_spans = iso_example();
        many_spans.spans = (0..25)
            .map(|i| span(&format!("Span number {i}"), i as f64, -(i as f64)))
            .collect();
        cases.push(many_spans);
        cases
    }

    /// Every font size is a plain number (at most two decimals).
    pub(crate) fn assert_plain_font_sizes(svg: &str) {
        for size in attr_values(svg, "font-size") {
            let decimals = size.split('.').nth(1).map_or(0, str::len);
            assert!(decimals <= 2, "font-size {size}");
        }
    }

    /// A chart stays small: under 80 000 bytes and 1 000 elements.
    pub(crate) fn assert_small(svg: &str) {
        let elements = svg.matches('<').count();
        assert!(svg.len() < 80_000, "{} bytes", svg.len());
        assert!(elements < 1_000, "{elements} elements");
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chart_kit::ticks;

    #[test]
    fn y_range_covers_everything_with_padding() {
        let (lo, hi) = y_range([-5.58, 4.36, 1.0]).expect("range");
        let span = 4.36 + 5.58;
        assert!((lo - (-5.58 - 0.08 * span)).abs() < 1e-9);
        assert!((hi - (4.36 + 0.08 * span)).abs() < 1e-9);
        // Zero is always inside.
        let (lo, hi) = y_range([3.0, 4.0]).expect("range");
        assert!(lo < 0.0 && hi > 4.0);
        // All equal (zero) still gives a usable range.
        let (lo, hi) = y_range([0.0, 0.0]).expect("range");
        assert!(lo < 0.0 && hi > 0.0);
        // Non-finite values are ignored.
        let (lo, hi) = y_range([f64::NAN, f64::INFINITY, 2.0]).expect("range");
        assert!(lo < 0.0 && hi > 2.0 && hi < 3.0);
        // A single target gets a window around it.
        let (lo, hi) = x_range(&[6.711]).expect("range");
        assert!(lo < 6.711 && hi > 6.711);
        assert!(x_range(&[]).is_none());
    }

    #[test]
    fn numbers_are_formatted_for_print() {
        assert_eq!(fmt_fixed_for_print(-1.5, 2), "−1.50");
        assert_eq!(fmt_fixed_for_print(-0.001, 2), "0.00");
        assert_eq!(fmt_fixed_for_print(1750.0, 0), "1750");
        assert_eq!(fmt_fixed_for_print(f64::INFINITY, 2), "∞");
        assert_eq!(fmt_fixed_for_print(-2.5e300, 0), "−2.50e300");
        assert_eq!(fmt_sig(9.59), "9.59");
        assert_eq!(fmt_sig(12.34), "12.3");
        assert_eq!(fmt_sig(0.0123), "0.0123");
        assert_eq!(fmt_sig(1234.0), "1234");
        assert_eq!(ticks((-6.0, 5.0), 8).1, 0);
        assert_eq!(ticks((-0.6, 0.5), 8).1, 1);
        assert_eq!(ticks((0.0, 3.12), 12).1, 1);
    }
}
