//! Cross-axis tables: the correction of one axis (the output) as a function of another's
//! position (the input), built from a straightness test (EYX: Y corrected along X), and
//! written and read in each controller's format, one file per format.
//!
//! **The convention of every table here**: the correction is *added to the output axis's
//! commanded position* at the input axis's position, as axcheck's pitch tables are
//! (`compensate::table`): c = −(the straightness deviation about its reference line), the
//! mean of both directions. The reference line's slope is not corrected: a laser's
//! straightness optics are aligned to the axis arbitrarily, so the slope belongs to the
//! squareness, which is corrected on its own. No source available to the project states
//! the sign a controller's cross table takes (`docs/cross-axis-compensation.md`, §0);
//! each format's file says the convention in words where it can hold a comment.

pub mod build;
pub mod csv;
pub mod heidenhain;
pub mod siemens_cec;
pub mod twincat;
pub mod verify;

use super::controllers::{Refused, Unreadable};
use crate::geometry::straightness::Straightness;

/// A correction of `output` by `input`'s position.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct CrossTable {
    /// The input axis's name on the controller (`X1`, `AX1`, `X`, TwinCAT's number `1`).
    pub input: String,
    /// The output (corrected) axis's name on the controller.
    pub output: String,
    /// The input axis's positions, mm, ascending.
    pub positions_mm: Vec<f64>,
    /// The corrections added to the output axis's commanded position there, µm.
    pub corrections_um: Vec<f64>,
}

/// A file of a table: its name's extension and its text.
#[derive(Debug, Clone, PartialEq)]
pub struct Part {
    pub extension: &'static str,
    pub text: String,
}

/// A controller's cross-table format: the files it writes and reads back.
pub trait CrossFormat: Sync {
    /// The name the command line and campaigns give it.
    fn name(&self) -> &'static str;
    /// The table's files, or why the format cannot hold it. `stem`: the files' name
    /// without extension, for formats whose files name each other (HEIDENHAIN's `.CMA`
    /// enters its `.COM` by name); empty: the format's own default name.
    fn write(&self, table: &CrossTable, stem: &str) -> Result<Vec<Part>, Refused>;
    /// The table the files hold (in the order `write` gives them).
    fn read(&self, parts: &[&str]) -> Result<CrossTable, Unreadable>;
    /// The largest difference a write and a read may make to a correction, µm (the
    /// format's resolution, half a unit of its last place).
    fn resolution_um(&self) -> f64;
    /// The extensions of the files `write` gives, in their order.
    fn extensions(&self) -> &'static [&'static str];
    /// Whether the format holds only equidistant points.
    fn equidistant(&self) -> bool {
        false
    }
}

/// Every format, in the order of the README.
pub fn formats() -> [&'static dyn CrossFormat; 4] {
    [
        &csv::Csv,
        &siemens_cec::SiemensCec,
        &heidenhain::Heidenhain,
        &twincat::TwinCat,
    ]
}

/// The format called `name` (as the command line and a machine's `controller` name it).
pub fn find(name: &str) -> Option<&'static dyn CrossFormat> {
    formats().into_iter().find(|f| f.name() == name)
}

/// The names of every format, for error messages.
pub fn names() -> Vec<&'static str> {
    formats().iter().map(|f| f.name()).collect()
}

/// The table that cancels `straightness`'s deviations about its reference line (measured
/// at `targets_mm`), on those targets: c = −residual.
pub fn from_straightness(
    straightness: &Straightness,
    targets_mm: &[f64],
    input: &str,
    output: &str,
) -> CrossTable {
    CrossTable {
        input: input.to_string(),
        output: output.to_string(),
        positions_mm: targets_mm.to_vec(),
        corrections_um: straightness.residuals_um.iter().map(|r| -r).collect(),
    }
}

impl CrossTable {
    /// The correction at `position_mm`, linear between points and held beyond the ends
    /// (as Siemens CEC holds its first and last value).
    pub fn at(&self, position_mm: f64) -> f64 {
        let (p, c) = (&self.positions_mm, &self.corrections_um);
        match p.iter().position(|x| *x >= position_mm) {
            None => c.last().copied().unwrap_or(0.0),
            Some(0) => c[0],
            Some(k) => {
                let t = (position_mm - p[k - 1]) / (p[k] - p[k - 1]);
                c[k - 1] + t * (c[k] - c[k - 1])
            }
        }
    }

    /// The same table on an equidistant grid of `step_mm` from the first position (the
    /// last point at or past the last position), for formats that take only those.
    pub fn resampled(&self, step_mm: f64) -> CrossTable {
        let (first, last) = match (self.positions_mm.first(), self.positions_mm.last()) {
            (Some(a), Some(b)) => (*a, *b),
            _ => return self.clone(),
        };
        let n = ((last - first) / step_mm - 1e-9).ceil().max(1.0) as usize + 1;
        let positions_mm: Vec<f64> = (0..n).map(|k| first + k as f64 * step_mm).collect();
        CrossTable {
            corrections_um: positions_mm.iter().map(|p| self.at(*p)).collect(),
            positions_mm,
            ..self.clone()
        }
    }

    /// The grid's step when its points are equidistant (within 1 µm), else `None`.
    pub fn step_mm(&self) -> Option<f64> {
        let p = &self.positions_mm;
        let step = (p.len() >= 2).then(|| p[1] - p[0])?;
        let equal = p.windows(2).all(|w| (w[1] - w[0] - step).abs() < 1e-3);
        (equal && step > 0.0).then_some(step)
    }
}

/// The positions must rise, and the axes be named as a file can hold them (letters,
/// digits and `_`, as the pitch tables' [`super::controllers::axis_name`]: a line break or a
/// bracket in a name would write lines of its own into a part program the control runs);
/// a format's writer refuses a table that is not so.
fn check_rising(table: &CrossTable) -> Result<(), Refused> {
    for name in [&table.input, &table.output] {
        let fits = !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
        if !fits {
            return Err(Refused::Grid(format!(
                "the axis name `{}` is not a name the file can hold (letters, digits and _)",
                name.escape_debug()
            )));
        }
    }
    let p = &table.positions_mm;
    if p.len() < 2 || p.windows(2).any(|w| w[1] <= w[0]) {
        return Err(Refused::Grid(
            "a cross table needs two points or more at rising positions".into(),
        ));
    }
    if !(p.iter().chain(&table.corrections_um)).all(|v| v.is_finite()) {
        return Err(Refused::Range(
            "a position or a correction is not a number".into(),
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests;
