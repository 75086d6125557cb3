//! `axcheck diagnose`: what the standard's model of the axis gets wrong, and why.

use super::text::{left, right, width};
use axcheck::diagnose::Diagnosis;
use axcheck::units::fmt_fixed;
use std::fmt::Write;

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
    if d.findings.is_empty() {
        let _ = writeln!(out, "  none: the base model explains the data");
    }
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
