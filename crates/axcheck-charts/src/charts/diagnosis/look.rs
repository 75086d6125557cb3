//! The look the diagnosis section's charts share — the residuals (with their time panels),
//! the periodogram and the model checks of [`crate::charts::check`]: tones, strokes,
//! markers, how text is measured, and the text, number, drawing and axes helpers they all use.
//! Chosen for charts about 900 px wide shown about 16 cm wide.

use super::frame::Frame;
use crate::chart_kit::{
    Area, AxesSpec, Chart, Conventions, DASHED, DOWN, Failed, INK, MUTED, Marker, SOLID, Stroke,
    UP, fmt_fixed_for_print, sig_decimals,
};
use plotters::prelude::*;

// ---------------------------------------------------------------------------------------------
// Look (the tones of the report's other charts)

/// ↓ readings: a lighter tone than ↑ so the two also differ in grey print.
pub(super) const DOWN_MID: RGBColor = RGBColor(0xB4, 0x4E, 0x4E);
/// Light bands: the ±2σ band, the unresolvable region, the simulated 95 % band.
pub(super) const BAND: RGBColor = RGBColor(0xE8, 0xE8, 0xE8);
pub(super) const SHADE: RGBColor = RGBColor(0xE4, 0xE4, 0xE4);
pub(crate) const CHECK_BAND: RGBColor = RGBColor(0xDD, 0xDD, 0xDD);
pub(super) const CURVE: RGBColor = RGBColor(0x1F, 0x3A, 0x6E);
pub(crate) const OUTSIDE: RGBColor = RGBColor(0x6E, 0x14, 0x14);

/// Text size of the notes, in SVG pixels (the `font-size` written into the SVG).
pub(crate) const NOTE_PX: f64 = 12.5;

pub(super) const FIT: Stroke = Stroke::new(INK, 2, SOLID);
pub(super) const POWER: Stroke = Stroke::new(CURVE, 2, SOLID);
pub(super) const THRESHOLD: Stroke = Stroke::new(DOWN, 2, DASHED);
pub(super) const MARKED: Stroke = Stroke::new(MUTED, 1, SOLID);
pub(super) const MARK_UP: (Marker, RGBColor) = (Marker::Dot(4), UP);
pub(super) const MARK_DOWN: (Marker, RGBColor) = (Marker::OpenTriangle(4), DOWN_MID);
pub(crate) const MARK_INSIDE: (Marker, RGBColor) = (Marker::Dot(5), INK);
pub(crate) const MARK_OUTSIDE: (Marker, RGBColor) = (Marker::Diamond(7), OUTSIDE);

/// How these charts measure text (see [`Conventions`]).
pub(crate) const KIT: Conventions = Conventions {
    narrow_superscripts: true,
};

// ---------------------------------------------------------------------------------------------
// Text

/// Bold text runs about 6 % wider.
pub(crate) fn bold_width(text: &str, px: f64) -> f64 {
    KIT.text_width(text, px) * 1.06
}

/// The unit of an axis description "Quantity / unit" (empty when there is none).
pub(super) fn unit_of(label: &str) -> &str {
    label.rsplit_once(" / ").map_or("", |(_, unit)| unit.trim())
}

// ---------------------------------------------------------------------------------------------
// Numbers

