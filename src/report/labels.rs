//! Chart text set by Typst instead of by the SVG decoder.
//!
//! plotters writes every label of a chart as an SVG `<text>` element. Typst's SVG decoder
//! shapes each of them with a freshly built font face, and the PDF writer then draws them
//! glyph by glyph: about a fifth of the time of a report went into its ~170 chart labels.
//! [`split`] cuts the labels out of a chart SVG; the template (`chart` in `style.typ`) places
//! them over the remaining drawing as ordinary Typst text, which is shaped once per string,
//! written as one text run and stays searchable in the PDF.
//!
//! Only labels in exactly the form plotters writes are cut out; anything else stays in the
//! SVG and is drawn by the decoder as before, so the picture never loses text.

use super::compact::{attribute_list as attributes, is_colour};
use serde::Serialize;

/// One label in SVG pixels: its anchor point, where its baseline and start lie relative to
/// the anchor (before rotation), and how it is set.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Label {
    /// Anchor point (`x`, `y` of the SVG element); rotation turns about it.
    pub x: f64,
    pub y: f64,
    /// Left edge of the box the text is aligned in, relative to the anchor.
    pub dx: f64,
    /// Baseline relative to the anchor (the element's `dy`).
    pub dy: f64,
    /// Width of that box: wider than the text, which is aligned in it by `align`.
    pub w: f64,
    /// `left`, `center` or `right` (SVG `text-anchor` start, middle, end).
    pub align: &'static str,
    /// Font size in SVG pixels.
    pub size: f64,
    /// Colour as `#RRGGBB`.
    pub fill: String,
    pub bold: bool,
    /// Clockwise rotation in degrees about the anchor (SVG `rotate(a, x, y)`).
    pub rotate: f64,
    /// The text; lines separated by `\n` when labels were stacked (see [`stack`]).
    pub text: String,
    /// Distance between the baselines of stacked lines, 0 for one line.
    pub pitch: f64,
}

/// A chart split into its drawing and its labels.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SplitChart {
    /// The SVG without the labels that were cut out.
    #[serde(skip)]
    pub svg: String,
    /// Size of the SVG's canvas in pixels: the labels' coordinate system.
    pub width: f64,
    pub height: f64,
    pub labels: Vec<Label>,
}

/// Cuts the labels out of `svg`, a chart written by plotters' SVG backend in `family`.
pub fn split(svg: &str, family: &str) -> SplitChart {
    let (width, height) = canvas_size(svg).unwrap_or((0.0, 0.0));
    let mut out = String::with_capacity(svg.len());
    let mut labels = Vec::new();
    let mut rest = svg;
    while let Some(start) = rest.find("<text ") {
        let Some(len) = rest[start..].find("</text>") else {
            break;
        };
        let end = start + len + "</text>".len();
        out.push_str(&rest[..start]);
        match parse_label(&rest[start..end], family) {
            Some(label) if width > 0.0 => {
                labels.push(label);
                // plotters ends each element with a newline; drop it with the element.
                if rest[end..].starts_with('\n') {
                    rest = &rest[end + 1..];
                    continue;
                }
            }
            _ => out.push_str(&rest[start..end]),
        }
        rest = &rest[end..];
    }
    out.push_str(rest);
    SplitChart {
        svg: out,
        width,
        height,
        labels: stack(labels),
    }
}

/// `width` and `height` of the root `<svg>` element, in pixels.
fn canvas_size(svg: &str) -> Option<(f64, f64)> {
    let start = svg.find("<svg ")?;
    let open = &svg[start..start + svg[start..].find('>')?];
    let attrs = attributes(&open["<svg ".len()..])?;
    let get = |key: &str| -> Option<f64> {
        let v: f64 = attrs.iter().find(|(k, _)| *k == key)?.1.parse().ok()?;
        (v.is_finite() && v > 0.0).then_some(v)
    };
    Some((get("width")?, get("height")?))
}

