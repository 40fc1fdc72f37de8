//! Cam design: a follower's program of rises, dwells and returns with their
//! motion laws; oscillating (rocker) and translating roller followers; the
//! pressure angle, the pitch curve, the cam's profile for a roller (the
//! envelope of the roller's circles, by inversion) and its radius of
//! curvature with undercut detection; and the smallest cam that keeps the
//! pressure angle within a limit.
//!
//! Conventions. The cam turns about the origin O by the angle φ; the
//! follower's displacement s(φ) is the distance its roller centre K travels
//! (along the arc of radius l for a rocker, ψ = s/l being the arm's swing).
//! Everything is worked out in the cam's frame, where the follower's pivot
//! (or guide) turns the other way (inversion). Derivatives with respect to
//! φ are analytic: the law's S′, S″ scaled by the segment.

mod drawing;
mod laws;

pub use laws::{Derivatives, Law};

use nalgebra::Vector2;
use std::f64::consts::{PI, TAU};

/// What went wrong designing a cam.
#[derive(Clone, Debug, PartialEq)]
pub enum CamError {
    BadSetting {
        what: &'static str,
        must: &'static str,
        value: f64,
    },
    TooLong {
        total: f64,
    },
    /// The profile's radius of curvature falls below zero: the roller
    /// cannot follow the pitch curve there.
    Undercut {
        roller: f64,
        /// (from, to) in degrees.
        ranges: Vec<(f64, f64)>,
    },
    NoSize {
        limit: f64,
        angle: f64,
    },
}

impl std::fmt::Display for CamError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::BadSetting { must, value, what } => {
                write!(f, "{what} must be {must}, got {value}")
            }
            Self::TooLong { total } => {
                write!(f, "the program's segments take {total}° of the cam's 360°")
            }
            Self::Undercut { ranges, roller } => write!(
                f,
                "undercut: the pitch curve's radius of curvature is below the roller's radius {roller} for cam angles {ranges:?} (degrees)"
            ),
            Self::NoSize { angle, limit } => write!(
                f,
                "no cam up to a base radius of {limit} keeps the pressure angle within {angle}°"
            ),
        }
    }
}

impl std::error::Error for CamError {}

/// One segment of the follower's program.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Segment {
    /// Out by the lift over `angle` (rad) of cam rotation.
    Rise { angle: f64, law: Law },
    /// At rest.
    Dwell { angle: f64 },
    /// Back by the lift, the law run backwards (a time-reversed rise, as
    /// the course project's return).
    Return { angle: f64, law: Law },
}

impl Segment {
    fn angle(&self) -> f64 {
        match *self {
            Segment::Rise { angle, .. }
            | Segment::Dwell { angle }
            | Segment::Return { angle, .. } => angle,
        }
    }
}

/// The follower's program over a turn of the cam: segments from φ = 0, the
/// rest of the turn a dwell at the start.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    pub lift: f64,
    pub segments: Vec<Segment>,
}

/// Which part of the program a cam angle falls in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stroke {
    Rise,
    Dwell,
    Return,
}

impl Program {
    pub fn new(lift: f64, segments: Vec<Segment>) -> Result<Program, CamError> {
        if !(lift.is_finite() && lift > 0.0) {
            return Err(CamError::BadSetting {
                what: "the lift",
                must: "positive",
                value: lift,
            });
        }
        let mut total = 0.0;
        for s in &segments {
            let a = s.angle();
            if !(a.is_finite() && a >= 0.0) {
                return Err(CamError::BadSetting {
                    what: "a segment's angle",
                    must: "finite and ≥ 0",
                    value: a,
                });
            }
            total += a;
        }
        if total > TAU * (1.0 + 1e-12) {
            return Err(CamError::TooLong {
                total: total.to_degrees(),
            });
        }
        Ok(Program { lift, segments })
    }

