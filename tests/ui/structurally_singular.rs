use linkage::prelude::*;

/// Two coordinates of u appear only in the first equation: no pairing of
/// one equation per coordinate exists.
#[linkage::linkage(
    u = [x, y, s],
    v = [t],
    closure = [
        x + y + s - t,
        s.sin() - a,
        s.cos() + a * t - b,
    ],
)]
pub struct Bad {
    pub a: f64,
    pub b: f64,
}

fn main() {}
