//! What a calibration certificate adds to a report (`campaign.certificate`; ISO/IEC
//! 17025:2017 7.8.2.1, 7.8.4.1): its number, the customer, the laboratory, the dates of
//! the measurement and of issue, the method and its deviations, the instruments' traceability
//! and who authorises it. Values only: the templates print the labels.

use crate::campaign::certificate::{CertificateRaw, Party, Signatory};
use crate::campaign::model::InstrumentEntry;
use crate::results::{AxisTest, CampaignResult};
use crate::words::Words;
use serde::Serialize;

/// The certificate block of one report.
#[derive(Serialize)]
pub struct CertificateSection<'a> {
    /// The title as the campaign writes it ("" for the report language's own).
    title: &'a str,
    /// This report's number (the summary's: the campaign's).
    number: String,
    issued: String,
    /// The date of the measurement (the campaign's).
    measured: String,
    /// Where the measurement was made (the campaign's site; "" when unstated).
    site: &'a str,
    customer: &'a Party,
    laboratory: &'a Party,
    authorised_by: &'a Signatory,
    /// The method: the standards and editions the reports follow.
    method: Vec<String>,
    /// Deviations from the method as stated ("" for none).
    deviations: &'a str,
    /// Each instrument the report's results rest on, once.
    instruments: Vec<InstrumentRow>,
}

/// One instrument of the traceability table.
#[derive(Serialize, PartialEq, Eq, PartialOrd, Ord)]
struct InstrumentRow {
    name: String,
    serial: String,
    certificate: String,
    calibrated_on: String,
    due: String,
    body: String,
}

impl InstrumentRow {
    fn of(i: &InstrumentEntry, words: &Words) -> InstrumentRow {
        let c = i.calibration.clone().unwrap_or_default();
        let text = |s: Option<String>| s.unwrap_or_default();
        let date = |d: Option<String>| d.map_or(String::new(), |d| words.date(&d));
        InstrumentRow {
            name: text(i.name.clone()),
            serial: text(i.serial.clone()),
            certificate: text(c.certificate),
            calibrated_on: date(c.calibrated_on),
            due: date(c.due),
            body: text(c.body),
        }
    }
}

/// The certificate block of the report of `tests` (one test's, or the summary's of all),
/// numbered `number`, in `words`' language; `None` when the campaign is no certificate.
pub fn certificate_section<'a>(
    result: &'a CampaignResult,
    tests: &[&'a AxisTest],
    number: Option<String>,
    words: &Words,
) -> Option<CertificateSection<'a>> {
    let c: &CertificateRaw = match tests {
        [t] => result.certificate_of(t)?,
        _ => result.info.certificate.as_ref()?,
    };
    let mut instruments: Vec<InstrumentRow> = (tests.iter())
        .filter_map(|t| t.spec.as_ref()?.raw.conditions.instrument.as_ref())
        .map(|i| InstrumentRow::of(i, words))
        .collect();
    instruments.sort();
    instruments.dedup();
    let mut method: Vec<String> = tests.iter().map(|t| method_of(t, words)).collect();
    method.retain(|m| !m.is_empty());
    method.sort();
    method.dedup();
    Some(CertificateSection {
        title: c.title.as_deref().unwrap_or_default(),
        number: number.unwrap_or_else(|| c.number.clone()),
        issued: c.issued.as_deref().map_or(String::new(), |d| words.date(d)),
        measured: (result.info.date.as_deref()).map_or(String::new(), |d| words.date(d)),
        site: result.info.site.as_deref().unwrap_or_default(),
        customer: &c.customer,
        laboratory: &c.laboratory,
        authorised_by: &c.authorised_by,
        method,
        deviations: c.deviations.as_deref().unwrap_or_default(),
        instruments,
    })
}

/// The method a test follows: its standard and edition (ISO 230-1's tests by name: the
/// project has not its clauses' numbers).
fn method_of(t: &AxisTest, words: &Words) -> String {
    use crate::geometry::TestKind;
    match (t.test_kind(), t.positioning_standard()) {
        (TestKind::Positioning, Some(s)) => words.standard(s),
        (TestKind::Positioning, None) => String::new(),
        (TestKind::Straightness, _) => words.get("method-straightness"),
        (TestKind::Angular, _) => words.get("method-angular"),
        (TestKind::Squareness, _) => words.get("method-squareness"),
    }
}
