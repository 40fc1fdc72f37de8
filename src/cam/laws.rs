//! Motion laws: the normalized displacement S(x) of a rise over x ∈ [0, 1]
//! and its derivatives, S(0) = 0, S(1) = 1, S′ = S″ = 0 at both ends where
//! the law allows.

use std::f64::consts::PI;

/// A law of motion for a rise (a return runs it backwards).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Law {
    /// Piecewise-constant acceleration: +A over the first 1/(k+1) of the
    /// segment, −A/k over the rest, A = 2(k+1) (the course project's law;
    /// k = 1 is the symmetric parabolic law). Velocity continuous,
    /// acceleration jumping (soft impacts).
    ConstantAcceleration { k: f64 },
    /// Simple harmonic: S = (1 − cos πx)/2. Acceleration jumps at the ends.
    Harmonic,
    /// Cycloidal: S = x − sin(2πx)/2π. Acceleration continuous, zero at the
    /// ends.
    Cycloidal,
    /// The 3-4-5 polynomial: S = 10x³ − 15x⁴ + 6x⁵.
    Polynomial345,
    /// The modified trapezoid: constant acceleration over the second and
    /// fourth eighths, sinusoidal blends between; acceleration continuous,
    /// the smallest peak acceleration of the smooth laws.
    ModifiedTrapezoid,
}

/// S, S′, S″, S‴ at x ∈ [0, 1].
pub type Derivatives = [f64; 4];

impl Law {
    /// S and its first three derivatives at x (clamped to [0, 1]). Where
    /// the jerk is a Dirac impulse (an acceleration jump), it is 0 here.
    /// NaN for a NaN x, and for a law that is not [valid](Law::is_valid).
    pub fn at(&self, x: f64) -> Derivatives {
        if x.is_nan() || !self.is_valid() {
            return [f64::NAN; 4];
        }
        let x = x.clamp(0.0, 1.0);
        match *self {
            Law::ConstantAcceleration { k } => {
                let a = 2.0 * (k + 1.0);
                let x1 = 1.0 / (k + 1.0);
                if x < x1 {
                    [0.5 * a * x * x, a * x, a, 0.0]
                } else {
                    // Back from the end: S = 1 − (A/2k)(1 − x)².
                    let y = 1.0 - x;
                    [1.0 - 0.5 * a / k * y * y, a / k * y, -a / k, 0.0]
                }
            }
            Law::Harmonic => [
                0.5 * (1.0 - (PI * x).cos()),
                0.5 * PI * (PI * x).sin(),
                0.5 * PI * PI * (PI * x).cos(),
                -0.5 * PI.powi(3) * (PI * x).sin(),
            ],
            Law::Cycloidal => {
                let w = 2.0 * PI;
                [
                    x - (w * x).sin() / w,
                    1.0 - (w * x).cos(),
                    w * (w * x).sin(),
                    w * w * (w * x).cos(),
                ]
            }
            Law::Polynomial345 => [
                x * x * x * (10.0 - 15.0 * x + 6.0 * x * x),
                30.0 * x * x * (1.0 - x) * (1.0 - x),
                60.0 * x * (1.0 - 3.0 * x + 2.0 * x * x),
                60.0 - 360.0 * x + 360.0 * x * x,
            ],
            Law::ModifiedTrapezoid => modified_trapezoid(x),
        }
    }

    /// Whether the law's parameter is in its range: the asymmetry k of the
    /// constant-acceleration law positive, and neither so small nor so large
    /// that its accelerations 2(k + 1) and 2(k + 1)/k overflow.
    /// [`super::Program::new`] accepts only valid laws.
    pub fn is_valid(&self) -> bool {
        match *self {
            Law::ConstantAcceleration { k } => {
                k > 0.0 && (2.0 * (k + 1.0)).is_finite() && (2.0 * (k + 1.0) / k).is_finite()
            }
            _ => true,
        }
    }

    /// Where the acceleration jumps, as fractions of the segment (the ends
    /// excluded; none for a law that is not valid).
    pub fn breakpoints(&self) -> Vec<f64> {
        match *self {
            Law::ConstantAcceleration { k } if self.is_valid() => vec![1.0 / (k + 1.0)],
            Law::ModifiedTrapezoid => vec![0.125, 0.375, 0.625, 0.875],
            _ => Vec::new(),
        }
    }
}

