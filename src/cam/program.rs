//! The follower's program: rises, dwells and returns with their motion
//! laws, over a turn of the cam.

use super::{CamError, Derivatives, Law};
use std::f64::consts::TAU;

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
/// rest of the turn a dwell at the start. Made by [`Program::new`], which
/// checks it.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    lift: f64,
    segments: Vec<Segment>,
}

/// Which part of the program a cam angle falls in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stroke {
    Rise,
    Dwell,
    Return,
}

/// A cam angle, checked: finite.
pub(super) fn cam_angle(phi: f64) -> Result<f64, CamError> {
    if phi.is_finite() {
        Ok(phi)
    } else {
        Err(CamError::BadSetting {
            what: "the cam angle",
            must: "finite",
            value: phi,
        })
    }
}

impl Program {
    /// The program of `segments`, each of a finite angle ≥ 0 and a valid
    /// law, taking at most a turn, for a `lift` > 0.
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
            if let Segment::Rise { law, .. } | Segment::Return { law, .. } = s {
                if let Law::ConstantAcceleration { k } = *law {
                    if !law.is_valid() {
                        return Err(CamError::BadSetting {
                            what: "the asymmetry k of a constant-acceleration law",
                            must: "positive, finite, and such that 2(k + 1)/k is finite",
                            value: k,
                        });
                    }
                }
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

    /// The follower's lift.
    pub fn lift(&self) -> f64 {
        self.lift
    }

    /// The segments, from φ = 0.
    pub fn segments(&self) -> &[Segment] {
        &self.segments
    }

    /// s(φ) and its derivatives s′, s″, s‴ with respect to φ (the cam
    /// angle, any finite one: the program repeats every turn), and the
    /// stroke.
    pub fn at(&self, phi: f64) -> Result<(Derivatives, Stroke), CamError> {
        let (s, stroke) = self.motion(cam_angle(phi)?);
        if !s.iter().all(|x| x.is_finite()) {
            return Err(CamError::Degenerate {
                phi,
                why: "the follower's derivatives leave the range of f64 (a segment too short for its lift)",
            });
        }
        Ok((s, stroke))
    }

    /// [`Program::at`] for a finite φ.
    pub(super) fn motion(&self, phi: f64) -> (Derivatives, Stroke) {
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
