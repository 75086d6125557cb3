//! What the test-plan rules know of an axis from the campaign: its kind, standard and
//! travels, its pitch, and the planned test it names (`plan:`), read beneath the
//! campaign's folder.

use crate::campaign::{AxisSpec, CampaignInfo, MachineInfo};
use crate::files::Root;
use crate::measurement::{AxisData, Recognised};
use crate::rules::{self, PlanContext};
use crate::units::AxisKind;

/// What the test-plan rules need to know of an axis from the campaign.
pub fn context(axis: &AxisSpec) -> PlanContext {
    PlanContext {
        kind: axis.raw.kind,
        standard: axis.standard,
        axis_travel: axis.raw.travel,
        measurement_travel: axis.raw.measurement_travel,
        pitch: axis.raw.pitch,
        planned: None,
        unstated: None,
        calibration: None,
    }
}

/// The planned test `raw` names, read as the rules compare it (or why it cannot be read).
pub fn planned(
    raw: &crate::campaign::model::PlanRaw,
    kind: AxisKind,
    files: &Root,
) -> rules::Planned {
    let unread = |e: &dyn std::fmt::Display| rules::PlanUnread::File(e.to_string());
    let read = || -> Result<(Vec<f64>, usize), rules::PlanUnread> {
        let path = files.resolve(&raw.file).map_err(|e| unread(&e))?;
        let text = files.read_to_string(&path).map_err(|e| unread(&e))?;
        let plan = crate::plan::file::from_yaml(&text, &raw.file).map_err(|e| unread(&e))?;
        if plan.axis.kind != kind {
            return Err(rules::PlanUnread::Kind {
                planned: plan.axis.kind,
                measured: kind,
            });
        }
        Ok((plan.targets, plan.runs))
    };
    rules::Planned {
        file: raw.file.clone(),
        read: read(),
        tolerance: raw.tolerance.unwrap_or(0.01),
    }
}

/// The clause 7.1 conditions of the test that neither the campaign nor the file states.
pub fn unstated(
    axis: &AxisSpec,
    machine: &MachineInfo,
    campaign: &CampaignInfo,
    recognised: &Recognised,
    data: &AxisData,
) -> Vec<&'static str> {
    let file_date = (recognised.info.as_ref()).is_some_and(|i| i.date.is_some());
    let air = |n: &String| n.to_ascii_lowercase().contains("air");
    let known = crate::campaign::clause7_1::Known {
        machine,
        dated: campaign.date.is_some() || file_date,
        material_per_reading: super::nde::has_material_temperatures(data),
        air_per_reading: data.temperature_names.iter().any(air),
    };
    crate::campaign::clause7_1::unstated(axis, &known)
}

/// The instrument's calibration against the test's date (the file's when it writes one
/// YYYY-MM-DD, else the campaign's): where a due date is stated, or always when the campaign
/// is a certificate (which must show the instrument's traceability).
pub fn calibration(
    axis: &AxisSpec,
    machine: &MachineInfo,
    campaign: &CampaignInfo,
    recognised: &Recognised,
) -> Option<rules::CalibrationDue> {
    let certifying = campaign.certificate.is_some() || machine.certificate.is_some();
    let instrument = axis.raw.conditions.instrument.as_ref();
    let c = instrument.and_then(|i| i.calibration.as_ref());
    if !certifying && c.is_none_or(|c| c.due.is_none() && c.calibrated_on.is_none()) {
        return None;
    }
    let file_date = (recognised.info.as_ref())
        .and_then(|i| i.date.clone())
        .filter(|d| crate::campaign::dates::is_iso_date(d));
    let name = instrument.map(|i| {
        let name = [i.name.clone(), i.serial.clone().map(|s| format!("s/n {s}"))]
            .into_iter()
            .flatten()
            .collect::<Vec<_>>()
            .join(" ");
        if name.is_empty() {
            "(unnamed)".into()
        } else {
            name
        }
    });
    Some(rules::CalibrationDue {
        instrument: name,
        certificate: c.and_then(|c| c.certificate.clone()),
        calibrated_on: c.and_then(|c| c.calibrated_on.clone()),
        due: c.and_then(|c| c.due.clone()),
        test_date: file_date.or_else(|| campaign.date.clone()),
        certifying,
    })
}
