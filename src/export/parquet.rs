//! `summary.parquet`: the summary table through polars, typed columns (text, integer,
//! float, boolean; empty cells are nulls).

use super::table::{Cell, ColumnKind, columns, rows};
use super::{ExportError, Exporter, OutputFile};
use crate::results::CampaignResult;
use polars::prelude::*;

pub(crate) struct ParquetExporter;

impl Exporter for ParquetExporter {
    fn name(&self) -> &'static str {
        "parquet"
    }

    fn export<'a>(&self, result: &'a CampaignResult) -> Result<Vec<OutputFile<'a>>, ExportError> {
        let err = |e: PolarsError| ExportError::Format {
            format: "parquet",
            message: e.to_string(),
        };
        let rows = rows(result);
        let height = rows.len();
        let cols: Vec<Column> = columns()
            .into_iter()
            .enumerate()
            .map(|(k, (name, kind))| {
                let cells = rows.iter().map(|r| &r[k]);
                match kind {
                    ColumnKind::Text => typed(&name, cells, |c| match c {
                        Cell::Text(s) => Some(s.clone()),
                        _ => None,
                    }),
                    ColumnKind::Int => typed(&name, cells, |c| match c {
                        Cell::Int(i) => Some(*i),
                        _ => None,
                    }),
                    ColumnKind::Number => typed(&name, cells, |c| match c {
                        Cell::Number(x) if x.is_finite() => Some(*x),
                        _ => None,
                    }),
                    ColumnKind::Bool => typed(&name, cells, |c| match c {
                        Cell::Bool(b) => Some(*b),
                        _ => None,
                    }),
                }
            })
            .collect();
        let mut df = DataFrame::new(height, cols).map_err(err)?;
        let mut bytes = Vec::new();
        ParquetWriter::new(&mut bytes)
            .finish(&mut df)
            .map_err(err)?;
        Ok(vec![OutputFile::new("summary.parquet", bytes)])
    }
}

/// A column of the cells `pick` types (`None` for an empty or other cell).
fn typed<'a, T>(
    name: &str,
    cells: impl Iterator<Item = &'a Cell>,
    pick: impl Fn(&Cell) -> Option<T>,
) -> Column
where
    Series: NamedFrom<Vec<Option<T>>, [Option<T>]>,
{
    Column::new(name.into(), cells.map(pick).collect::<Vec<Option<T>>>())
}
