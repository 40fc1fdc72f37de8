//! Piecewise-linear tables, such as process-force diagrams.

use super::MachineError;

/// A piecewise-linear function of one variable through given points
/// (held constant beyond its ends), such as a process-force diagram. It may
/// jump: two consecutive points at the same abscissa are the values just
/// before and just after it (a cutting force that starts at full value),
/// and at the jump itself the table takes the second.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    points: Vec<(f64, f64)>,
}

impl Table {
    /// Through `points`, finite, with abscissae that never decrease and
    /// repeat at most once (a jump).
    pub fn new(points: Vec<(f64, f64)>) -> Result<Table, MachineError> {
        if points.len() < 2 {
            return Err(MachineError::BadTable {
                why: format!("it needs at least two points, got {}", points.len()),
            });
        }
        for (i, &(x, y)) in points.iter().enumerate() {
            if !(x.is_finite() && y.is_finite()) {
                return Err(MachineError::BadTable {
                    why: format!("point {i} is ({x}, {y})"),
                });
            }
            if i > 0 && x < points[i - 1].0 {
                return Err(MachineError::BadTable {
                    why: format!(
                        "its abscissae must not decrease, but point {i} has {x} after {}",
                        points[i - 1].0
                    ),
                });
            }
            if i > 1 && x == points[i - 1].0 && x == points[i - 2].0 {
                return Err(MachineError::BadTable {
                    why: format!(
                        "points {} to {i} share the abscissa {x}: a jump is two points",
                        i - 2
                    ),
                });
            }
        }
        if points[0].0 == points[points.len() - 1].0 {
            return Err(MachineError::BadTable {
                why: "its abscissae span nothing".into(),
            });
        }
        let table = Table { points };
        let slopes_finite = table
            .points
            .windows(2)
            .all(|w| w[0].0 == w[1].0 || ((w[1].1 - w[0].1) / (w[1].0 - w[0].0)).is_finite());
        if !(slopes_finite && table.area().is_finite()) {
            return Err(MachineError::BadTable {
                why: "its numbers are so large that its slopes or its area overflow".into(),
            });
        }
        Ok(table)
    }

    /// The value at x (NaN for a NaN x): at a jump, the value after it.
    pub fn at(&self, x: f64) -> f64 {
        let p = &self.points;
        if x.is_nan() {
            return f64::NAN;
        }
        if x < p[0].0 {
            return p[0].1;
        }
        if x >= p[p.len() - 1].0 {
            return p[p.len() - 1].1;
        }
        // The last point at or before x, and the one after it.
        let k = p.partition_point(|&(xi, _)| xi <= x) - 1;
        let ((x0, y0), (x1, y1)) = (p[k], p[k + 1]);
        y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    }

    /// The slope at x: of the segment x lies in (after a breakpoint, the
    /// segment that starts there), 0 beyond the ends; NaN for a NaN x.
    pub fn slope(&self, x: f64) -> f64 {
        let p = &self.points;
        if x.is_nan() {
            return f64::NAN;
        }
        if x < p[0].0 || x >= p[p.len() - 1].0 {
            return 0.0;
        }
        let k = p.partition_point(|&(xi, _)| xi <= x) - 1;
        let ((x0, y0), (x1, y1)) = (p[k], p[k + 1]);
        (y1 - y0) / (x1 - x0)
    }

    /// Whether the table jumps anywhere (two points at one abscissa with
    /// different values).
    pub fn jumps(&self) -> bool {
        self.points
            .windows(2)
            .any(|w| w[0].0 == w[1].0 && w[0].1 != w[1].1)
    }

    /// The abscissae where the slope changes or the value jumps, ascending,
    /// each once.
    pub fn breakpoints(&self) -> impl Iterator<Item = f64> + '_ {
        let p = &self.points;
        (0..p.len())
            .filter(|&i| i == 0 || p[i].0 != p[i - 1].0)
            .map(|i| p[i].0)
    }

    /// ∫ over the whole table, exactly (trapezoids).
    pub fn area(&self) -> f64 {
        self.points
            .windows(2)
            .map(|w| 0.5 * (w[0].1 + w[1].1) * (w[1].0 - w[0].0))
            .sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolates_holds_and_integrates() {
        let t = Table::new(vec![(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0)]).unwrap();
        assert_eq!(t.at(0.5), 1.0);
        assert_eq!(t.at(2.0), 2.0);
        assert_eq!(t.at(3.5), 1.0);
        assert_eq!(t.at(-1.0), 0.0);
        assert_eq!(t.at(9.0), 0.0);
        assert_eq!(t.area(), 6.0);
        assert_eq!(t.breakpoints().count(), 4);
        assert_eq!(
            [0.5, 1.0, 2.0, 3.5, -1.0, 9.0].map(|x| t.slope(x)),
            [2.0, 0.0, 0.0, -2.0, 0.0, 0.0]
        );
        assert!(!t.jumps());
        assert!(Table::new(vec![(0.0, 1.0)]).is_err());
        assert!(Table::new(vec![(0.0, 1.0), (1.0, f64::NAN)]).is_err());
        assert!(Table::new(vec![(1.0, 1.0), (0.0, 1.0)]).is_err());
    }

    /// A force that starts at full value: the jump holds the value after it
    /// from its abscissa on, and the area has no sliver at the jump.
    #[test]
    fn jumps() {
        let t = Table::new(vec![
            (0.0, 0.0),
            (1.0, 0.0),
            (1.0, 5.0),
            (3.0, 5.0),
            (3.0, 0.0),
        ])
        .unwrap();
        assert_eq!(t.at(0.999), 0.0);
        assert_eq!(t.at(1.0), 5.0);
        assert_eq!(t.at(2.0), 5.0);
        assert_eq!(t.at(3.0), 0.0);
        assert_eq!(t.area(), 10.0);
        assert_eq!(t.breakpoints().collect::<Vec<_>>(), vec![0.0, 1.0, 3.0]);
        assert!(t.at(f64::NAN).is_nan());
        assert!(t.jumps());
        assert_eq!([0.5, 1.0, 3.0].map(|x| t.slope(x)), [0.0, 0.0, 0.0]);
        // Three points at one abscissa, or none spanned, are no table.
        assert!(Table::new(vec![(0.0, 0.0), (1.0, 1.0), (1.0, 2.0), (1.0, 3.0)]).is_err());
        assert!(Table::new(vec![(1.0, 0.0), (1.0, 1.0)]).is_err());
    }
}
