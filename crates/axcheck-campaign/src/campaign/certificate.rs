//! `campaign.certificate`: what a calibration laboratory's report carries beyond the
//! results (ISO/IEC 17025:2017 7.8.2.1, 7.8.4.1): its number on every report, the customer,
//! the laboratory, who authorises it, the date of issue, the deviations from the method.
//!
//! A report's number is `report_number` (default `{number}/{machine}-{axis}-{test}`) with
//! `{number}` the campaign's, `{machine}` and `{axis}` their names and `{test}` the test's
//! own part: `P` for a positioning test (ISO 230-2), the ISO 230-1 symbol of another
//! (`EYX`), followed by `-1`, `-2` … when the entry has several files. The summary carries
//! `{number}` itself.

use super::dates::iso_date;
use crate::yaml::{Located, LocationIndex};
use serde::{Deserialize, Serialize};

/// The default pattern of a report's number: unique for every report of a campaign.
pub const DEFAULT_REPORT_NUMBER: &str = "{number}/{machine}-{axis}-{test}";

/// The placeholders a report number's pattern may hold.
const PLACEHOLDERS: [&str; 4] = ["number", "machine", "axis", "test"];

/// `campaign.certificate`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CertificateRaw {
    /// The campaign's certificate number: the summary's, and `{number}` in each report's.
    pub number: String,
    /// The pattern of each report's number (see the module).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub report_number: Option<String>,
    /// The report's title; "Calibration certificate" (in the report's language) when absent.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub title: Option<String>,
    /// Date of issue, YYYY-MM-DD (7.8.2.1 j).
    #[serde(default, deserialize_with = "iso_date")]
    pub issued: Option<String>,
    /// The customer (7.8.2.1 e).
    pub customer: Party,
    /// The laboratory (7.8.2.1 b) and its accreditation.
    pub laboratory: Party,
    /// Who authorises the report (7.8.2.1 o).
    pub authorised_by: Signatory,
    /// Additions to, deviations from or exclusions from the method (7.8.2.1 n); "none" when
    /// absent.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub deviations: Option<String>,
}

/// A customer or a laboratory.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Party {
    pub name: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub address: Option<String>,
    /// A laboratory's accreditation (body and number), e.g. "DAkkS D-K-12345-01-00".
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub accreditation: Option<String>,
}

/// The person who authorises the report: name and role (a line is left for the signature).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Signatory {
    pub name: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub role: Option<String>,
}

/// What a report's number is made of.
pub struct ReportId<'a> {
    pub machine: &'a str,
    pub axis: &'a str,
    /// ISO 230-1's symbol of a straightness, angular or squareness test; `None`: a
    /// positioning test.
    pub symbol: Option<&'a str>,
    /// The test's index among its entry's files (1-based) and their number.
    pub test: usize,
    pub tests: usize,
}

impl CertificateRaw {
    /// The pattern of the reports' numbers.
    pub fn pattern(&self) -> &str {
        self.report_number
            .as_deref()
            .unwrap_or(DEFAULT_REPORT_NUMBER)
    }

    /// The number of the report `id`.
    pub fn report_number(&self, id: &ReportId) -> String {
        let mut test = id.symbol.unwrap_or("P").to_string();
        if id.tests > 1 {
            test = format!("{test}-{}", id.test);
        }
        let pattern = self.pattern();
        // A pattern without `{test}` still numbers an entry's files apart.
        let suffix = if !pattern.contains("{test}") && id.tests > 1 {
            format!("-{}", id.test)
        } else {
            String::new()
        };
        let number = pattern
            .replace("{number}", &self.number)
            .replace("{machine}", id.machine)
            .replace("{axis}", id.axis)
            .replace("{test}", &test);
        number + &suffix
    }
}

