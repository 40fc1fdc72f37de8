//! The stability study: each method, approaching a singular pose of a
//! four-bar, against the 50-digit reference of `tests/data/`.
//!
//! Shared by `cargo run --release --example stability` (the charts),
//! `tests/sweep/stability_near_singular.rs` (the assertions) and
//! `tests/draw/diagrams.rs` (the charts' legends).
#![allow(dead_code)]

use linkage::mechanisms::BareFourBar;
use linkage::prelude::*;

/// A singular pose approached.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Case {
    /// The non-Grashof four-bar (l2 = 45) at its limit position.
    Limit,
    /// The change-point four-bar (l2 = 40) at its branch point θ2 = π.
    Branch,
}

impl Case {
    pub fn bar(self) -> BareFourBar {
        let l2 = match self {
            Case::Limit => 45.0,
            Case::Branch => 40.0,
        };
        BareFourBar {
            l1: 80.0,
            l2,
            l3: 50.0,
            l4: 70.0,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Case::Limit => "limit position (non-Grashof, l₂ = 45)",
            Case::Branch => "branch point (change-point, l₂ = 40)",
        }
    }

    fn data(self) -> &'static str {
        match self {
            Case::Limit => include_str!("../../tests/data/near_limit.csv"),
            Case::Branch => include_str!("../../tests/data/near_branch.csv"),
        }
    }

    /// The reference rows: δ, θ2, θ3, θ4, ω3, ω4, α3, α4 (analogs).
    pub fn reference(self) -> Vec<[f64; 8]> {
        self.data()
            .lines()
            .filter(|l| !l.starts_with('#') && !l.starts_with("delta"))
            .map(|l| {
                let v: Vec<f64> = l.split(',').map(|x| x.parse().expect("a number")).collect();
                [v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]]
            })
            .collect()
    }
}

/// A way of computing the pose and its analogs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// The library's API with its defaults: generated Jacobians.
    Generated,
    /// The same runtime with num-dual Jacobians.
    Dual,
    /// The same runtime with finite-difference Jacobians.
    FiniteDifference,
    /// The hand-written closed form in f64.
    ClosedForm,
    /// The generated code with the conditioning check switched off
    /// (`accuracy = ∞`): what the numbers are worth past the threshold.
    Unguarded,
}

impl Method {
    pub const ALL: [Method; 5] = [
        Method::Generated,
        Method::Dual,
        Method::FiniteDifference,
        Method::ClosedForm,
        Method::Unguarded,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Method::Generated => "generated (library defaults)",
            Method::Dual => "num-dual Jacobians",
            Method::FiniteDifference => "finite differences",
            Method::ClosedForm => "closed form",
            Method::Unguarded => "generated, no conditioning check",
        }
    }
}

/// One method at one distance from the singular pose.
#[derive(Clone, Debug)]
pub struct Row {
    pub delta: f64,
    pub method: Method,
    /// `None` for a typed error (its message in `error`).
    pub iterations: Option<usize>,
    pub error: Option<String>,
    /// Whether the error is [`Error::Singular`] (the conditioning check).
    pub singular: bool,
    /// Absolute error of θ3, θ4 (rad); errors of the analogs ω, α relative
    /// to their size (at least 1).
    pub position: f64,
    pub velocity: f64,
    pub acceleration: f64,
    /// 1/rcond of Ψ_u at the reference pose.
    pub condition: f64,
    /// |α by method A − α by method B| / |α| (generated methods only).
    pub methods_ab: f64,
}

/// |a − b| for angles: a Newton that lands on θ + 2πk found the same pose.
fn angle_error(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(std::f64::consts::TAU);
    d.min(std::f64::consts::TAU - d)
}

/// The error of a pair of analogs relative to their size, but at least 1:
/// the analogs of these four-bars are of order 1 over the cycle, and near a
/// branch point the accelerations pass through zero.
fn relative(a: [f64; 2], b: [f64; 2]) -> f64 {
    let diff = (a[0] - b[0]).abs().max((a[1] - b[1]).abs());
    diff / b[0].abs().max(b[1].abs()).max(1.0)
}

