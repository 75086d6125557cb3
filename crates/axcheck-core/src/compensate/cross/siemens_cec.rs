//! SINUMERIK 840D sl sag and angularity compensation (CEC) as an INI part program
//! (SINUMERIK Extended Functions, Function Manual 03/2013, 6FC5397-1BP40-3BA1, §4.4.3,
//! pp. 237–266): `$AN_CEC[t,N]` the value of point N of table t in mm, `$AN_CEC_INPUT_AXIS`
//! the axis whose setpoint is the input, `$AN_CEC_OUTPUT_AXIS` the axis corrected,
//! `$AN_CEC_STEP`, `$AN_CEC_MIN`, `$AN_CEC_MAX` an equidistant grid of (MAX − MIN)/STEP + 1
//! points, `$AN_CEC_DIRECTION` 0 (both directions), `$AN_CEC_MULT_BY_TABLE` 0,
//! `$AN_CEC_IS_MODULO` 0, in `%_N_NC_CEC_INI`, `CHANDATA(1)` … `M17`. MD18342
//! `$MN_MM_CEC_MAX_POINTS[t]` must hold the points; load with MD32710 `$MA_CEC_ENABLE` of
//! the output axis 0, then enable it and SD41300 `$SN_CEC_TABLE_ENABLE[t]`. The value
//! written is the correction added to the output axis (see [`super`]): the manual's
//! examples do not settle the sign, which a one-point test on the machine must.

use super::{CrossFormat, CrossTable, Part, check_rising};
use crate::compensate::controllers::{Refused, Unreadable};

pub struct SiemensCec;

/// The table number t written (the first).
const T: usize = 0;

impl CrossFormat for SiemensCec {
    fn name(&self) -> &'static str {
        "siemens-840d"
    }

    fn write(&self, t: &CrossTable, _stem: &str) -> Result<Vec<Part>, Refused> {
        check_rising(t)?;
        let step = t.step_mm().ok_or_else(|| {
            Refused::Grid("CEC takes an equidistant grid ($AN_CEC_STEP): resample the table".into())
        })?;
        let mut text = String::from("%_N_NC_CEC_INI\n");
        text.push_str(&format!(
            "; axcheck cross-axis table: {} corrected as a function of {}; each value (mm) is the correction added to {}\n",
            t.output, t.input, t.output
        ));
        text.push_str("CHANDATA(1)\n");
        for (n, c) in t.corrections_um.iter().enumerate() {
            text.push_str(&format!("$AN_CEC[{T},{n}]={:.6}\n", c / 1000.0));
        }
        let (min, max) = (t.positions_mm[0], t.positions_mm[t.positions_mm.len() - 1]);
        for (key, value) in [
            ("INPUT_AXIS", format!("({})", t.input)),
            ("OUTPUT_AXIS", format!("({})", t.output)),
            ("STEP", format!("{step:.6}")),
            ("MIN", format!("{min:.6}")),
            ("MAX", format!("{max:.6}")),
            ("DIRECTION", "0".into()),
            ("MULT_BY_TABLE", "0".into()),
            ("IS_MODULO", "0".into()),
        ] {
            text.push_str(&format!("$AN_CEC_{key}[{T}]={value}\n"));
        }
        text.push_str("M17\n");
        Ok(vec![Part {
            extension: "ini",
            text,
        }])
    }

    fn read(&self, parts: &[&str]) -> Result<CrossTable, Unreadable> {
        let text = parts.first().ok_or_else(|| Unreadable::file("no file"))?;
        let mut values: Vec<(usize, f64)> = Vec::new();
        let mut keys = std::collections::BTreeMap::new();
        for (k, line) in text.lines().enumerate().map(|(k, l)| (k + 1, l.trim())) {
            let line = line.split(';').next().unwrap_or("").trim();
            let Some(rest) = line.strip_prefix("$AN_CEC") else {
                continue;
            };
            let (name, value) = rest
                .split_once('=')
                .ok_or_else(|| Unreadable::at(k, "expected `=`"))?;
            let (key, index) = name
                .split_once('[')
                .ok_or_else(|| Unreadable::at(k, "expected `[t]`"))?;
            let index = index.trim_end_matches(']');
            let field = format!("$AN_CEC{key}");
            if key.is_empty() {
                let (t, n) = index
                    .split_once(',')
                    .ok_or_else(|| Unreadable::field(k, &field, "expected [t,N]"))?;
                let n: usize = n
                    .trim()
                    .parse()
                    .map_err(|_| Unreadable::field(k, &field, "N is not a point number"))?;
                if t.trim() != T.to_string() {
                    continue;
                }
                let v: f64 = value.trim().parse().map_err(|_| {
                    Unreadable::field(k, &field, format!("`{value}` is not a number"))
                })?;
                values.push((n, v * 1000.0));
            } else if index.trim() == T.to_string() {
                keys.insert(
                    key.trim_start_matches('_').to_string(),
                    (k, value.trim().to_string()),
                );
            }
        }
        let get = |key: &str| {
            keys.get(key)
                .ok_or_else(|| Unreadable::file(format!("no $AN_CEC_{key}[{T}]")))
        };
        let number = |key: &str| -> Result<f64, Unreadable> {
            let (k, v) = get(key)?;
            v.parse().map_err(|_| {
                Unreadable::field(
                    *k,
                    format!("$AN_CEC_{key}"),
                    format!("`{v}` is not a number"),
                )
            })
        };
        let axis = |key: &str| -> Result<String, Unreadable> {
            Ok(get(key)?
                .1
                .trim_start_matches('(')
                .trim_end_matches(')')
                .to_string())
        };
        let (step, min, max) = (number("STEP")?, number("MIN")?, number("MAX")?);
        values.sort_by_key(|(n, _)| *n);
        let points = ((max - min) / step).round() as usize + 1;
        if values.len() != points || values.iter().enumerate().any(|(k, (n, _))| *n != k) {
            return Err(Unreadable::file(format!(
                "MIN {min}, MAX {max} and STEP {step} make {points} points; the file has $AN_CEC[{T},0…] for {} (each point once, from 0)",
                values.len()
            )));
        }
        Ok(CrossTable {
            input: axis("INPUT_AXIS")?,
            output: axis("OUTPUT_AXIS")?,
            positions_mm: (0..points).map(|k| min + k as f64 * step).collect(),
            corrections_um: values.into_iter().map(|(_, v)| v).collect(),
        })
    }

    fn extensions(&self) -> &'static [&'static str] {
        &["ini"]
    }

    fn equidistant(&self) -> bool {
        true
    }

    fn resolution_um(&self) -> f64 {
        0.0005
    }
}
