//! `axcheck diagnose`: what the standard's model of the axis gets wrong, and why; with
//! several files (tests of one axis), each also predicted by the models fitted on each
//! other test, as a campaign axis with several data files is
//! ([`axcheck::diagnose::cross`]).

use super::text::{left, right, width};
use anyhow::{Result, bail};
use axcheck::diagnose::cross::{OutOfTest, out_of_test};
use axcheck::diagnose::{Diagnosis, DiagnosisJson, Options};
use axcheck::measurement::{self, AxisData, ReadOptions};
use axcheck::simulate::Simulation;
use axcheck::units::fmt_fixed;
use std::fmt::Write;
use std::path::PathBuf;

/// What `axcheck diagnose` prints, and the extended model of a single file (for
/// `--write-model`).
pub struct DiagnoseOutput {
    pub text: String,
    pub extended_model: Option<Simulation>,
}

/// Reads and diagnoses `files`, the tests of one axis; with several, each is predicted
/// by the models of every other (out of test). `write_model` asks for the extended
/// model, which one file has.
pub fn run(
    files: &[PathBuf],
    read: &ReadOptions,
    options: &Options,
    json: bool,
    write_model: bool,
) -> Result<DiagnoseOutput> {
    if write_model && files.len() > 1 {
        bail!(
            "--write-model writes the extended model of one test: give one file ({} given)",
            files.len()
        );
    }
    let mut tests: Vec<(String, AxisData)> = Vec::with_capacity(files.len());
    for file in files {
        let data = measurement::read_file_with(file, read)?.data;
        tests.push((file.display().to_string(), data));
    }
    one_kind(&tests)?;
    let diagnoses: Vec<Diagnosis> = tests
        .iter()
        .map(|(_, data)| axcheck::diagnose::diagnose(data, options))
        .collect();
    let predicted = across(&tests, &diagnoses);
    let text = if json {
        to_json(&tests, &diagnoses, &predicted)?
    } else {
        let parts: Vec<String> = (tests.iter().zip(&diagnoses).zip(&predicted))
            .map(|(((name, _), d), p)| render(name, d) + &out_of_test_text(d, p))
            .collect();
        parts.join("\n")
    };
    let extended_model = (diagnoses.len() == 1).then(|| diagnoses[0].extended_model.clone());
    Ok(DiagnoseOutput {
        text,
        extended_model,
    })
}

/// Tests of one axis have one kind: a linear and a rotary file cannot predict each other.
fn one_kind(tests: &[(String, AxisData)]) -> Result<()> {
    if let Some(((a, first), (b, other))) = tests.first().and_then(|t0| {
        tests
            .iter()
            .find(|t| t.1.kind != t0.1.kind)
            .map(|t| (t0, t))
    }) {
        bail!(
            "{a} is a {} axis and {b} a {} one: the files of one diagnose are tests of one axis",
            first.kind,
            other.kind
        );
    }
    Ok(())
}

/// Each test predicted by the models of every other test (1-based test numbers in the
/// order of the files), as [`axcheck::batch`] does for a campaign axis.
fn across(tests: &[(String, AxisData)], diagnoses: &[Diagnosis]) -> Vec<Vec<OutOfTest>> {
    tests
        .iter()
        .enumerate()
        .map(|(k, (_, data))| {
            (diagnoses.iter().enumerate())
                .filter(|(j, _)| *j != k)
                .filter_map(|(j, d)| out_of_test(d, j + 1, Some(tests[j].0.clone()), data))
                .collect()
        })
        .collect()
}

/// `--json`: one file's diagnosis with `file` (as before); several files as
/// `{"tests": [...]}`, each that object with `out_of_test` (the fields of
/// `results.json`'s `out_of_test`).
fn to_json(
    tests: &[(String, AxisData)],
    diagnoses: &[Diagnosis],
    predicted: &[Vec<OutOfTest>],
) -> serde_json::Result<String> {
    fn json(d: &Diagnosis) -> DiagnosisJson<'_> {
        d.json(axcheck::simulate::model_text)
    }
    if let ([(name, _)], [d]) = (tests, diagnoses) {
        return super::json_with_file(&json(d), name);
    }
    #[derive(serde::Serialize)]
    struct Test<'a> {
        #[serde(flatten)]
        diagnosis: DiagnosisJson<'a>,
        file: &'a str,
        out_of_test: &'a [OutOfTest],
    }
    #[derive(serde::Serialize)]
    struct Tests<'a> {
        tests: Vec<Test<'a>>,
    }
    let tests = (tests.iter().zip(diagnoses).zip(predicted))
        .map(|(((name, _), diagnosis), p)| Test {
            diagnosis: json(diagnosis),
            file: name,
            out_of_test: p,
        })
        .collect();
    Ok(serde_json::to_string_pretty(&Tests { tests })? + "\n")
}

/// The out-of-test predictions of one test, as text (nothing for a single file).
fn out_of_test_text(d: &Diagnosis, predicted: &[OutOfTest]) -> String {
    let mut out = String::new();
    if predicted.is_empty() {
        return out;
    }
    let unit = d.kind.deviation_symbol();
    let _ = writeln!(
        out,
        "\nOut of test: this test predicted by the models fitted on each other test (position-dependent terms only; one datum offset fitted)"
    );
    for o in predicted {
        let _ = writeln!(
            out,
            "  from test {} ({}): {} readings inside its travel, datum offset {} {unit}; base model {} {unit} RMS, extended model {} {unit} RMS (held out within that test: {} {unit})",
            o.from_test,
            o.from_file.as_deref().unwrap_or("?"),
            o.readings,
            fmt_fixed(o.datum_offset, 3),
            fmt_fixed(o.base_rms, 3),
            fmt_fixed(o.extended_rms, 3),
            fmt_fixed(o.in_test_rms, 3),
        );
    }
    out
}

