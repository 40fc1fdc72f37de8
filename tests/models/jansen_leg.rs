//! Jansen's leg: one crank driving an eight-link, one-degree-of-freedom leg
//! whose foot walks on a nearly straight line.

/// Jansen's leg with the published "holy numbers": the crank axle O at the
/// origin, the frame pivot Z at (−a, −l); the crank m (its angle θ the
/// driver) carries the pin M; the links j and k join M to J, on the upper
/// triangle (sides b = ZJ, d = ZQ, e = JQ, turning about Z), and to K, on
/// the link c about Z; the link f joins Q to R, on the foot triangle
/// (sides g = KR, i = K–Foot, h = R–Foot). Three vector loops, each a dyad
/// closed at a joint (M–J, M–K, Q–R); each triangle's angle at its pivot by
/// the law of cosines. The compiled twin of `mechanisms/jansen_leg.toml`.
#[linkage::linkage(
    u = [phi_j, phi_b, phi_k, phi_c, phi_f, phi_g],
    v = [theta],
    points = [
        M = (m * theta.cos(), m * theta.sin()),
        J = (-a + b * phi_b.cos(), -l + b * phi_b.sin()),
        K = (-a + c * phi_c.cos(), -l + c * phi_c.sin()),
        Q = (
            -a + d * (phi_b + ((b * b + d * d - e * e) / (2.0 * b * d)).acos()).cos(),
            -l + d * (phi_b + ((b * b + d * d - e * e) / (2.0 * b * d)).acos()).sin()
        ),
        R = (K.x + g * phi_g.cos(), K.y + g * phi_g.sin()),
        Foot = (
            K.x + i * (phi_g + ((g * g + i * i - h * h) / (2.0 * g * i)).acos()).cos(),
            K.y + i * (phi_g + ((g * g + i * i - h * h) / (2.0 * g * i)).acos()).sin()
        ),
    ],
    closure = [
        M.x + j * phi_j.cos() - J.x,
        M.y + j * phi_j.sin() - J.y,
        M.x + k * phi_k.cos() - K.x,
        M.y + k * phi_k.sin() - K.y,
        Q.x + f * phi_f.cos() - R.x,
        Q.y + f * phi_f.sin() - R.y,
    ],
)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JansenLeg {
    pub a: f64,
    pub b: f64,
    pub c: f64,
    pub d: f64,
    pub e: f64,
    pub f: f64,
    pub g: f64,
    pub h: f64,
    pub i: f64,
    pub j: f64,
    pub k: f64,
    pub l: f64,
    pub m: f64,
}

/// The holy numbers (lengths in the units of the drawings, read as mm).
pub const JANSEN_LEG: JansenLeg = JansenLeg {
    a: 38.0,
    b: 41.5,
    c: 39.3,
    d: 40.1,
    e: 55.8,
    f: 39.4,
    g: 36.7,
    h: 65.7,
    i: 49.0,
    j: 50.0,
    k: 61.9,
    l: 7.8,
    m: 15.0,
};
