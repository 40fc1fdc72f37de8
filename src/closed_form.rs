//! Hand-written closed-form solutions of the classic mechanisms: the
//! references the general method is checked against, and the floor its
//! speed is measured against. Also the Grashof classification of a four-bar
//! and the driver angles where it reaches its limits.
//!
//! The four-bar follows the Maple worksheet: ground A = (0, 0) to
//! D = (l1, 0), crank AB (l2, θ2), coupler BC (l3, θ3), rocker CD (l4, θ4,
//! the angle of the vector C→D).

use nalgebra::Vector2;

/// The point at distances `r0` from `p0` and `r1` from `p1`, on the side
/// `sigma` (+1: to the left of p0→p1, −1: to the right); `None` if the
/// circles do not meet. Tangent circles (within rounding) meet once.
pub fn circle_intersection(
    p0: Vector2<f64>,
    r0: f64,
    p1: Vector2<f64>,
    r1: f64,
    sigma: f64,
) -> Option<Vector2<f64>> {
    let d = p1 - p0;
    let length = d.x.hypot(d.y);
    if length == 0.0 || !length.is_finite() {
        return None;
    }
    // a: from p0 along p0→p1 to the foot of the common chord.
    let a = (r0 * r0 - r1 * r1 + length * length) / (2.0 * length);
    // h² = r0² − a², factored to keep its digits near tangency.
    let h2 = (r0 - a) * (r0 + a);
    let tolerance = 8.0 * f64::EPSILON * r0 * r0;
    let h = if h2 >= 0.0 {
        h2.sqrt()
    } else if h2 > -tolerance {
        0.0
    } else {
        return None;
    };
    let e = d / length;
    let perp = Vector2::new(-e.y, e.x);
    Some(p0 + e * a + perp * (sigma * h))
}

/// A four-bar in the worksheet's convention.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FourBar {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
}

/// The kinematic state of a four-bar from the closed form.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FourBarState {
    /// θ3, θ4
    pub angles: [f64; 2],
    /// ω3, ω4
    pub velocities: [f64; 2],
    /// α3, α4
    pub accelerations: [f64; 2],
}

/// A four-bar's state with the coupler's and the rocker's angles given by
/// their directions (see [`FourBar::directions_from_crank`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FourBarDirections {
    /// (cos θ3, sin θ3)
    pub coupler: Vector2<f64>,
    /// (cos θ4, sin θ4)
    pub rocker: Vector2<f64>,
    /// ω3, ω4
    pub velocities: [f64; 2],
    /// α3, α4
    pub accelerations: [f64; 2],
}

/// Grashof's classification of a four-bar by its link lengths s ≤ p ≤ q ≤ l.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Grashof {
    /// s + l < p + q, the crank (l2) shortest: it turns fully, the rocker rocks.
    CrankRocker,
    /// s + l < p + q, the ground (l1) shortest: both crank and rocker turn fully.
    DoubleCrank,
    /// s + l < p + q, the coupler (l3) shortest: crank and rocker both rock,
    /// the coupler turns fully.
    GrashofDoubleRocker,
    /// s + l < p + q, the rocker (l4) shortest: it turns fully, the crank rocks.
    RockerCrank,
    /// s + l > p + q: no link turns fully; the input rocks between two limit
    /// positions.
    TripleRocker,
    /// s + l = p + q: the four joints become collinear, where the two
    /// assembly branches cross.
    ChangePoint,
}

/// The unit directions (cos θ, sin θ) of the crank, the coupler and the
/// rocker.
struct Directions {
    crank: Vector2<f64>,
    coupler: Vector2<f64>,
    rocker: Vector2<f64>,
}

impl Directions {
    fn of_angles(theta2: f64, [theta3, theta4]: [f64; 2]) -> Directions {
        let unit = |angle: f64| {
            let (s, c) = angle.sin_cos();
            Vector2::new(c, s)
        };
        Directions {
            crank: unit(theta2),
            coupler: unit(theta3),
            rocker: unit(theta4),
        }
    }
}

impl FourBar {
    /// B, the crank pin.
    pub fn b(&self, theta2: f64) -> Vector2<f64> {
        Vector2::new(self.l2 * theta2.cos(), self.l2 * theta2.sin())
    }

    /// D, the rocker's ground pivot.
    pub fn d(&self) -> Vector2<f64> {
        Vector2::new(self.l1, 0.0)
    }

