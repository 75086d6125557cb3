//! The uncertainty budget's set-up from the campaign's clause 7.1 block (ISO 230-2 7.1,
//! ISO/TR 230-9): the instrument, the air, the material sensors and the NDE correction.

use crate::campaign::{AxisSpec, SensorKind};
use crate::measurement::AxisData;
use crate::nde::NdeCorrection;
use crate::uncertainty::{Distribution, InstrumentKind, Setup};

/// What the uncertainty budget knows of a test from the campaign (clause 7.1 block): the
/// instrument (its `kind`, else guessed from its name, else the axis kind's usual one),
/// the air temperature's change, the material sensors' readings, the expansion
/// coefficient and whether the deviations are corrected to 20 °C (NDE, clause 3.1).
pub fn setup(axis: &AxisSpec, data: &AxisData, nde: Option<&NdeCorrection>) -> Setup {
    let c = &axis.raw.conditions;
    let kind = c.instrument.as_ref().and_then(|i| {
        i.kind
            .or_else(|| i.name.as_deref().and_then(InstrumentKind::from_name))
    });
    let mut setup = kind.map_or_else(|| Setup::for_axis(axis.raw.kind), Setup::for_instrument);
    if let Some(i) = &c.instrument {
        stated_instrument(&mut setup, i);
    }
    if let (Some(air), Some(a)) = (setup.air.as_mut(), c.air.as_ref())
        && let (Some(start), Some(end)) = (a.temperature_start_c, a.temperature_end_c)
    {
        air.temperature_change_c = end - start;
    }
    let material: Vec<(f64, f64)> = c
        .temperature_sensors
        .iter()
        .filter(|s| s.kind == SensorKind::Material)
        .filter_map(|s| Some((s.start_c?, s.end_c?)))
        .collect();
    setup.thermal.set_from_sensors(&material);
    if let Some(alpha) = c.nde.as_ref().and_then(|n| n.coefficient_um_per_m_c) {
        setup.thermal.coefficient_um_per_m_c = alpha;
    }
    setup.thermal.nde_corrected = nde.is_some() || c.nde.as_ref().is_some_and(|n| n.corrected);
    if let Some(n) = nde {
        setup.thermal.mean_c = Some(n.mean_temperature_c);
        // Corrected reading by reading: the change during the test is corrected too.
        if super::nde::has_material_temperatures(data) {
            setup.thermal.change_c = 0.0;
        }
    }
    setup
}

/// What the campaign states of the instrument over its kind's defaults: its accuracy (a
/// specification's limits, or a certificate's U with its k), resolution, dead path and
/// beam walk.
fn stated_instrument(setup: &mut Setup, i: &crate::campaign::InstrumentEntry) {
    let ins = &mut setup.instrument;
    if i.accuracy_fixed.is_some() || i.accuracy_ppm.is_some() {
        ins.calibration_fixed = i.accuracy_fixed.unwrap_or(0.0);
        ins.calibration_ppm = i.accuracy_ppm.unwrap_or(0.0);
    }
    if let Some(k) = i.accuracy_k {
        ins.calibration_distribution = Distribution::Normal { k };
    }
    if let Some(r) = i.resolution {
        ins.resolution = r;
    }
    if let Some(d) = i.dead_path_mm {
        setup.dead_path_mm = d;
    }
    if let Some(w) = i.beam_walk_mm {
        setup.misalignment_offset_mm = w;
    }
}
