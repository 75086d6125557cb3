//! serde's and the YAML parser's messages in the user's words: what was expected where,
//! and what the file has there (`expected a number, got the text `abc``), never a Rust
//! type name (`f64`, `struct AxisRaw`, `untagged enum Travel`).

use serde::Deserialize;
use serde::de::{DeserializeOwned, Deserializer, Error as _};
use serde_norway::Value;

/// What a value is, for "got …": `the number 5`, `the text `long``, `a list of 4 items`.
pub fn describe(value: &Value) -> String {
    match value {
        Value::Null => "nothing".into(),
        Value::Bool(b) => format!("`{b}`"),
        Value::Number(n) => format!("the number {n}"),
        Value::String(s) if s.trim().is_empty() => "empty text".into(),
        Value::String(s) => format!("the text `{}`", shorten(s)),
        Value::Sequence(items) => count(items.len(), "an empty list", "a list of"),
        Value::Mapping(map) => match map.len() {
            0 => "an empty mapping".into(),
            1 => "a mapping with 1 key".into(),
            n => format!("a mapping with {n} keys"),
        },
        Value::Tagged(tagged) => format!("a value tagged `{}`", tagged.tag),
    }
}

/// `a list of 1 item`, `a list of 4 items`, or `empty` for none.
fn count(n: usize, empty: &str, some: &str) -> String {
    match n {
        0 => empty.to_string(),
        1 => format!("{some} 1 item"),
        n => format!("{some} {n} items"),
    }
}

/// The first line of `text`, cut at 40 characters.
fn shorten(text: &str) -> String {
    let line = text.lines().next().unwrap_or("");
    if line.chars().count() > 40 || line.len() < text.len() {
        format!("{}…", line.chars().take(40).collect::<String>())
    } else {
        line.to_string()
    }
}

/// serde's description of an unexpected value (`integer `5``, `string "abc"`, `sequence`)
/// in words, for when the value itself is not at hand.
fn describe_unexpected(text: &str) -> String {
    let quoted = |prefix: &str| {
        text.strip_prefix(prefix)
            .and_then(|rest| rest.strip_suffix('`'))
            .map(str::to_string)
    };
    if let Some(n) = quoted("integer `").or_else(|| quoted("floating point `")) {
        return format!("the number {n}");
    }
    if let Some(b) = quoted("boolean `") {
        return format!("`{b}`");
    }
    if let Some(s) = text
        .strip_prefix("string \"")
        .and_then(|s| s.strip_suffix('"'))
    {
        return format!("the text `{}`", shorten(s));
    }
    match text {
        "sequence" => "a list".into(),
        "map" => "a mapping".into(),
        "unit value" | "Option value" => "nothing".into(),
        other => other.to_string(),
    }
}

/// serde's "expected …" (a Rust type or a visitor's description) in words.
fn expected_words(expected: &str) -> String {
    let words = match expected {
        "f64" | "f32" => "a number",
        "u8" | "u16" | "u32" | "u64" | "u128" | "usize" => "a whole number ≥ 0",
        "i8" | "i16" | "i32" | "i64" | "i128" | "isize" => "a whole number",
        "a string" | "a borrowed string" | "a character" => "text",
        "a boolean" => "true or false",
        "a sequence" => "a list",
        "a map" => "a mapping",
        "fewer elements in sequence" | "fewer elements in array" => "a shorter list",
        other => {
            if other.starts_with("struct ") {
                return "a mapping (key: value)".into();
            }
            let length = other
                .strip_prefix("an array of length ")
                .or_else(|| other.strip_prefix("a tuple of size "))
                .or_else(|| other.strip_prefix("tuple of "))
                .map(|rest| rest.trim_end_matches(" elements"));
            return match length {
                Some(n) => format!("a list of {n} items"),
                None => other.to_string(),
            };
        }
    };
    words.to_string()
}

/// The names quoted with backticks in serde's "expected one of `a`, `b`" / "`a` or `b`".
fn quoted_names(list: &str) -> Vec<String> {
    list.split('`')
        .skip(1)
        .step_by(2)
        .map(str::to_string)
        .collect()
}

/// `a`, `a or b`, `a, b or c`.
pub fn or_list(names: &[String]) -> String {
    match names {
        [] => String::new(),
        [one] => one.clone(),
        [head @ .., last] => format!("{} or {last}", head.join(", ")),
    }
}