    /// s(φ) and its derivatives s′, s″, s‴ with respect to φ (the cam
    /// angle, wrapped to one turn), and the stroke.
    pub fn at(&self, phi: f64) -> (Derivatives, Stroke) {
        let phi = phi.rem_euclid(TAU);
        let mut start = 0.0;
        let mut level = 0.0;
        for s in &self.segments {
            let a = s.angle();
            if phi < start + a
                || (phi == start + a && a > 0.0 && !matches!(s, Segment::Dwell { .. }))
            {
                let x = (phi - start) / a;
                let scale = |d: Derivatives, sign: f64| -> Derivatives {
                    [
                        d[0],
                        sign * d[1] / a,
                        d[2] / (a * a),
                        sign * d[3] / (a * a * a),
                    ]
                };
                return match *s {
                    Segment::Dwell { .. } => ([level, 0.0, 0.0, 0.0], Stroke::Dwell),
                    Segment::Rise { law, .. } => {
                        let d = scale(law.at(x), 1.0);
                        (
                            [
                                self.lift * d[0],
                                self.lift * d[1],
                                self.lift * d[2],
                                self.lift * d[3],
                            ],
                            Stroke::Rise,
                        )
                    }
                    Segment::Return { law, .. } => {
                        let d = scale(law.at(1.0 - x), -1.0);
                        (
                            [
                                self.lift * d[0],
                                self.lift * d[1],
                                self.lift * d[2],
                                self.lift * d[3],
                            ],
                            Stroke::Return,
                        )
                    }
                };
            }
            start += a;
            level = match s {
                Segment::Rise { .. } => self.lift,
                Segment::Return { .. } => 0.0,
                Segment::Dwell { .. } => level,
            };
        }
        ([level, 0.0, 0.0, 0.0], Stroke::Dwell)
    }

    /// The cam angles where a segment starts or a law's acceleration
    /// jumps, ascending in [0, 2π).
    pub fn breakpoints(&self) -> Vec<f64> {
        let mut out = vec![0.0];
        let mut start = 0.0;
        for s in &self.segments {
            let a = s.angle();
            match s {
                Segment::Rise { law, .. } => {
                    out.extend(law.breakpoints().iter().map(|b| start + b * a))
                }
                Segment::Return { law, .. } => {
                    out.extend(law.breakpoints().iter().map(|b| start + (1.0 - b) * a))
                }
                Segment::Dwell { .. } => {}
            }
            start += a;
            if start < TAU {
                out.push(start);
            }
        }
        out.sort_by(f64::total_cmp);
        out.dedup_by(|a, b| (*a - *b).abs() < 1e-15);
        out
    }
}

/// The sense in which the cam turns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rotation {
    CounterClockwise,
    Clockwise,
}

impl Rotation {
    fn sign(self) -> f64 {
        match self {
            Rotation::CounterClockwise => 1.0,
            Rotation::Clockwise => -1.0,
        }
    }
}

/// The follower.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Follower {
    /// A rocker pivoted at the distance `centre_distance` from the cam's
    /// centre, in the direction `pivot_angle` (rad) at φ = 0; the arm of
    /// length `arm` makes the angle `initial_angle` + ψ with the line from
    /// the pivot to the cam's centre, ψ = s/arm the swing.
    Rocker {
        arm: f64,
        centre_distance: f64,
        initial_angle: f64,
        pivot_angle: f64,
    },
    /// A translating follower whose axis is parallel to the direction
    /// `axis_angle` at φ = 0, offset by `offset` (to the axis's left), the
    /// roller centre at `base` from the cam's centre at s = 0.
    Translating {
        offset: f64,
        base: f64,
        axis_angle: f64,
    },
}

/// A cam mechanism: a program, a follower and the cam's sense of rotation.
#[derive(Clone, Debug, PartialEq)]
pub struct Cam {
    pub program: Program,
    pub follower: Follower,
    pub rotation: Rotation,
}

/// The roller centre K in the cam's frame at one cam angle, with its
/// derivatives, and the direction the follower moves K in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pitch {
    pub phi: f64,
    pub k: Vector2<f64>,
    pub dk: Vector2<f64>,
    pub ddk: Vector2<f64>,
    /// The unit direction of K's motion as s grows (in the cam's frame).
    pub motion: Vector2<f64>,
    pub stroke: Stroke,
    /// s, s′, s″, s‴.
    pub s: Derivatives,
}

