//! The words of the reports in the report's language: one Fluent catalogue per language
//! (`locales/en.ftl`, `zh.ftl`, `ru.ftl`, embedded), the same keys in each (a test
//! compares them). The data builders take a [`Words`] and look labels and sentences up by
//! key; the templates get the whole catalogue as data ([`Words::all`]) and never hold
//! English of their own.
//!
//! Numbers for people follow the language too ([`Words::number`]: a decimal comma in
//! Russian). The data builders format numbers in many places, so the language of the
//! numbers is set for the building of one document on its thread ([`Words::scope`]) and
//! read by `data::num` and its kin; JSON, CSV and `results.json` never pass through it.

use crate::evaluate::StandardId;
use crate::lang::Lang;
use crate::param_key::ParamKey;
use fluent_bundle::concurrent::FluentBundle;
use fluent_bundle::{FluentArgs, FluentResource, FluentValue};
use std::cell::Cell;
use std::collections::BTreeMap;
use std::sync::LazyLock;

/// The catalogues' sources, by language.
pub const SOURCES: [(Lang, &str); 3] = [
    (Lang::En, include_str!("../locales/en.ftl")),
    (Lang::Zh, include_str!("../locales/zh.ftl")),
    (Lang::Ru, include_str!("../locales/ru.ftl")),
];

type Bundle = FluentBundle<FluentResource>;

static BUNDLES: LazyLock<Vec<(Lang, Bundle)>> = LazyLock::new(|| {
    SOURCES
        .iter()
        .map(|&(lang, source)| {
            let resource = FluentResource::try_new(source.to_string())
                .unwrap_or_else(|(_, errors)| panic!("locales/{lang}.ftl: {errors:?}"));
            let id = lang.code().parse().expect("a language identifier");
            let mut bundle = FluentBundle::new_concurrent(vec![id]);
            // No Unicode isolation marks around arguments: the reports are left to right,
            // and the marks would reach the PDF's text.
            bundle.set_use_isolating(false);
            bundle.add_resource(resource).expect("keys given once");
            (lang, bundle)
        })
        .collect()
});

thread_local! {
    static NUMBERS: Cell<Lang> = const { Cell::new(Lang::En) };
}

/// The words of one language.
#[derive(Clone, Copy)]
pub struct Words {
    lang: Lang,
    bundle: &'static Bundle,
}

impl Default for Words {
    fn default() -> Self {
        Words::new(Lang::En)
    }
}

impl Words {
    pub fn new(lang: Lang) -> Words {
        let bundle = &BUNDLES
            .iter()
            .find(|(l, _)| *l == lang)
            .expect("every language")
            .1;
        Words { lang, bundle }
    }

    pub fn lang(&self) -> Lang {
        self.lang
    }

    /// The message `key` (with no arguments).
    pub fn get(&self, key: &str) -> String {
        self.format(key, None)
    }

    /// The message `key` with its arguments.
    pub fn args(&self, key: &str, args: &[(&str, &str)]) -> String {
        let mut fluent = FluentArgs::new();
        for (name, value) in args {
            fluent.set(*name, FluentValue::from(*value));
        }
        self.format(key, Some(&fluent))
    }

    fn format(&self, key: &str, args: Option<&FluentArgs>) -> String {
        let Some(pattern) = self.bundle.get_message(key).and_then(|m| m.value()) else {
            // A key missing from a catalogue is a defect the catalogue test finds; the
            // report shows the key rather than fail.
            return key.to_string();
        };
        let mut errors = Vec::new();
        self.bundle
            .format_pattern(pattern, args, &mut errors)
            .into_owned()
    }