    /// θ3, θ4 at the crank angle θ2 on the assembly branch `sigma` (+1 or −1:
    /// the side of B→D that C is on); `None` where it cannot be assembled.
    pub fn position(&self, theta2: f64, sigma: f64) -> Option<[f64; 2]> {
        let b = self.b(theta2);
        let c = circle_intersection(b, self.l3, self.d(), self.l4, sigma)?;
        let bc = c - b;
        let cd = self.d() - c;
        Some([bc.y.atan2(bc.x), cd.y.atan2(cd.x)])
    }

    /// The branch (+1 or −1) of a pose: the side of B→D that C is on.
    pub fn branch(&self, theta2: f64, theta3: f64) -> f64 {
        let b = self.b(theta2);
        let bd = self.d() - b;
        let bc = Vector2::new(theta3.cos(), theta3.sin());
        (bd.x * bc.y - bd.y * bc.x).signum()
    }

    /// ω3, ω4 in closed form.
    pub fn velocities(&self, theta2: f64, angles: [f64; 2], omega2: f64) -> [f64; 2] {
        let directions = Directions::of_angles(theta2, angles);
        self.rates(&directions, omega2, 0.0, None).0
    }

    /// α3, α4 in closed form.
    pub fn accelerations(
        &self,
        theta2: f64,
        angles: [f64; 2],
        omega2: f64,
        alpha2: f64,
        omegas: [f64; 2],
    ) -> [f64; 2] {
        let directions = Directions::of_angles(theta2, angles);
        self.rates(&directions, omega2, alpha2, Some(omegas)).1
    }

    /// Positions, velocities and accelerations in closed form.
    pub fn state(&self, theta2: f64, omega2: f64, alpha2: f64, sigma: f64) -> Option<FourBarState> {
        self.state_from_crank(theta2.sin_cos(), omega2, alpha2, sigma)
    }

    /// [`FourBar::state`] from the crank's sine and cosine (sin θ2, cos θ2),
    /// which a sweep can carry from sample to sample instead of computing
    /// them: [`FourBar::directions_from_crank`], then θ3 and θ4 by `atan2`.
    pub fn state_from_crank(
        &self,
        crank: (f64, f64),
        omega2: f64,
        alpha2: f64,
        sigma: f64,
    ) -> Option<FourBarState> {
        let d = self.directions_from_crank(crank, omega2, alpha2, sigma)?;
        Some(FourBarState {
            angles: [d.coupler.y.atan2(d.coupler.x), d.rocker.y.atan2(d.rocker.x)],
            velocities: d.velocities,
            accelerations: d.accelerations,
        })
    }

    /// The coupler's and the rocker's directions, velocities and
    /// accelerations from the crank's sine and cosine, with no sine, cosine
    /// or arctangent: the circle intersection gives C, and with it
    /// (cos θ3, sin θ3) = (C − B)/l3 and (cos θ4, sin θ4) = (D − C)/l4; the
    /// velocities and accelerations need only sines and cosines of angle
    /// differences, which are products of those. Per call a hypot, a square
    /// root and four divisions.
    pub fn directions_from_crank(
        &self,
        crank: (f64, f64),
        omega2: f64,
        alpha2: f64,
        sigma: f64,
    ) -> Option<FourBarDirections> {
        let (s2, c2) = crank;
        let b = Vector2::new(self.l2 * c2, self.l2 * s2);
        let c = circle_intersection(b, self.l3, self.d(), self.l4, sigma)?;
        let directions = Directions {
            crank: Vector2::new(c2, s2),
            coupler: (c - b) / self.l3,
            rocker: (self.d() - c) / self.l4,
        };
        let (velocities, accelerations) = self.rates(&directions, omega2, alpha2, None);
        Some(FourBarDirections {
            coupler: directions.coupler,
            rocker: directions.rocker,
            velocities,
            accelerations,
        })
    }

    /// (ω3, ω4) and (α3, α4) from the links' directions: the velocity
    /// equations solved by Cramer's rule, and the accelerations likewise
    /// with the centripetal terms (`omegas` given, or the velocities just
    /// found).
    fn rates(
        &self,
        e: &Directions,
        omega2: f64,
        alpha2: f64,
        omegas: Option<[f64; 2]>,
    ) -> ([f64; 2], [f64; 2]) {
        let (l2, l3, l4) = (self.l2, self.l3, self.l4);
        // sin and cos of θi − θj
        let sin = |a: &Vector2<f64>, b: &Vector2<f64>| a.y * b.x - a.x * b.y;
        let cos = |a: &Vector2<f64>, b: &Vector2<f64>| a.x * b.x + a.y * b.y;
        let s34 = sin(&e.coupler, &e.rocker);
        let (s24, c24) = (sin(&e.crank, &e.rocker), cos(&e.crank, &e.rocker));
        let (s23, c23) = (sin(&e.crank, &e.coupler), cos(&e.crank, &e.coupler));
        let c34 = cos(&e.coupler, &e.rocker);
        let velocities = [
            -l2 * omega2 * s24 / (l3 * s34),
            l2 * omega2 * s23 / (l4 * s34),
        ];
        let [w3, w4] = omegas.unwrap_or(velocities);
        let accelerations = [
            (-alpha2 * l2 * s24 - l2 * omega2 * omega2 * c24 - l3 * w3 * w3 * c34 - l4 * w4 * w4)
                / (l3 * s34),
            (alpha2 * l2 * s23 + l2 * omega2 * omega2 * c23 + l3 * w3 * w3 + l4 * w4 * w4 * c34)
                / (l4 * s34),
        ];
        (velocities, accelerations)
    }

