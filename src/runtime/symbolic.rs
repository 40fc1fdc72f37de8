//! The symbolic text table a `#[linkage]` struct carries: every generated
//! quantity as a readable formula, for printing beside a worksheet.

use core::fmt;

/// One generated matrix, entry by entry as text.
#[derive(Clone, Copy, Debug)]
pub struct SymbolicMatrix {
    /// The name of the generated function (`"psi_u"`), or `"det_psi_u"`,
    /// `"points"`, `"point_velocities"`, `"point_accelerations"`.
    pub key: &'static str,
    /// The mathematical name (`"Ψ_u"`).
    pub title: &'static str,
    pub rows: usize,
    pub cols: usize,
    pub row_labels: &'static [&'static str],
    pub col_labels: &'static [&'static str],
    /// The entries that are not identically zero: (row, column, formula).
    pub nonzero: &'static [(usize, usize, &'static str)],
}

/// Every generated quantity of one mechanism as text.
#[derive(Clone, Copy, Debug)]
pub struct SymbolicTable {
    /// The struct's name.
    pub name: &'static str,
    /// The dependent coordinates as displayed (`θ3`).
    pub u: &'static [&'static str],
    /// The driving coordinates as displayed.
    pub v: &'static [&'static str],
    pub matrices: &'static [SymbolicMatrix],
    /// Whether the macro proved, by expanding both into polynomials in q̇,
    /// that method A and method B give the same γ (`None`: too large to
    /// expand).
    pub methods_agree: Option<bool>,
    /// How Ψ_u splits into diagonal blocks solved one after another ("Ψ_u
    /// is block lower triangular: 32 blocks of 2×2."), found from which of
    /// its entries are not identically zero.
    pub structure: &'static str,
}

impl SymbolicTable {
    /// The matrix with this key (e.g. `"psi_u"`, `"det_psi_u"`).
    pub fn get(&self, key: &str) -> Option<&SymbolicMatrix> {
        self.matrices.iter().find(|m| m.key == key)
    }
}

impl SymbolicMatrix {
    /// The formula of the entry in row `i`, column `j` (`"0"` if it is
    /// identically zero).
    pub fn entry(&self, i: usize, j: usize) -> &'static str {
        self.nonzero
            .iter()
            .find(|&&(r, c, _)| r == i && c == j)
            .map_or("0", |&(_, _, f)| f)
    }

    /// Every entry, row-major.
    pub fn entries(&self) -> Vec<&'static str> {
        (0..self.rows)
            .flat_map(|i| (0..self.cols).map(move |j| (i, j)))
            .map(|(i, j)| self.entry(i, j))
            .collect()
    }

    /// The entry as laid out in its column: a leading space where another
    /// entry of the column has a minus sign, so that the terms line up.
    fn cell(&self, i: usize, j: usize) -> String {
        let signed = (0..self.rows).any(|r| self.entry(r, j).starts_with('-'));
        let e = self.entry(i, j);
        if signed && !e.starts_with('-') {
            format!(" {e}")
        } else {
            e.to_owned()
        }
    }
}

/// Display width: combining marks (the dots of θ̇) take no column.
fn width(s: &str) -> usize {
    s.chars()
        .filter(|c| !('\u{300}'..='\u{36f}').contains(c))
        .count()
}

fn pad(s: &str, w: usize) -> String {
    format!("{s}{}", " ".repeat(w.saturating_sub(width(s))))
}

impl fmt::Display for SymbolicMatrix {
    /// The matrix with its row and column labels in aligned columns, or
    /// entry by entry when it would be wider than 120 characters.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "{} =", self.title)?;
        let label_w = self.row_labels.iter().map(|l| width(l)).max().unwrap_or(0);
        let col_w: Vec<usize> = (0..self.cols)
            .map(|j| {
                let head = self.col_labels.get(j).map_or(0, |l| width(l));
                (0..self.rows)
                    .map(|i| width(&self.cell(i, j)))
                    .max()
                    .unwrap_or(0)
                    .max(head)
            })
            .collect();
        let total = label_w + col_w.iter().map(|w| w + 3).sum::<usize>();
        if total <= 120 {
            let has_heads = self.col_labels.iter().any(|l| !l.is_empty());
            if has_heads {
                let heads: Vec<String> = (0..self.cols)
                    .map(|j| pad(self.col_labels.get(j).copied().unwrap_or(""), col_w[j]))
                    .collect();
                writeln!(
                    f,
                    "  {}   {}",
                    " ".repeat(label_w),
                    heads.join("   ").trim_end()
                )?;
            }
            for i in 0..self.rows {
                let cells: Vec<String> = (0..self.cols)
                    .map(|j| pad(&self.cell(i, j), col_w[j]))
                    .collect();
                let label = pad(self.row_labels.get(i).copied().unwrap_or(""), label_w);
                writeln!(f, "  {label} [ {} ]", cells.join("   "))?;
            }
        } else {
            if self.nonzero.len() < self.rows * self.cols {
                writeln!(f, "  (entries not listed are 0)")?;
            }
            for &(i, j, formula) in self.nonzero {
                {
                    let row = self.row_labels.get(i).copied().unwrap_or("");
                    let col = self.col_labels.get(j).copied().unwrap_or("");
                    let at = match (row.is_empty(), col.is_empty()) {
                        (false, false) => format!("{row}, {col}"),
                        (false, true) => row.to_owned(),
                        (true, false) => col.to_owned(),
                        (true, true) => String::new(),
                    };
                    writeln!(f, "  [{at}] {formula}")?;
                }
            }
        }
        Ok(())
    }
}

impl fmt::Display for SymbolicTable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "{}: u = [{}], v = [{}]",
            self.name,
            self.u.join(", "),
            self.v.join(", ")
        )?;
        if !self.structure.is_empty() {
            writeln!(f, "{}", self.structure)?;
        }
        for m in self.matrices {
            writeln!(f)?;
            write!(f, "{m}")?;
        }
        Ok(())
    }
}
