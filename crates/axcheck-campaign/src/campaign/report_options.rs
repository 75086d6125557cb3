//! `campaign.report` and a machine's `report`: how the reports for people are written
//! (README "Report languages").

use crate::lang::Lang;
use serde::{Deserialize, Serialize};

/// `report: {lang: …}`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ReportOptions {
    /// `en`, `zh` or `ru` (English when absent).
    #[serde(
        default,
        deserialize_with = "crate::yaml::optional_keyword",
        skip_serializing_if = "Option::is_none"
    )]
    pub lang: Option<Lang>,
}

/// The language of a machine's reports: `cli` (`--lang`), else the machine's
/// `report.lang`, else the campaign's (`campaign.report`), else English.
pub fn report_lang(
    cli: Option<Lang>,
    campaign: Option<&ReportOptions>,
    machine: Option<&ReportOptions>,
) -> Lang {
    cli.or_else(|| machine.and_then(|m| m.lang))
        .or_else(|| campaign.and_then(|c| c.lang))
        .unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_command_line_then_the_machine_then_the_campaign() {
        let zh = ReportOptions {
            lang: Some(Lang::Zh),
        };
        let ru = ReportOptions {
            lang: Some(Lang::Ru),
        };
        let none = ReportOptions::default();
        assert_eq!(report_lang(None, Some(&zh), Some(&ru)), Lang::Ru);
        assert_eq!(report_lang(None, Some(&zh), Some(&none)), Lang::Zh);
        assert_eq!(report_lang(None, Some(&zh), None), Lang::Zh);
        assert_eq!(report_lang(Some(Lang::En), Some(&zh), Some(&ru)), Lang::En);
        assert_eq!(report_lang(None, None, None), Lang::En);
    }
}
