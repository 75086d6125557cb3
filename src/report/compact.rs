//! Runs of like SVG elements drawn as one path.
//!
//! plotters writes every marker, tick and line segment of a chart as an element of its own:
//! a chart of 11 targets × 5 runs has about 250. Typst's SVG decoder and the PDF writer pay
//! per element (style resolution, a path object, a graphics state in the page's content
//! stream), which made the drawings about a seventh of the work of a report. [`merge_runs`]
//! draws each run of consecutive elements with the same paint as one `<path>` with a
//! subpath per element. Only opaque paint is merged, fills without a stroke and strokes
//! without a fill or dashes: there, painting the subpaths together gives the same pixels
//! as painting them one after the other, and keeping runs consecutive keeps the drawing
//! order. Any element in another form is kept as it is.

/// `svg` (as plotters writes it: one element per line) with runs of like elements merged.
pub fn merge_runs(svg: &str) -> String {
    let mut out = String::with_capacity(svg.len());
    let mut run: Option<Run> = None;
    let mut d = String::new();
    for line in svg.split_inclusive('\n') {
        d.clear();
        match shape(line.trim_end(), &mut d) {
            Some(paint) => match &mut run {
                Some(r) if r.paint == paint => {
                    r.d.push(' ');
                    r.d.push_str(&d);
                    r.count += 1;
                }
                _ => {
                    if let Some(r) = run.take() {
                        r.finish(&mut out);
                    }
                    run = Some(Run {
                        paint,
                        first_line: line,
                        d: d.clone(),
                        count: 1,
                    });
                }
            },
            None => {
                if let Some(r) = run.take() {
                    r.finish(&mut out);
                }
                out.push_str(line);
            }
        }
    }
    if let Some(r) = run.take() {
        r.finish(&mut out);
    }
    out
}

/// How a merged path is painted: a fill, or a stroke of a width, in an opaque colour.
#[derive(PartialEq)]
enum Paint<'a> {
    Fill(&'a str),
    Stroke(&'a str, &'a str),
}

/// Consecutive elements with one paint.
struct Run<'a> {
    paint: Paint<'a>,
    first_line: &'a str,
    d: String,
    count: usize,
}

impl Run<'_> {
    fn finish(self, out: &mut String) {
        if self.count == 1 {
            out.push_str(self.first_line);
            return;
        }
        match self.paint {
            Paint::Fill(colour) => {
                out.push_str("<path opacity=\"1\" fill=\"");
                out.push_str(colour);
                out.push_str("\" stroke=\"none\"");
            }
            Paint::Stroke(colour, width) => {
                out.push_str("<path fill=\"none\" opacity=\"1\" stroke=\"");
                out.push_str(colour);
                out.push_str("\" stroke-width=\"");
                out.push_str(width);
                out.push('"');
            }
        }
        out.push_str(" d=\"");
        out.push_str(&self.d);
        out.push_str("\"/>\n");
    }
}

/// The paint of one mergeable element, with its path data appended to `d`.
fn shape<'a>(line: &'a str, d: &mut String) -> Option<Paint<'a>> {
    let body = line.strip_prefix('<')?.strip_suffix("/>")?;
    let (tag, rest) = body.split_once(' ')?;
    let mut a = Attributes::default();
    for (key, value) in attributes(rest) {
        let slot = match key? {
            "opacity" => &mut a.opacity,
            "fill" => &mut a.fill,
            "stroke" => &mut a.stroke,
            "stroke-width" => &mut a.stroke_width,
            "points" => &mut a.points,
            "x1" => &mut a.x1,
            "y1" => &mut a.y1,
            "x2" => &mut a.x2,
            "y2" => &mut a.y2,
            "cx" => &mut a.cx,
            "cy" => &mut a.cy,
            "r" => &mut a.r,
            _ => return None,
        };
        *slot = Some(value);
    }
    if a.opacity != Some("1") {
        return None;
    }
    let stroke = |a: &Attributes<'a>| -> Option<Paint<'a>> {
        let colour = a.stroke.filter(|c| is_colour(c))?;
        let width = a.stroke_width?;
        let ok = width.parse::<f64>().is_ok_and(|w| w.is_finite() && w > 0.0);
        ok.then_some(Paint::Stroke(colour, width))
    };
    let fill = |a: &Attributes<'a>| a.fill.filter(|c| is_colour(c)).map(Paint::Fill);
    match tag {
        "polyline" if a.fill == Some("none") && a.has_only(&[1, 2, 3, 4, 5]) => {
            let paint = stroke(&a)?;
            (points(a.points?, d)? >= 2).then_some(paint)
        }
        "line" if a.has_only(&[1, 3, 4, 6, 7, 8, 9]) => {
            let paint = stroke(&a)?;
            d.push('M');
            push_pair(d, a.x1?, a.y1?)?;
            d.push_str(" L");
            push_pair(d, a.x2?, a.y2?)?;
            Some(paint)
        }
        "polygon" if a.has_only(&[1, 2, 5]) => {
            let paint = fill(&a)?;
            let n = points(a.points?, d)?;
            d.push_str(" Z");
            (n >= 3).then_some(paint)
        }
        "circle" if a.stroke == Some("none") && a.has_only(&[1, 2, 3, 4, 10, 11, 12]) => {
            let paint = fill(&a)?;
            let number = |v: &str| v.parse::<f64>().ok().filter(|v| v.is_finite());
            let (cx, cy, r) = (number(a.cx?)?, number(a.cy?)?, number(a.r?)?);
            if r <= 0.0 {
                return None;
            }
            // Two half-circle arcs from the leftmost point.
            d.push('M');
            push_number(d, cx - r);
            d.push(',');
            push_number(d, cy);
            for dx in [2.0 * r, -2.0 * r] {
                d.push_str(" a");
                push_number(d, r);
                d.push(',');
                push_number(d, r);
                d.push_str(" 0 1,0 ");
                push_number(d, dx);
                d.push_str(",0");
            }
            d.push_str(" Z");
            Some(paint)
        }
        _ => None,
    }
}

