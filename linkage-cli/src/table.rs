//! What a command prints: a table of numbers with named columns, written
//! as aligned text for a terminal, as CSV, or as JSON.

use serde::Serialize;
use std::io::{self, Write};

/// How a table is written.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// Aligned columns for reading on a terminal.
    Table,
    /// Comma-separated values with a header line.
    Csv,
    /// One JSON object: `{"title", "columns", "units", "rows"}`.
    Json,
}

/// A table: one row per pose (or per quantity, or per event), one column
/// per number, each column with its unit; rows may have names (a first
/// column of text, headed `row_header`).
#[derive(Clone, Debug, Default, Serialize)]
pub struct Table {
    pub title: String,
    #[serde(skip_serializing_if = "String::is_empty")]
    pub row_header: String,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub row_names: Vec<String>,
    pub columns: Vec<String>,
    pub units: Vec<String>,
    pub rows: Vec<Vec<f64>>,
}

impl Table {
    /// An empty table with these columns (name, unit).
    pub fn new(title: impl Into<String>, columns: Vec<(String, String)>) -> Table {
        let (columns, units) = columns.into_iter().unzip();
        Table {
            title: title.into(),
            columns,
            units,
            ..Table::default()
        }
    }

    /// Adds a row with a name.
    pub fn push_named(&mut self, name: &str, row: Vec<f64>) {
        self.row_names.push(name.to_owned());
        self.push(row);
    }

    /// The row names, if the rows have them, with their header first.
    fn names(&self) -> Option<(String, &[String])> {
        (!self.row_names.is_empty()).then(|| (self.row_header.clone(), self.row_names.as_slice()))
    }

    /// Adds a row; it must have one value per column.
    pub fn push(&mut self, row: Vec<f64>) {
        debug_assert_eq!(row.len(), self.columns.len());
        self.rows.push(row);
    }

    /// Writes the table in `format`.
    pub fn write(&self, format: Format, out: &mut impl Write) -> io::Result<()> {
        match format {
            Format::Table => self.write_text(out),
            Format::Csv => self.write_csv(out),
            Format::Json => {
                serde_json::to_writer_pretty(&mut *out, self).map_err(io::Error::other)?;
                writeln!(out)
            }
        }
    }

    fn write_text(&self, out: &mut impl Write) -> io::Result<()> {
        if !self.title.is_empty() {
            writeln!(out, "{}", self.title)?;
        }
        let mut cells: Vec<Vec<String>> = self
            .rows
            .iter()
            .map(|row| row.iter().map(|x| number(*x)).collect())
            .collect();
        let mut heads: Vec<String> = (self.columns.iter().zip(&self.units))
            .map(|(c, u)| {
                if u.is_empty() {
                    c.clone()
                } else {
                    format!("{c} [{u}]")
                }
            })
            .collect();
        if let Some((header, names)) = self.names() {
            heads.insert(0, header);
            for (row, name) in cells.iter_mut().zip(names) {
                row.insert(0, name.clone());
            }
        }
        let widths: Vec<usize> = (0..heads.len())
            .map(|j| {
                cells
                    .iter()
                    .map(|r| r[j].chars().count())
                    .chain([heads[j].chars().count()])
                    .max()
                    .unwrap_or(0)
            })
            .collect();
        let line = |out: &mut dyn Write, cells: &[String]| -> io::Result<()> {
            let padded: Vec<String> = cells
                .iter()
                .zip(&widths)
                .enumerate()
                .map(|(j, (c, w))| {
                    if j == 0 && self.names().is_some() {
                        format!("{c:<w$}")
                    } else {
                        format!("{c:>w$}")
                    }
                })
                .collect();
            writeln!(out, "{}", padded.join("  ").trim_end())
        };
        line(out, &heads)?;
        for row in &cells {
            line(out, row)?;
        }
        Ok(())
    }

    fn write_csv(&self, out: &mut impl Write) -> io::Result<()> {
        let mut heads: Vec<String> = (self.columns.iter().zip(&self.units))
            .map(|(c, u)| {
                if u.is_empty() {
                    csv_field(c)
                } else {
                    csv_field(&format!("{c} [{u}]"))
                }
            })
            .collect();
        let names = self.names();
        if let Some((header, _)) = &names {
            heads.insert(0, csv_field(header));
        }
        writeln!(out, "{}", heads.join(","))?;
        for (k, row) in self.rows.iter().enumerate() {
            let mut cells: Vec<String> = row.iter().map(|x| format!("{x:e}")).collect();
            if let Some((_, names)) = &names {
                cells.insert(0, csv_field(&names[k]));
            }
            writeln!(out, "{}", cells.join(","))?;
        }
        Ok(())
    }
}

/// A number for reading: 10 significant digits, exponent only when needed.
fn number(x: f64) -> String {
    if x == 0.0 {
        return "0".to_owned();
    }
    let magnitude = x.abs().log10();
    if (-4.0..9.0).contains(&magnitude) {
        let decimals = (9 - magnitude.floor() as i32).clamp(0, 13) as usize;
        let text = format!("{x:.decimals$}");
        let text = text.trim_end_matches('0');
        text.trim_end_matches('.').to_owned()
    } else {
        format!("{x:.9e}")
    }
}

/// A CSV field, quoted when it holds a comma, a quote or a line break.
fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_owned()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> Table {
        let mut t = Table::new(
            "poses",
            vec![
                ("theta2".into(), "rad".into()),
                ("C.x, mm".into(), String::new()),
            ],
        );
        t.push(vec![0.5, -1234.5]);
        t.push(vec![1e-7, 0.0]);
        t
    }

    #[test]
    fn csv_round_trips_every_bit_and_quotes_headers() {
        let mut out = Vec::new();
        sample().write(Format::Csv, &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        let mut lines = text.lines();
        assert_eq!(lines.next().unwrap(), "theta2 [rad],\"C.x, mm\"");
        let values: Vec<f64> = lines
            .flat_map(|l| l.split(',').map(|x| x.parse::<f64>().unwrap()))
            .collect();
        assert_eq!(values, [0.5, -1234.5, 1e-7, 0.0]);
    }

    #[test]
    fn json_holds_columns_units_and_rows() {
        let mut out = Vec::new();
        sample().write(Format::Json, &mut out).unwrap();
        let back: serde_json::Value = serde_json::from_slice(&out).unwrap();
        assert_eq!(back["columns"][0], "theta2");
        assert_eq!(back["units"][0], "rad");
        assert_eq!(back["rows"][0][1], -1234.5);
    }

    #[test]
    fn text_is_aligned() {
        let mut out = Vec::new();
        sample().write(Format::Table, &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        let lines: Vec<&str> = text.lines().skip(1).collect();
        assert_eq!(lines.len(), 3);
        assert!(lines.iter().all(|l| l.len() == lines[0].len()), "{text}");
        assert_eq!(number(0.1 + 0.2), "0.3");
        assert_eq!(number(-1234.5), "-1234.5");
        assert_eq!(number(1e-7), "1.000000000e-7");
    }
}