/// A label from one `<text …>…</text>` element in plotters' form, else `None`.
fn parse_label(element: &str, family: &str) -> Option<Label> {
    let open_end = element.find('>')?;
    let attrs = attributes(&element["<text ".len()..open_end])?;
    let content = &element[open_end + 1..element.len() - "</text>".len()];
    let mut x = None;
    let mut y = None;
    let mut dy = None;
    let mut align = None;
    let mut size = None;
    let mut fill = None;
    let mut bold = false;
    let mut rotate = 0.0;
    let mut family_ok = false;
    for (key, value) in attrs {
        match key {
            "x" => x = value.parse::<f64>().ok(),
            "y" => y = value.parse::<f64>().ok(),
            "dy" => dy = Some(value),
            "text-anchor" => {
                align = Some(match value {
                    "start" => "left",
                    "middle" => "center",
                    "end" => "right",
                    _ => return None,
                })
            }
            "font-family" => family_ok = value == family,
            "font-size" => size = value.parse::<f64>().ok(),
            "opacity" if value == "1" => {}
            "fill" if is_colour(value) => fill = Some(value.to_string()),
            "font-weight" if value == "bold" => bold = true,
            "transform" => rotate = parse_rotation(value, x?, y?)?,
            _ => return None,
        }
    }
    let (x, y, size) = (x?, y?, size?);
    if !(x.is_finite() && y.is_finite() && size.is_finite() && size > 0.0 && family_ok) {
        return None;
    }
    // The SVG decoder's units: 1 em is the font size, 1 ex half of it.
    let dy = match dy? {
        "0.76em" => 0.76 * size,
        "0.5ex" => 0.25 * size,
        "-0.5ex" => -0.25 * size,
        _ => return None,
    };
    let text = unescape(content)?;
    if text.is_empty() {
        return None;
    }
    // No glyph of the sans face is wider than 1.2 em: the box never makes the text wrap.
    let w = size * (1.2 * text.chars().count() as f64 + 2.0);
    let align = align?;
    let dx = match align {
        "left" => 0.0,
        "center" => -w / 2.0,
        _ => -w,
    };
    Some(Label {
        x,
        y,
        dx,
        dy,
        w,
        align,
        size,
        fill: fill?,
        bold,
        rotate,
        text,
        pitch: 0.0,
    })
}

/// How far (SVG pixels) a stacked line may lie from the baseline its label had: the tick
/// positions plotters writes are rounded to whole pixels, so evenly spaced ticks are up to
/// a pixel apart from even (0.3 pt on the page).
const STACK_TOLERANCE_PX: f64 = 0.75;

/// Labels that form a column (same anchor `x`, alignment and look, one line each, baselines
/// evenly spaced: an axis' tick values, a chart's row names) merged into one label of
/// several lines. Typst's cost is per placed element, not per line, and a chart's labels
/// are mostly such columns. The order of labels changes (they are drawn over the chart,
/// apart from each other); the result is deterministic.
pub fn stack(labels: Vec<Label>) -> Vec<Label> {
    // Candidates by look and anchor, in order of first appearance.
    let mut groups: Vec<Vec<Label>> = Vec::new();
    for label in labels {
        match groups.iter_mut().find(|g| stackable(&g[0], &label)) {
            Some(group) => group.push(label),
            None => groups.push(vec![label]),
        }
    }
    let mut out = Vec::new();
    for mut group in groups {
        group.sort_by(|a, b| baseline(a).total_cmp(&baseline(b)));
        let mut column: Vec<Label> = Vec::new();
        for label in group {
            if !evenly_spaced(column.iter().chain([&label])) {
                out.extend(merge(std::mem::take(&mut column)));
            }
            column.push(label);
        }
        out.extend(merge(column));
    }
    out
}

fn stackable(a: &Label, b: &Label) -> bool {
    a.rotate == 0.0
        && b.rotate == 0.0
        && a.pitch == 0.0
        && b.pitch == 0.0
        && a.x == b.x
        && a.align == b.align
        && a.size == b.size
        && a.fill == b.fill
        && a.bold == b.bold
        && !a.text.contains('\n')
        && !b.text.contains('\n')
}

fn baseline(l: &Label) -> f64 {
    l.y + l.dy
}

/// Whether the baselines, in order, are strictly monotonic and within the tolerance of an
/// even spacing that keeps lines apart.
fn evenly_spaced<'a>(labels: impl Iterator<Item = &'a Label>) -> bool {
    let lines: Vec<f64> = labels.map(baseline).collect();
    let n = lines.len();
    if n < 2 {
        return true;
    }
    let pitch = (lines[n - 1] - lines[0]) / (n - 1) as f64;
    pitch.abs() > 0.0
        && lines
            .windows(2)
            .all(|w| (w[1] - w[0]).signum() == pitch.signum())
        && lines
            .iter()
            .enumerate()
            .all(|(i, y)| (y - (lines[0] + pitch * i as f64)).abs() <= STACK_TOLERANCE_PX)
}

