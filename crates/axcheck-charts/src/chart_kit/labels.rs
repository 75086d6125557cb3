//! Chart text set by Typst: the template (`chart` in `style.typ`) places each label over
//! the drawing as ordinary Typst text, which is shaped once per string, written as one text
//! run and stays searchable in the PDF.

use crate::chart_kit::scene::{Align, Reader, Scene, Text, put_len};
use serde::Serialize;

/// One label in chart pixels: its anchor point, where its baseline and start lie relative to
/// the anchor (before rotation), and how it is set.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Label {
    /// Anchor point; rotation turns about it.
    pub x: f64,
    pub y: f64,
    /// Left edge of the box the text is aligned in, relative to the anchor.
    pub dx: f64,
    /// Baseline relative to the anchor.
    pub dy: f64,
    /// Width of that box: wider than the text, which is aligned in it by `align`.
    pub w: f64,
    /// `left`, `center` or `right`.
    pub align: &'static str,
    /// Font size in pixels.
    pub size: f64,
    /// Colour as `#RRGGBB`.
    pub fill: String,
    pub bold: bool,
    /// Clockwise rotation in degrees about the anchor.
    pub rotate: f64,
    /// The text; lines separated by `\n` when labels were stacked (see [`stack`]).
    pub text: String,
    /// Distance between the baselines of stacked lines, 0 for one line.
    pub pitch: f64,
}

/// A chart's labels (`/charts/NAME.json`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChartLabels {
    /// Size of the chart's canvas in pixels: the labels' coordinate system.
    pub width: f64,
    pub height: f64,
    pub labels: Vec<Label>,
}

impl ChartLabels {
    /// The labels of a chart, columns stacked (see [`stack`]).
    pub fn of(scene: &Scene) -> ChartLabels {
        ChartLabels {
            width: scene.drawing.width.into(),
            height: scene.drawing.height.into(),
            labels: stack(scene.texts.iter().map(label).collect()),
        }
    }
}

/// The labels as bytes, after the drawing in `/charts/NAME.drawing` (read by
/// `chart-drawing`, which sets them): per label its numbers, then its alignment, look and
/// text. Integers and floats little-endian, strings as their length and UTF-8.
impl ChartLabels {
    pub fn encode(&self, out: &mut Vec<u8>) {
        let put_f64 = |out: &mut Vec<u8>, v: f64| out.extend_from_slice(&v.to_le_bytes());
        let put_str = |out: &mut Vec<u8>, s: &str| {
            put_len(out, s.len());
            out.extend_from_slice(s.as_bytes());
        };
        put_f64(out, self.width);
        put_f64(out, self.height);
        put_len(out, self.labels.len());
        for l in &self.labels {
            for v in [l.x, l.y, l.dx, l.dy, l.w, l.size, l.rotate, l.pitch] {
                put_f64(out, v);
            }
            let align = ["left", "center", "right"]
                .iter()
                .position(|a| *a == l.align);
            out.push(align.map_or(0, |i| i as u8));
            out.push(u8::from(l.bold));
            put_str(out, &l.fill);
            put_str(out, &l.text);
        }
    }

    /// The labels [`ChartLabels::encode`] wrote, which must fill `bytes`.
    pub fn decode(bytes: &[u8]) -> Option<ChartLabels> {
        let mut r = Reader(bytes);
        let (width, height) = (r.f64()?, r.f64()?);
        let mut labels = Vec::with_capacity(r.len()?);
        for _ in 0..labels.capacity() {
            let mut v = [0.0; 8];
            for x in &mut v {
                *x = r.f64()?;
            }
            let [x, y, dx, dy, w, size, rotate, pitch] = v;
            let [align, bold] = r.take::<2>()?;
            labels.push(Label {
                x,
                y,
                dx,
                dy,
                w,
                align: ["left", "center", "right"].get(usize::from(align))?,
                size,
                fill: r.str()?.to_string(),
                bold: bold != 0,
                rotate,
                text: r.str()?.to_string(),
                pitch,
            });
        }
        r.0.is_empty().then_some(ChartLabels {
            width,
            height,
            labels,
        })
    }
}

/// The label that sets `text` where plotters placed it.
fn label(text: &Text) -> Label {
    let size = text.size;
    // No glyph of the sans face is wider than 1.2 em: the box never makes the text wrap.
    let w = size * (1.2 * text.text.chars().count() as f64 + 2.0);
    let (align, dx) = match text.align {
        Align::Left => ("left", 0.0),
        Align::Center => ("center", -w / 2.0),
        Align::Right => ("right", -w),
    };
    Label {
        x: text.at.0.into(),
        y: text.at.1.into(),
        dx,
        dy: text.dy(),
        w,
        align,
        size,
        fill: text.colour.hex(),
        bold: text.bold,
        rotate: text.rotate.into(),
        text: text.text.clone(),
        pitch: 0.0,
    }
}

/// How far (pixels) a stacked line may lie from the baseline its label had: the tick
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

#[cfg(test)]
mod tests {
    use super::*;

    use crate::chart_kit::scene::{Baseline, Colour};

    #[test]
    fn every_text_becomes_a_label_with_its_placement() {
        let text = |at, align, baseline, size, rotate, s: &str| Text {
            at,
            align,
            baseline,
            size,
            colour: Colour(0x1A, 0x1A, 0x1A),
            bold: s.contains('<'),
            rotate,
            text: s.to_string(),
        };
        let mut scene = Scene::default();
        scene.drawing.width = 900;
        scene.drawing.height = 420;
        scene.texts = vec![
            text(
                (393, 414),
                Align::Center,
                Baseline::Bottom,
                15.5,
                0,
                "Target position Pi / mm",
            ),
            text(
                (50, 361),
                Align::Right,
                Baseline::Middle,
                14.0,
                0,
                "a < b & c",
            ),
            text(
                (4, 213),
                Align::Left,
                Baseline::Top,
                14.0,
                270,
                "Deviation / µm",
            ),
        ];
        let chart = ChartLabels::of(&scene);
        assert_eq!((chart.width, chart.height), (900.0, 420.0));
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
    fn labels_read_back_from_their_bytes() {
        let mut turned = tick(160.0, "Deviation / µm");
        turned.rotate = 270.0;
        turned.align = "left";
        turned.bold = true;
        let labels = ChartLabels {
            width: 900.0,
            height: 420.0,
            labels: vec![tick(100.0, "a\nb"), turned],
        };
        let mut bytes = Vec::new();
        labels.encode(&mut bytes);
        assert_eq!(ChartLabels::decode(&bytes), Some(labels));
        assert_eq!(ChartLabels::decode(&bytes[..bytes.len() - 1]), None);
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
}
