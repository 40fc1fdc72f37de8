//! What pylinkage did, read from the file `benches/peers/synthesis.sh`
//! writes (`benches/results/synthesis_pylinkage.csv`): the targets it was
//! given, the designs it returned with their joints at their first frame,
//! the runs that returned none, its optimisers' convergence and its
//! objective's evaluation rate. Its designs become ours to judge: a
//! [`CouplerFourBar`] (or [`FourBar`]) and the pose they were exported at.

use linkage::mechanisms::{CouplerFourBar, FourBar};
use linkage::prelude::*;

/// One line of the file.
#[derive(Clone, Debug)]
pub struct Row {
    /// target, design, none, trace or rate.
    pub record: String,
    /// path5, path9 or function.
    pub task: String,
    pub method: String,
    pub run: usize,
    pub evaluations: f64,
    pub seconds: f64,
    /// A, B, C, D, P: x and y of each.
    pub joints: [f64; 10],
}

impl Row {
    fn point(&self, i: usize) -> Vector2<f64> {
        vector![self.joints[2 * i], self.joints[2 * i + 1]]
    }

    /// A target's x and y (θ2 and φ for the function task).
    pub fn target(&self) -> (f64, f64) {
        (self.joints[8], self.joints[9])
    }

    /// The design as our path four-bar, with its pose (θ3, θ4) and θ2 at
    /// its first frame.
    pub fn coupler_four_bar(&self) -> (CouplerFourBar, SVector<f64, 2>, f64) {
        let [a, b, c, d, p] = [0, 1, 2, 3, 4].map(|i| self.point(i));
        let e = (c - b).normalize();
        let left = vector![-e.y, e.x];
        let model = CouplerFourBar {
            xa: a.x,
            ya: a.y,
            xd: d.x,
            yd: d.y,
            l2: (b - a).norm(),
            l3: (c - b).norm(),
            l4: (d - c).norm(),
            px: (p - b).dot(&e),
            py: (p - b).dot(&left),
        };
        let angle = |from: Vector2<f64>, to: Vector2<f64>| (to - from).y.atan2((to - from).x);
        (model, vector![angle(b, c), angle(c, d)], angle(a, b))
    }

    /// The design as our four-bar (A at the origin, D on the x axis), with
    /// its pose (θ3, θ4) and θ2 at its first frame.
    pub fn four_bar(&self) -> Result<(FourBar, SVector<f64, 2>, f64), String> {
        let (bar, u, v) = self.coupler_four_bar();
        if bar.xa.abs() + bar.ya.abs() + bar.yd.abs() > 1e-12 * bar.xd.abs() {
            return Err(format!(
                "{}: its ground is not from the origin along x",
                self.method
            ));
        }
        let model = FourBar {
            l1: bar.xd,
            l2: bar.l2,
            l3: bar.l3,
            l4: bar.l4,
        };
        Ok((model, u, v))
    }
}

/// The rows of `text`, comments (`#`) and the header skipped.
pub fn parse(text: &str) -> Result<Vec<Row>, String> {
    let mut rows = Vec::new();
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.starts_with('#') && !l.trim().is_empty());
    let header = lines.next().ok_or("no header")?;
    if !header.1.starts_with("record,task,method,run,") {
        return Err(format!("line {}: not the expected header", header.0 + 1));
    }
    for (n, line) in lines {
        let cells: Vec<&str> = line.split(',').collect();
        if cells.len() != 17 {
            return Err(format!(
                "line {}: {} cells, 17 expected",
                n + 1,
                cells.len()
            ));
        }
        let number = |i: usize| -> Result<f64, String> {
            cells[i]
                .parse::<f64>()
                .map_err(|e| format!("line {}, cell {}: {e}", n + 1, i + 1))
        };
        let mut joints = [0.0; 10];
        for (k, joint) in joints.iter_mut().enumerate() {
            *joint = number(7 + k)?;
        }
        rows.push(Row {
            record: cells[0].to_owned(),
            task: cells[1].to_owned(),
            method: cells[2].to_owned(),
            run: cells[3]
                .parse()
                .map_err(|e| format!("line {}: run: {e}", n + 1))?,
            evaluations: number(4)?,
            seconds: number(5)?,
            joints,
        });
    }
    Ok(rows)
}

/// The methods of `task` with a `record` row, in the file's order.
pub fn methods<'a>(rows: &'a [Row], task: &str, records: &[&str]) -> Vec<&'a str> {
    let mut out: Vec<&str> = Vec::new();
    for row in rows
        .iter()
        .filter(|r| r.task == task && records.contains(&r.record.as_str()))
    {
        if !out.contains(&row.method.as_str()) {
            out.push(&row.method);
        }
    }
    out
}
