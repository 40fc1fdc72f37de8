//! The documentation of the generated functions: formulas laid out as
//! matrices, prose wrapped at 90 columns.

use super::Generator;
use crate::derivatives::Matrix;
use crate::display::Formatter;
use proc_macro2::TokenStream;
use quote::quote;

impl Generator<'_> {
    /// A formula matrix as a doc block.
    pub(super) fn formula_block(&self, matrix: &Matrix, fmt: &Formatter) -> String {
        let text: Vec<String> = matrix.entries.iter().map(|&e| fmt.format(e)).collect();
        let mut out = vec!["```text".to_owned()];
        out.extend(layout(matrix.rows, matrix.cols, &text));
        out.push("```".to_owned());
        out.join("\n")
    }
}

/// Doc lines as `#[doc]` attributes, the prose wrapped.
pub fn doc_attributes(lines: &[String]) -> TokenStream {
    let doc = wrap_doc(&lines.join("\n"));
    let doc_lines = doc.iter().map(|l| format!(" {l}"));
    quote!(#(#[doc = #doc_lines])*)
}

/// A matrix of formulas laid out in aligned columns, or one entry per line
/// when the rows would be too wide to read.
pub fn layout(rows: usize, cols: usize, text: &[String]) -> Vec<String> {
    // A leading space where another entry of the column has a minus sign.
    let text: Vec<String> = (0..rows * cols)
        .map(|k| {
            let j = k % cols;
            let signed = (0..rows).any(|i| text[i * cols + j].starts_with('-'));
            if signed && !text[k].starts_with('-') {
                format!(" {}", text[k])
            } else {
                text[k].clone()
            }
        })
        .collect();
    let width = |s: &str| {
        s.chars()
            .filter(|c| !('\u{300}'..='\u{36f}').contains(c))
            .count()
    };
    let col_width: Vec<usize> = (0..cols)
        .map(|j| {
            (0..rows)
                .map(|i| width(&text[i * cols + j]))
                .max()
                .unwrap_or(0)
        })
        .collect();
    let total: usize = col_width.iter().sum::<usize>() + 3 * cols + 1;
    if total <= 100 {
        (0..rows)
            .map(|i| {
                let cells: Vec<String> = (0..cols)
                    .map(|j| {
                        let t = &text[i * cols + j];
                        format!("{t}{}", " ".repeat(col_width[j] - width(t)))
                    })
                    .collect();
                format!("[ {} ]", cells.join("   ")).trim_end().to_owned()
            })
            .collect()
    } else {
        // Too wide to lay out: the entries one per line, zeros left out.
        let mut out = Vec::new();
        for i in 0..rows {
            for j in 0..cols {
                let t = text[i * cols + j].trim_start();
                if t == "0" {
                    continue;
                }
                if cols == 1 {
                    out.push(format!("[{}] = {t}", i + 1));
                } else {
                    out.push(format!("[{}, {}] = {t}", i + 1, j + 1));
                }
            }
        }
        if out.len() < rows * cols {
            out.push("(entries not listed are 0)".to_owned());
        }
        out
    }
}

/// Doc text with its prose wrapped at 90 columns; code blocks untouched.
fn wrap_doc(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut in_code = false;
    for line in text.lines() {
        if line.starts_with("```") {
            in_code = !in_code;
            out.push(line.to_owned());
            continue;
        }
        if in_code || line.chars().count() <= 90 {
            out.push(line.to_owned());
            continue;
        }
        let mut current = String::new();
        for word in line.split(' ') {
            if !current.is_empty() && current.chars().count() + 1 + word.chars().count() > 90 {
                out.push(std::mem::take(&mut current));
            }
            if !current.is_empty() {
                current.push(' ');
            }
            current.push_str(word);
        }
        out.push(current);
    }
    out
}