/// The attributes a mergeable element may have, by name.
#[derive(Default)]
struct Attributes<'a> {
    opacity: Option<&'a str>,
    fill: Option<&'a str>,
    stroke: Option<&'a str>,
    stroke_width: Option<&'a str>,
    points: Option<&'a str>,
    x1: Option<&'a str>,
    y1: Option<&'a str>,
    x2: Option<&'a str>,
    y2: Option<&'a str>,
    cx: Option<&'a str>,
    cy: Option<&'a str>,
    r: Option<&'a str>,
}

impl Attributes<'_> {
    /// Whether no attribute is set but those numbered in `allowed` (in field order from
    /// 1 = opacity); opacity is always required.
    fn has_only(&self, allowed: &[usize]) -> bool {
        let set = [
            self.opacity,
            self.fill,
            self.stroke,
            self.stroke_width,
            self.points,
            self.x1,
            self.y1,
            self.x2,
            self.y2,
            self.cx,
            self.cy,
            self.r,
        ];
        set.iter()
            .enumerate()
            .all(|(i, v)| v.is_none() || allowed.contains(&(i + 1)))
    }
}

/// Appends `x,y x,y …` (plotters' `points`) to `d` as `Mx,y Lx,y x,y …`; the number of
/// points, or `None` if one is not a pair of plain numbers.
fn points(text: &str, d: &mut String) -> Option<usize> {
    let mut n = 0;
    for pair in text.split_whitespace() {
        let (x, y) = pair.split_once(',')?;
        d.push_str(match n {
            0 => "M",
            1 => " L",
            _ => " ",
        });
        push_pair(d, x, y)?;
        n += 1;
    }
    Some(n)
}

/// Appends `x,y`, both plain decimal numbers as written (no exponent, no entity).
fn push_pair(d: &mut String, x: &str, y: &str) -> Option<()> {
    if !(is_plain_number(x) && is_plain_number(y)) {
        return None;
    }
    d.push_str(x);
    d.push(',');
    d.push_str(y);
    Some(())
}

/// `-`? digits (`.` digits)?, as plotters writes coordinates.
fn is_plain_number(v: &str) -> bool {
    let digits = v.strip_prefix('-').unwrap_or(v);
    let (int, frac) = digits.split_once('.').unwrap_or((digits, "0"));
    !int.is_empty()
        && !frac.is_empty()
        && int.bytes().all(|b| b.is_ascii_digit())
        && frac.bytes().all(|b| b.is_ascii_digit())
}

/// Appends `v`, an integer without a fraction (plotters' coordinates are whole pixels).
fn push_number(d: &mut String, v: f64) {
    use std::fmt::Write;
    // Integer formatting is several times cheaper than `f64`'s shortest round trip.
    let _ = if v.fract() == 0.0 && v.abs() < 1e15 {
        write!(d, "{}", v as i64)
    } else {
        write!(d, "{v}")
    };
}

/// `#RRGGBB`, as plotters writes colours.
pub(crate) fn is_colour(value: &str) -> bool {
    value.len() == 7 && value.starts_with('#') && value[1..].bytes().all(|b| b.is_ascii_hexdigit())
}

/// `key="value"` pairs of an opening tag's attribute text; `None` if malformed.
pub(crate) fn attribute_list(text: &str) -> Option<Vec<(&str, &str)>> {
    attributes(text.trim_end_matches('/'))
        .map(|(key, value)| Some((key?, value)))
        .collect()
}

