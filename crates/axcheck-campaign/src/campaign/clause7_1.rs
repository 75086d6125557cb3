//! ISO 230-2:1997 clause 7.1 (method of presentation): what a test report states beside
//! the results. [`unstated`] lists, in the clause's order, the items an axis's campaign
//! entry (with what its measurement file adds) leaves out: each report prints them as
//! "not stated", the rule `iso-7.1-conditions` names them, the console and the summaries
//! count them.
//!
//! The items, as the clause lists them, and where a campaign states each: the position of
//! the measuring instrument (`instrument.position`); the positions of the temperature
//! sensors and the kind of NDE correction (`temperature_sensors[].position`, `nde`); the
//! test date (`campaign.date`, or the file's); the machine's model, type and the axis
//! travel (`model`, `type`, `travel`); the test equipment with maker, type and serial
//! numbers (`equipment`, or the instrument's `serial`); the positioning element and its
//! expansion coefficient for the NDE correction (`positioning_element`,
//! `nde.coefficient_um_per_m_c`); the position of the measuring line relative to the axes
//! not under test (`other_axes`, `tool_offset`/`workpiece_offset`); feed rate and dwell at
//! each target (`feed_mm_per_min`, `dwell_s`); the warm-up (`warm_up`); the material and
//! air temperatures at the start and end (`temperature_sensors`, `air`, or the file's
//! temperature columns); air pressure and humidity "if necessary", that is for an
//! instrument measuring through air (a laser or angular interferometer); whether internal
//! compensation was active (`compensation`). Two items are always known: the number of
//! targets and of runs come from the data. The pressure of air or oil "when used" is
//! printed when given but never counted missing: the campaign cannot say whether either
//! was used.

use super::AxisSpec;
use super::model::{Conditions, InstrumentEntry, MachineInfo, SensorKind};
use crate::uncertainty::InstrumentKind;
use crate::units::AxisKind;

/// What [`unstated`] needs beside the axis's entry.
#[derive(Debug, Clone, Copy)]
pub struct Known<'a> {
    pub machine: &'a MachineInfo,
    /// The test date is given (by the campaign or the measurement file).
    pub dated: bool,
    /// The file gives a material temperature per reading (`temp_<name>_c` columns).
    pub(crate) material_per_reading: bool,
    /// The file gives the air temperature per reading.
    pub(crate) air_per_reading: bool,
}

/// The clause 7.1 items `axis` does not state, in the clause's order, as reports print
/// them (`Position of the measuring instrument`).
pub fn unstated(axis: &AxisSpec, known: &Known) -> Vec<&'static str> {
    let c = &axis.raw.conditions;
    let m = known.machine;
    let given = |s: &Option<String>| s.as_deref().is_some_and(|s| !s.trim().is_empty());
    let instrument = c.instrument.as_ref();
    let sensors_placed = !c.temperature_sensors.is_empty()
        && (c.temperature_sensors.iter()).all(|s| given(&s.position));
    let items: [(&'static str, bool); 17] = [
        (
            "Position of the measuring instrument",
            instrument.is_some_and(|i| given(&i.position)),
        ),
        ("Positions of the temperature sensors", sensors_placed),
        ("NDE correction (3.1)", c.nde.is_some()),
        ("Test date", known.dated),
        ("Machine model", given(&m.model)),
        ("Machine type", given(&m.machine_type)),
        ("Axis travel", axis.raw.travel.is_some()),
        (
            "Test equipment (maker, type, serial numbers)",
            !c.equipment.is_empty() || instrument.is_some_and(|i| given(&i.serial)),
        ),
        ("Positioning element", given(&c.positioning_element)),
        (
            "Expansion coefficient of the positioning element",
            c.nde
                .as_ref()
                .is_some_and(|n| n.coefficient_um_per_m_c.is_some()),
        ),
        ("Positions of the other axes (3.2)", given(&c.other_axes)),
        (
            "Tool and workpiece offsets",
            given(&c.tool_offset) || given(&c.workpiece_offset),
        ),
        ("Feed rate", c.feed_mm_per_min.is_some()),
        ("Dwell at each target", c.dwell_s.is_some()),
        ("Warm-up (3.3)", given(&c.warm_up)),
        (
            "Material temperatures at start and end",
            known.material_per_reading || sensor_span(c, SensorKind::Material),
        ),
        (
            "Air temperature at start and end",
            known.air_per_reading || air_span(c),
        ),
    ];
    let mut missing: Vec<&'static str> = (items.into_iter())
        .filter(|(_, stated)| !stated)
        .map(|(label, _)| label)
        .collect();
    let air = c.air.as_ref();
    let pressure_humidity =
        air.is_some_and(|a| a.pressure_kpa.is_some() && a.humidity_pct.is_some());
    if through_air(instrument, axis.raw.kind) && !pressure_humidity {
        missing.push("Air pressure and humidity at start and end");
    }
    if !given(&c.compensation) {
        missing.push("Compensation active during the test (3.2)");
    }
    missing
}

/// A sensor of `kind` read at the start and the end of the test.
fn sensor_span(c: &Conditions, kind: SensorKind) -> bool {
    (c.temperature_sensors.iter())
        .any(|s| s.kind == kind && s.start_c.is_some() && s.end_c.is_some())
}

/// The air temperature at the start and the end (the `air` block or an air sensor).
fn air_span(c: &Conditions) -> bool {
    let block = (c.air.as_ref())
        .is_some_and(|a| a.temperature_start_c.is_some() && a.temperature_end_c.is_some());
    block || sensor_span(c, SensorKind::Air)
}

/// Whether the instrument measures through air, so that air pressure and humidity set its
/// wavelength (a laser or angular interferometer; the axis kind's usual one when the
/// campaign names none).
fn through_air(instrument: Option<&InstrumentEntry>, kind: AxisKind) -> bool {
    let named = instrument
        .and_then(|i| (i.kind).or_else(|| i.name.as_deref().and_then(InstrumentKind::from_name)));
    let usual = match kind {
        AxisKind::Linear => InstrumentKind::LaserInterferometer,
        AxisKind::Rotary => InstrumentKind::AngularInterferometer,
    };
    matches!(
        named.unwrap_or(usual),
        InstrumentKind::LaserInterferometer | InstrumentKind::AngularInterferometer
    )
}
