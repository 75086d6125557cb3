//! The names serde reads for a struct, asked of the struct's own `Deserialize`, so that a
//! table kept beside a struct (the simulation file's unit spellings) can be checked
//! against them instead of copying them.

use serde::Deserialize;
use serde::de::{self, Deserializer, Visitor};

/// Every name `T`'s derived `Deserialize` accepts for a field, field by field in the
/// struct's order; serde lists a field's name together with its aliases, sorted. Empty
/// for a type that is no struct of named fields, or one with a flattened field (serde
/// reads those as a map).
pub fn field_names<T: for<'de> Deserialize<'de>>() -> &'static [&'static str] {
    match T::deserialize(FieldNames) {
        Err(Stopped(Some(fields))) => fields,
        _ => &[],
    }
}

/// A deserializer that reads nothing: asked for a struct, it stops with the names of the
/// struct's fields, which serde hands it.
struct FieldNames;

/// How [`FieldNames`] stops: with the field names, or without for anything but a struct.
#[derive(Debug, thiserror::Error)]
#[error("only the field names of a struct are read")]
struct Stopped(Option<&'static [&'static str]>);

impl de::Error for Stopped {
    fn custom<M: std::fmt::Display>(_: M) -> Stopped {
        Stopped(None)
    }
}

impl<'de> Deserializer<'de> for FieldNames {
    type Error = Stopped;

    fn deserialize_any<V: Visitor<'de>>(self, _: V) -> Result<V::Value, Stopped> {
        Err(Stopped(None))
    }

    fn deserialize_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        fields: &'static [&'static str],
        _: V,
    ) -> Result<V::Value, Stopped> {
        Err(Stopped(Some(fields)))
    }

    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string bytes byte_buf
        option unit unit_struct newtype_struct seq tuple tuple_struct map enum identifier
        ignored_any
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Deserialize)]
    #[allow(dead_code)]
    struct Example {
        plain: u8,
        #[serde(alias = "with_unit_mm", alias = "with_unit_deg")]
        with_unit: f64,
        #[serde(rename = "type", default)]
        kind: Option<String>,
    }

    #[test]
    fn names_field_by_field_with_aliases() {
        assert_eq!(
            field_names::<Example>(),
            [
                "plain",
                "with_unit",
                "with_unit_deg",
                "with_unit_mm",
                "type"
            ]
        );
        assert!(field_names::<f64>().is_empty());
        assert!(field_names::<Vec<Example>>().is_empty());
    }
}