/// A serde message about the value at a key in the user's words: `key` is the key's
/// name (for "unknown kind `linar`"), `found` the value there when known, `spell` names a
/// missing field as the file would write it.
pub fn in_words(
    message: &str,
    key: &str,
    found: Option<&Value>,
    spell: &dyn Fn(&str) -> String,
) -> String {
    let got = |unexpected: &str| found.map_or_else(|| describe_unexpected(unexpected), describe);
    let type_error = message
        .strip_prefix("invalid type: ")
        .or_else(|| message.strip_prefix("invalid value: "));
    if let Some((unexpected, expected)) = type_error.and_then(|r| r.rsplit_once(", expected ")) {
        return format!(
            "expected {}, got {}",
            expected_words(expected),
            got(unexpected)
        );
    }
    if let Some((n, expected)) = message
        .strip_prefix("invalid length ")
        .and_then(|r| r.split_once(", expected "))
    {
        let got = match found {
            Some(Value::Sequence(items)) => describe(&Value::Sequence(items.clone())),
            _ => count(n.parse().unwrap_or(0), "an empty list", "a list of"),
        };
        return format!("expected {}, got {got}", expected_words(expected));
    }
    if let Some((variant, expected)) = message
        .strip_prefix("unknown variant `")
        .and_then(|r| r.split_once("`, expected "))
    {
        let names = quoted_names(expected);
        let candidates: Vec<&str> = names.iter().map(String::as_str).collect();
        let hint = crate::suggest::hint(variant, &candidates);
        return format!(
            "unknown {key} `{variant}`{hint}; expected {}",
            or_list(&names)
        );
    }
    let field = |prefix: &str| {
        message
            .strip_prefix(prefix)
            .and_then(|r| r.strip_suffix('`'))
            .map(spell)
    };
    if let Some(missing) = field("missing field `") {
        return format!("missing key `{missing}`");
    }
    if let Some(twice) = field("duplicate field `") {
        // A mapping holds each key once: the field was given under two of its spellings.
        return format!("`{twice}` is given twice, under two of its spellings; keep one");
    }
    message.to_string()
}

/// A serde message about a key that is not text (`1: 2`, `[a]: 1`) in words.
pub(crate) fn key_in_words(message: &str) -> String {
    let unexpected = message
        .strip_prefix("invalid type: ")
        .and_then(|r| r.rsplit_once(", expected "))
        .map_or(message, |(unexpected, _)| unexpected);
    format!(
        "keys are names, got {} as a key",
        describe_unexpected(unexpected)
    )
}

/// The names a unit-variant enum `T` is written as, from its own deserializer (its error
/// for an unknown name lists them).
pub fn names_of<T: DeserializeOwned>() -> Vec<String> {
    match T::deserialize(Value::String(String::new())) {
        Ok(_) => Vec::new(),
        Err(e) => quoted_names(e.to_string().split_once("expected ").map_or("", |(_, l)| l)),
    }
}

/// Reads a name from a fixed set (a unit-variant enum such as `AxisKind`), for
/// `#[serde(deserialize_with)]`: text is read by `T`'s own deserializer (its error for an
/// unknown name lists the names); anything else is refused with the names, which serde's
/// enum error for a list or a number would not give.
pub fn keyword<'de, D, T>(deserializer: D) -> Result<T, D::Error>
where
    D: Deserializer<'de>,
    T: DeserializeOwned,
{
    let value = Value::deserialize(deserializer)?;
    if let Value::String(_) = value {
        return T::deserialize(value).map_err(D::Error::custom);
    }
    Err(D::Error::custom(not_a_name::<T>(&value)))
}

/// [`keyword`] for an optional key (absent or empty: `None`).
pub fn optional_keyword<'de, D, T>(deserializer: D) -> Result<Option<T>, D::Error>
where
    D: Deserializer<'de>,
    T: DeserializeOwned,
{
    match Value::deserialize(deserializer)? {
        Value::Null => Ok(None),
        value => keyword(value).map(Some).map_err(D::Error::custom),
    }
}

/// `expected linear or rotary, got a list of 1 item`.
pub fn not_a_name<T: DeserializeOwned>(value: &Value) -> String {
    format!(
        "expected {}, got {}",
        or_list(&names_of::<T>()),
        describe(value)
    )
}