/// One label for a column sorted top to bottom (a single label as it is).
fn merge(mut column: Vec<Label>) -> Option<Label> {
    if column.len() < 2 {
        return column.pop();
    }
    let n = column.len();
    let pitch = (baseline(&column[n - 1]) - baseline(&column[0])) / (n - 1) as f64;
    let text = column
        .iter()
        .map(|l| l.text.as_str())
        .collect::<Vec<_>>()
        .join("\n");
    let w = column.iter().map(|l| l.w).fold(0.0, f64::max);
    let first = column.swap_remove(0);
    Some(Label {
        text,
        pitch,
        w,
        dx: match first.align {
            "left" => 0.0,
            "center" => -w / 2.0,
            _ => -w,
        },
        ..first
    })
}

/// The angle of `rotate(a, x, y)` turning about the label's own anchor.
fn parse_rotation(value: &str, x: f64, y: f64) -> Option<f64> {
    let inner = value.strip_prefix("rotate(")?.strip_suffix(')')?;
    let parts: Vec<f64> = inner
        .split(',')
        .map(|p| p.trim().parse::<f64>().ok())
        .collect::<Option<_>>()?;
    match parts[..] {
        [a, cx, cy] if cx == x && cy == y && a.is_finite() => Some(a),
        _ => None,
    }
}

/// The element's text as SVG shows it: entities decoded, white space collapsed and trimmed
/// (SVG's default `xml:space`); `None` for markup or entities plotters does not write.
fn unescape(content: &str) -> Option<String> {
    if content.contains('<') {
        return None;
    }
    let mut out = String::with_capacity(content.len());
    let mut rest = content;
    while let Some(at) = rest.find('&') {
        out.push_str(&rest[..at]);
        let semi = rest[at..].find(';')?;
        out.push(match &rest[at..at + semi + 1] {
            "&lt;" => '<',
            "&gt;" => '>',
            "&amp;" => '&',
            "&quot;" => '"',
            "&apos;" => '\'',
            _ => return None,
        });
        rest = &rest[at + semi + 1..];
    }
    out.push_str(rest);
    Some(out.split_whitespace().collect::<Vec<_>>().join(" "))
}

#[cfg(test)]
mod tests {
    use super::*;

    const SVG: &str = "<svg width=\"900\" height=\"420\" viewBox=\"0 0 900 420\" xmlns=\"http://www.w3.org/2000/svg\">\n\
<rect x=\"0\" y=\"0\" width=\"900\" height=\"420\" opacity=\"1\" fill=\"#FFFFFF\" stroke=\"none\"/>\n\
<text x=\"393\" y=\"414\" dy=\"-0.5ex\" text-anchor=\"middle\" font-family=\"Inter\" font-size=\"15.5\" opacity=\"1\" fill=\"#1A1A1A\">\n\
Target position Pi / mm\n\
</text>\n\
<line opacity=\"1\" stroke=\"#E2E2E2\" stroke-width=\"1\" x1=\"80\" y1=\"363\" x2=\"80\" y2=\"62\"/>\n\
<text x=\"50\" y=\"361\" dy=\"0.5ex\" text-anchor=\"end\" font-family=\"Inter\" font-size=\"14\" opacity=\"1\" fill=\"#1A1A1A\" font-weight=\"bold\">\n\
a &lt; b &amp; c\n\
</text>\n\
<text x=\"4\" y=\"213\" dy=\"0.76em\" text-anchor=\"start\" font-family=\"Inter\" font-size=\"14\" opacity=\"1\" fill=\"#5F5F5F\" transform=\"rotate(270, 4, 213)\">\n\
Deviation / µm\n\
</text>\n\
</svg>\n";

