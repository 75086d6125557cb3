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
    let (Some(e), Some(kind), Some(standard)) = (t.evaluated(), t.kind(), t.standard()) else {
        return Vec::new();
    };
    // Not diagnosed: empty; diagnosed with nothing found: `none`.
    let effects = (e.diagnosis.as_deref())
        .map(|d| d.effects_label())
        .unwrap_or_default();
    let kind_text = kind.to_string();
    let head = Head::of(
        campaign,
        date,
        t,
        &t.axis,
        [&kind_text, standard.key(), kind.deviation_unit(), &effects],
    );
    (e.evaluation.parameters.iter())
        .filter(|p| p.value.is_finite())
        .map(|p| {
            let limit = (e.judgement.as_ref())
                .and_then(|j| j.limits.values.get(&p.def.key))
                .map(|(limit, _)| *limit);
            let u = (e.uncertainty.as_ref()).and_then(|u| u.expanded_of(p.def.key));
            head.record(p.key(), p.value, limit, u)
        })
        .collect()
}

/// What every row of one test shares, each text one copy for all its rows.
struct Head {
    campaign: SharedText,
    date: NaiveDate,
    machine: SharedText,
    serial: Option<SharedText>,
    axis: SharedText,
    test: u32,
    verdict: SharedText,
    /// Kind, standard, unit and effects.
    texts: [SharedText; 4],
}

impl Head {
    fn of(campaign: &str, date: NaiveDate, t: &AxisTest, axis: &str, texts: [&str; 4]) -> Head {
        Head {
            campaign: campaign.into(),
            date,
            machine: t.machine.id.as_str().into(),
            serial: t.machine.serial.as_deref().map(Into::into),
            axis: axis.into(),
            test: u32::try_from(t.test).unwrap_or(u32::MAX),
            verdict: t.verdict().name().into(),
            texts: texts.map(Into::into),
        }
    }

    fn record(&self, parameter: &str, value: f64, limit: Option<f64>, u: Option<f64>) -> Record {
        let [kind, standard, unit, effects] = self.texts.clone();
        Record {
            schema_version: SCHEMA_VERSION,
            campaign: self.campaign.clone(),
            date: self.date,
            machine: self.machine.clone(),
            serial: self.serial.clone(),
            axis: self.axis.clone(),
            test: self.test,
            kind,
            standard,
            verdict: self.verdict.clone(),
            parameter: parameter.into(),
            unit,
            value,
            limit,
            uncertainty: u,
            effects,
        }
    }
}

/// The rows of a straightness, angular or squareness test: one per value it has (the
/// straightness and its local value, the angular deviation, the squareness), its series
/// named by the axis and ISO 230-1's symbol (`X EYX`, `X-Y squareness`), so that each
/// test of an axis measured whole has its own trends beside the positioning test's.
fn other_records(campaign: &str, date: NaiveDate, t: &AxisTest) -> Vec<Record> {
    let Some(o) = t.other() else {
        return Vec::new();
    };
    let head = Head::of(
        campaign,
        date,
        t,
        &t.axis_label(),
        ["linear", OTHER_STANDARD, o.unit(), ""],
    );
    (o.values())
        .filter(|(_, value, _)| value.is_finite())
        .map(|(key, value, check)| {
            head.record(
                key.as_str(),
                value,
                check.map(|c| c.limit),
                Some(o.uncertainty.expanded),
            )
        })
        .collect()
}

/// The `standard` of the other laser tests' rows: their definitions are ISO 230-1's.
const OTHER_STANDARD: &str = "iso230-1";