    /// Every message, for the templates: arguments as `{name}`, which the templates'
    /// `tr` replaces.
    pub fn all(&self) -> &'static BTreeMap<String, String> {
        static ALL: LazyLock<Vec<(Lang, BTreeMap<String, String>)>> = LazyLock::new(|| {
            (Lang::ALL.into_iter())
                .map(|lang| (lang, Words::new(lang).all_now()))
                .collect()
        });
        &ALL.iter()
            .find(|(l, _)| *l == self.lang)
            .expect("every language")
            .1
    }

    fn all_now(&self) -> BTreeMap<String, String> {
        let source = SOURCES
            .iter()
            .find(|(l, _)| *l == self.lang)
            .expect("every language")
            .1;
        let resource = FluentResource::try_new(source.to_string()).expect("checked above");
        message_args(&resource)
            .into_iter()
            .map(|(key, names)| {
                let placeholders: Vec<(String, String)> = names
                    .iter()
                    .map(|n| (n.clone(), format!("{{{n}}}")))
                    .collect();
                let args: Vec<(&str, &str)> = placeholders
                    .iter()
                    .map(|(n, p)| (n.as_str(), p.as_str()))
                    .collect();
                let text = self.args(&key, &args);
                (key, text)
            })
            .collect()
    }

    /// A number as axcheck writes it, in this language's form.
    pub fn number(&self, text: &str) -> String {
        self.lang.number(text)
    }

    /// A date `YYYY-MM-DD` in this language's form.
    pub fn date(&self, iso: &str) -> String {
        self.lang.date(iso)
    }

    /// `build` with the numbers of this thread in this language ([`numbers`]).
    pub fn scope<T>(&self, build: impl FnOnce() -> T) -> T {
        let before = NUMBERS.with(|n| n.replace(self.lang));
        let out = build();
        NUMBERS.with(|n| n.set(before));
        out
    }

    /// The name of parameter `key` as `standard` words it in this language (GB/T
    /// 17421.2's terms in Chinese for ISO 230-2 and GB/T tests, GOST 27843's in Russian),
    /// or `english` when the catalogue has none.
    pub fn parameter(&self, standard: StandardId, key: ParamKey, english: &str) -> String {
        let id = format!("param-{}-{}", family(standard), key.as_str());
        match self.bundle.get_message(&id) {
            Some(_) => self.get(&id),
            None => english.to_string(),
        }
    }

    /// The message `key`, or `default` when the catalogue has none (words that come from
    /// an open list, such as an uncertainty contributor's key).
    pub fn get_or(&self, key: &str, default: &str) -> String {
        match self.bundle.get_message(key) {
            Some(_) => self.get(key),
            None => default.to_string(),
        }
    }

    /// A unit symbol (`µm`, `mm`, `arcsec`, `°`, `s`) as this language writes it (`мкм`,
    /// `мм` in Russian); other text as it is.
    pub fn unit(&self, symbol: &str) -> String {
        let key = match symbol {
            "µm" | "um" => "unit-um",
            "mm" => "unit-mm",
            "arcsec" => "unit-arcsec",
            "s" => "unit-s",
            _ => return symbol.to_string(),
        };
        self.get(key)
    }

    /// A standard's title as this language writes it (`ГОСТ 27843-88` in Russian).
    pub fn standard(&self, standard: StandardId) -> String {
        let key = format!("standard-{}", family_key(standard));
        self.get_or(&key, standard.title())
    }

    /// The word for a verdict key (`pass`, `fail`, …) in this language.
    pub fn verdict(&self, key: &str) -> String {
        self.get(&format!("verdict-{}", key.replace('_', "-")))
    }
}

/// The language numbers are formatted in on this thread ([`Words::scope`]; English
/// outside one).
pub fn numbers() -> Lang {
    NUMBERS.with(Cell::get)
}

/// The catalogue family of a standard's parameter names: ISO 230-2 and GB/T 17421.2 share
/// their terms.
/// The catalogue's name of a standard's title.
fn family_key(standard: StandardId) -> &'static str {
    match standard {
        StandardId::Iso230_2 => "iso230-2",
        StandardId::Gbt17421_2 => "gbt17421-2",
        StandardId::Gost27843 => "gost27843",
        StandardId::Vdi3441 => "vdi3441",
        StandardId::Nmtba => "nmtba",
    }
}

fn family(standard: StandardId) -> &'static str {
    match standard {
        StandardId::Iso230_2 | StandardId::Gbt17421_2 => "iso",
        StandardId::Gost27843 => "gost",
        StandardId::Vdi3441 => "vdi",
        StandardId::Nmtba => "nmtba",
    }
}