/// The certificate at `path` (`campaign.certificate`, `machines[0].certificate`) checked at
/// its lines: a number, an issue date not before the measurement's, a pattern of known
/// placeholders naming the machine and the axis; and the campaign dated (7.8.2.1 i).
pub(super) fn check(
    c: &CertificateRaw,
    path: &str,
    measured: Option<&str>,
    index: &LocationIndex,
) -> Result<(), Located> {
    let at = |key: &str, message: String| {
        let path = format!("{path}{key}");
        Located::new(index.value(&path), format!("{path}: {message}"))
    };
    if c.number.trim().is_empty() {
        return Err(at(".number", "the certificate number is empty".into()));
    }
    let Some(issued) = &c.issued else {
        return Err(at(
            "",
            "a certificate states its date of issue (issued: YYYY-MM-DD; ISO/IEC 17025:2017 7.8.2.1 j)".into(),
        ));
    };
    let Some(measured) = measured else {
        return Err(at(
            "",
            "a certificate states the date of the measurement: add campaign.date (ISO/IEC 17025:2017 7.8.2.1 i)".into(),
        ));
    };
    if issued.as_str() < measured {
        return Err(at(
            ".issued",
            format!("{issued} is before the measurement on {measured} (campaign.date)"),
        ));
    }
    check_pattern(c.pattern()).map_err(|why| at(".report_number", why))
}

/// A report number's pattern: only known placeholders, and `{machine}` and `{axis}` among
/// them, so that each report of a campaign has its own number.
fn check_pattern(pattern: &str) -> Result<(), String> {
    let mut rest = pattern;
    while let Some(open) = rest.find('{') {
        let Some(close) = rest[open..].find('}') else {
            return Err(format!("`{pattern}` opens a `{{` it does not close"));
        };
        let name = &rest[open + 1..open + close];
        if !PLACEHOLDERS.contains(&name) {
            return Err(format!(
                "`{{{name}}}` is not a placeholder of a report number; use {}",
                PLACEHOLDERS.map(|p| format!("{{{p}}}")).join(", ")
            ));
        }
        rest = &rest[open + close + 1..];
    }
    for needed in ["{machine}", "{axis}"] {
        if !pattern.contains(needed) {
            return Err(format!(
                "`{pattern}` lacks {needed}: each report needs its own number (e.g. `{DEFAULT_REPORT_NUMBER}`)"
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn certificate(pattern: Option<&str>) -> CertificateRaw {
        CertificateRaw {
            number: "K-2026-0417".into(),
            report_number: pattern.map(str::to_string),
            title: None,
            issued: Some("2026-12-01".into()),
            customer: Party::default(),
            laboratory: Party::default(),
            authorised_by: Signatory::default(),
            deviations: None,
        }
    }

    fn id<'a>(symbol: Option<&'a str>, test: usize, tests: usize) -> ReportId<'a> {
        ReportId {
            machine: "VMC-07",
            axis: "X",
            symbol,
            test,
            tests,
        }
    }

    #[test]
    fn numbers_follow_the_pattern_and_tell_tests_apart() {
        let c = certificate(None);
        assert_eq!(c.report_number(&id(None, 1, 1)), "K-2026-0417/VMC-07-X-P");
        assert_eq!(
            c.report_number(&id(Some("EYX"), 1, 1)),
            "K-2026-0417/VMC-07-X-EYX"
        );
        assert_eq!(c.report_number(&id(None, 2, 3)), "K-2026-0417/VMC-07-X-P-2");
        let own = certificate(Some("{machine}/{axis}"));
        assert_eq!(own.report_number(&id(None, 1, 1)), "VMC-07/X");
        assert_eq!(own.report_number(&id(None, 2, 2)), "VMC-07/X-2");
    }

    #[test]
    fn patterns_name_machine_and_axis_with_known_placeholders() {
        assert!(check_pattern(DEFAULT_REPORT_NUMBER).is_ok());
        let unknown = check_pattern("{number}/{machine}/{axes}").unwrap_err();
        assert!(
            unknown.contains("`{axes}` is not a placeholder"),
            "{unknown}"
        );
        let lacks = check_pattern("{number}/{machine}").unwrap_err();
        assert!(lacks.contains("lacks {axis}"), "{lacks}");
        assert!(check_pattern("{number/{machine}-{axis}").is_err());
    }
}