/// The modified trapezoid, normalized: a = A sin 4πx on [0, ⅛], A on
/// [⅛, ⅜], A cos 4π(x − ⅜) on [⅜, ⅝], −A on [⅝, ⅞], −A cos 4π(x − ⅞) on
/// [⅞, 1], integrated in closed form piece by piece, A fixed by S(1) = 1.
fn modified_trapezoid(x: f64) -> Derivatives {
    // With A = 1: the values at the joints.
    let w = 4.0 * PI;
    let pieces = |a: f64, x: f64| -> Derivatives {
        let v1 = a / w;
        let s1 = a / w * (0.125 - 1.0 / w);
        let v2 = v1 + a / 4.0;
        let s2 = s1 + v1 / 4.0 + a / 32.0;
        let s3 = s2 + v2 / 4.0 + 2.0 * a / (w * w);
        let v3 = v2;
        let v4 = v3 - a / 4.0;
        let s4 = s3 + v3 / 4.0 - a / 32.0;
        if x <= 0.125 {
            [
                a / w * (x - (w * x).sin() / w),
                a / w * (1.0 - (w * x).cos()),
                a * (w * x).sin(),
                a * w * (w * x).cos(),
            ]
        } else if x <= 0.375 {
            let d = x - 0.125;
            [s1 + v1 * d + 0.5 * a * d * d, v1 + a * d, a, 0.0]
        } else if x <= 0.625 {
            let d = x - 0.375;
            [
                s2 + v2 * d + a / (w * w) * (1.0 - (w * d).cos()),
                v2 + a / w * (w * d).sin(),
                a * (w * d).cos(),
                -a * w * (w * d).sin(),
            ]
        } else if x <= 0.875 {
            let d = x - 0.625;
            [s3 + v3 * d - 0.5 * a * d * d, v3 - a * d, -a, 0.0]
        } else {
            let d = x - 0.875;
            [
                s4 + v4 * d + a / (w * w) * ((w * d).cos() - 1.0),
                v4 - a / w * (w * d).sin(),
                -a * (w * d).cos(),
                a * w * (w * d).sin(),
            ]
        }
    };
    let a = 1.0 / pieces(1.0, 1.0)[0];
    pieces(a, x)
}

#[cfg(test)]
mod tests {
    use super::*;

    const LAWS: [Law; 6] = [
        Law::ConstantAcceleration { k: 1.0 },
        Law::ConstantAcceleration { k: 2.0 },
        Law::Harmonic,
        Law::Cycloidal,
        Law::Polynomial345,
        Law::ModifiedTrapezoid,
    ];

    #[test]
    fn every_law_rises_from_rest_to_rest() {
        for law in LAWS {
            let [s0, v0, ..] = law.at(0.0);
            let [s1, v1, ..] = law.at(1.0);
            assert!(s0.abs() < 1e-15 && (s1 - 1.0).abs() < 1e-14, "{law:?}");
            assert!(v0.abs() < 1e-14 && v1.abs() < 1e-13, "{law:?}: {v0} {v1}");
        }
        // The smooth laws start and end at zero acceleration.
        for law in [Law::Cycloidal, Law::Polynomial345, Law::ModifiedTrapezoid] {
            assert!(
                law.at(0.0)[2].abs() < 1e-13 && law.at(1.0)[2].abs() < 1e-12,
                "{law:?}"
            );
        }
        // The modified trapezoid's peak acceleration, 4.888.
        let peak = (0..=1000)
            .map(|i| Law::ModifiedTrapezoid.at(i as f64 / 1000.0)[2])
            .fold(0.0, f64::max);
        assert!((peak - 4.888).abs() < 1e-3, "{peak}");
    }

    /// Each derivative against central differences of the one before, and
    /// each function against the integral of its derivative.
    #[test]
    fn derivatives_agree_with_numerical_differentiation_and_integration() {
        for law in LAWS {
            let breaks = law.breakpoints();
            let h = 1e-6;
            for i in 1..200 {
                let x = i as f64 / 200.0;
                if breaks.iter().any(|b| (x - b).abs() < 2.0 * h) {
                    continue;
                }
                let (p, m) = (law.at(x + h), law.at(x - h));
                let d = law.at(x);
                for k in 0..3 {
                    let numeric = (p[k] - m[k]) / (2.0 * h);
                    let scale = d[k + 1].abs().max(1.0);
                    assert!(
                        (numeric - d[k + 1]).abs() <= 1e-6 * scale,
                        "{law:?} x = {x}: derivative {k}: {numeric} vs {}",
                        d[k + 1]
                    );
                }
            }
            // S(1) − S(0) = ∫ S′ by Simpson's rule on 2000 panels.
            let n = 2000;
            let simpson: f64 = (0..=n)
                .map(|i| {
                    let w = if i == 0 || i == n {
                        1.0
                    } else if i % 2 == 1 {
                        4.0
                    } else {
                        2.0
                    };
                    w * law.at(i as f64 / n as f64)[1]
                })
                .sum::<f64>()
                / (3.0 * n as f64);
            assert!((simpson - 1.0).abs() < 1e-6, "{law:?}: {simpson}");
        }
    }
}
