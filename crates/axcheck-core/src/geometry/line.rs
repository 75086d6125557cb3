//! Reference straight lines (ISO 230-1:2012 3.4.12): the line fitted to a measured
//! trajectory to which straightness deviations are referred. ISO 230-1 allows the minimum
//! zone, the least-squares and the end-point line (as quoted in Renishaw TE328,
//! "Calibration of machine squareness"); the laser packages remove the slope by least
//! squares or end points (HP 5528A User's Guide, §21 "Straightness and Squareness
//! Considerations", pp. 21-1 to 21-6). axcheck fits those two.

use serde::{Deserialize, Serialize};

/// How the reference straight line is fitted.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ReferenceLine {
    /// Least squares over every target (HP 5528A §21: Y = mX + b minimising the squared
    /// residuals), the laser packages' default.
    #[default]
    #[serde(alias = "least-squares")]
    LeastSquares,
    /// Through the first and the last target (HP 5528A §21: m = (last − first) / length).
    #[serde(alias = "end-point")]
    EndPoint,
}

impl ReferenceLine {
    /// The name campaigns and the command line use: `least_squares`, `end_point`.
    pub fn key(self) -> &'static str {
        match self {
            ReferenceLine::LeastSquares => "least_squares",
            ReferenceLine::EndPoint => "end_point",
        }
    }

    /// The method named `key` (`least_squares`/`least-squares`, `end_point`/`end-point`).
    pub fn parse(key: &str) -> Option<ReferenceLine> {
        match key.replace('-', "_").as_str() {
            "least_squares" => Some(ReferenceLine::LeastSquares),
            "end_point" => Some(ReferenceLine::EndPoint),
            _ => None,
        }
    }
}

/// A straight line y = offset + slope · position, position in mm, y in µm.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Line {
    /// The line's value at position 0, µm.
    pub offset_um: f64,
    /// Its slope, µm per metre of travel.
    pub slope_um_per_m: f64,
}

impl Line {
    /// The line's value at `position_mm`, µm.
    pub fn at(&self, position_mm: f64) -> f64 {
        self.offset_um + self.slope_um_per_m * position_mm / 1000.0
    }
}

/// The reference line of `values` (µm) at `positions_mm` by `method`; `None` for fewer
/// than two distinct positions.
pub fn fit(method: ReferenceLine, positions_mm: &[f64], values: &[f64]) -> Option<Line> {
    let n = positions_mm.len().min(values.len());
    if n < 2 || positions_mm[0] == positions_mm[n - 1] {
        return None;
    }
    let slope_per_mm = match method {
        ReferenceLine::EndPoint => {
            (values[n - 1] - values[0]) / (positions_mm[n - 1] - positions_mm[0])
        }
        ReferenceLine::LeastSquares => {
            let mx = positions_mm[..n].iter().sum::<f64>() / n as f64;
            let my = values[..n].iter().sum::<f64>() / n as f64;
            let (mut sxy, mut sxx) = (0.0, 0.0);
            for (x, y) in positions_mm.iter().zip(values) {
                sxy += (x - mx) * (y - my);
                sxx += (x - mx) * (x - mx);
            }
            if sxx == 0.0 {
                return None;
            }
            sxy / sxx
        }
    };
    let anchor = match method {
        ReferenceLine::EndPoint => (positions_mm[0], values[0]),
        ReferenceLine::LeastSquares => (
            positions_mm[..n].iter().sum::<f64>() / n as f64,
            values[..n].iter().sum::<f64>() / n as f64,
        ),
    };
    Some(Line {
        offset_um: anchor.1 - slope_per_mm * anchor.0,
        slope_um_per_m: slope_per_mm * 1000.0,
    })
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// HP 5528A User's Guide §21, pp. 21-4 and 21-6: axis 1 (0 to 0.9 m, step 0.1 m)
    /// and axis 2 (0 to 0.45 m, step 0.05 m), the slopes the guide prints.
    pub(crate) fn hp_axis_1() -> (Vec<f64>, Vec<f64>) {
        let x = (0..10).map(|k| k as f64 * 100.0).collect();
        let y = vec![-0.3, 0.9, 1.5, 2.5, 2.9, 3.6, 4.2, 5.1, 5.9, 7.2];
        (x, y)
    }

    pub(crate) fn hp_axis_2() -> (Vec<f64>, Vec<f64>) {
        let x = (0..10).map(|k| k as f64 * 50.0).collect();
        let y = vec![-0.5, -1.2, -2.5, -3.8, -4.0, -4.8, -5.9, -6.2, -7.4, -8.8];
        (x, y)
    }

    #[test]
    fn the_hp_5528a_worked_slopes() {
        let (x, y) = hp_axis_1();
        let ls = fit(ReferenceLine::LeastSquares, &x, &y).unwrap();
        assert_eq!(format!("{:.2}", ls.slope_um_per_m), "7.65");
        let ep = fit(ReferenceLine::EndPoint, &x, &y).unwrap();
        // (7.2 − (−0.3)) / 0.9 m = 8.33 µm/m; the guide prints 8.3.
        assert_eq!(format!("{:.1}", ep.slope_um_per_m), "8.3");
        assert_eq!(ep.at(0.0), -0.3);
        let (x, y) = hp_axis_2();
        let ls = fit(ReferenceLine::LeastSquares, &x, &y).unwrap();
        assert_eq!(format!("{:.2}", ls.slope_um_per_m), "-17.42");
        assert_eq!(format!("{:.3}", ls.offset_um), "-0.591");
    }

    #[test]
    fn a_line_needs_two_positions() {
        assert_eq!(fit(ReferenceLine::LeastSquares, &[5.0], &[1.0]), None);
        assert_eq!(fit(ReferenceLine::EndPoint, &[5.0, 5.0], &[1.0, 2.0]), None);
        assert_eq!(
            ReferenceLine::parse("end-point"),
            Some(ReferenceLine::EndPoint)
        );
        assert_eq!(ReferenceLine::parse("minimum_zone"), None);
    }
}
