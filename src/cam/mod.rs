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

//!
//! The area's files: the motion laws (`laws.rs`), the follower's program
//! (`program.rs`), the cam's geometry (here), the smallest cam
//! (`sizing.rs`) and the drawing (`drawing.rs`, with the `draw` feature).

#[cfg(feature = "draw")]
mod drawing;
mod laws;
mod program;
mod sizing;

pub use laws::{Derivatives, Law};
pub use program::{Program, Segment, Stroke};
pub use sizing::{smallest_rocker, smallest_translating};

use crate::numerics;
use nalgebra::Vector2;
use program::cam_angle;
use std::f64::consts::{PI, TAU};

/// What went wrong designing a cam.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum CamError {
    /// A number given is out of its range (a NaN or an infinity among them).
    BadSetting {
        what: &'static str,
        must: &'static str,
        value: f64,
    },
    /// The program's segments take more than a turn.
    TooLong {
        total: f64,
    },
    /// The cam's geometry breaks down at a cam angle: the pitch curve stops
    /// (the roller centre does not move in the cam's frame) or leaves the
    /// range of f64, so that its normal, the pressure angle or the
    /// curvature is not defined there.
    Degenerate {
        /// The cam angle, rad.
        phi: f64,
        why: &'static str,
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

crate::error::error_impls! {
    CamError {
        Self::BadSetting { must, value, what } => ("{what} must be {must}, got {value}"),
        Self::TooLong { total } => ("the program's segments take {total}° of the cam's 360°"),
        Self::Undercut { ranges, roller } => ("undercut: the pitch curve's radius of curvature is below the roller's radius {roller} for cam angles {ranges:?} (degrees)"),
        Self::NoSize { angle, limit } => ("no cam up to a base radius of {limit} keeps the pressure angle within {angle}°"),
        Self::Degenerate { phi, why } => ("the cam is degenerate at φ = {}°: {why}", phi.to_degrees()),
    }
    wraps {  }
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
/// Made by [`Cam::new`], which checks the follower.
#[derive(Clone, Debug, PartialEq)]
pub struct Cam {
    program: Program,
    follower: Follower,
    rotation: Rotation,
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
    /// The profile's curvature, 1/ρ: positive where convex, negative where
    /// concave, 0 where straight (an inflection).
    pub curvature: f64,
}

/// (φ, value): a value at a cam angle.
pub type AngleAt = (f64, f64);

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

/// A number of a follower, checked.
fn setting(what: &'static str, must: &'static str, value: f64, ok: bool) -> Result<(), CamError> {
    if ok && value.is_finite() {
        Ok(())
    } else {
        Err(CamError::BadSetting { what, must, value })
    }
}

/// A limit on the pressure angle, checked: in (0, 90°).
fn pressure_limit(limit: f64) -> Result<f64, CamError> {
    setting(
        "the pressure angle's limit",
        "between 0 and 90° (π/2 rad), exclusive",
        limit,
        limit > 0.0 && limit < PI / 2.0,
    )?;
    Ok(limit)
}

impl Cam {
    /// A cam of `program` driving `follower`, turning in `rotation`. A
    /// rocker needs an arm and a centre distance positive and finite and
    /// finite angles; a translating follower a finite axis angle and an
    /// offset smaller than its base distance, which must be positive.
    pub fn new(program: Program, follower: Follower, rotation: Rotation) -> Result<Cam, CamError> {
        match follower {
            Follower::Rocker {
                arm,
                centre_distance,
                initial_angle,
                pivot_angle,
            } => {
                setting("the rocker's arm", "positive and finite", arm, arm > 0.0)?;
                setting(
                    "the distance from the cam's centre to the rocker's pivot",
                    "positive and finite",
                    centre_distance,
                    centre_distance > 0.0,
                )?;
                setting("the rocker's initial angle", "finite", initial_angle, true)?;
                setting("the rocker's pivot angle", "finite", pivot_angle, true)?;
            }
            Follower::Translating {
                offset,
                base,
                axis_angle,
            } => {
                setting(
                    "the follower's base distance",
                    "positive and finite",
                    base,
                    base > 0.0,
                )?;
                setting(
                    "the follower's offset",
                    "finite and smaller than its base distance",
                    offset,
                    offset.abs() < base,
                )?;
                setting("the follower's axis angle", "finite", axis_angle, true)?;
            }
        }
        let cam = Cam {
            program,
            follower,
            rotation,
        };
        // Numbers so large that the pitch curve leaves the range of f64.
        cam.pitch(0.0)?;
        if !cam.base_radius().is_finite() {
            return Err(CamError::Degenerate {
                phi: 0.0,
                why: "the base radius leaves the range of f64",
            });
        }
        Ok(cam)
    }

    pub fn program(&self) -> &Program {
        &self.program
    }

    pub fn follower(&self) -> &Follower {
        &self.follower
    }

    pub fn rotation(&self) -> Rotation {
        self.rotation
    }

    /// The pitch curve at φ (any finite cam angle), by inversion: the
    /// follower turned by −φ about the cam's centre (for a counter-clockwise
    /// cam).
    pub fn pitch(&self, phi: f64) -> Result<Pitch, CamError> {
        let p = self.pitch_at(cam_angle(phi)?);
        let finite = [p.k, p.dk, p.ddk, p.motion]
            .iter()
            .all(|v| v.iter().all(|x| x.is_finite()));
        if !finite {
            return Err(CamError::Degenerate {
                phi,
                why: "the pitch curve leaves the range of f64",
            });
        }
        Ok(p)
    }

    /// [`Cam::pitch`] for a finite φ, unchecked.
    fn pitch_at(&self, phi: f64) -> Pitch {
        let (s, stroke) = self.program.motion(phi);
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
                // √(base² − offset²), without squaring a huge base.
                let s0 = base * (1.0 - (offset / base).powi(2)).max(0.0).sqrt();
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

    /// The pitch curve at φ with its unit tangent, or why there is none.
    fn tangent(&self, phi: f64) -> Result<(Pitch, Vector2<f64>), CamError> {
        let p = self.pitch(phi)?;
        let speed = p.dk.x.hypot(p.dk.y);
        if !(speed > 0.0 && speed.is_finite()) {
            return Err(CamError::Degenerate {
                phi,
                why: "the pitch curve stops there (K′ = 0): it has no normal",
            });
        }
        Ok((p, p.dk / speed))
    }

    /// The pressure angle at φ: between the common normal at the contact
    /// (the pitch curve's normal) and the direction the follower moves the
    /// roller centre, signed as the course project (positive on the rise
    /// of its rocker), in radians.
    pub fn pressure_angle(&self, phi: f64) -> Result<f64, CamError> {
        let (p, tangent) = self.tangent(phi)?;
        // The normal to the pitch curve, towards the cam's centre side.
        let mut normal = perp(tangent);
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
        Ok(self.rotation.sign() * folded)
    }

    /// The base radius r0 = |OK| at φ = 0 (the roller centre's distance at
    /// the start of the rise).
    pub fn base_radius(&self) -> f64 {
        let k = self.pitch_at(0.0).k;
        k.x.hypot(k.y)
    }

    /// The worst excess of |θ| over `limit` (rad, in (0, π/2)) in a turn
    /// (negative when the pressure angle stays within it everywhere).
    pub fn pressure_excess(&self, limit: f64) -> Result<f64, CamError> {
        let limit = pressure_limit(limit)?;
        let ((_, hi), (_, lo)) = self.pressure_extremes()?;
        Ok((hi - limit).max(-lo - limit))
    }

    /// dθ/dφ, the pressure angle's derivative at φ, exact (from K′ and K″):
    /// θ is σ times the angle of the pitch curve's normal less that of the
    /// follower's direction of motion, up to constants, so
    /// θ′ = σ·((K′ × K″)/|K′|² − the direction's turning rate), the rate
    /// being β′ = −σ + s′/l for a rocker's arm and −σ for a translating
    /// follower's axis.
    fn pressure_slope(&self, phi: f64) -> Result<f64, CamError> {
        let (p, tangent) = self.tangent(phi)?;
        let sigma = self.rotation.sign();
        let speed = p.dk.x.hypot(p.dk.y);
        let normal_rate = cross(tangent, p.ddk) / speed;
        let motion_rate = match self.follower {
            Follower::Rocker { arm, .. } => -sigma + p.s[1] / arm,
            Follower::Translating { .. } => -sigma,
        };
        Ok(sigma * (normal_rate - motion_rate))
    }

    /// The extremes of the pressure angle over a turn: ((φ, θ) at the
    /// maximum, (φ, θ) at the minimum). Each piece of the program between
    /// its breakpoints (where a segment starts or a law's acceleration
    /// jumps) is scanned at 49 cam angles; the best of them is refined to
    /// the root of the exact derivative dθ/dφ beside it, and the pieces'
    /// ends are candidates too. An extreme inside a piece is placed to
    /// 1e-14 rad (measured: 1.3e-15 rad at worst on four cams against a
    /// 50-digit reference), an extreme at a breakpoint is the breakpoint,
    /// and θ is right to rounding (1e-15 rad). Where θ is constant over a
    /// range (a dwell), φ is one of its cam angles.
    pub fn pressure_extremes(&self) -> Result<(AngleAt, AngleAt), CamError> {
        let mut breaks = self.program.breakpoints();
        breaks.push(TAU);
        let mut best_max = (0.0, f64::NEG_INFINITY);
        let mut best_min = (0.0, f64::INFINITY);
        for w in breaks.windows(2) {
            let (a, b) = (w[0], w[1]);
            if b - a <= 0.0 {
                continue;
            }
            let xs = numerics::samples(a, b, 1e-10, 48);
            let ys: Vec<f64> = xs
                .iter()
                .map(|&x| self.pressure_angle(x))
                .collect::<Result<_, _>>()?;
            for (sign, best) in [(1.0, &mut best_max), (-1.0, &mut best_min)] {
                let signed: Vec<f64> = ys.iter().map(|y| sign * y).collect();
                let k = numerics::argmax(&signed);
                let (x, value) = self.extreme_near(sign, &xs, k)?;
                // The segment's ends too (an extreme at a law's joint).
                for (x, value) in [
                    (x, value),
                    (a, self.pressure_angle(a)?),
                    (b, self.pressure_angle(b)?),
                ] {
                    if sign * value > sign * best.1 {
                        *best = (x, value);
                    }
                }
            }
        }
        Ok((best_max, best_min))
    }

    /// The extreme of θ (a maximum of sign·θ) near the sample `xs[k]`, the
    /// best of a scan: the root of sign·θ′ between `xs[k]` and the
    /// neighbour it rises towards, found to the precision of f64; where θ′
    /// does not change sign there (θ flat to rounding, or the scan's best at
    /// a piece's end), Brent's search on the value between the neighbours.
    fn extreme_near(&self, sign: f64, xs: &[f64], k: usize) -> Result<AngleAt, CamError> {
        let mut slope = |x: f64| self.pressure_slope(x).map(|d| sign * d);
        let (lo, hi) = (xs[k.saturating_sub(1)], xs[(k + 1).min(xs.len() - 1)]);
        let at = slope(xs[k])?;
        let bracket = if at > 0.0 && hi > xs[k] && slope(hi)? < 0.0 {
            Some((xs[k], hi))
        } else if at < 0.0 && lo < xs[k] && slope(lo)? > 0.0 {
            Some((lo, xs[k]))
        } else {
            None
        };
        match bracket {
            Some((from, to)) => {
                let x = numerics::root(&mut slope, from, to)?;
                Ok((x, self.pressure_angle(x)?))
            }
            None => {
                let mut f = |x: f64| self.pressure_angle(x).map(|theta| -sign * theta);
                let (x, fx) = numerics::refine(&mut f, xs, k, 1e-11)?;
                Ok((x, -sign * fx))
            }
        }
    }

    /// The pitch curve's curvature at φ, 1/ρ: positive where it bends
    /// towards the cam's centre (convex), negative where concave, 0 at an
    /// inflection.
    pub fn pitch_curvature(&self, phi: f64) -> Result<f64, CamError> {
        let (p, tangent) = self.tangent(phi)?;
        let mut outward = perp(tangent);
        if outward.dot(&p.k) < 0.0 {
            outward = -outward;
        }
        // κ = (K′ × K″)/|K′|³, with K″ across the unit tangent.
        let speed = p.dk.x.hypot(p.dk.y);
        let kappa = cross(tangent, p.ddk) / (speed * speed) * perp(tangent).dot(&(-outward));
        if !kappa.is_finite() {
            return Err(CamError::Degenerate {
                phi,
                why: "the pitch curve's curvature leaves the range of f64",
            });
        }
        Ok(kappa)
    }

    /// The largest roller that does not undercut: the smallest convex
    /// radius of the pitch curve, 1/κ at its largest curvature, and the cam
    /// angle where it is.
    pub fn largest_roller(&self) -> Result<(f64, f64), CamError> {
        let mut breaks = self.program.breakpoints();
        breaks.push(TAU);
        // The largest curvature (the smallest convex radius).
        let mut best = (0.0, 0.0);
        for w in breaks.windows(2) {
            let (a, b) = (w[0], w[1]);
            if b - a <= 0.0 {
                continue;
            }
            let xs = numerics::samples(a, b, 1e-10, 48);
            let ys: Vec<f64> = xs
                .iter()
                .map(|&x| self.pitch_curvature(x))
                .collect::<Result<_, _>>()?;
            let k = numerics::argmax(&ys);
            let mut f = |x: f64| self.pitch_curvature(x).map(|kappa| -kappa);
            let (x, minus_kappa) = numerics::refine(&mut f, &xs, k, 1e-11)?;
            for (x, kappa) in [(x, -minus_kappa), (xs[k], ys[k])] {
                if kappa > best.1 {
                    best = (x, kappa);
                }
            }
        }
        let (phi, kappa) = best;
        let convex = kappa > 0.0; // false for NaN too
        if !convex {
            return Err(CamError::Degenerate {
                phi,
                why: "the pitch curve is nowhere convex",
            });
        }
        Ok((phi, 1.0 / kappa))
    }

    /// The profile for a roller of radius `roller` at `points` cam angles
    /// (8 to 10⁶) over a turn: the inner envelope of the roller's circles,
    /// K − r·n (n the pitch curve's unit normal away from the cam's
    /// centre), with its curvature κ/(1 − κr). An undercut (1/κ < r where
    /// the pitch curve is convex) is an error naming the cam angles.
    pub fn profile(&self, roller: f64, points: usize) -> Result<Vec<ProfilePoint>, CamError> {
        if !(roller.is_finite() && roller >= 0.0) {
            return Err(CamError::BadSetting {
                what: "the roller radius",
                must: "finite and ≥ 0",
                value: roller,
            });
        }
        if !(8..=1_000_000).contains(&points) {
            return Err(CamError::BadSetting {
                what: "the number of profile points",
                must: "from 8 to 10⁶",
                value: points as f64,
            });
        }
        let n = points;
        let mut out = Vec::with_capacity(n + 1);
        let mut bad: Vec<f64> = Vec::new();
        for i in 0..=n {
            let phi = TAU * i as f64 / n as f64;
            let (p, tangent) = self.tangent(phi)?;
            let mut normal = perp(tangent);
            if normal.dot(&p.k) < 0.0 {
                normal = -normal;
            }
            let kappa = self.pitch_curvature(phi)?;
            if kappa > 0.0 && kappa * roller >= 1.0 {
                bad.push(phi.to_degrees());
            }
            out.push(ProfilePoint {
                phi,
                pitch: p.k,
                profile: p.k - normal * roller,
                curvature: kappa / (1.0 - kappa * roller),
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
