//! A run's results as history rows: one per evaluated parameter of each axis test.

use super::record::SharedText;
use super::{HistoryError, Record, SCHEMA_VERSION};
use crate::campaign::CampaignInfo;
use crate::results::{AxisTest, CampaignResult};
use chrono::NaiveDate;

/// The run's date (`campaign.date`), which a history needs, checked with the history file
/// name it gives (before the evaluation: not after the outputs are written); `file` names
/// the campaign file in the error.
pub fn run_date(info: &CampaignInfo, file: &str) -> Result<NaiveDate, HistoryError> {
    if info.name.trim().is_empty() {
        return Err(HistoryError::MissingName { file: file.into() });
    }
    let date = info
        .date
        .as_deref()
        .ok_or_else(|| HistoryError::MissingDate { file: file.into() })?;
    let date = NaiveDate::parse_from_str(date, "%Y-%m-%d").map_err(|_| HistoryError::BadDate {
        file: file.into(),
        date: date.into(),
    })?;
    let name = super::file_name(&info.name, date);
    if name.len() > super::MAX_FILE_NAME_BYTES {
        return Err(HistoryError::NameTooLong {
            file: file.into(),
            bytes: name.len(),
        });
    }
    Ok(date)
}

/// One row per (axis test, evaluated parameter), in campaign order then the standard's
/// parameter order. Tests without an evaluation (errors before it) have no rows; a value
/// that could not be computed (not finite) has none either.
pub fn records(result: &CampaignResult) -> Result<Vec<Record>, HistoryError> {
    let date = run_date(&result.info, &result.file_name)?;
    Ok(result
        .tests
        .iter()
        .flat_map(|t| test_records(&result.info.name, date, t))
        .collect())
}

fn test_records(campaign: &str, date: NaiveDate, t: &AxisTest) -> Vec<Record> {
    if t.other().is_some() {
        return other_records(campaign, date, t);
    }
    let (Some(evaluation), Some(kind), Some(standard)) =
        (t.evaluated().map(|e| &e.evaluation), t.kind(), t.standard())
    else {
        return Vec::new();
    };
    // Not diagnosed: empty; diagnosed with nothing found: `none`.
    let effects = t
        .evaluated()
        .and_then(|e| e.diagnosis.as_deref())
        .map(|d| d.effects_label())
        .unwrap_or_default();
    // One copy of each text for the test's rows.
    let text = |s: &str| -> SharedText { s.into() };
    let (campaign, machine, axis) = (text(campaign), text(&t.machine.id), text(&t.axis));
    let serial = t.machine.serial.as_deref().map(text);
    let (kind_text, standard_key) = (text(&kind.to_string()), text(standard.key()));
    let (verdict, unit, effects) = (
        text(t.verdict().name()),
        text(kind.deviation_unit()),
        text(&effects),
    );
    evaluation
        .parameters
        .iter()
        .filter(|p| p.value.is_finite())
        .map(|p| {
            let key = p.key();
            Record {
                schema_version: SCHEMA_VERSION,
                campaign: campaign.clone(),
                date,
                machine: machine.clone(),
                serial: serial.clone(),
                axis: axis.clone(),
                test: u32::try_from(t.test).unwrap_or(u32::MAX),
                kind: kind_text.clone(),
                standard: standard_key.clone(),
                verdict: verdict.clone(),
                parameter: text(key),
                unit: unit.clone(),
                value: p.value,
                limit: t
                    .evaluated()
                    .and_then(|e| e.judgement.as_ref())
                    .and_then(|j| j.limits.values.get(&p.def.key))
                    .map(|(limit, _)| *limit),
                uncertainty: t
                    .evaluated()
                    .and_then(|e| e.uncertainty.as_ref())
                    .and_then(|u| u.expanded_of(p.def.key)),
                effects: effects.clone(),
            }
        })
        .collect()
}

/// The rows of a straightness, angular or squareness test: one per value it has (the
/// straightness and its local value, the angular deviation, the squareness), its series
/// named by the axis and ISO 230-1's symbol (`X EYX`, `X-Y squareness`), so that each
/// test of an axis measured whole has its own trends beside the positioning test's.
fn other_records(campaign: &str, date: NaiveDate, t: &AxisTest) -> Vec<Record> {
    let Some(o) = t.other() else {
        return Vec::new();
    };
    let text = |s: &str| -> SharedText { s.into() };
    let (campaign, machine, axis) = (text(campaign), text(&t.machine.id), text(&t.axis_label()));
    let serial = t.machine.serial.as_deref().map(text);
    let (verdict, unit) = (text(t.verdict().name()), text(o.unit()));
    let check = |key| o.judgement.checks.iter().find(|c| c.key == key);
    (crate::param_key::ParamKey::GEOMETRY.into_iter())
        .filter_map(|key| Some((key, o.result.value(key).filter(|v| v.is_finite())?)))
        .map(|(key, value)| Record {
            schema_version: SCHEMA_VERSION,
            campaign: campaign.clone(),
            date,
            machine: machine.clone(),
            serial: serial.clone(),
            axis: axis.clone(),
            test: u32::try_from(t.test).unwrap_or(u32::MAX),
            kind: text("linear"),
            standard: text(OTHER_STANDARD),
            verdict: verdict.clone(),
            parameter: text(key.as_str()),
            unit: unit.clone(),
            value,
            limit: check(key).map(|c| c.limit),
            uncertainty: Some(o.uncertainty.expanded),
            effects: text(""),
        })
        .collect()
}

/// The `standard` of the other laser tests' rows: their definitions are ISO 230-1's.
const OTHER_STANDARD: &str = "iso230-1";