/// Each message's key with the names of the arguments it uses.
pub fn message_args(resource: &FluentResource) -> BTreeMap<String, Vec<String>> {
    use fluent_syntax::ast::{Entry, Expression, InlineExpression, Pattern, PatternElement};
    fn inline(e: &InlineExpression<&str>, out: &mut Vec<String>) {
        match e {
            InlineExpression::VariableReference { id } => out.push(id.name.to_string()),
            InlineExpression::Placeable { expression } => expression_args(expression, out),
            _ => {}
        }
    }
    fn expression_args(e: &Expression<&str>, out: &mut Vec<String>) {
        match e {
            Expression::Inline(i) => inline(i, out),
            Expression::Select { selector, variants } => {
                inline(selector, out);
                for v in variants {
                    pattern_args(&v.value, out);
                }
            }
        }
    }
    fn pattern_args(p: &Pattern<&str>, out: &mut Vec<String>) {
        for element in &p.elements {
            if let PatternElement::Placeable { expression } = element {
                expression_args(expression, out);
            }
        }
    }
    resource
        .entries()
        .filter_map(|e| match e {
            Entry::Message(m) => {
                let mut names = Vec::new();
                if let Some(p) = &m.value {
                    pattern_args(p, &mut names);
                }
                names.sort();
                names.dedup();
                Some((m.id.name.to_string(), names))
            }
            _ => None,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::{SOURCES, Words, message_args};
    use crate::evaluate::{StandardId, catalogue};
    use crate::lang::Lang;
    use fluent_bundle::FluentResource;
    use std::collections::BTreeMap;

    fn catalogue_of(lang: Lang) -> BTreeMap<String, Vec<String>> {
        let source = SOURCES.iter().find(|(l, _)| *l == lang).unwrap().1;
        let resource = FluentResource::try_new(source.to_string())
            .unwrap_or_else(|(_, e)| panic!("locales/{lang}.ftl does not parse: {e:?}"));
        message_args(&resource)
    }

    /// Every key in every language, each message with the same arguments.
    #[test]
    fn every_key_exists_in_every_language_with_the_same_arguments() {
        let en = catalogue_of(Lang::En);
        assert!(en.len() > 150, "{} keys", en.len());
        for lang in [Lang::Zh, Lang::Ru] {
            let other = catalogue_of(lang);
            let missing: Vec<&String> = en.keys().filter(|k| !other.contains_key(*k)).collect();
            let extra: Vec<&String> = other.keys().filter(|k| !en.contains_key(*k)).collect();
            assert!(missing.is_empty(), "{lang}.ftl lacks {missing:?}");
            assert!(
                extra.is_empty(),
                "{lang}.ftl has keys en.ftl lacks: {extra:?}"
            );
            for (key, args) in &en {
                assert_eq!(&other[key], args, "{lang}.ftl `{key}` uses other arguments");
            }
        }
    }

    /// The messages that read the same in every language: symbols and units only.
    const SAME_EVERYWHERE: &[&str] = &[
        "col-u",
        "other-tool-ours",
        "verdict-zone",
        "unit-um",
        "unit-mm",
        "unit-s",
        "html-u-unit",
        // SI symbols that Chinese writes as English does.
        "unit-mm-per-min",
        "unit-deg-per-min",
        "unit-kpa",
        // Titles of standards Chinese writes in Latin letters.
        "standard-gost27843",
    ];

    /// No English left in Chinese or Russian: a message equal to its English text is one
    /// of [`SAME_EVERYWHERE`].
    #[test]
    fn no_english_message_is_left_untranslated() {
        for lang in [Lang::Zh, Lang::Ru] {
            let (en, other) = (Words::new(Lang::En).all(), Words::new(lang).all());
            let same: Vec<&String> = (en.iter())
                .filter(|(k, v)| other.get(*k) == Some(v) && !SAME_EVERYWHERE.contains(&k.as_str()))
                .map(|(k, _)| k)
                .collect();
            assert!(same.is_empty(), "{lang}: untranslated {same:?}");
        }
    }

    /// Each ISO 230-2 and GOST 27843 parameter has its name in each language, in the
    /// standards' own terms where the acceptance asks for them.
    #[test]
    fn parameters_are_named_with_the_standards_terms() {
        for def in catalogue::CATALOGUE {
            for standard in [StandardId::Iso230_2, StandardId::Gost27843] {
                if !def.standards.contains(&standard) {
                    continue;
                }
                for lang in Lang::ALL {
                    let name = Words::new(lang).parameter(standard, def.key, "");
                    assert!(!name.is_empty(), "{lang} {standard:?} {}", def.key);
                }
                assert_eq!(
                    Words::new(Lang::En).parameter(standard, def.key, ""),
                    def.name
                );
            }
        }
        let zh = Words::new(Lang::Zh);
        let iso = |k| zh.parameter(StandardId::Gbt17421_2, k, "");
        use crate::param_key::ParamKey::*;
        assert_eq!(iso(A), "轴线双向定位精度");
        assert_eq!(iso(R), "轴线双向重复定位精度");
        assert_eq!(iso(B), "轴线反向差值");
        assert_eq!(iso(BMean), "轴线平均反向差值");
        assert_eq!(iso(E), "轴线双向定位系统偏差");
        let ru = Words::new(Lang::Ru);
        let gost = |k| ru.parameter(StandardId::Gost27843, k, "");
        assert!(gost(A).starts_with("точность позиционирования"));
        assert_eq!(gost(RUp), "повторяемость одностороннего позиционирования ↑");
        assert_eq!(gost(BMax), "максимальная зона нечувствительности");
    }

    #[test]
    fn arguments_are_filled_and_templates_get_placeholders() {
        let ru = Words::new(Lang::Ru);
        assert_eq!(
            ru.args("results-heading", &[("unit", "мкм")]),
            "Результаты (значения в мкм)"
        );
        assert_eq!(
            Words::new(Lang::En).all()["results-heading"],
            "Results (values in {unit})"
        );
        assert_eq!(ru.verdict("not_judged"), "НЕ ОЦЕНЁН");
    }
}
