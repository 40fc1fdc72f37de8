//! Choosing one mode: by its index, by a point's side of a line, or as the
//! one nearest a sketch.

use super::error::AssemblyError;
use super::modes::{Mode, Modes};
use crate::error::NameKind;
use crate::quantity::find;
use nalgebra::{SVector, Vector2};
use std::fmt;

/// Who names the points of a pick, in its errors.
const OWNER: &str = "the pick of an assembly mode";
/// Two distances to a sketch closer than this (relative) are a tie.
const TIE: f64 = 1e-9;

/// A side of a directed line.
///
/// ```
/// use linkage::assembly::{Pick, Side, Spot};
/// use linkage::prelude::*;
///
/// let pick: Pick<2> = Pick::right_of("C", "B", vector![80.0, 0.0]);
/// let Pick::Side { side, to, .. } = &pick else { unreachable!() };
/// assert_eq!(*side, Side::Right);
/// assert_eq!(*to, Spot::At(vector![80.0, 0.0]));
/// assert_eq!(pick.to_string(), "C right of B → (80, 0)");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// To the left, looking from the line's first point to its second
    /// (counter-clockwise of it).
    Left,
    Right,
}

/// A place in the plane: a named point of the mechanism (where the mode
/// puts it), or a fixed position (a ground pivot that is not a named
/// point).
///
/// ```
/// use linkage::assembly::Spot;
/// use linkage::prelude::*;
///
/// assert_eq!(Spot::from("B"), Spot::Point("B".to_owned()));
/// assert_eq!(Spot::from(vector![80.0, 0.0]).to_string(), "(80, 0)");
/// ```
#[derive(Clone, Debug, PartialEq)]
pub enum Spot {
    Point(String),
    At(Vector2<f64>),
}

impl From<&str> for Spot {
    fn from(name: &str) -> Spot {
        Spot::Point(name.to_owned())
    }
}

impl From<Vector2<f64>> for Spot {
    fn from(at: Vector2<f64>) -> Spot {
        Spot::At(at)
    }
}

impl fmt::Display for Spot {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Spot::Point(name) => f.write_str(name),
            Spot::At(at) => write!(f, "({}, {})", at.x, at.y),
        }
    }
}

/// Which mode to take among those found ([`Modes::pick`]).
///
/// ```
/// use linkage::assembly::{Pick, Search, modes};
/// use linkage::mechanisms::FourBar;
/// use linkage::prelude::*;
///
/// let found = modes(&FourBar::WORKSHEET, &vector![20f64.to_radians()], &Search::default())?;
/// // C to the left of the line from B to the ground pivot D = (80, 0).
/// let left = found.pick(&Pick::left_of("C", "B", vector![80.0, 0.0]))?;
/// // The same mode from a rough sketch of the joint C.
/// let sketch = found.pick(&Pick::nearest_points(&[("C", vector![35.0, 65.0])]))?;
/// assert_eq!(left, sketch);
/// assert!((left.u[0].to_degrees() - 70.550_765_47).abs() < 1e-8);
/// # Ok::<(), linkage::assembly::AssemblyError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub enum Pick<const M: usize> {
    /// The mode of this index in [`Modes::modes`].
    Index(usize),
    /// The one mode that puts the named point `point` on `side` of the
    /// line through `from` and `to`.
    Side {
        point: String,
        side: Side,
        from: Spot,
        to: Spot,
    },
    /// The mode nearest these coordinates: the distance is the root of the
    /// sum of the squared differences, each in the coordinate's unit
    /// ([`Modes::unit`]), an angle's up to whole turns.
    NearestCoordinates(SVector<f64, M>),
    /// The mode nearest a sketch of named points: the least sum of the
    /// squared distances between each named point and its position in the
    /// sketch.
    NearestPoints(Vec<(String, Vector2<f64>)>),
}

