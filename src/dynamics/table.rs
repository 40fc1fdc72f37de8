//! Piecewise-linear tables, such as process-force diagrams.

use super::MachineError;

/// A piecewise-linear function of one variable through given points
/// (held constant beyond its ends), such as a process-force diagram.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    points: Vec<(f64, f64)>,
}

impl Table {
    /// Through `points`, with strictly increasing abscissae.
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
            if i > 0 && x <= points[i - 1].0 {
                return Err(MachineError::BadTable {
                    why: format!(
                        "its abscissae must increase, but point {i} has {x} after {}",
                        points[i - 1].0
                    ),
                });
            }
        }
        Ok(Table { points })
    }

    /// The value at x.
    pub fn at(&self, x: f64) -> f64 {
        let p = &self.points;
        if x <= p[0].0 {
            return p[0].1;
        }
        if x >= p[p.len() - 1].0 {
            return p[p.len() - 1].1;
        }
        let k = p.partition_point(|&(xi, _)| xi <= x).max(1) - 1;
        let ((x0, y0), (x1, y1)) = (p[k], p[k + 1]);
        y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    }

    /// The abscissae of the points: where the slope changes.
    pub fn breakpoints(&self) -> impl Iterator<Item = f64> + '_ {
        self.points.iter().map(|&(x, _)| x)
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
        assert!(Table::new(vec![(0.0, 1.0)]).is_err());
        assert!(Table::new(vec![(0.0, 1.0), (1.0, f64::NAN)]).is_err());
        assert!(Table::new(vec![(1.0, 1.0), (0.0, 1.0)]).is_err());
    }
}