/// A point of the cam's profile.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProfilePoint {
    pub phi: f64,
    /// The roller centre (pitch curve) and the contact point (profile).
    pub pitch: Vector2<f64>,
    pub profile: Vector2<f64>,
    /// The profile's radius of curvature: positive where convex.
    pub radius: f64,
}

/// Brent's minimum of a function that cannot fail.
fn minimize(
    f: &mut impl FnMut(f64) -> Result<f64, std::convert::Infallible>,
    a: f64,
    b: f64,
    tolerance: f64,
) -> (f64, f64) {
    match crate::dynamics::numerics::minimize(f, a, b, tolerance) {
        Ok(x) => x,
        Err(never) => match never {},
    }
}

fn rotate(v: Vector2<f64>, angle: f64) -> Vector2<f64> {
    let (s, c) = angle.sin_cos();
    Vector2::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

fn perp(v: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(-v.y, v.x)
}

fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

impl Cam {
    /// The pitch curve at φ, by inversion: the follower turned by −φ about
    /// the cam's centre (for a counter-clockwise cam).
    pub fn pitch(&self, phi: f64) -> Pitch {
        let (s, stroke) = self.program.at(phi);
        let sigma = self.rotation.sign();
        match self.follower {
            Follower::Rocker {
                arm,
                centre_distance,
                initial_angle,
                pivot_angle,
            } => {
                // The pivot G at angle γ = pivot_angle − σφ; the arm at
                // β = γ + π + initial_angle + ψ, ψ = s/l.
                let gamma = pivot_angle - sigma * phi;
                let (psi, dpsi, ddpsi) = (s[0] / arm, s[1] / arm, s[2] / arm);
                let beta = gamma + PI + initial_angle + psi;
                let (dgamma, dbeta, ddbeta) = (-sigma, -sigma + dpsi, ddpsi);
                let u_g = Vector2::new(gamma.cos(), gamma.sin());
                let u_b = Vector2::new(beta.cos(), beta.sin());
                let k = u_g * centre_distance + u_b * arm;
                let dk = perp(u_g) * (centre_distance * dgamma) + perp(u_b) * (arm * dbeta);
                let ddk = -u_g * (centre_distance * dgamma * dgamma) + perp(u_b) * (arm * ddbeta)
                    - u_b * (arm * dbeta * dbeta);
                Pitch {
                    phi,
                    k,
                    dk,
                    ddk,
                    motion: perp(u_b),
                    stroke,
                    s,
                }
            }
            Follower::Translating {
                offset,
                base,
                axis_angle,
            } => {
                // In the follower's frame K = (offset ⟂ axis) + (s0 + s)
                // along the axis; in the cam's frame, turned by −σφ.
                let axis = Vector2::new(axis_angle.cos(), axis_angle.sin());
                let s0 = (base * base - offset * offset).max(0.0).sqrt();
                let local = perp(axis) * offset + axis * (s0 + s[0]);
                let turn = -sigma * phi;
                let k = rotate(local, turn);
                let d_local = axis * s[1];
                let dd_local = axis * s[2];
                // d/dφ R(−σφ)v = R(−σφ)(v′ − σ ⟂v).
                let dk = rotate(d_local - perp(local) * sigma, turn);
                let ddk = rotate(dd_local - perp(d_local) * (2.0 * sigma) - local, turn);
                Pitch {
                    phi,
                    k,
                    dk,
                    ddk,
                    motion: rotate(axis, turn),
                    stroke,
                    s,
                }
            }
        }
    }

    /// The pressure angle at φ: between the common normal at the contact
    /// (the pitch curve's normal) and the direction the follower moves the
    /// roller centre, signed as the course project (positive on the rise
    /// of its rocker), in radians.
    pub fn pressure_angle(&self, phi: f64) -> f64 {
        let p = self.pitch(phi);
        // The normal to the pitch curve, towards the cam's centre side.
        let mut normal = perp(p.dk);
        if normal.dot(&p.k) > 0.0 {
            normal = -normal;
        }
        // The force the cam exerts pushes along −normal (outwards).
        let push = -normal;
        let (along, across) = (push.dot(&p.motion), cross(p.motion, push));
        let theta = across.atan2(along);
        // Fold to (−90°, 90°]: the follower may move either way along its
        // direction.
        let folded = if theta > PI / 2.0 {
            theta - PI
        } else if theta <= -PI / 2.0 {
            theta + PI
        } else {
            theta
        };
        self.rotation.sign() * folded
    }

    /// The base radius r0 = |OK| at φ = 0 (the roller centre's distance at
    /// the start of the rise).
    pub fn base_radius(&self) -> f64 {
        self.pitch(0.0).k.norm()
    }

    /// The worst excess of |θ| over `limit` in a turn (negative when the
    /// pressure angle stays within it everywhere).
    pub fn pressure_excess(&self, limit: f64) -> f64 {
        let ((_, hi), (_, lo)) = self.pressure_extremes();
        (hi - limit).max(-lo - limit)
    }

    /// The extremes of the pressure angle over a turn: ((φ, θ) at the
    /// maximum, (φ, θ) at the minimum), located to 1e-10 rad.
    pub fn pressure_extremes(&self) -> ((f64, f64), (f64, f64)) {
        let mut breaks = self.program.breakpoints();
        breaks.push(TAU);
        let mut best_max = (0.0, f64::NEG_INFINITY);
        let mut best_min = (0.0, f64::INFINITY);
        for w in breaks.windows(2) {
            let (a, b) = (w[0], w[1]);
            if b - a <= 0.0 {
                continue;
            }
            let n = 48;
            let inset = 1e-10;
            let xs: Vec<f64> = (0..=n)
                .map(|i| a + inset + (b - a - 2.0 * inset) * i as f64 / n as f64)
                .collect();
            let ys: Vec<f64> = xs.iter().map(|&x| self.pressure_angle(x)).collect();
            for (sign, best) in [(1.0, &mut best_max), (-1.0, &mut best_min)] {
                let k = (0..ys.len())
                    .max_by(|&p, &q| (sign * ys[p]).total_cmp(&(sign * ys[q])))
                    .unwrap_or(0);
                let (lo, hi) = (xs[k.saturating_sub(1)], xs[(k + 1).min(n)]);
                let mut f =
                    |x: f64| Ok::<f64, std::convert::Infallible>(-sign * self.pressure_angle(x));
                let (x, fx) = minimize(&mut f, lo, hi, 1e-11);
                // The segment's ends too (an extreme at a law's joint).
                for (x, value) in [
                    (x, -sign * fx),
                    (a, self.pressure_angle(a)),
                    (b, self.pressure_angle(b)),
                ] {
                    if sign * value > sign * best.1 {
                        *best = (x, value);
                    }
                }
            }
        }
        (best_max, best_min)
    }

    /// The pitch curve's radius of curvature at φ, positive where it bends
    /// towards the cam's centre (convex), negative where concave.
    pub fn pitch_radius(&self, phi: f64) -> f64 {
        let p = self.pitch(phi);
        let speed = p.dk.norm();
        let mut outward = perp(p.dk) / speed;
        if outward.dot(&p.k) < 0.0 {
            outward = -outward;
        }
        let kappa = cross(p.dk, p.ddk) / speed.powi(3) * (perp(p.dk) / speed).dot(&(-outward));
        1.0 / kappa
    }

    /// The largest roller that does not undercut: the smallest convex
    /// radius of the pitch curve, and the cam angle where it is.
    pub fn largest_roller(&self) -> (f64, f64) {
        let mut breaks = self.program.breakpoints();
        breaks.push(TAU);
        let mut best = (0.0, f64::INFINITY);
        for w in breaks.windows(2) {
            let (a, b) = (w[0], w[1]);
            if b - a <= 0.0 {
                continue;
            }
            let convex = |phi: f64| {
                let r = self.pitch_radius(phi);
                if r > 0.0 { r } else { f64::INFINITY }
            };
            let n = 48;
            let inset = 1e-10;
            let xs: Vec<f64> = (0..=n)
                .map(|i| a + inset + (b - a - 2.0 * inset) * i as f64 / n as f64)
                .collect();
            let k = (0..xs.len())
                .min_by(|&p, &q| convex(xs[p]).total_cmp(&convex(xs[q])))
                .unwrap_or(0);
            let (lo, hi) = (xs[k.saturating_sub(1)], xs[(k + 1).min(n)]);
            let mut f = |x: f64| Ok::<f64, std::convert::Infallible>(convex(x));
            let (x, r) = minimize(&mut f, lo, hi, 1e-11);
            for (x, r) in [(x, r), (xs[k], convex(xs[k]))] {
                if r < best.1 {
                    best = (x, r);
                }
            }
        }
        best
    }

    /// The profile for a roller of radius `roller` at `points` cam angles
    /// over a turn: the inner envelope of the roller's circles, K − r·n
    /// (n the pitch curve's unit normal away from the cam's centre), with
    /// its radius of curvature ρ_pitch − r. An undercut (ρ_pitch < r where
    /// the pitch curve is convex) is an error naming the cam angles.
    pub fn profile(&self, roller: f64, points: usize) -> Result<Vec<ProfilePoint>, CamError> {
        if !(roller.is_finite() && roller >= 0.0) {
            return Err(CamError::BadSetting {
                what: "the roller radius",
                must: "finite and ≥ 0",
                value: roller,
            });
        }
        let n = points.max(8);
        let mut out = Vec::with_capacity(n + 1);
        let mut bad: Vec<f64> = Vec::new();
        for i in 0..=n {
            let phi = TAU * i as f64 / n as f64;
            let p = self.pitch(phi);
            let speed = p.dk.norm();
            let mut normal = perp(p.dk) / speed;
            if normal.dot(&p.k) < 0.0 {
                normal = -normal;
            }
            // The curvature, positive where the curve bends towards the
            // cam's centre (convex): the curvature vector is
            // κ_s·⟂T̂, κ_s = (K′ × K″)/|K′|³.
            let signed = cross(p.dk, p.ddk) / speed.powi(3);
            let kappa = signed * (perp(p.dk) / speed).dot(&(-normal));
            let radius = if kappa != 0.0 {
                1.0 / kappa - roller
            } else {
                f64::INFINITY
            };
            if kappa > 0.0 && kappa * roller >= 1.0 {
                bad.push(phi.to_degrees());
            }
            out.push(ProfilePoint {
                phi,
                pitch: p.k,
                profile: p.k - normal * roller,
                radius,
            });
        }
        if !bad.is_empty() {
            // Contiguous runs (in samples) as ranges.
            let step = 360.0 / n as f64;
            let mut ranges: Vec<(f64, f64)> = Vec::new();
            for a in bad {
                match ranges.last_mut() {
                    Some(last) if a - last.1 <= 1.5 * step => last.1 = a,
                    _ => ranges.push((a, a)),
                }
            }
            return Err(CamError::Undercut { roller, ranges });
        }
        Ok(out)
    }
}

/// The smallest rocker cam whose pressure angle stays within ±`limit` (rad)
/// over the turn, for a given program, arm, pivot direction and rotation:
/// the base radius by bisection, and for each candidate base radius the
/// initial arm angle (with the centre distance it implies by the law of
/// cosines, r0² = a² + l² − 2al·cos ψ0) that best balances the rise's and
/// the return's extremes. Returns the cam.
pub fn smallest_rocker(
    program: &Program,
    arm: f64,
    pivot_angle: f64,
    rotation: Rotation,
    limit: f64,
) -> Result<Cam, CamError> {
    let make = |r0: f64, psi0: f64| -> Option<Cam> {
        let disc = r0 * r0 - arm * arm * psi0.sin().powi(2);
        if disc < 0.0 {
            return None;
        }
        let a = arm * psi0.cos() + disc.sqrt();
        (a > arm * 1e-6).then(|| Cam {
            program: program.clone(),
            follower: Follower::Rocker {
                arm,
                centre_distance: a,
                initial_angle: psi0,
                pivot_angle,
            },
            rotation,
        })
    };
    let excess = |cam: &Cam| cam.pressure_excess(limit);
    // For a base radius: the best initial angle, and its excess.
    let best = |r0: f64| -> (f64, f64) {
        let upper = (r0 / arm).clamp(-1.0, 1.0).asin().min(PI / 2.0 - 1e-9);
        let mut f = |psi0: f64| {
            Ok::<f64, std::convert::Infallible>(
                make(r0, psi0).map_or(f64::INFINITY, |c| excess(&c)),
            )
        };
        // Coarse, then Brent around the best.
        let n = 24;
        let xs: Vec<f64> = (0..=n)
            .map(|i| 1e-3 + (upper - 2e-3) * i as f64 / n as f64)
            .collect();
        let k = (0..xs.len())
            .min_by(|&p, &q| {
                f(xs[p])
                    .unwrap_or(f64::INFINITY)
                    .total_cmp(&f(xs[q]).unwrap_or(f64::INFINITY))
            })
            .unwrap_or(0);
        let (lo, hi) = (xs[k.saturating_sub(1)], xs[(k + 1).min(n)]);
        minimize(&mut f, lo, hi, 1e-12)
    };
    let (mut lo, mut hi) = (arm * 0.05, arm * 0.5);
    let limit_radius = 100.0 * arm;
    while best(hi).1 > 0.0 {
        lo = hi;
        hi *= 1.5;
        if hi > limit_radius {
            return Err(CamError::NoSize {
                limit: limit_radius,
                angle: limit.to_degrees(),
            });
        }
    }
    if best(lo).1 <= 0.0 {
        lo = 0.0;
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if best(mid).1 <= 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
        if hi - lo <= 1e-13 * hi {
            break;
        }
    }
    let (psi0, _) = best(hi);
    make(hi, psi0).ok_or(CamError::NoSize {
        limit: hi,
        angle: limit.to_degrees(),
    })
}

/// The smallest translating cam (base radius, with the offset that best
/// balances the strokes) whose pressure angle stays within ±`limit`.
pub fn smallest_translating(
    program: &Program,
    axis_angle: f64,
    rotation: Rotation,
    limit: f64,
) -> Result<Cam, CamError> {
    let make = |base: f64, offset: f64| Cam {
        program: program.clone(),
        follower: Follower::Translating {
            offset,
            base,
            axis_angle,
        },
        rotation,
    };
    let excess = |cam: &Cam| cam.pressure_excess(limit);
    let best = |base: f64| -> (f64, f64) {
        let mut f = |e: f64| Ok::<f64, std::convert::Infallible>(excess(&make(base, e)));
        let n = 24;
        let xs: Vec<f64> = (0..=n)
            .map(|i| -0.95 * base + 1.9 * base * i as f64 / n as f64)
            .collect();
        let k = (0..xs.len())
            .min_by(|&p, &q| {
                f(xs[p])
                    .unwrap_or(f64::INFINITY)
                    .total_cmp(&f(xs[q]).unwrap_or(f64::INFINITY))
            })
            .unwrap_or(0);
        let (lo, hi) = (xs[k.saturating_sub(1)], xs[(k + 1).min(n)]);
        minimize(&mut f, lo, hi, 1e-13 * base)
    };
    let lift = program.lift;
    let (mut lo, mut hi) = (0.0, lift);
    while best(hi).1 > 0.0 {
        lo = hi;
        hi *= 1.5;
        if hi > 1e4 * lift {
            return Err(CamError::NoSize {
                limit: hi,
                angle: limit.to_degrees(),
            });
        }
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if best(mid).1 <= 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
        if hi - lo <= 1e-13 * hi {
            break;
        }
    }
    let (offset, _) = best(hi);
    Ok(make(hi, offset))
}
