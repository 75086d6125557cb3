//! The diagnosis part of an axis report: the findings with their evidence, the held-out
//! gain, the parameters with the identified effects removed, and the data of the
//! diagnosis charts (model checks, residuals in time and along the axis, periodogram).

use crate::data::{key_words, num};
use crate::diagnose::cross::OutOfTest;
use crate::diagnose::effects::periodic::Periodic;
use crate::diagnose::{Diagnosis, Effect, Finding, TimeEffect, Unconfirmed};
use crate::evaluate::ParamKey;
use crate::units::{AxisKind, Direction, fmt_fixed};
use serde::Serialize;

/// The diagnosis section of an axis report, as the template reads it.
#[derive(Serialize)]
pub(crate) struct DiagnosisSection<'a> {
    unit: &'static str,
    /// The model check's verdict in one sentence (findings and checks together).
    verdict: String,
    findings: Vec<FindingLine<'a>>,
    /// Findings of the tests whose term the held-out prediction does not confirm.
    unconfirmed: Vec<UnconfirmedLine<'a>>,
    /// What this plan can confirm, per effect, in words.
    detectable: Vec<String>,
    /// The time chart shows a kept effect in time against the run means.
    has_time_effect: bool,
    base_rms: String,
    extended_rms: String,
    base_terms: String,
    extended_terms: String,
    /// Held-out gain in %, `–` when not finite.
    gain: String,
    /// Each judged term's gain under its scheme, as text.
    term_gains: Vec<String>,
    validation: &'static str,
    /// The effect of `corrected` (`all` when several were removed).
    corrected_label: String,
    corrected: Vec<CorrectedLine>,
    notes: &'a [String],
    has_periodogram: bool,
    /// This test predicted by the models of the axis's other tests.
    out_of_test: Vec<OutOfTestLine>,
}

/// Out-of-test prediction from another test of the axis ([`crate::diagnose::cross`]).
#[derive(Serialize)]
struct OutOfTestLine {
    /// `test 2 (data/x-work.csv)`.
    from: String,
    readings: usize,
    base_rms: String,
    extended_rms: String,
    /// The extended model's held-out RMS within the other test, as a phrase.
    in_test: String,
    datum_offset: String,
}

impl OutOfTestLine {
    fn new(o: &OutOfTest, unit: &str) -> OutOfTestLine {
        let from = match &o.from_file {
            Some(file) => format!("test {} ({file})", o.from_test),
            None => format!("test {}", o.from_test),
        };
        let fixed = |v: f64| {
            if v.is_finite() {
                fmt_fixed(v, 3)
            } else {
                "–".to_string()
            }
        };
        OutOfTestLine {
            from,
            readings: o.readings,
            base_rms: fixed(o.base_rms),
            extended_rms: fixed(o.extended_rms),
            in_test: if o.in_test_rms.is_finite() {
                format!(
                    "held out within that test: {} {unit} RMS",
                    fixed(o.in_test_rms)
                )
            } else {
                "no held-out figure within that test (a single run)".to_string()
            },
            datum_offset: fixed(o.datum_offset),
        }
    }
}

/// One finding: its message, its parameters and its evidence as text.
#[derive(Serialize)]
struct FindingLine<'a> {
    effect: &'static str,
    message: &'a str,
    params: String,
    evidence: String,
    /// What to do next.
    advice: String,
}

/// A finding of a test that the held-out prediction does not confirm: its message, its
/// evidence and its held-out gain beside the unrelated terms'.
#[derive(Serialize)]
struct UnconfirmedLine<'a> {
    effect: &'static str,
    message: &'a str,
    /// The evidence and the held-out gain beside the unrelated terms', as one text.
    detail: String,
}

impl<'a> From<&'a Unconfirmed> for UnconfirmedLine<'a> {
    fn from(u: &'a Unconfirmed) -> UnconfirmedLine<'a> {
        UnconfirmedLine {
            effect: u.finding.effect().name(),
            message: &u.finding.message,
            detail: format!("{}; {}", u.finding.evidence.describe(fmt), u.describe()),
        }
    }
}

/// One parameter as measured and with the effects removed.
#[derive(Serialize)]
struct CorrectedLine {
    /// The parameter's symbol (`E↑`).
    key: String,
    measured: String,
    corrected: String,
}