/// `key="value"` pairs of an opening tag; an item is `None` where the text is malformed.
fn attributes(text: &str) -> impl Iterator<Item = (Option<&str>, &str)> {
    let mut rest = text.trim();
    std::iter::from_fn(move || {
        if rest.is_empty() {
            return None;
        }
        let Some(eq) = rest.find("=\"") else {
            rest = "";
            return Some((None, ""));
        };
        let key = &rest[..eq];
        let Some(len) = rest[eq + 2..].find('"') else {
            rest = "";
            return Some((None, ""));
        };
        let value = &rest[eq + 2..eq + 2 + len];
        rest = rest[eq + 2 + len + 1..].trim_start();
        Some((Some(key), value))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn runs_of_like_elements_become_one_path_in_drawing_order() {
        let svg = "<svg width=\"10\" height=\"10\">\n\
<polyline fill=\"none\" opacity=\"1\" stroke=\"#9A9A9A\" stroke-width=\"1\" points=\"53,361 57,361 \"/>\n\
<polyline fill=\"none\" opacity=\"1\" stroke=\"#9A9A9A\" stroke-width=\"1\" points=\"53,328 57,328 60,330 \"/>\n\
<line opacity=\"1\" stroke=\"#9A9A9A\" stroke-width=\"1\" x1=\"80\" y1=\"363\" x2=\"80\" y2=\"62\"/>\n\
<circle cx=\"82\" cy=\"280\" r=\"2\" opacity=\"1\" fill=\"#5F7FB0\" stroke=\"none\" stroke-width=\"1\"/>\n\
<circle cx=\"90\" cy=\"270\" r=\"2\" opacity=\"1\" fill=\"#5F7FB0\" stroke=\"none\" stroke-width=\"1\"/>\n\
<polygon opacity=\"1\" fill=\"#5F7FB0\" points=\"1,1 3,1 2,3 \"/>\n\
<text x=\"1\" y=\"2\">a</text>\n\
<circle cx=\"9\" cy=\"9\" r=\"2\" opacity=\"1\" fill=\"#5F7FB0\" stroke=\"none\" stroke-width=\"1\"/>\n\
</svg>\n";
        let merged = merge_runs(svg);
        let lines: Vec<&str> = merged.lines().collect();
        assert_eq!(
            lines[1],
            "<path fill=\"none\" opacity=\"1\" stroke=\"#9A9A9A\" stroke-width=\"1\" \
             d=\"M53,361 L57,361 M53,328 L57,328 60,330 M80,363 L80,62\"/>"
        );
        assert_eq!(
            lines[2],
            "<path opacity=\"1\" fill=\"#5F7FB0\" stroke=\"none\" \
             d=\"M80,280 a2,2 0 1,0 4,0 a2,2 0 1,0 -4,0 Z M88,270 a2,2 0 1,0 4,0 a2,2 0 1,0 -4,0 Z \
             M1,1 L3,1 2,3 Z\"/>"
        );
        // A lone element stays as written; what comes after other content is a new run.
        assert_eq!(lines[3], "<text x=\"1\" y=\"2\">a</text>");
        assert!(lines[4].starts_with("<circle cx=\"9\""));
        assert_eq!(lines[5], "</svg>");
        assert_eq!(lines.len(), 6);
    }

    #[test]
    fn paint_that_would_change_when_merged_is_kept_apart() {
        let kept = [
            // Translucent: overlaps would no longer darken.
            "<circle cx=\"1\" cy=\"1\" r=\"2\" opacity=\"0.5\" fill=\"#5F7FB0\" stroke=\"none\" stroke-width=\"1\"/>",
            // Stroked and filled: a later fill would no longer cover an earlier outline.
            "<circle cx=\"1\" cy=\"1\" r=\"2\" opacity=\"1\" fill=\"#5F7FB0\" stroke=\"#000000\" stroke-width=\"1\"/>",
            // Dashed: the pattern would run on across elements.
            "<polyline fill=\"none\" opacity=\"1\" stroke=\"#9A9A9A\" stroke-width=\"1\" stroke-dasharray=\"4 2\" points=\"1,1 5,5 \"/>",
            "<rect x=\"0\" y=\"0\" width=\"1\" height=\"1\" opacity=\"1\" fill=\"#000000\" stroke=\"none\"/>",
        ];
        for element in kept {
            let svg = format!("{element}\n{element}\n");
            assert_eq!(merge_runs(&svg), svg, "{element}");
        }
        let two_colours = "<line opacity=\"1\" stroke=\"#111111\" stroke-width=\"1\" x1=\"0\" y1=\"0\" x2=\"1\" y2=\"1\"/>\n\
<line opacity=\"1\" stroke=\"#222222\" stroke-width=\"1\" x1=\"0\" y1=\"0\" x2=\"1\" y2=\"1\"/>\n";
        assert_eq!(merge_runs(two_colours), two_colours);
    }
}
