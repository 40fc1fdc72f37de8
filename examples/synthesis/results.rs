//! The judged results of each tool's method on each task, the table they
//! make and the CSV of every design.

use crate::judge::Judged;
use linkage::mechanisms::CouplerFourBar;
use linkage::prelude::*;
use std::fmt::Write as _;

/// A design, judged.
#[derive(Clone, Debug)]
pub struct Design {
    /// Its dimensions, named.
    pub params: Vec<(&'static str, f64)>,
    pub judged: Judged,
    /// A path design and its pose at θ2 (to draw it).
    pub drawn: Option<(CouplerFourBar, SVector<f64, 2>, f64)>,
}

/// One run of a method: its wall time and the designs it returned.
#[derive(Clone, Debug)]
pub struct Run {
    pub index: usize,
    pub seconds: f64,
    pub designs: Vec<Design>,
}

impl Run {
    /// The run's best design (the smallest error), if any.
    pub fn best(&self) -> Option<&Design> {
        self.designs
            .iter()
            .min_by(|a, b| a.judged.error().total_cmp(&b.judged.error()))
    }
}

/// A method of a tool on a task.
#[derive(Clone, Debug)]
pub struct Method {
    pub task: String,
    pub tool: &'static str,
    pub name: String,
    /// What one run is.
    pub setting: String,
    pub runs: Vec<Run>,
}

/// The median of `values` (the mean of the middle two for an even count).
pub fn median(values: &[f64]) -> f64 {
    let mut v = values.to_vec();
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n == 0 {
        f64::NAN
    } else if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

impl Method {
    fn designs(&self) -> impl Iterator<Item = &Design> {
        self.runs.iter().flat_map(|r| &r.designs)
    }

    pub fn seconds(&self) -> Vec<f64> {
        self.runs.iter().map(|r| r.seconds).collect()
    }

    /// Each run's best error (∞ for a run without a design).
    pub fn best_errors(&self) -> Vec<f64> {
        self.runs
            .iter()
            .map(|r| r.best().map_or(f64::INFINITY, |d| d.judged.error()))
            .collect()
    }

    /// The best design of all runs.
    pub fn best(&self) -> Option<&Design> {
        self.runs
            .iter()
            .filter_map(Run::best)
            .min_by(|a, b| a.judged.error().total_cmp(&b.judged.error()))
    }

    pub fn count(&self) -> usize {
        self.designs().count()
    }

    pub fn defective(&self) -> usize {
        self.designs()
            .filter(|d| d.judged.verdict.defective())
            .count()
    }

    pub fn not_assembling(&self) -> usize {
        self.designs()
            .filter(|d| !d.judged.verdict.assembles())
            .count()
    }

    pub fn largest_error(&self) -> f64 {
        self.designs()
            .map(|d| d.judged.error())
            .fold(f64::NAN, f64::max)
    }
}

/// A time in s or ms.
pub fn time(seconds: f64) -> String {
    if !seconds.is_finite() {
        "–".to_owned()
    } else if seconds < 1e-3 {
        format!("{:.1} µs", seconds * 1e6)
    } else if seconds < 1.0 {
        format!("{:.1} ms", seconds * 1e3)
    } else {
        format!("{seconds:.1} s")
    }
}

/// An error with its unit: mm for a path, degrees for a function; ∞ for
/// no design, or one that does not run the range.
pub fn error(task: &str, e: f64) -> String {
    if e.is_nan() {
        "–".to_owned()
    } else if e.is_infinite() {
        "∞".to_owned()
    } else if task == "function" {
        format!("{:.1e}°", e.to_degrees())
    } else {
        format!("{e:.1e} mm")
    }
}

/// The side-by-side table, in Markdown.
pub fn table(methods: &[Method]) -> String {
    let mut t = String::new();
    let _ = writeln!(
        t,
        "| task | tool: method | one run | runs | wall time per run, median (min–max) | error of a run's best design, median (worst run) | designs returned | largest error of any | branch or order defects | not assembling over the range |"
    );
    let _ = writeln!(t, "|---|---|---|---:|---:|---:|---:|---:|---:|---:|");
    for m in methods {
        let seconds = m.seconds();
        let (lo, hi) = (
            seconds.iter().copied().fold(f64::INFINITY, f64::min),
            seconds.iter().copied().fold(0.0, f64::max),
        );
        let spread = if m.runs.len() > 1 {
            format!(" ({}–{})", time(lo), time(hi))
        } else {
            String::new()
        };
        let errors = m.best_errors();
        let worst = errors.iter().copied().fold(0.0, f64::max);
        let worst = if m.runs.len() > 1 {
            format!(" ({})", error(&m.task, worst))
        } else {
            String::new()
        };
        let _ = writeln!(
            t,
            "| {} | {}: {} | {} | {} | {}{spread} | {}{worst} | {} | {} | {} | {} |",
            task_name(&m.task),
            m.tool,
            m.name,
            m.setting,
            m.runs.len(),
            time(median(&seconds)),
            error(&m.task, median(&errors)),
            m.count(),
            error(&m.task, m.largest_error()),
            m.defective(),
            m.not_assembling(),
        );
    }
    t
}

pub fn task_name(task: &str) -> &'static str {
    match task {
        "path5" => "path, 5 points",
        "path9" => "path, 9 points",
        "function" => "function, 3 points",
        _ => "?",
    }
}

/// Every design: its task, tool, method, run, dimensions, error and the
/// certificate's verdict.
pub fn csv(methods: &[Method]) -> String {
    let mut out = String::from(
        "task,tool,method,run,design,seconds,xa,ya,xd,yd,l1,l2,l3,l4,px,py,error,error_unit,error_over_range,verdict\n",
    );
    let columns = ["xa", "ya", "xd", "yd", "l1", "l2", "l3", "l4", "px", "py"];
    for m in methods {
        for run in &m.runs {
            for (i, d) in run.designs.iter().enumerate() {
                let _ = write!(
                    out,
                    "{},{},{},{},{i},{:.6e}",
                    m.task,
                    m.tool,
                    csv_field(&m.name),
                    run.index,
                    run.seconds
                );
                for c in columns {
                    match d.params.iter().find(|p| p.0 == c) {
                        Some((_, value)) => {
                            let _ = write!(out, ",{value:.15e}");
                        }
                        None => out.push(','),
                    }
                }
                let (unit, scale) = if m.task == "function" {
                    ("deg", 180.0 / std::f64::consts::PI)
                } else {
                    ("mm", 1.0)
                };
                let over = d
                    .judged
                    .over_range
                    .map_or(String::new(), |e| format!("{:.6e}", e * scale));
                let _ = writeln!(
                    out,
                    ",{:.6e},{unit},{over},{}",
                    d.judged.error() * scale,
                    csv_field(&d.judged.verdict.describe())
                );
            }
        }
    }
    out
}

/// A CSV field: quoted (its quotes doubled) if it holds a comma or a quote.
fn csv_field(text: &str) -> String {
    if text.contains([',', '"']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_owned()
    }
}