/// The YAML parser's message in words: the location it repeats is dropped (the error
/// names it), the construct it was reading is said with where it starts, and a key
/// given twice is said so.
pub(crate) fn syntax_in_words(message: &str) -> String {
    let (path, message) = match message.split_once(": ") {
        Some((path, rest)) if !path.contains(' ') => (format!("{path}: "), rest),
        _ => (String::new(), message),
    };
    if let Some(key) = message
        .strip_prefix("duplicate entry with key \"")
        .and_then(|r| r.split_once('"'))
        .map(|(k, _)| k)
    {
        return format!("{path}key `{key}` is given twice");
    }
    let Some((problem, rest)) = message.split_once(" at line ") else {
        return format!("{path}{}", whole_document_in_words(message));
    };
    let problem = whole_document_in_words(problem);
    let context = rest.split_once(", ").map(|(_, context)| context);
    match context.map(|c| c.rsplit_once(" at line ").unwrap_or((c, ""))) {
        None => format!("{path}{problem}"),
        Some((context, "")) => format!("{path}{problem} ({context})"),
        Some((context, mark)) => {
            let at = mark.replacen(" column ", ":", 1);
            format!("{path}{problem} ({context} that starts at {at})")
        }
    }
}

/// The path of the key that serde_norway's "duplicate entry" error names
/// (`machines[0].axes[0].tolerances.A`), if the error is one.
pub(crate) fn duplicate_key(message: &str) -> Option<String> {
    let (path, rest) = match message.split_once(": ") {
        Some((path, rest)) if !path.contains(' ') => (path, rest),
        _ => ("", message),
    };
    let key = rest
        .strip_prefix("duplicate entry with key \"")?
        .split_once('"')?
        .0;
    Some(super::join(path, key))
}

/// The YAML reader's errors about the document as a whole, said plainly.
fn whole_document_in_words(message: &str) -> String {
    match message {
        "deserializing from YAML containing more than one document is not supported" => {
            "more than one YAML document (a `---` line starts another); the file holds one".into()
        }
        "unknown anchor" => {
            "unknown anchor: an alias `*name` needs an anchor `&name` before it".into()
        }
        "repetition limit exceeded" => {
            "repetition limit exceeded: the aliases expand to too many values".into()
        }
        "recursion limit exceeded" => "recursion limit exceeded: the values nest too deeply".into(),
        other => other.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::units::AxisKind;

    fn words(message: &str, found: Option<&Value>) -> String {
        in_words(message, "kind", found, &|f| f.to_string())
    }

    #[test]
    fn type_errors_say_what_was_expected_and_found() {
        let list: Value = serde_norway::from_str("[1, 2, 3, 4]").unwrap();
        assert_eq!(
            words("invalid type: sequence, expected f64", Some(&list)),
            "expected a number, got a list of 4 items"
        );
        assert_eq!(
            words("invalid type: string \"abc\", expected u64", None),
            "expected a whole number ≥ 0, got the text `abc`"
        );
        assert_eq!(
            words(
                "invalid type: integer `5`, expected struct ErrorModel",
                None
            ),
            "expected a mapping (key: value), got the number 5"
        );
        assert_eq!(
            words("invalid length 3, expected an array of length 2", None),
            "expected a list of 2 items, got a list of 3 items"
        );
        assert_eq!(words("missing field `count`", None), "missing key `count`");
    }

    #[test]
    fn unknown_names_get_a_suggestion_and_the_list() {
        assert_eq!(
            words(
                "unknown variant `linar`, expected `linear` or `rotary`",
                None
            ),
            "unknown kind `linar` (did you mean `linear`?); expected linear or rotary"
        );
        assert_eq!(
            names_of::<AxisKind>(),
            vec!["linear".to_string(), "rotary".to_string()]
        );
        assert_eq!(
            not_a_name::<AxisKind>(&Value::Sequence(vec![Value::Null])),
            "expected linear or rotary, got a list of 1 item"
        );
    }

    #[test]
    fn syntax_messages_drop_repeated_locations() {
        assert_eq!(
            syntax_in_words(
                "did not find expected ',' or '}' at line 3 column 1, while parsing a flow mapping at line 2 column 7"
            ),
            "did not find expected ',' or '}' (while parsing a flow mapping that starts at 2:7)"
        );
        assert_eq!(
            syntax_in_words("a.b: duplicate entry with key \"A\" at line 5 column 66"),
            "a.b: key `A` is given twice"
        );
    }
}
