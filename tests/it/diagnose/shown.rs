//! What the diagnosis shows of its judgement (issue 31): a finding whose term the held-out
//! prediction does not confirm is listed apart, in the JSON and the text; a
//! kept effect in time comes with the run means and the fitted curve for the report's
//! time chart.

use super::*;

/// Run offsets that their test sees on a clean 5-target, 5-run axis (F = 7.12 on 3 and 33
/// df, p = 0.0008, a seed of the sweep, as `axcheck simulate` writes it and `axcheck
/// diagnose` reads it back) but whose term predicts the held-out readings worse (−6.5 %)
/// than the base model does on tests simulated without it (up to +2.5 %). (The drift and
/// warm-up this test used before were a barely bent curve that free run offsets explain
/// better; such a curve is no longer taken for a warm-up.)
#[test]
fn a_finding_not_confirmed_by_prediction_is_listed_apart() {
    let dir = crate::common::scratch("unconfirmed");
    let model = dir.join("clean.yaml");
    std::fs::write(&model, sweep::small_clean_case(380_049).sim.to_yaml()).unwrap();
    let (code, csv, err) = crate::common::axcheck(&["simulate", model.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let file = dir.join("data/clean.csv");
    std::fs::write(&file, csv).unwrap();
    let file = file.to_str().unwrap();
    let (code, json, err) = crate::common::axcheck(&["diagnose", file, "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert!(
        v["findings"].as_array().unwrap().is_empty(),
        "{}",
        v["findings"]
    );
    let u = &v["unconfirmed"][0];
    assert_eq!(u["effect"], "run_offset");
    assert_eq!(u["scheme"], "k_fold_rms");
    assert_eq!(u["null"], "simulated_tests");
    assert!(u["evidence"]["p_value"].as_f64().unwrap() < diagnose::ALPHA);
    let (gain, threshold) = (
        u["gain_pct"].as_f64().unwrap(),
        u["threshold_pct"].as_f64().unwrap(),
    );
    assert!(
        (gain + 6.54).abs() < 0.01 && (threshold - 2.51).abs() < 0.01,
        "{u}"
    );
    assert_eq!(v["unconfirmed"].as_array().unwrap().len(), 1);
    // The same numbers as its term's judgement, which leaves it out of the model.
    let g = &v["term_gains"][0];
    assert_eq!(
        (g["effect"].as_str(), g["kept"].as_bool()),
        (Some("run_offset"), Some(false))
    );
    assert_eq!(g["gain_pct"], u["gain_pct"]);
    assert_eq!(g["threshold_pct"], u["threshold_pct"]);
    let terms = v["extended"]["terms"].as_array().unwrap();
    assert!(!terms.iter().any(|t| t == "run_offset"), "{terms:?}");
    // Listed once, not again among the notes.
    let notes = v["notes"].as_array().unwrap();
    assert!(
        !notes
            .iter()
            .any(|n| n.as_str().unwrap().starts_with("run_offset")),
        "{notes:?}"
    );
    let (_, text, _) = crate::common::axcheck(&["diagnose", file]);
    let listed = text
        .split("\nSeen by its test, not confirmed by prediction")
        .nth(1)
        .unwrap_or_else(|| panic!("{text}"));
    assert!(
        listed.contains("\n  run_offset: whole runs are shifted, not in time order (zero-point instability): offsets 0.157, 0.040, -0.425, 0.061, 0.167 µm (RMS 0.218; F = 7.12, p = 0.0008)"),
        "{text}"
    );
    assert!(
        listed.contains("held out: -6.5 % held out (k-fold over readings, RMS); 19 tests simulated without it up to +2.5 %"),
        "{text}"
    );
    // Every model check inside its band: the verdict may say the base model explains the
    // data (a statistic outside its band would be named: `verdict.rs`).
    assert!(
        text.contains("Findings\n  none: the base model explains the data (all 7 model checks inside their simulated 95 % bands)"),
        "{text}"
    );
    std::fs::remove_dir_all(dir).unwrap();
}

/// The kept drift against the run means: the curve is the extended model's drift at its
/// rate, about the effect's mean; the run means, put on the same footing (each reading less
/// its cell's systematic deviation), average to zero over the readings and lie about the
/// line, one per run and direction.
#[test]
fn a_kept_drift_is_drawn_against_the_run_means() {
    let case = drift_case(4);
    let (data, d) = run_case(&case);
    assert!(d.has(Effect::Drift), "{:?}", d.findings);
    let t = d
        .residuals
        .time_effect
        .as_ref()
        .expect("a time effect to draw");
    assert_eq!(t.terms, [Effect::Drift]);
    assert_eq!(t.run_means.len(), 2 * data.runs());
    let (first, last) = (t.curve[0], t.curve[t.curve.len() - 1]);
    let hours = (last.time_s.unwrap() - first.time_s.unwrap()) / 3600.0;
    let rate = (last.value - first.value) / hours;
    let model_rate = d.extended_model.model.drift_per_h;
    assert!(
        (rate - model_rate).abs() <= 1e-4 + 1e-6 * rate.abs(),
        "{rate} vs {model_rate}"
    );
    assert!(rel_err(rate, case.truth) < 0.2, "{rate} vs {}", case.truth);
    // The readings' mean of the partial residuals is zero (every cell complete).
    let weighted: f64 = t.run_means.iter().map(|m| m.mean * m.readings as f64).sum();
    assert!(weighted.abs() < 1e-9, "{weighted}");
    // Each run mean against the line at its time: within the band but for chance (a
    // run mean lies outside in 5 % of tests), never far off.
    let at = |s: f64| {
        let k = t
            .curve
            .partition_point(|c| c.time_s.unwrap() < s)
            .min(t.curve.len() - 1);
        t.curve[k].value
    };
    let off: Vec<f64> = t
        .run_means
        .iter()
        .map(|m| (m.mean - at(m.time_s.unwrap())) / t.band)
        .collect();
    assert!(off.iter().all(|o| o.abs() < 2.0), "{off:?}");
    assert!(
        off.iter().filter(|o| o.abs() <= 1.0).count() * 10 >= 7 * off.len(),
        "{off:?}"
    );
    assert!((t.band - 2.0 * t.sigma / (data.target_count() as f64).sqrt()).abs() < 1e-12);
    // Clean data keep no time effect and draw none.
    let (_, clean) = run_case(&clean_case(80_000));
    assert!(clean.residuals.time_effect.is_none());
}

/// The kept warm-up: the curve is an exponential approach with the extended model's time
/// constant, rises from the first reading by about the finding's amplitude less what
/// remains at the end (the finding's fit and the extended model's differ a little), and
/// the first run is the furthest from the final level.
#[test]
fn a_kept_warm_up_is_drawn_against_the_run_means() {
    let case = warm_up_case(90_004, false);
    let (_, d) = run_case(&case);
    let t = d
        .residuals
        .time_effect
        .as_ref()
        .expect("a time effect to draw");
    assert_eq!(t.terms, [Effect::WarmUp]);
    // Equal steps in time: successive rises shrink by e^(−Δt/τ).
    let tau_min = d.extended_model.model.warm_up_tau_min;
    let c = &t.curve;
    let step_min = (c[1].time_s.unwrap() - c[0].time_s.unwrap()) / 60.0;
    let ratio = (c[2].value - c[1].value) / (c[1].value - c[0].value);
    assert!(
        (ratio - (-step_min / tau_min).exp()).abs() < 1e-6,
        "{ratio} vs τ {tau_min}"
    );
    let (first, last) = (c[0], c[c.len() - 1]);
    let amplitude = param(&d, Effect::WarmUp, "amplitude_um").abs();
    let remaining = param(&d, Effect::WarmUp, "remaining_at_end_um").abs();
    let rise = (last.value - first.value).abs();
    assert!(
        rel_err(rise, amplitude - remaining) < 0.1,
        "{rise} vs {amplitude} − {remaining}"
    );
    let up = last.value > first.value;
    assert!(c.windows(2).all(|w| (w[1].value >= w[0].value) == up));
    let spread = |m: &diagnose::RunMean| (m.mean - last.value).abs();
    let worst = t
        .run_means
        .iter()
        .max_by(|a, b| spread(a).total_cmp(&spread(b)))
        .unwrap();
    assert_eq!(worst.run, 1, "{:?}", t.run_means);
}
