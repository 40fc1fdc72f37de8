//! Ready mechanisms: the four-bar of the Maple worksheet, with and without
//! its named points, a four-bar with its ground pivots and coupler point
//! free for path generation, and an offset slider-crank. The examples,
//! tests and benchmarks use these; a user can too, without writing the
//! attribute. (The closed-form
//! four-bar is [`crate::closed_form::FourBar`].)

/// The four-bar of the Maple worksheet: ground A–D of length l1, crank AB
/// (l2, angle θ2), coupler BC (l3, θ3), rocker CD (l4, θ4 the angle of
/// C→D); the points B and C, and the link midpoints G2, G3, G4 the
/// worksheet draws its arrows from.
#[crate::linkage(
    u = [theta3, theta4],
    v = [theta2],
    points = [
        B = (l2 * theta2.cos(), l2 * theta2.sin()),
        C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
        G2 = (0.5 * B.x, 0.5 * B.y),
        G3 = (0.5 * (B.x + C.x), 0.5 * (B.y + C.y)),
        G4 = (C.x + 0.5 * l4 * theta4.cos(), C.y + 0.5 * l4 * theta4.sin()),
    ],
    closure = [
        l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
        l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
    ],
)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FourBar {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
}

impl FourBar {
    /// The same four-bar in closed form (its assemblies solved exactly).
    pub fn closed_form(&self) -> crate::closed_form::FourBar {
        crate::closed_form::FourBar {
            l1: self.l1,
            l2: self.l2,
            l3: self.l3,
            l4: self.l4,
        }
    }

    /// Grashof's classification of its lengths.
    pub fn grashof(&self) -> crate::closed_form::Grashof {
        self.closed_form().grashof()
    }

    /// The worksheet's lengths: l = (80, 20, 50, 70) mm.
    pub const WORKSHEET: FourBar = FourBar {
        l1: 80.0,
        l2: 20.0,
        l3: 50.0,
        l4: 70.0,
    };
}

/// The same four-bar without named points: its closure equations alone,
/// the least work per pose (sweeps of many designs, benchmarks).
#[crate::linkage(
    u = [theta3, theta4],
    v = [theta2],
    closure = [
        l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
        l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
    ],
)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BareFourBar {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
}

impl BareFourBar {
    /// The same four-bar in closed form (its assemblies solved exactly).
    pub fn closed_form(&self) -> crate::closed_form::FourBar {
        crate::closed_form::FourBar {
            l1: self.l1,
            l2: self.l2,
            l3: self.l3,
            l4: self.l4,
        }
    }

    /// Grashof's classification of its lengths.
    pub fn grashof(&self) -> crate::closed_form::Grashof {
        self.closed_form().grashof()
    }

    /// The worksheet's lengths: l = (80, 20, 50, 70) mm.
    pub const WORKSHEET: BareFourBar = BareFourBar {
        l1: 80.0,
        l2: 20.0,
        l3: 50.0,
        l4: 70.0,
    };
}

/// A four-bar for path generation, every dimension free: ground pivots
/// A = (xa, ya) and D = (xd, yd) anywhere, crank AB (l2, θ2 its angle from
/// the x axis, the driver), coupler BC (l3, θ3), rocker CD (l4, θ4 the
/// angle of C→D), and the coupler point P at (px, py) in the coupler's
/// frame: px along B→C, py to its left. Nine parameters.
#[crate::linkage(
    u = [theta3, theta4],
    v = [theta2],
    points = [
        B = (xa + l2 * theta2.cos(), ya + l2 * theta2.sin()),
        C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
        P = (
            B.x + px * theta3.cos() - py * theta3.sin(),
            B.y + px * theta3.sin() + py * theta3.cos()
        ),
    ],
    closure = [
        xa + l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - xd,
        ya + l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin() - yd,
    ],
)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CouplerFourBar {
    pub xa: f64,
    pub ya: f64,
    pub xd: f64,
    pub yd: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
    pub px: f64,
    pub py: f64,
}

impl CouplerFourBar {
    /// The same four-bar in closed form: its ground link |AD|, the crank,
    /// coupler and rocker (the closed form's frame has A at the origin and
    /// D on the x axis).
    pub fn closed_form(&self) -> crate::closed_form::FourBar {
        crate::closed_form::FourBar {
            l1: (self.xd - self.xa).hypot(self.yd - self.ya),
            l2: self.l2,
            l3: self.l3,
            l4: self.l4,
        }
    }

    /// Grashof's classification of its lengths.
    pub fn grashof(&self) -> crate::closed_form::Grashof {
        self.closed_form().grashof()
    }

    /// The worksheet's four-bar (A at the origin, D = (80, 0) mm, l = 20,
    /// 50, 70 mm) tracing its coupler's midpoint G3: P = (25, 0) mm.
    pub const WORKSHEET: CouplerFourBar = CouplerFourBar {
        xa: 0.0,
        ya: 0.0,
        xd: 80.0,
        yd: 0.0,
        l2: 20.0,
        l3: 50.0,
        l4: 70.0,
        px: 25.0,
        py: 0.0,
    };
}

/// An offset slider-crank: crank AB (r, θ2 its angle from the x axis, the
/// driver), connecting rod BC (l, θ3), the slider C at (s, e) on a line
/// parallel to the x axis, e from the crank's pivot. Its crank turns
/// fully while l ≥ r + |e|; the slider's stroke is
/// √((l + r)² − e²) − √((l − r)² − e²).
#[crate::linkage(
    u = [theta3, s],
    v = [theta2],
    points = [
        B = (r * theta2.cos(), r * theta2.sin()),
    ],
    closure = [
        r * theta2.cos() + l * theta3.cos() - s,
        r * theta2.sin() + l * theta3.sin() - e,
    ],
)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OffsetSliderCrank {
    pub r: f64,
    pub l: f64,
    pub e: f64,
}
