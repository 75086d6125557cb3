//! What a finding is made of, below the effects that write one: the units of its
//! parameters ([`Units`]), its evidence ([`Evidence`]), what each effect's estimate gives
//! the stable interface ([`Fields`]) and the number formats of the messages. The finding
//! itself ([`super::Finding`]: one named cause with its typed estimate, the evidence and a
//! message) stands with the vocabulary of effects, since its estimate is one of theirs.
//!
//! The estimate is one type per effect (`effects/`); its parameters reach the JSON
//! under keys that carry the units (`rate_um_per_h`, `period_mm` …). Those keys are a
//! stable interface (`diagnose --json`, `results.json`), so each effect builds them in one
//! place, its `params`, which the JSON, the text and the report all read; beside them its
//! `advice`, what a user can do about the cause.

use super::prep::TimeUnit;
use crate::units::{AxisKind, fmt_fixed};
use serde::ser::{Serialize, SerializeMap, Serializer};

/// The units a finding's parameters are expressed in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Units {
    pub kind: AxisKind,
    pub time: TimeUnit,
}

impl Units {
    /// Deviation unit in keys: `um` or `arcsec`.
    pub fn dev(self) -> &'static str {
        self.kind.deviation_unit()
    }

    /// Position unit in keys: `mm` or `deg`.
    pub fn pos(self) -> &'static str {
        self.kind.position_unit()
    }

    /// Time unit in keys: `h`, or `run` without time stamps.
    pub fn time(self) -> &'static str {
        self.time.key()
    }

    /// Deviation unit in messages: `µm` or `arcsec`.
    pub fn symbol(self) -> &'static str {
        self.kind.deviation_symbol()
    }

    /// The time unit in words: `hour` or `run`.
    pub fn per(self) -> &'static str {
        match self.time {
            TimeUnit::Hours => "hour",
            TimeUnit::Runs => "run",
        }
    }
}

/// The evidence for a finding.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Evidence {
    /// What was computed, e.g. `t of the drift rate (df 98, against the scatter)`.
    pub statistic: String,
    pub value: f64,
    /// p-value of the test (false-alarm probability for the periodic search, Bonferroni
    /// adjusted for outliers).
    pub p_value: Option<f64>,
    /// Size of the effect relative to the scatter σ (drift and growth over the test,
    /// offsets' RMS, amplitude, change of B along the axis, outlier size); for scatter
    /// variation the ratio σ(end)/σ(start).
    pub effect_size: Option<f64>,
}

impl Evidence {
    /// `t of … = 3.617, p = 0.0005, effect size 2.171`, with numbers written by `num`
    /// (the text and the report each have their number format).
    pub fn describe(&self, num: impl Fn(f64) -> String) -> String {
        let mut text = format!("{} = {}", self.statistic, num(self.value));
        if let Some(p) = self.p_value {
            text.push_str(&format!(", p = {}", fmt_p(p)));
        }
        if let Some(s) = self.effect_size {
            text.push_str(&format!(", effect size {}", num(s)));
        }
        text
    }
}

/// What each effect's estimate gives the stable interface.
pub(crate) trait Fields {
    /// Numeric parameters, keys with units, in output order.
    fn params(&self, units: Units) -> Vec<(String, f64)>;
    /// Non-numeric facts, in output order.
    fn labels(&self) -> Vec<(&'static str, &'static str)> {
        Vec::new()
    }
    /// What to do next: the remedy for this cause, with its size where it has one.
    fn advice(&self, units: Units) -> String;
}

/// Pairs serialised as a map, in order.
pub(crate) struct Keyed<K, V>(pub(crate) Vec<(K, V)>);

impl<K: Serialize, V: Serialize> Serialize for Keyed<K, V> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(Some(self.0.len()))?;
        for (k, v) in &self.0 {
            map.serialize_entry(k, v)?;
        }
        map.end()
    }
}

/// Pairs serialised as a map (for the other views of the diagnosis).
pub(crate) fn keyed<K: Serialize, V: Serialize>(pairs: Vec<(K, V)>) -> impl Serialize {
    Keyed(pairs)
}

/// Values at their targets as a finding lists them: `1.24 µm at 20 mm, 4.37 µm at 120 mm`.
pub(crate) fn per_target_list(values: &[(f64, f64)], u: Units) -> String {
    let ds = u.symbol();
    (values.iter())
        .map(|(p, v)| {
            format!(
                "{} {ds} at {}",
                fmt(*v),
                crate::measurement::fmt_target(u.kind, *p)
            )
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// A number in a message: more decimals for small values, `n/a` when not finite.
pub(crate) fn fmt(v: f64) -> String {
    if v.is_finite() {
        let a = v.abs();
        let d = if a >= 100.0 {
            1
        } else if a >= 1.0 {
            2
        } else if a >= 0.01 {
            3
        } else {
            5
        };
        fmt_fixed(v, d)
    } else {
        "n/a".into()
    }
}

/// A p-value in a message.
pub(crate) fn fmt_p(p: f64) -> String {
    if p < 1e-4 {
        format!("{p:.1e}")
    } else {
        format!("{p:.4}")
    }
}

/// The effect size relative to the scatter σ, when σ is known.
pub(crate) fn relative(size: f64, sigma: f64) -> Option<f64> {
    (sigma > 0.0).then(|| size / sigma)
}
