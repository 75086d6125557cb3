//! TwinCAT CNC (ISG kernel) cross compensation ("Kreuzkompensation"): an axis
//! compensation list of the slave (output) axis, `kw.crosscomp.*` (Beckhoff TF5200
//! Axis compensation, "Cross compensation", infosys.beckhoff.com …/308709003.html and
//! the parameter list P-COMP-00005/7): `kopf.achs_nr` the slave's logical number,
//! `kw.crosscomp.master_ax_nr` the master (input) axis whose command position is the
//! input, `kw.crosscomp.unit 1` (metric, 0.1 µm), `kw.crosscomp.last_index`, and per
//! point `kw.crosscomp.table[i].setpoint` and `.correction` in 0.1 µm. Activated with
//! `lr_param.crosscomp 1` in the slave's axis parameters and the list in the start-up
//! list. The correction is written as the value added to the slave (see [`super`]); the
//! documentation does not settle its sign.

use super::{CrossFormat, CrossTable, Part, check_rising};
use crate::compensate::controllers::{Refused, Unreadable};

pub struct TwinCat;

/// 0.1 µm per unit.
const PER_MM: f64 = 10_000.0;

impl CrossFormat for TwinCat {
    fn name(&self) -> &'static str {
        "twincat"
    }

    fn write(&self, t: &CrossTable, _stem: &str) -> Result<Vec<Part>, Refused> {
        check_rising(t)?;
        let number = |s: &str| s.parse::<u32>().ok();
        let (Some(slave), Some(master)) = (number(&t.output), number(&t.input)) else {
            return Err(Refused::Grid(format!(
                "TwinCAT names axes by their logical numbers: give the output and input axes as numbers, not `{}` and `{}`",
                t.output, t.input
            )));
        };
        let units = |mm: f64| (mm * PER_MM).round();
        if (t.positions_mm.iter().chain(
            &t.corrections_um
                .iter()
                .map(|c| c / 1000.0)
                .collect::<Vec<_>>(),
        ))
        .any(|v| units(*v).abs() > i32::MAX as f64)
        {
            return Err(Refused::Range(
                "a position or a correction beyond ±214 m in 0.1 µm".into(),
            ));
        }
        let mut text = format!(
            "# axcheck cross-axis table: axis {slave} corrected as a function of axis {master}; each correction is added to axis {slave}\n"
        );
        let line = |key: &str, value: String| format!("{key:<40} {value}\n");
        text.push_str(&line("kopf.achs_nr", slave.to_string()));
        text.push_str(&line("kw.crosscomp.master_ax_nr", master.to_string()));
        text.push_str(&line("kw.crosscomp.unit", "1".into()));
        text.push_str(&line(
            "kw.crosscomp.last_index",
            (t.positions_mm.len() - 1).to_string(),
        ));
        for (i, (p, c)) in t.positions_mm.iter().zip(&t.corrections_um).enumerate() {
            text.push_str(&line(
                &format!("kw.crosscomp.table[{i}].setpoint"),
                format!("{}", units(*p)),
            ));
            text.push_str(&line(
                &format!("kw.crosscomp.table[{i}].correction"),
                format!("{}", units(c / 1000.0)),
            ));
        }
        Ok(vec![Part {
            extension: "lis",
            text,
        }])
    }

    fn read(&self, parts: &[&str]) -> Result<CrossTable, Unreadable> {
        let text = parts.first().ok_or_else(|| Unreadable::file("no file"))?;
        let mut keys = std::collections::BTreeMap::new();
        for (k, line) in text.lines().enumerate().map(|(k, l)| (k + 1, l.trim())) {
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let mut words = line.split_whitespace();
            let (Some(key), Some(value)) = (words.next(), words.next()) else {
                return Err(Unreadable::at(k, "expected `key value`"));
            };
            keys.insert(key.to_string(), (k, value.to_string()));
        }
        let get = |key: &str| -> Result<f64, Unreadable> {
            let (k, v) = keys
                .get(key)
                .ok_or_else(|| Unreadable::file(format!("no {key}")))?;
            v.parse()
                .map_err(|_| Unreadable::field(*k, key, format!("`{v}` is not a number")))
        };
        if get("kw.crosscomp.unit")? != 1.0 {
            return Err(Unreadable::file(
                "kw.crosscomp.unit is not 1 (metric, 0.1 µm): increments need the encoder's resolution",
            ));
        }
        let last = get("kw.crosscomp.last_index")?;
        if !(0.0..=100_000.0).contains(&last) || last.fract() != 0.0 {
            return Err(Unreadable::file(format!(
                "kw.crosscomp.last_index {last} is not a point index"
            )));
        }
        let mut t = CrossTable {
            input: format!("{}", get("kw.crosscomp.master_ax_nr")?),
            output: format!("{}", get("kopf.achs_nr")?),
            positions_mm: Vec::new(),
            corrections_um: Vec::new(),
        };
        for i in 0..=last as usize {
            t.positions_mm
                .push(get(&format!("kw.crosscomp.table[{i}].setpoint"))? / PER_MM);
            t.corrections_um
                .push(get(&format!("kw.crosscomp.table[{i}].correction"))? / PER_MM * 1000.0);
        }
        Ok(t)
    }

    fn extensions(&self) -> &'static [&'static str] {
        &["lis"]
    }

    fn resolution_um(&self) -> f64 {
        0.05
    }
}