    #[test]
    fn every_plotters_label_is_cut_out_with_its_placement() {
        let chart = split(SVG, "Inter");
        assert_eq!((chart.width, chart.height), (900.0, 420.0));
        assert!(!chart.svg.contains("<text"), "{}", chart.svg);
        assert!(chart.svg.contains("<line opacity"));
        assert!(chart.svg.ends_with("</svg>\n"));
        let texts: Vec<&str> = chart.labels.iter().map(|l| l.text.as_str()).collect();
        assert_eq!(
            texts,
            ["Target position Pi / mm", "a < b & c", "Deviation / µm"]
        );

        let title = &chart.labels[0];
        assert_eq!((title.x, title.y, title.size), (393.0, 414.0, 15.5));
        assert_eq!(title.dy, -0.25 * 15.5);
        assert_eq!(title.align, "center");
        assert_eq!(title.dx, -title.w / 2.0);
        assert!(title.w > 15.5 * 23.0);
        assert!(!title.bold);

        let tick = &chart.labels[1];
        assert_eq!((tick.align, tick.dx, tick.dy), ("right", -tick.w, 3.5));
        assert!(tick.bold);
        assert_eq!(tick.fill, "#1A1A1A");

        let axis = &chart.labels[2];
        assert_eq!((axis.align, axis.dx, axis.rotate), ("left", 0.0, 270.0));
        assert_eq!(axis.dy, 0.76 * 14.0);
        assert_eq!(axis.fill, "#5F5F5F");
    }

    fn tick(y: f64, text: &str) -> Label {
        Label {
            x: 50.0,
            y,
            dx: -60.0,
            dy: 3.5,
            w: 60.0,
            align: "right",
            size: 14.0,
            fill: "#1A1A1A".into(),
            bold: false,
            rotate: 0.0,
            text: text.into(),
            pitch: 0.0,
        }
    }

    #[test]
    fn a_column_of_evenly_spaced_labels_becomes_one_label_of_lines_top_down() {
        // Tick values bottom to top, at pixel-rounded positions 33 and 32 px apart.
        let ticks = vec![
            tick(361.0, "−4"),
            tick(328.0, "−2"),
            tick(296.0, "0"),
            tick(263.0, "2"),
            tick(231.0, "4"),
        ];
        let stacked = stack(ticks);
        assert_eq!(stacked.len(), 1);
        let column = &stacked[0];
        assert_eq!(column.text, "4\n2\n0\n−2\n−4");
        assert_eq!((column.y, column.dy), (231.0, 3.5));
        assert_eq!(column.pitch, 32.5);
        assert_eq!((column.align, column.dx, column.w), ("right", -60.0, 60.0));
    }

    #[test]
    fn labels_apart_in_place_or_look_stay_apart() {
        // Uneven spacing: a column runs while it stays even, then a new one starts.
        let uneven = stack(vec![
            tick(100.0, "a"),
            tick(120.0, "b"),
            tick(140.0, "c"),
            tick(190.0, "d"),
        ]);
        let texts: Vec<&str> = uneven.iter().map(|l| l.text.as_str()).collect();
        assert_eq!(texts, ["a\nb\nc", "d"]);
        let mut other_x = tick(120.0, "b");
        other_x.x = 51.0;
        let mut bold = tick(140.0, "c");
        bold.bold = true;
        let mut turned = tick(160.0, "d");
        turned.rotate = 270.0;
        let apart = stack(vec![tick(100.0, "a"), other_x, bold, turned]);
        assert_eq!(apart.len(), 4);
        assert!(apart.iter().all(|l| l.pitch == 0.0));
    }

    #[test]
    fn labels_in_another_form_stay_in_the_drawing() {
        for odd in [
            "font-family=\"Inter\" font-size=\"14\" opacity=\"0.5\"",
            "font-family=\"Other\" font-size=\"14\" opacity=\"1\"",
            "font-family=\"Inter\" font-size=\"14\" opacity=\"1\" font-style=\"italic\"",
            "font-family=\"Inter\" font-size=\"-3\" opacity=\"1\"",
        ] {
            let svg = SVG.replace(
                "font-family=\"Inter\" font-size=\"15.5\" opacity=\"1\"",
                odd,
            );
            let chart = split(&svg, "Inter");
            assert_eq!(chart.labels.len(), 2, "{odd}");
            assert!(chart.svg.contains("Target position Pi / mm"), "{odd}");
        }
        let rotated_elsewhere = SVG.replace("rotate(270, 4, 213)", "rotate(270, 5, 213)");
        assert_eq!(split(&rotated_elsewhere, "Inter").labels.len(), 2);
        let entity = SVG.replace("&amp;", "&#38;");
        assert_eq!(split(&entity, "Inter").labels.len(), 2);
        let no_size = SVG.replace("width=\"900\"", "");
        let chart = split(&no_size, "Inter");
        assert!(chart.labels.is_empty());
        assert_eq!(chart.svg, no_size);
    }
}