/// Runs every method at every distance of the reference.
pub fn run(case: Case) -> Vec<Row> {
    let bar = case.bar();
    let closed = bar.closed_form();
    let mut rows = Vec::new();
    for r in case.reference() {
        let [delta, theta2, t3, t4, w3, w4, a3, a4] = r;
        let v = vector![theta2];
        let condition = 1.0 / linkage::invert(&bar.psi_u(&vector![t3, t4], &v)).rcond;
        // Newton starts from the pose half a δ farther from the singularity:
        // what a continuation predictor would offer.
        let start = closed
            .position(theta2 - 0.5 * delta, 1.0)
            .expect("assembled farther away");
        let guess = vector![start[0], start[1]];
        for method in Method::ALL {
            let mut row = Row {
                delta,
                method,
                iterations: None,
                error: None,
                singular: false,
                position: f64::NAN,
                velocity: f64::NAN,
                acceleration: f64::NAN,
                condition,
                methods_ab: f64::NAN,
            };
            let result: Result<([f64; 6], usize), Error> = match method {
                Method::ClosedForm => match closed.state(theta2, 1.0, 0.0, 1.0) {
                    Some(s) => Ok((
                        [
                            s.angles[0],
                            s.angles[1],
                            s.velocities[0],
                            s.velocities[1],
                            s.accelerations[0],
                            s.accelerations[1],
                        ],
                        0,
                    )),
                    None => Err(Error::NonFiniteValue {
                        stage: Stage::Position,
                        quantity: "closed form",
                    }),
                },
                _ => {
                    let options = match method {
                        Method::Dual => Options {
                            jacobian: JacobianSource::Dual,
                            ..Options::default()
                        },
                        Method::FiniteDifference => Options {
                            jacobian: JacobianSource::FiniteDifference,
                            ..Options::default()
                        },
                        Method::Unguarded => Options {
                            accuracy: f64::INFINITY,
                            ..Options::default()
                        },
                        _ => Options::default(),
                    };
                    bar.analyze(&guess, &v, &vector![1.0], &vector![0.0], &options)
                        .map(|a| {
                            if matches!(method, Method::Generated | Method::Unguarded) {
                                let with = |m| Options {
                                    method: m,
                                    ..options
                                };
                                let alpha = |m| {
                                    bar.acceleration(
                                        &a.u,
                                        &v,
                                        &a.udot,
                                        &vector![1.0],
                                        &vector![0.0],
                                        &with(m),
                                    )
                                };
                                if let (Ok(x), Ok(y)) =
                                    (alpha(AccelerationMethod::A), alpha(AccelerationMethod::B))
                                {
                                    row.methods_ab = (x - y).amax() / y.amax();
                                }
                            }
                            (
                                [a.u[0], a.u[1], a.udot[0], a.udot[1], a.uddot[0], a.uddot[1]],
                                a.iterations,
                            )
                        })
                }
            };
            match result {
                Ok((x, iterations)) => {
                    row.iterations = Some(iterations);
                    row.position = angle_error(x[0], t3).max(angle_error(x[1], t4));
                    row.velocity = relative([x[2], x[3]], [w3, w4]);
                    row.acceleration = relative([x[4], x[5]], [a3, a4]);
                }
                Err(e) => {
                    row.singular = matches!(e, Error::Singular { .. });
                    row.error = Some(e.to_string());
                }
            }
            rows.push(row);
        }
    }
    rows
}

/// The boom of the tests, driven by its actuator length: its method-A and
/// method-B code differ (the mixed blocks are non-zero).
#[linkage::linkage(
    u = [theta, phi],
    v = [length],
    closure = [
        ax + length * phi.cos() - b * theta.cos(),
        ay + length * phi.sin() - b * theta.sin(),
    ],
)]
#[derive(Clone, Copy, Debug)]
pub struct Boom {
    pub ax: f64,
    pub ay: f64,
    pub b: f64,
}

pub const BOOM: Boom = Boom {
    ax: 0.4,
    ay: -0.3,
    b: 1.0,
};

/// Methods A and B near the boom's limit position (full extension).
#[derive(Clone, Debug)]
pub struct MethodsRow {
    pub delta: f64,
    /// 1/rcond of Ψ_u.
    pub condition: f64,
    /// Errors of the second analogs d²u/dL² against the reference, relative
    /// to their size: method A, method B, fused.
    pub error_a: f64,
    pub error_b: f64,
    pub error_fused: f64,
    /// |A − B| and |fused − B|, relative to the size of the analog.
    pub a_minus_b: f64,
    pub fused_minus_b: f64,
    /// The library's answer with its defaults: `None` if it returned a
    /// typed error.
    pub library: Option<f64>,
}

/// A and B near the boom's limit, against `tests/data/near_limit_boom.csv`.
pub fn methods_near_limit() -> Vec<MethodsRow> {
    let text = include_str!("../../tests/data/near_limit_boom.csv");
    let mut rows = Vec::new();
    for line in text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("delta"))
    {
        let x: Vec<f64> = line
            .split(',')
            .map(|x| x.parse().expect("a number"))
            .collect();
        let [delta, length, theta, phi, _, _, ddtheta, ddphi] =
            [x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]];
        let v = vector![length];
        let unguarded = Options {
            accuracy: f64::INFINITY,
            ..Options::default()
        };
        // Start Newton from the reference rounded to 8 digits.
        let guess = vector![(theta * 1e8).round() / 1e8, (phi * 1e8).round() / 1e8];
        let Ok(p) = BOOM.solve_position(&guess, &v, &unguarded) else {
            continue;
        };
        let condition = 1.0 / linkage::invert(&BOOM.psi_u(&p.u, &v)).rcond;
        let Ok(vel) = BOOM.velocity(&p.u, &v, &vector![1.0], &unguarded) else {
            continue;
        };
        let second = |method| {
            BOOM.acceleration(
                &p.u,
                &v,
                &vel.udot,
                &vector![1.0],
                &vector![0.0],
                &Options {
                    method,
                    ..unguarded
                },
            )
            .map(|a| [a[0], a[1]])
            .unwrap_or([f64::NAN; 2])
        };
        let (a, b, f) = (
            second(AccelerationMethod::A),
            second(AccelerationMethod::B),
            second(AccelerationMethod::Fused),
        );
        let reference = [ddtheta, ddphi];
        let size = ddtheta.abs().max(ddphi.abs()).max(1.0);
        let diff = |x: [f64; 2], y: [f64; 2]| (x[0] - y[0]).abs().max((x[1] - y[1]).abs()) / size;
        let library = BOOM
            .analyze(
                &guess,
                &v,
                &vector![1.0],
                &vector![0.0],
                &Options::default(),
            )
            .ok()
            .map(|l| diff([l.uddot[0], l.uddot[1]], reference));
        rows.push(MethodsRow {
            delta,
            condition,
            error_a: diff(a, reference),
            error_b: diff(b, reference),
            error_fused: diff(f, reference),
            a_minus_b: diff(a, b),
            fused_minus_b: diff(f, b),
            library,
        });
    }
    rows
}