fn num(x: f64) -> String {
    if x != 0.0 && (x.abs() < 0.01 || x.abs() >= 1e5) {
        format!("{x:.3e}")
    } else {
        fmt_fixed(x, 3)
    }
}

/// The report printed by `axcheck diagnose`.
pub fn render(file: &str, d: &Diagnosis) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{file}");
    let _ = writeln!(
        out,
        "Model check and diagnosis · {} axis · base model of {}: smooth systematic deviation, one reversal value, white scatter with one σ, nothing in time",
        d.kind,
        d.standard.title()
    );
    checks(&mut out, d);
    findings(&mut out, d);
    unconfirmed(&mut out, d);
    detectable(&mut out, d);
    held_out(&mut out, d);
    corrected(&mut out, d);
    for note in &d.notes {
        let _ = writeln!(out, "  note: {note}");
    }
    out
}

/// The model checks: each statistic against its simulated band.
fn checks(out: &mut String, d: &Diagnosis) {
    let _ = writeln!(
        out,
        "\nModel check: measured statistic against the 95 % band of tests simulated from the fitted base model"
    );
    let w = d
        .checks
        .iter()
        .map(|c| width(&c.statistic))
        .max()
        .unwrap_or(0);
    for c in &d.checks {
        let _ = writeln!(
            out,
            "  {}  {}   band {} … {}{}",
            left(&c.statistic, w),
            right(&num(c.measured), 10),
            num(c.simulated_low),
            num(c.simulated_high),
            if c.outside { "   OUTSIDE" } else { "" }
        );
    }
}

/// The findings with their parameters and evidence.
fn findings(out: &mut String, d: &Diagnosis) {
    let _ = writeln!(out, "\nFindings");
    let _ = writeln!(out, "  {}", d.model_check.sentence);
    for f in &d.findings {
        let _ = writeln!(out, "  {}: {}", f.effect().name(), f.message);
        let params = f.params_text(num);
        if !params.is_empty() {
            let _ = writeln!(out, "      {params}");
        }
        let evidence = f.evidence.describe(num);
        let _ = writeln!(out, "      evidence: {evidence}");
        let _ = writeln!(out, "      what to do: {}", f.advice());
    }
}

/// The smallest effect of each kind this plan confirms.
fn detectable(out: &mut String, d: &Diagnosis) {
    if d.detectable.is_empty() {
        return;
    }
    let _ = writeln!(
        out,
        "\nWhat this plan can confirm (the size found in 80 % of tests)"
    );
    for x in &d.detectable {
        let _ = writeln!(out, "  {}: {}", x.effect.name(), x.advice);
    }
}

/// The findings of the tests whose term the held-out prediction does not confirm.
fn unconfirmed(out: &mut String, d: &Diagnosis) {
    if d.unconfirmed.is_empty() {
        return;
    }
    let _ = writeln!(
        out,
        "\nSeen by its test, not confirmed by prediction (its term gains no more held out than an unrelated term of the same size; not a finding)"
    );
    for u in &d.unconfirmed {
        let f = &u.finding;
        let _ = writeln!(out, "  {}: {}", f.effect().name(), f.message);
        let _ = writeln!(out, "      evidence: {}", f.evidence.describe(num));
        let _ = writeln!(out, "      held out: {}", u.describe());
    }
}

/// The held-out error of the base and the extended model.
fn held_out(out: &mut String, d: &Diagnosis) {
    let unit = d.kind.deviation_symbol();
    let _ = writeln!(out, "\nHeld-out error ({})", d.validation);
    let _ = writeln!(
        out,
        "  base model      {} {unit} RMS   terms: {}",
        fmt_fixed(d.base.heldout_rms, 3),
        d.base.terms.join(", ")
    );
    let _ = writeln!(
        out,
        "  extended model  {} {unit} RMS   terms: {}",
        fmt_fixed(d.extended.heldout_rms, 3),
        d.extended.terms.join(", ")
    );
    let _ = writeln!(out, "  gain {} %", fmt_fixed(d.gain_pct, 1));
    if !d.term_gains.is_empty() {
        let _ = writeln!(out, "  per term, under the scheme that can show it:");
    }
    for g in &d.term_gains {
        let _ = writeln!(out, "    {}", g.describe(unit));
    }
}

/// The standard's parameters as measured and with each identified effect removed.
fn corrected(out: &mut String, d: &Diagnosis) {
    if d.corrected.is_empty() {
        return;
    }
    let _ = writeln!(
        out,
        "\nParameters as measured and with the identified effect removed ({})",
        d.kind.deviation_symbol()
    );
    for c in &d.corrected {
        let row: Vec<String> = c
            .parameters
            .iter()
            .map(|p| {
                format!(
                    "{} {} → {}",
                    p.key,
                    fmt_fixed(p.measured, 2),
                    fmt_fixed(p.corrected, 2)
                )
            })
            .collect();
        let _ = writeln!(out, "  without {}: {}", c.effect, row.join(", "));
    }
}