/// Up to three significant digits, trailing zeros dropped ("0.35", "12.3", "1750").
pub(super) fn fmt_short(v: f64) -> String {
    let s = fmt_fixed_for_print(v, sig_decimals(v));
    if s.contains('.') && !s.contains('e') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// A range symmetric about zero holding every value with 10 % to spare (residuals scatter
/// about zero, so zero sits in the middle); ±1 when everything is (practically) zero.
pub(super) fn symmetric_range(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
    let m = values
        .into_iter()
        .filter(|v| v.is_finite())
        .map(f64::abs)
        .fold(0.0, f64::max);
    let m = if m < 1e-9 { 1.0 } else { m * 1.1 };
    (m.is_finite() && (2.0 * m).is_finite()).then_some((-m, m))
}

// ---------------------------------------------------------------------------------------------
// Drawing primitives (in backend pixels, on the root area)

/// A filled arrow head with its tip at `tip`, pointing left (`dir` < 0) or right.
pub(crate) fn draw_arrow(
    root: &Area,
    tip: (i32, i32),
    dir: i32,
    half: i32,
    color: RGBColor,
) -> Result<(), Failed> {
    let back = tip.0 - dir.signum() * (half + 3);
    root.draw(&Polygon::new(
        vec![tip, (back, tip.1 - half), (back, tip.1 + half)],
        color.filled(),
    ))?;
    Ok(())
}

pub(crate) fn fill_rect(
    root: &Area,
    a: (i32, i32),
    b: (i32, i32),
    color: RGBColor,
) -> Result<(), Failed> {
    if a.0 != b.0 && a.1 != b.1 {
        root.draw(&Rectangle::new([a, b], color.filled()))?;
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Axes

/// Builds the chart with grid, ticks and frame (no zero line: callers draw bands first).
pub(super) fn build_axes<'a>(
    area: &'a Area,
    spec: &AxesSpec,
    y_label_w: u32,
) -> Result<(Chart<'a>, Frame), Failed> {
    let chart = crate::chart_kit::build_axes(area, spec, y_label_w)?;
    let frame = Frame::of(&chart, spec.x, spec.y);
    Ok((chart, frame))
}

pub(super) fn non_empty(text: &str) -> Option<&str> {
    Some(text.trim()).filter(|t| !t.is_empty())
}

#[cfg(test)]
pub(crate) mod testing {
    //! What the tests of the diagnosis section's charts share.

    use crate::chart_kit::Style;
    use crate::chart_kit::svg_probe::attr_values;

    pub(crate) fn style(height_px: u32) -> Style {
        Style {
            width_px: 900,
            height_px,
        }
    }

    /// A small deterministic generator (no dev-dependencies needed).
    pub(crate) struct Lcg(pub(crate) u64);

    impl Lcg {
        pub(crate) fn uniform(&mut self) -> f64 {
            self.0 = self
                .0
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            ((self.0 >> 11) as f64 + 0.5) / (1u64 << 53) as f64
        }

        pub(crate) fn normal(&mut self) -> f64 {
            let (u, v) = (self.uniform(), self.uniform());
            (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
        }
    }

    pub(crate) fn circles_in(svg: &str, color: &str) -> usize {
        svg.split("<circle")
            .skip(1)
            .filter(|p| p.contains(&format!("fill=\"{color}\"")))
            .count()
    }

    /// Every font size is a plain number (at most two decimals).
    pub(crate) fn assert_plain_font_sizes(svg: &str) {
        for size in attr_values(svg, "font-size") {
            let decimals = size.split('.').nth(1).map_or(0, str::len);
            assert!(decimals <= 2, "font-size {size}");
        }
    }

    /// A chart stays small: under 60 000 bytes and 1 500 elements.
    pub(crate) fn assert_small(svg: &str) {
        assert!(svg.len() < 60_000, "{} bytes", svg.len());
        assert!(svg.matches('<').count() < 1_500);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_formatted_for_print() {
        assert_eq!(fmt_fixed_for_print(-1.5, 2), "−1.50");
        assert_eq!(fmt_fixed_for_print(-0.001, 2), "0.00");
        assert_eq!(fmt_fixed_for_print(f64::NEG_INFINITY, 2), "−∞");
        assert_eq!(fmt_short(0.35), "0.35");
        assert_eq!(fmt_short(10.02), "10");
        assert_eq!(fmt_short(12.5), "12.5");
        assert_eq!(fmt_short(-0.0004567), "−0.000457");
        assert_eq!(unit_of("Residual / µm"), "µm");
        assert_eq!(unit_of("Reading order"), "");
    }
}