impl<const M: usize> Pick<M> {
    /// The mode that puts `point` to the left of the line from `from` to
    /// `to` ("C left of A→B").
    pub fn left_of(point: &str, from: impl Into<Spot>, to: impl Into<Spot>) -> Pick<M> {
        Pick::Side {
            point: point.to_owned(),
            side: Side::Left,
            from: from.into(),
            to: to.into(),
        }
    }

    /// The mode that puts `point` to the right of the line from `from` to
    /// `to`.
    pub fn right_of(point: &str, from: impl Into<Spot>, to: impl Into<Spot>) -> Pick<M> {
        Pick::Side {
            point: point.to_owned(),
            side: Side::Right,
            from: from.into(),
            to: to.into(),
        }
    }

    /// The mode nearest the approximate coordinates `u`.
    pub fn nearest(u: SVector<f64, M>) -> Pick<M> {
        Pick::NearestCoordinates(u)
    }

    /// The mode nearest a sketch: approximate positions of named points.
    pub fn nearest_points(sketch: &[(&str, Vector2<f64>)]) -> Pick<M> {
        Pick::NearestPoints(
            sketch
                .iter()
                .map(|(name, at)| ((*name).to_owned(), *at))
                .collect(),
        )
    }
}

impl<const M: usize> fmt::Display for Pick<M> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Pick::Index(index) => write!(f, "mode {index}"),
            Pick::Side {
                point,
                side,
                from,
                to,
            } => {
                let side = match side {
                    Side::Left => "left",
                    Side::Right => "right",
                };
                write!(f, "{point} {side} of {from} → {to}")
            }
            Pick::NearestCoordinates(u) => write!(f, "nearest u = {:?}", u.as_slice()),
            Pick::NearestPoints(sketch) => {
                f.write_str("nearest the sketch")?;
                for (name, at) in sketch {
                    write!(f, " {name} = ({}, {})", at.x, at.y)?;
                }
                Ok(())
            }
        }
    }
}

impl<const M: usize, const F: usize> Modes<M, F> {
    /// The mode `pick` chooses.
    ///
    /// ```
    /// use linkage::assembly::{AssemblyError, Pick, Search, modes};
    /// use linkage::mechanisms::FourBar;
    /// use linkage::prelude::*;
    ///
    /// let found = modes(&FourBar::WORKSHEET, &vector![0.35], &Search::default())?;
    /// assert_eq!(found.pick(&Pick::Index(0))?, &found.modes[0]);
    /// let unknown = found.pick(&Pick::left_of("Q", "B", "C")).unwrap_err();
    /// assert!(matches!(unknown, AssemblyError::UnknownName(_)));
    /// # Ok::<(), AssemblyError>(())
    /// ```
    ///
    /// Errors: no regular mode but dead centres
    /// ([`AssemblyError::AtDeadCentre`]); an index beyond the modes; no
    /// mode on the side asked ([`AssemblyError::NoMatch`]: a point on the
    /// line is on neither side); more than one there, or two modes equally
    /// near the sketch ([`AssemblyError::Ambiguous`]); a point the model
    /// does not have ([`AssemblyError::UnknownName`]).
    pub fn pick(&self, pick: &Pick<M>) -> Result<&Mode<M>, AssemblyError> {
        Ok(&self.modes[self.index_of(pick)?])
    }