/// The model's terms in words, as a list.
fn terms_in_words(terms: &[impl AsRef<str>]) -> String {
    (terms.iter())
        .map(|t| key_words(t.as_ref()))
        .collect::<Vec<_>>()
        .join(", ")
}

/// A statistic or parameter: scientific notation when very small or large.
fn fmt(x: f64) -> String {
    if x != 0.0 && (x.abs() < 0.01 || x.abs() >= 1e5) {
        format!("{x:.2e}")
    } else {
        num(x)
    }
}

impl<'a> From<&'a Finding> for FindingLine<'a> {
    fn from(f: &'a Finding) -> FindingLine<'a> {
        let evidence = f.evidence.describe(fmt);
        // As `params_text`, with the keys in words for the customer.
        let params = (f.params().iter())
            .map(|(k, v)| format!("{} = {}", key_words(k), fmt(*v)))
            .chain(
                f.labels()
                    .iter()
                    .map(|(k, v)| format!("{} = {}", key_words(k), v.replace('_', " "))),
            )
            .collect::<Vec<_>>()
            .join(", ");
        FindingLine {
            effect: f.effect().name(),
            message: &f.message,
            params,
            evidence,
            advice: f.advice(),
        }
    }
}

/// The diagnosis section: findings with evidence, the held-out gain, parameters with the
/// identified effects removed (beside the measured ones), notes.
pub(crate) fn diagnosis_section<'a>(
    d: &'a Diagnosis,
    out_of_test: &[OutOfTest],
    symbol: impl Fn(ParamKey) -> String,
) -> DiagnosisSection<'a> {
    let all = d
        .corrected
        .iter()
        .find(|c| c.effect == "all")
        .or_else(|| d.corrected.last());
    let corrected = all.map_or(Vec::new(), |c| {
        c.parameters
            .iter()
            .map(|p| CorrectedLine {
                key: symbol(p.key),
                measured: num(p.measured),
                corrected: num(p.corrected),
            })
            .collect()
    });
    DiagnosisSection {
        unit: d.kind.deviation_symbol(),
        verdict: d.model_check.in_words(),
        findings: d.findings.iter().map(FindingLine::from).collect(),
        unconfirmed: d.unconfirmed.iter().map(UnconfirmedLine::from).collect(),
        detectable: (d.detectable.iter())
            .map(|x| format!("{}: {}", x.effect.name().replace('_', " "), x.advice))
            .collect(),
        has_time_effect: d.residuals.time_effect.is_some(),
        base_rms: fmt_fixed(d.base.heldout_rms, 3),
        extended_rms: fmt_fixed(d.extended.heldout_rms, 3),
        base_terms: terms_in_words(&d.base.terms),
        extended_terms: terms_in_words(&d.extended.terms),
        gain: if d.gain_pct.is_finite() {
            fmt_fixed(d.gain_pct, 1)
        } else {
            "–".to_string()
        },
        term_gains: d
            .term_gains
            .iter()
            .map(|g| {
                let text = g.describe(d.kind.deviation_symbol());
                let name = g.effect.name();
                match text.strip_prefix(name) {
                    Some(rest) => format!("{}{rest}", key_words(name)),
                    None => text,
                }
            })
            .collect(),
        validation: d.validation,
        corrected_label: all.map_or(String::new(), |c| key_words(&c.effect)),
        corrected,
        notes: &d.notes,
        has_periodogram: !d.residuals.periodogram.is_empty(),
        out_of_test: out_of_test
            .iter()
            .map(|o| OutOfTestLine::new(o, d.kind.deviation_symbol()))
            .collect(),
    }
}

