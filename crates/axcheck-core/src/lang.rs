//! The language of the reports meant for people (`--lang`, `campaign.report.lang`, a
//! machine's `report.lang`): English, simplified Chinese or Russian. Only text for people
//! changes with it; `results.json`, the CSV tables and the JSON files never do.

use serde::{Deserialize, Serialize};

/// A report language.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Lang {
    /// English (the default).
    #[default]
    En,
    /// Simplified Chinese: the terms of GB/T 17421.2-2000.
    Zh,
    /// Russian: the terms of GOST 27843-88.
    Ru,
}

impl Lang {
    pub const ALL: [Lang; 3] = [Lang::En, Lang::Zh, Lang::Ru];

    /// The code of `--lang` and `report.lang` (`en`, `zh`, `ru`), also Typst's `lang`.
    pub fn code(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::Zh => "zh",
            Lang::Ru => "ru",
        }
    }

    /// `text` (a number as axcheck writes it, with a decimal point) in the language's
    /// form: a decimal comma in Russian (`7,27`), a point otherwise.
    pub fn number(self, text: &str) -> String {
        match self {
            Lang::Ru => decimal_comma(text),
            Lang::En | Lang::Zh => text.to_string(),
        }
    }

    /// A date `YYYY-MM-DD` in the language's form: `DD.MM.YYYY` in Russian (GOST R
    /// 7.0.97), `YYYY-MM-DD` in English and Chinese (GB/T 7408, the numeric form); any
    /// other text as it is.
    pub fn date(self, iso: &str) -> String {
        let parts: Vec<&str> = iso.split('-').collect();
        let numeric = |p: &str, n: usize| p.len() == n && p.bytes().all(|b| b.is_ascii_digit());
        match (self, parts.as_slice()) {
            (Lang::Ru, [y, m, d]) if numeric(y, 4) && numeric(m, 2) && numeric(d, 2) => {
                format!("{d}.{m}.{y}")
            }
            _ => iso.to_string(),
        }
    }
}

/// Every point between two digits as a comma (`−7.27 µm` → `−7,27 µm`); points elsewhere
/// (an abbreviation, a clause `2.23` spelt apart) are kept only when not between digits.
fn decimal_comma(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let digit = |i: Option<&char>| i.is_some_and(|c| c.is_ascii_digit());
    (0..chars.len())
        .map(|i| {
            let c = chars[i];
            let between = i > 0 && digit(chars.get(i - 1)) && digit(chars.get(i + 1));
            if c == '.' && between { ',' } else { c }
        })
        .collect()
}

impl std::str::FromStr for Lang {
    type Err = String;

    fn from_str(s: &str) -> Result<Lang, String> {
        Lang::ALL
            .into_iter()
            .find(|l| l.code() == s)
            .ok_or_else(|| format!("unknown language `{s}`: expected en, zh or ru"))
    }
}

impl std::fmt::Display for Lang {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.code())
    }
}

#[cfg(test)]
mod tests {
    use super::Lang;

    #[test]
    fn numbers_and_dates_in_the_locale_forms() {
        assert_eq!(Lang::Ru.number("−7.27 µm"), "−7,27 µm");
        assert_eq!(Lang::Ru.number("0 … 250.5 mm"), "0 … 250,5 mm");
        assert_eq!(Lang::Zh.number("7.27"), "7.27");
        assert_eq!(Lang::Ru.date("2024-03-05"), "05.03.2024");
        assert_eq!(Lang::Zh.date("2024-03-05"), "2024-03-05");
        assert_eq!(Lang::Ru.date("soon"), "soon");
        assert_eq!("ru".parse::<Lang>(), Ok(Lang::Ru));
        assert!("de".parse::<Lang>().unwrap_err().contains("en, zh or ru"));
    }
}