    /// The index in [`Modes::modes`] of the mode `pick` chooses (errors as
    /// [`Modes::pick`]).
    ///
    /// ```
    /// use linkage::assembly::{Pick, Search, modes};
    /// use linkage::mechanisms::FourBar;
    /// use linkage::prelude::*;
    /// use std::f64::consts::TAU;
    ///
    /// let found = modes(&FourBar::WORKSHEET, &vector![0.35], &Search::default())?;
    /// // Rough angles, up to whole turns: the worksheet's pose.
    /// let rough = Pick::nearest(vector![1.2 + TAU, -0.9]);
    /// assert_eq!(found.index_of(&rough)?, 1);
    /// # Ok::<(), linkage::assembly::AssemblyError>(())
    /// ```
    pub fn index_of(&self, pick: &Pick<M>) -> Result<usize, AssemblyError> {
        if self.modes.is_empty() {
            return Err(AssemblyError::AtDeadCentre {
                dead_centres: self.dead_centres.len(),
            });
        }
        match pick {
            Pick::Index(index) => {
                if *index < self.modes.len() {
                    Ok(*index)
                } else {
                    Err(AssemblyError::IndexOutOfRange {
                        index: *index,
                        modes: self.modes.len(),
                    })
                }
            }
            Pick::Side {
                point,
                side,
                from,
                to,
            } => {
                let point = self.point(point)?;
                let (from, to) = (self.spot(from)?, self.spot(to)?);
                let on_side = (0..self.modes.len())
                    .filter(|&k| {
                        let at = |spot: Result<usize, Vector2<f64>>| match spot {
                            Ok(index) => self.modes[k].points[index],
                            Err(at) => at,
                        };
                        let (a, b, p) = (at(from), at(to), self.modes[k].points[point]);
                        let cross = (b - a).perp(&(p - a));
                        match side {
                            Side::Left => cross > 0.0,
                            Side::Right => cross < 0.0,
                        }
                    })
                    .collect();
                self.one(pick, on_side)
            }
            Pick::NearestCoordinates(u) => self.nearest(pick, |mode| {
                (0..M)
                    .map(|j| {
                        let d = (mode.u[j] - u[j]) / self.unit(j);
                        let d = if self.angle[j] {
                            super::scale::within_a_turn(d)
                        } else {
                            d
                        };
                        d * d
                    })
                    .sum::<f64>()
            }),
            Pick::NearestPoints(sketch) => {
                let named: Vec<(usize, Vector2<f64>)> = sketch
                    .iter()
                    .map(|(name, at)| Ok((self.point(name)?, *at)))
                    .collect::<Result<_, AssemblyError>>()?;
                self.nearest(pick, |mode| {
                    named
                        .iter()
                        .map(|(index, at)| (mode.points[*index] - at).norm_squared())
                        .sum()
                })
            }
        }
    }

    /// The index of the named point `name`.
    fn point(&self, name: &str) -> Result<usize, AssemblyError> {
        Ok(find(
            NameKind::Point,
            OWNER,
            name,
            self.point_names.iter().copied(),
        )?)
    }

    /// A spot: a named point's index, or a fixed position.
    fn spot(&self, spot: &Spot) -> Result<Result<usize, Vector2<f64>>, AssemblyError> {
        Ok(match spot {
            Spot::Point(name) => Ok(self.point(name)?),
            Spot::At(at) => Err(*at),
        })
    }

    /// The one mode among `matching`, or why there is not one.
    fn one(&self, pick: &Pick<M>, matching: Vec<usize>) -> Result<usize, AssemblyError> {
        match matching[..] {
            [index] => Ok(index),
            [] => Err(AssemblyError::NoMatch {
                pick: pick.to_string(),
            }),
            _ => Err(AssemblyError::Ambiguous {
                pick: pick.to_string(),
                modes: matching,
            }),
        }
    }

    /// The mode of the least `distance`, unless another ties with it.
    fn nearest(
        &self,
        pick: &Pick<M>,
        distance: impl Fn(&Mode<M>) -> f64,
    ) -> Result<usize, AssemblyError> {
        let distances: Vec<f64> = self.modes.iter().map(distance).collect();
        if distances.iter().any(|d| d.is_nan()) {
            return Err(AssemblyError::NoMatch {
                pick: pick.to_string(),
            });
        }
        let least = distances.iter().copied().fold(f64::INFINITY, f64::min);
        let nearest = (0..distances.len())
            .filter(|&k| distances[k] <= least + TIE * least.max(f64::MIN_POSITIVE))
            .collect();
        self.one(pick, nearest)
    }
}
