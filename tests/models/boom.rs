//! A boom raised by a hydraulic cylinder, driven by the actuator length.

/// A boom pivoted at the origin, raised by a hydraulic cylinder from the
/// ground pivot A = (ax, ay) to the boom point at distance b: driven by the
/// actuator length L, so Ψ_u depends on v and Ψ_v on u (the mixed blocks of
/// method B are non-zero).
#[linkage::linkage(
    u = [theta, phi],
    v = [length],
    points = [
        K = (b * theta.cos(), b * theta.sin()),
        T = (lb * theta.cos(), lb * theta.sin()),
    ],
    closure = [
        ax + length * phi.cos() - b * theta.cos(),
        ay + length * phi.sin() - b * theta.sin(),
    ],
)]
#[derive(Clone, Debug)]
pub struct Boom {
    pub ax: f64,
    pub ay: f64,
    pub b: f64,
    /// The boom's length, to its tip T.
    pub lb: f64,
}

/// The one the tests use.
pub const BOOM: Boom = Boom {
    ax: 0.4,
    ay: -0.3,
    b: 1.0,
    lb: 2.5,
};
