//! The plot frame of the diagnosis charts: data to backend pixels in f64, so that far-out
//! values are clipped before they are rounded, and polylines clipped to the plot.

use crate::chart_kit::{Area, Chart, Failed, Px, Stroke, draw_line};

/// The plot rectangle of a chart and the data ranges it shows; maps data to pixels in f64 so
/// far-out values can be clipped before they are rounded.
#[derive(Clone, Copy)]
pub(super) struct Frame {
    pub x: (f64, f64),
    pub y: (f64, f64),
    pub l: f64,
    pub r: f64,
    pub t: f64,
    pub b: f64,
}

impl Frame {
    pub fn of(chart: &Chart, x: (f64, f64), y: (f64, f64)) -> Frame {
        let (l, b) = chart.backend_coord(&(x.0, y.0));
        let (r, t) = chart.backend_coord(&(x.1, y.1));
        Frame {
            x,
            y,
            l: l as f64,
            r: r as f64,
            t: t as f64,
            b: b as f64,
        }
    }

    pub fn px(&self, x: f64, y: f64) -> Px {
        let fx = (x - self.x.0) / (self.x.1 - self.x.0);
        let fy = (y - self.y.0) / (self.y.1 - self.y.0);
        (
            self.l + fx * (self.r - self.l),
            self.b - fy * (self.b - self.t),
        )
    }
}

/// The part of segment a–b inside the frame's rectangle (Liang–Barsky), if any.
fn clip_segment(a: Px, b: Px, f: &Frame) -> Option<(Px, Px)> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let mut t0: f64 = 0.0;
    let mut t1: f64 = 1.0;
    for (p, q) in [
        (-dx, a.0 - f.l),
        (dx, f.r - a.0),
        (-dy, a.1 - f.t),
        (dy, f.b - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    if t0 > t1 {
        return None;
    }
    let at = |t: f64| (a.0 + dx * t, a.1 + dy * t);
    Some((
        if t0 > 0.0 { at(t0) } else { a },
        if t1 < 1.0 { at(t1) } else { b },
    ))
}

/// The pieces of a polyline inside the frame; non-finite points break the line.
pub(super) fn clip_polyline(points: &[Px], f: &Frame) -> Vec<Vec<Px>> {
    let mut out: Vec<Vec<Px>> = Vec::new();
    let mut current: Vec<Px> = Vec::new();
    for w in points.windows(2) {
        let (a, b) = (w[0], w[1]);
        let finite = a.0.is_finite() && a.1.is_finite() && b.0.is_finite() && b.1.is_finite();
        match clip_segment(a, b, f).filter(|_| finite) {
            Some((p, q)) => {
                if current.last() != Some(&p) {
                    if current.len() >= 2 {
                        out.push(std::mem::take(&mut current));
                    }
                    current = vec![p];
                }
                current.push(q);
            }
            None => {
                if current.len() >= 2 {
                    out.push(std::mem::take(&mut current));
                }
                current.clear();
            }
        }
    }
    if current.len() >= 2 {
        out.push(current);
    }
    out
}

/// Draws a polyline clipped to the frame.
pub(super) fn draw_clipped(
    root: &Area,
    points: &[Px],
    frame: &Frame,
    stroke: Stroke,
) -> Result<(), Failed> {
    for piece in clip_polyline(points, frame) {
        draw_line(root, &piece, stroke)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clipping_keeps_what_is_inside() {
        let f = Frame {
            x: (0.0, 1.0),
            y: (0.0, 1.0),
            l: 0.0,
            r: 100.0,
            t: 0.0,
            b: 50.0,
        };
        let pieces = clip_polyline(&[(-50.0, 25.0), (50.0, 25.0), (150.0, 25.0)], &f);
        assert_eq!(pieces, vec![vec![(0.0, 25.0), (50.0, 25.0), (100.0, 25.0)]]);
        // Out, in, out again: two pieces.
        let pieces = clip_polyline(
            &[(10.0, 10.0), (10.0, 90.0), (20.0, 90.0), (20.0, 10.0)],
            &f,
        );
        assert_eq!(pieces.len(), 2);
        assert!(clip_polyline(&[(200.0, 0.0), (300.0, 0.0)], &f).is_empty());
        assert!(clip_polyline(&[(1.0, 1.0), (f64::NAN, 2.0), (3.0, 3.0)], &f).is_empty());
        assert!(clip_polyline(&[], &f).is_empty());
    }
}