/// Chart data of a diagnosis: model checks, residuals in time and along the axis, the
/// periodogram.
pub fn diagnosis_charts(
    d: &Diagnosis,
) -> (
    Vec<crate::charts::check::CheckBar>,
    crate::charts::diagnosis::ResidualsChart,
    crate::charts::diagnosis::ResidualsChart,
    crate::charts::diagnosis::Periodogram,
) {
    use crate::charts::check::CheckBar;
    use crate::charts::diagnosis::{Periodogram, ResidualsChart};
    // The charts' words in the language of the document being built.
    let words = crate::words::Words::new(crate::words::numbers());
    let (pos_unit, dev_unit) = match d.kind {
        AxisKind::Linear => (words.unit("mm"), words.unit("µm")),
        AxisKind::Rotary => ("°".to_string(), words.unit("arcsec")),
    };
    let checks = d
        .checks
        .iter()
        .map(|c| CheckBar {
            label: words.get_or(
                &format!("check-{}", c.statistic.replace('_', "-")),
                &c.statistic.replace('_', " "),
            ),
            measured: c.measured,
            low: c.simulated_low,
            high: c.simulated_high,
            outside: c.outside,
            decimals: None,
        })
        .collect();
    let readings = &d.residuals.readings;
    let timed = readings.iter().all(|r| r.time_s.is_some());
    let sigma = {
        let n = readings.len().max(1) as f64;
        (readings
            .iter()
            .map(|r| r.residual * r.residual)
            .sum::<f64>()
            / n)
            .sqrt()
    };
    let in_time = ResidualsChart {
        x: readings
            .iter()
            .map(|r| {
                if timed {
                    r.time_s.unwrap_or(0.0) / 60.0
                } else {
                    r.order as f64 + 1.0
                }
            })
            .collect(),
        y: readings.iter().map(|r| r.residual).collect(),
        up: readings
            .iter()
            .map(|r| r.direction == crate::units::Direction::Up)
            .collect(),
        x_label: words.get(if timed { "diag-x-time" } else { "diag-x-order" }),
        y_label: words.args("diag-y-residual", &[("unit", &dev_unit)]),
        band: Some(2.0 * sigma),
        fit: None,
        time: d
            .residuals
            .time_effect
            .as_ref()
            .map(|t| time_panels(d, t, timed)),
    };
    let along = ResidualsChart {
        x: readings.iter().map(|r| r.position).collect(),
        x_label: words.args("chart-target-position", &[("unit", &pos_unit)]),
        ..ResidualsChart {
            x: Vec::new(),
            y: in_time.y.clone(),
            up: in_time.up.clone(),
            x_label: String::new(),
            y_label: in_time.y_label.clone(),
            band: in_time.band,
            fit: None,
            time: None,
        }
    };
    let marked = d
        .estimates::<Periodic>()
        .next()
        .map(|p| (p.period, format!("{} {pos_unit}", fmt_fixed(p.period, 2))));
    let periodogram = Periodogram {
        period: d.residuals.periodogram.iter().map(|p| p.period).collect(),
        power: d.residuals.periodogram.iter().map(|p| p.power).collect(),
        period_label: words.args("diag-period", &[("unit", &pos_unit)]),
        threshold: None,
        marked,
        unresolved_below: None,
    };
    (checks, in_time, along, periodogram)
}

/// The two panels of the time chart: the run means with the kept effect in time and its
/// band, and the residuals after the extended model; time in minutes with time stamps,
/// else the reading's place in the test cycle (1-based), as the one-panel chart has it.
fn time_panels(d: &Diagnosis, t: &TimeEffect, timed: bool) -> crate::charts::diagnosis::TimePanels {
    let x = |time_s: Option<f64>, order: f64| {
        if timed {
            time_s.map_or(f64::NAN, |s| s / 60.0)
        } else {
            order + 1.0
        }
    };
    let up = |dir: Direction| dir == Direction::Up;
    let names: Vec<&str> = t
        .terms
        .iter()
        .map(|e| match e {
            Effect::WarmUp => "warm-up",
            Effect::ThermalGrowth => "thermal growth at the mean target",
            _ => "drift",
        })
        .collect();
    crate::charts::diagnosis::TimePanels {
        means: (t.run_means.iter())
            .map(|m| (x(m.time_s, m.order), m.mean, up(m.direction)))
            .collect(),
        curve: t
            .curve
            .iter()
            .map(|c| (x(c.time_s, c.order), c.value))
            .collect(),
        band: t.band,
        curve_label: format!("fitted {}", names.join(" and ")),
        after: (d.residuals.readings.iter())
            .map(|r| {
                let order = r.order as f64;
                (x(r.time_s, order), r.extended_residual, up(r.direction))
            })
            .collect(),
        after_band: Some(2.0 * t.sigma).filter(|b| b.is_finite()),
    }
}
