//! HEIDENHAIN nonlinear axis error compensation with a dependence on another axis: a
//! compensation value table `*.COM` and its assignment in `*.CMA` (MANUALplus 620 /
//! TNC 640 Technical Manual 01/2012, §6.10.3, pp. 713–718; iTNC 530 HSCI Technical Manual
//! 07/2013, §6.4): the `.COM` holds the input axis's positions from the machine datum in
//! `AXISPOS` and the values in the column of the axis compensated; the `.CMA` enters the
//! `.COM` in the column of the input axis ("[axis in column from *.com] = F(axis in column
//! from *.cma, in which *.com is entered)"), its line made active with `*`. Tables in
//! HEIDENHAIN's table syntax: `BEGIN NAME.EXT MM`, a header line whose words name the
//! columns, the rows, `[END]` (as pyLSV2's table reader reads them). Values in mm, four
//! decimals (0.1 µm). The exact column widths of the manual's example were not available
//! to the project; the columns are separated by spaces and aligned under their names.

use super::{CrossFormat, CrossTable, Part, check_rising};
use crate::compensate::controllers::{Refused, Unreadable};

pub struct Heidenhain;

/// The `.COM` file's name for a table: the stem given (letters, digits, `-` and `_`
/// kept), else `YX.COM` (Y corrected along X).
fn com_name(t: &CrossTable, stem: &str) -> String {
    let clean = |s: &str, also: &[char]| {
        s.chars()
            .filter(|c| c.is_ascii_alphanumeric() || also.contains(c))
            .collect::<String>()
    };
    let stem = clean(stem, &['-', '_']);
    if stem.is_empty() {
        format!("{}{}.COM", clean(&t.output, &[]), clean(&t.input, &[])).to_uppercase()
    } else {
        format!("{stem}.COM")
    }
}

impl CrossFormat for Heidenhain {
    fn name(&self) -> &'static str {
        "heidenhain"
    }

    fn write(&self, t: &CrossTable, stem: &str) -> Result<Vec<Part>, Refused> {
        check_rising(t)?;
        let valid = |s: &str| !s.is_empty() && s.chars().all(|c| c.is_ascii_alphanumeric());
        if !valid(&t.input) || !valid(&t.output) {
            return Err(Refused::Grid(format!(
                "HEIDENHAIN names axes by their column (CfgAxes/axisList): `{}` and `{}` must be letters and digits",
                t.input, t.output
            )));
        }
        let name = com_name(t, stem);
        let mut com = format!("BEGIN {name} MM\nNR   AXISPOS      {}\n", t.output);
        for (k, (p, c)) in t.positions_mm.iter().zip(&t.corrections_um).enumerate() {
            com.push_str(&format!("{k:<4} {p:<+12.4} {:+.4}\n", c / 1000.0));
        }
        com.push_str("[END]\n");
        let cma = format!(
            "BEGIN CONFIG.CMA\nNR   ACTIVE  {}\n0    *       {name}\n[END]\n",
            t.input
        );
        Ok(vec![
            Part {
                extension: "COM",
                text: com,
            },
            Part {
                extension: "CMA",
                text: cma,
            },
        ])
    }

    fn read(&self, parts: &[&str]) -> Result<CrossTable, Unreadable> {
        let [com, cma] = parts else {
            return Err(Unreadable::file(
                "a HEIDENHAIN cross table is a .COM file and its .CMA",
            ));
        };
        let (header, rows) = table(com)?;
        let column = |name: &str| header.iter().position(|h| h == name);
        let at = column("AXISPOS").ok_or_else(|| Unreadable::at(2, "no AXISPOS column"))?;
        let value = (0..header.len())
            .find(|&k| !matches!(header[k].as_str(), "NR" | "AXISPOS" | "BACKLASH"))
            .ok_or_else(|| Unreadable::at(2, "no column of a compensated axis"))?;
        let mut t = CrossTable {
            input: String::new(),
            output: header[value].clone(),
            positions_mm: Vec::new(),
            corrections_um: Vec::new(),
        };
        for (line, cells) in rows {
            let cell = |k: usize| -> Result<f64, Unreadable> {
                let text = cells
                    .get(k)
                    .ok_or_else(|| Unreadable::field(line, &header[k], "missing"))?;
                text.parse().map_err(|_| {
                    Unreadable::field(line, &header[k], format!("`{text}` is not a number"))
                })
            };
            t.positions_mm.push(cell(at)?);
            t.corrections_um.push(cell(value)? * 1000.0);
        }
        let name = com
            .lines()
            .next()
            .and_then(|l| l.split_whitespace().nth(1))
            .unwrap_or("");
        let (header, rows) = table(cma)?;
        let active = (rows.iter()).find(|(_, cells)| cells.get(1).is_some_and(|c| c == "*"));
        let (_, cells) =
            active.ok_or_else(|| Unreadable::file("the .CMA has no line marked `*` in ACTIVE"))?;
        let input =
            (2..header.len()).find(|&k| cells.get(k).is_some_and(|c| c.eq_ignore_ascii_case(name)));
        t.input = input.map(|k| header[k].clone()).ok_or_else(|| {
            Unreadable::file(format!("the .CMA's active line does not enter {name}"))
        })?;
        Ok(t)
    }

    fn extensions(&self) -> &'static [&'static str] {
        &["COM", "CMA"]
    }

    fn resolution_um(&self) -> f64 {
        0.05
    }
}

/// A HEIDENHAIN table's header words and its rows' words with their line numbers.
type Rows = Vec<(usize, Vec<String>)>;

fn table(text: &str) -> Result<(Vec<String>, Rows), Unreadable> {
    let mut lines = text.lines().enumerate().map(|(k, l)| (k + 1, l.trim()));
    match lines.next() {
        Some((_, l)) if l.starts_with("BEGIN ") => {}
        _ => return Err(Unreadable::at(1, "expected `BEGIN NAME.EXT`")),
    }
    let (_, header) = lines
        .next()
        .ok_or_else(|| Unreadable::at(2, "no header line"))?;
    let words = |l: &str| l.split_whitespace().map(str::to_string).collect::<Vec<_>>();
    let rows = lines
        .take_while(|(_, l)| *l != "[END]")
        .filter(|(_, l)| !l.is_empty())
        .map(|(k, l)| (k, words(l)))
        .collect();
    Ok((words(header), rows))
}
