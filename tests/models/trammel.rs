//! An elliptic trammel: a double slider, driven by one of its sliders.

/// An elliptic trammel: the bar AB (l, its angle φ from A to B) with the
/// slider A on the x axis (at x_a, the driver) and the slider B on the y
/// axis (at y_b); the point P on the bar, p from A, traces the ellipse
/// x²/(l − p)² + y²/p² = 1. Dead centres where the bar lies along the x
/// axis (x_a = ±l). The compiled twin of `mechanisms/trammel.toml`.
#[linkage::linkage(
    u = [phi, y_b],
    v = [x_a],
    points = [
        A = (x_a, 0.0),
        B = (0.0, y_b),
        P = (x_a + p * phi.cos(), p * phi.sin()),
    ],
    closure = [
        x_a + l * phi.cos(),
        l * phi.sin() - y_b,
    ],
)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Trammel {
    pub l: f64,
    pub p: f64,
}

/// The bar 0.25 m, P 0.1 m from A (m).
pub const TRAMMEL: Trammel = Trammel { l: 0.25, p: 0.1 };
