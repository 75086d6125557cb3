//! `axcheck simulate`: an error model and a test plan produce a measurement file.

use anyhow::{Context, Result};
use axcheck::measurement::csv;
use axcheck::simulate::Simulation;
use std::path::Path;

/// Simulates `model` and returns the CSV text.
pub fn run(model: &Path, seed: Option<u64>) -> Result<String> {
    let text = std::fs::read_to_string(model)
        .with_context(|| format!("cannot read the model file {}", model.display()))?;
    let sim = Simulation::from_yaml(&text, &model.display().to_string())?;
    let seed = seed.unwrap_or(sim.seed);
    let data = sim.run(seed);
    let name = model
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let mut comments = vec![format!(
        "simulated by axcheck {} from {name}, seed {seed}, {} cycle",
        env!("CARGO_PKG_VERSION"),
        sim.plan.cycle.name()
    )];
    if let Some(d) = &sim.description {
        comments.push(d.clone());
    }
    Ok(csv::write(&data, &comments))
}