    /// Grashof's classification.
    pub fn grashof(&self) -> Grashof {
        let mut sorted = [self.l1, self.l2, self.l3, self.l4];
        sorted.sort_by(f64::total_cmp);
        let [s, p, q, l] = sorted;
        let lhs = s + l;
        let rhs = p + q;
        if (lhs - rhs).abs() <= 4.0 * f64::EPSILON * rhs {
            return Grashof::ChangePoint;
        }
        if lhs > rhs {
            return Grashof::TripleRocker;
        }
        if s == self.l1 {
            Grashof::DoubleCrank
        } else if s == self.l2 {
            Grashof::CrankRocker
        } else if s == self.l3 {
            Grashof::GrashofDoubleRocker
        } else {
            Grashof::RockerCrank
        }
    }

    /// The crank angles θ2 ∈ [0, π] at which the coupler and rocker are
    /// collinear — BD = l3 + l4 (stretched) or |l3 − l4| (folded) — by the
    /// law of cosines; their negatives (2π − θ2) are the same positions on
    /// the other side. For a triple rocker these are the limit positions of
    /// the input; for a change-point linkage, the crossing of the branches.
    pub fn collinear_crank_angles(&self) -> Vec<f64> {
        let (l1, l2) = (self.l1, self.l2);
        [self.l3 + self.l4, (self.l3 - self.l4).abs()]
            .into_iter()
            .filter_map(|bd| {
                let c = (l1 * l1 + l2 * l2 - bd * bd) / (2.0 * l1 * l2);
                (-1.0..=1.0).contains(&c).then(|| c.acos())
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const WORKSHEET: FourBar = FourBar {
        l1: 80.0,
        l2: 20.0,
        l3: 50.0,
        l4: 70.0,
    };

    #[test]
    fn the_worksheet_pose() {
        let s = WORKSHEET
            .state(20f64.to_radians(), 41.88790204786391, 0.0, 1.0)
            .unwrap();
        assert!((s.angles[0] - 1.231_343_147_254_347_3).abs() < 1e-15);
        assert!((s.angles[1] + 0.880_796_908_593_408_3).abs() < 1e-15);
        assert!((s.velocities[0] + 18.425_284_259_084_822).abs() < 1e-12);
        assert!((s.accelerations[1] - 584.710_757_984_326_3).abs() < 1e-10);
        assert_eq!(WORKSHEET.branch(20f64.to_radians(), s.angles[0]), 1.0);
    }

    #[test]
    fn grashof_classes() {
        assert_eq!(WORKSHEET.grashof(), Grashof::CrankRocker);
        assert_eq!(
            FourBar {
                l2: 40.0,
                ..WORKSHEET
            }
            .grashof(),
            Grashof::ChangePoint
        );
        assert_eq!(
            FourBar {
                l2: 45.0,
                ..WORKSHEET
            }
            .grashof(),
            Grashof::TripleRocker
        );
        assert_eq!(
            FourBar {
                l1: 20.0,
                l2: 60.0,
                ..WORKSHEET
            }
            .grashof(),
            Grashof::DoubleCrank
        );
        assert_eq!(
            FourBar {
                l3: 20.0,
                l2: 80.0,
                ..WORKSHEET
            }
            .grashof(),
            Grashof::GrashofDoubleRocker
        );
    }

    #[test]
    fn limit_positions_by_the_law_of_cosines() {
        let angles = FourBar {
            l2: 45.0,
            ..WORKSHEET
        }
        .collinear_crank_angles();
        assert_eq!(angles.len(), 1);
        assert!((angles[0].to_degrees() - 146.084_473_399_991_7).abs() < 1e-12);
        assert!(
            FourBar {
                l2: 45.0,
                ..WORKSHEET
            }
            .position(std::f64::consts::PI, 1.0)
            .is_none()
        );
    }
}
