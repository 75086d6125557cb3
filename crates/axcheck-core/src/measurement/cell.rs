//! One cell of a measurement table and where it is: the text or number it holds
//! ([`Value`]), its column ([`Field`]), and the file (and sheet) errors name ([`Origin`]),
//! which also reads a cell as a number.

use super::error::{Location, ReadError, ReadErrorKind};
use super::number::{NumberError, parse_number};
use std::borrow::Cow;

/// What one field holds.
#[derive(Debug, Clone, PartialEq)]
pub enum Value<'a> {
    /// Text as written (trimmed when read as a number or a name): a CSV field, borrowed
    /// from its line unless it had quotes, or a sheet's text cell.
    Text(Cow<'a, str>),
    /// A sheet's numeric cell.
    Number(f64),
    /// A sheet's cell that is neither text nor a number (a date, a truth value, an error
    /// such as `#DIV/0!`): what it is, for messages.
    Other(String),
    /// Nothing (a sheet's empty cell inside the table).
    Empty,
}

impl Value<'_> {
    /// The field as a column name: trimmed, lower case.
    pub fn name(&self) -> String {
        match self {
            Value::Text(t) => t.trim().to_ascii_lowercase(),
            Value::Number(x) => crate::units::fmt_position(*x),
            Value::Other(what) => what.clone(),
            Value::Empty => String::new(),
        }
    }

    /// The field as shown in messages.
    pub fn shown(&self) -> String {
        match self {
            Value::Text(t) => t.trim().to_string(),
            other => other.name(),
        }
    }

    /// True for an empty cell or blank text.
    pub fn is_blank(&self) -> bool {
        match self {
            Value::Text(t) => t.trim().is_empty(),
            Value::Empty => true,
            _ => false,
        }
    }
}

/// One field with its 1-based column: the character column of a CSV line, the column of
/// a sheet (A = 1).
#[derive(Debug, Clone, PartialEq)]
pub struct Field<'a> {
    pub column: usize,
    pub value: Value<'a>,
}

/// Where a table comes from: the file (and sheet) errors name, and whether text numbers
/// may use a decimal comma.
#[derive(Debug, Clone)]
pub struct Origin {
    pub file: String,
    pub sheet: Option<String>,
    pub(crate) decimal_comma: bool,
}

impl Origin {
    pub fn text(file: &str, decimal_comma: bool) -> Origin {
        Origin {
            file: file.to_string(),
            sheet: None,
            decimal_comma,
        }
    }

    /// A sheet: its text cells hold numbers with a decimal point only (`1,234` could be a
    /// thousands separator).
    pub fn sheet(file: &str, sheet: &str) -> Origin {
        Origin {
            file: file.to_string(),
            sheet: Some(sheet.to_string()),
            decimal_comma: false,
        }
    }

    fn located(&self, location: Location) -> Location {
        match &self.sheet {
            Some(sheet) => location.in_sheet(sheet),
            None => location,
        }
    }

    pub fn whole(&self) -> Location {
        self.located(Location::file(&self.file))
    }

    pub fn line(&self, number: usize) -> Location {
        self.located(Location::line(&self.file, number))
    }

    pub fn at(&self, number: usize, column: usize) -> Location {
        self.located(Location::at(&self.file, number, column))
    }

    /// `line 7` in a text file, `row 7` in a sheet.
    pub fn line_word(&self, number: usize) -> String {
        match self.sheet {
            Some(_) => format!("row {number}"),
            None => format!("line {number}"),
        }
    }

    pub fn error(&self, number: usize, column: usize, kind: ReadErrorKind) -> ReadError {
        ReadError::new(self.at(number, column), kind)
    }

    /// The number in `field` of row `number`, or an error naming its `column`.
    pub fn number(&self, number: usize, field: &Field, column: &str) -> Result<f64, ReadError> {
        let column = || column.to_string();
        let kind = match &field.value {
            Value::Number(x) if x.is_finite() => return Ok(*x),
            Value::Number(x) => ReadErrorKind::NonFinite {
                column: column(),
                found: x.to_string(),
            },
            Value::Text(t) => match parse_number(t, self.decimal_comma) {
                Ok(x) => return Ok(x),
                Err(_) if t.trim().is_empty() => ReadErrorKind::EmptyCell { column: column() },
                Err(NumberError::NotANumber) => ReadErrorKind::NotANumber {
                    column: column(),
                    found: t.trim().to_string(),
                },
                Err(NumberError::NonFinite) => ReadErrorKind::NonFinite {
                    column: column(),
                    found: t.trim().to_string(),
                },
            },
            Value::Other(what) => ReadErrorKind::WrongCellType {
                column: column(),
                found: what.clone(),
            },
            Value::Empty => ReadErrorKind::EmptyCell { column: column() },
        };
        Err(self.error(number, field.column, kind))
    }
}
