//! The shaping machine of the Mathcad course project: a
//! quick-return slotted-lever mechanism, its synthesis from the time ratio
//! K_V, the stroke H and the distance l_OC between the pivots, and its masses
//! and loads.
//!
//! Frame: y up, the crank pivot O at the origin, the rocker pivot C at
//! (0, −l_OC). The crank OA turns clockwise: its angle is φ1 = φ0 − φ, φ the
//! generalized coordinate, φ0 = π + β/2, so that φ = 0 is the left dead
//! position (crank ⟂ rocker, ram at its leftmost). Block 2, pinned to the
//! crank at A, slides along the rocker CD (3); block 4, pinned to the rocker
//! at D, slides in a vertical slot of the ram (5), which translates
//! horizontally at the height y_F.
//!
//! Shared by `examples/shaper` and `tests/machine/shaper/`.

#![allow(dead_code)]

use linkage::ground::Ground;
use linkage::machine::kinetostatics::{Guide, Kinetostatics, KinetostaticsError};
use linkage::machine::{Body, Load, Machine, MachineError, Table};
use linkage::prelude::*;

/// The mechanism: u = (φ3, s, x_D) — the rocker's angle, the distance C→A
/// along it, the ram's x — and the driver φ.
#[linkage::linkage(
    u = [phi3, s, x_d],
    v = [phi],
    points = [
        A = (l_oa * (phi0 - phi).cos(), l_oa * (phi0 - phi).sin()),
        D = (l_cd * phi3.cos(), y_c + l_cd * phi3.sin()),
        S3 = (lambda_s3 * D.x, y_c + lambda_s3 * (D.y - y_c)),
        F = (x_d, y_f),
        S5 = (x_d + l_s5, y_f),
        K = (x_d + l_s5, y_f - l_p),
    ],
    closure = [
        l_oa * (phi0 - phi).cos() - s * phi3.cos(),
        l_oa * (phi0 - phi).sin() - y_c - s * phi3.sin(),
        x_d - l_cd * phi3.cos(),
    ],
)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shaper {
    /// Crank OA.
    pub l_oa: f64,
    /// Rocker CD.
    pub l_cd: f64,
    /// The rocker pivot's y (−l_OC).
    pub y_c: f64,
    /// The ram's guide height.
    pub y_f: f64,
    /// The crank's angle at φ = 0.
    pub phi0: f64,
    /// S3 = C + λ_S3·(D − C), the rocker's centre of mass.
    pub lambda_s3: f64,
    /// The ram's centre of mass S5 is l_S5 ahead of the slot F.
    pub l_s5: f64,
    /// The cutting force acts l_p below the guide, at K.
    pub l_p: f64,
}

/// The course project's data (SI units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Data {
    /// Crank speed, rev/s.
    pub n1: f64,
    /// Motor speed, rev/s.
    pub n_motor: f64,
    /// Time ratio of the strokes (working / return).
    pub k_v: f64,
    /// The stroke H of the ram, m. The course project never defines it; H = 0.5 m
    /// reproduces its l_CD, F_Cx(f) and cam angles (tests/data/README.md).
    pub stroke: f64,
    pub l_oc: f64,
    pub m3: f64,
    pub m5: f64,
    /// The rocker's moment of inertia about S3, kg·m².
    pub i3s: f64,
    pub lambda_s3: f64,
    pub l_s5: f64,
    pub l_p: f64,
    /// The coefficient of speed fluctuation.
    pub delta: f64,
    /// mD² of the motor's rotor and of the gears, kg·m².
    pub md2_motor: f64,
    pub md2_gears: f64,
    /// Friction on the ram's guide, N.
    pub friction: f64,
    /// The cutting-force diagram: the ram's displacement as a fraction of
    /// H, and the force, N.
    pub cutting: [(f64, f64); 7],
    pub g: f64,
}

/// The course project's numbers.
pub const COURSE_PROJECT: Data = Data {
    n1: 73.0 / 60.0,
    n_motor: 23.54,
    k_v: 1.6,
    stroke: 0.5,
    l_oc: 0.36,
    m3: 20.0,
    m5: 65.0,
    i3s: 1.1,
    lambda_s3: 0.5,
    l_s5: 0.164,
    l_p: 0.095,
    delta: 0.05,
    md2_motor: 0.35,
    md2_gears: 0.65,
    friction: 170.0,
    cutting: [
        (0.0, 0.0),
        (0.05, 0.0),
        (0.2, 1100.0),
        (0.75, 1100.0),
        (0.85, 2000.0),
        (0.95, 0.0),
        (1.0, 0.0),
    ],
    g: 9.81,
};

/// The synthesis of the slotted-lever mechanism (the course project's section 1).
///
/// ```text
/// β    = π (K_V − 1)/(K_V + 1)        the rocker's swing (= the crank angle of the return stroke − π)
/// l_OA = l_OC sin(β/2)                 the crank is ⟂ to the rocker at both dead positions
/// l_CD = H / (2 sin(β/2))              D's chord between the dead positions is the stroke
/// y_F  = y_C + l_CD − ½ l_CD (1 − cos(β/2))   the guide half-way down the sagitta of D's arc
/// φ0   = π + β/2                       the crank's angle at the left dead position
/// ```
///
/// K_V must exceed 1 (the working stroke slower than the return: K_V ≤ 1
/// would give a swing β ≤ 0, a mirrored or collapsed machine), and the
/// stroke H and the distance l_OC must be positive.
pub fn synthesize(data: &Data) -> Result<Shaper, MachineError> {
    let bad = |what, must, value| Err(MachineError::BadSetting { what, must, value });
    if !(data.k_v > 1.0 && data.k_v.is_finite()) {
        return bad(
            "the time ratio K_V",
            "above 1 (the working stroke slower than the return) and finite",
            data.k_v,
        );
    }
    for (what, value) in [("the stroke H", data.stroke), ("l_OC", data.l_oc)] {
        if !(value > 0.0 && value.is_finite()) {
            return bad(what, "positive and finite", value);
        }
    }
    let beta = std::f64::consts::PI * (data.k_v - 1.0) / (data.k_v + 1.0);
    let half = 0.5 * beta;
    let l_cd = data.stroke / (2.0 * half.sin());
    let y_c = -data.l_oc;
    Ok(Shaper {
        l_oa: data.l_oc * half.sin(),
        l_cd,
        y_c,
        y_f: y_c + l_cd - 0.5 * l_cd * (1.0 - half.cos()),
        phi0: std::f64::consts::PI + half,
        lambda_s3: data.lambda_s3,
        l_s5: data.l_s5,
        l_p: data.l_p,
    })
}

impl Shaper {
    /// β, the rocker's swing.
    pub fn beta(&self) -> f64 {
        2.0 * (self.phi0 - std::f64::consts::PI)
    }

    /// The course project's analysed position f: the crank at φ1 = 60°.
    pub fn analysed_position(&self) -> f64 {
        self.phi0 - 60f64.to_radians()
    }

    /// A rough guess of the pose at φ = 0 (the rocker upright, A near C's
    /// vertical): Newton takes it from there.
    pub fn guess(&self) -> SVector<f64, 3> {
        vector![std::f64::consts::FRAC_PI_2, -self.y_c, 0.0]
    }

    /// The course project's closed form, φ3 = π/2 − atan(x_A/(y_A − y_C)), for the
    /// tests' cross-check.
    pub fn closed_form_phi3(&self, phi: f64) -> f64 {
        let (x_a, y_a) = (
            self.l_oa * (self.phi0 - phi).cos(),
            self.l_oa * (self.phi0 - phi).sin(),
        );
        std::f64::consts::FRAC_PI_2 - (x_a / (y_a - self.y_c)).atan()
    }
}

/// The machine: the rocker (mass and inertia) and the ram (mass), the
/// massless crank and blocks; the cutting force on the working stroke,
/// Coulomb friction on the ram's guide, and gravity.
pub fn machine(shaper: &Shaper, data: &Data) -> Result<Machine<Shaper, 3>, MachineError> {
    let table = Table::new(
        data.cutting
            .iter()
            .map(|&(s, f)| (s * data.stroke, f))
            .collect(),
    )?;
    Machine::new(*shaper, shaper.guess())
        .body(
            Body::new("rocker 3")
                .mass(data.m3)
                .at("S3")
                .inertia(data.i3s)
                .angle("phi3"),
        )
        .body(Body::new("ram 5").mass(data.m5).at("S5"))
        // Massless, but in the force analysis: the crank turns clockwise.
        .body(Body::new("crank 1").angle_as("phi", -1.0))
        .body(Body::new("block 2"))
        .body(Body::new("block 4"))
        // The cutting force: the diagram over the ram's displacement from
        // its position at φ = 0, against the motion, on the working stroke.
        .load(Load::process("cutting", "K", vector![1.0, 0.0], table))
        .load(Load::friction(
            "friction",
            "F",
            vector![1.0, 0.0],
            data.friction,
        ))
        .load(Load::gravity("gravity", vector![0.0, -data.g]))
        .build()
}

/// The frame's fixed points, written once: the crank's pivot O and the
/// rocker's pivot C. The picture and the force analysis both take them.
pub fn ground(shaper: &Shaper) -> Ground {
    Ground::new()
        .point("O", [0.0, 0.0])
        .point("C", [0.0, shaper.y_c])
}

/// The course project's force analysis: bodies 1–5 (crank, block, rocker, block,
/// ram), the joint table 10, 12, 30, 34 (revolute), 23, 45, 50 (prismatic)
/// in the course project's order, the loads on the ram, the flywheel's J_PRI on the
/// crank, and the balancing moment on the crank.
pub fn kinetostatics<'m>(
    machine: &'m Machine<Shaper, 3>,
    flywheel: f64,
) -> Result<Kinetostatics<'m, Shaper, 3>, KinetostaticsError> {
    let shaper = machine.model();
    Kinetostatics::new(machine)
        .with_ground(&ground(shaper))
        .body("crank 1")
        .body("block 2")
        .body("rocker 3")
        .body("block 4")
        .body("ram 5")
        .revolute("10", "crank 1", "ground", "O")
        .revolute("12", "crank 1", "block 2", "A")
        .revolute("30", "rocker 3", "ground", "C")
        .revolute("34", "rocker 3", "block 4", "D")
        // Block 2 slides along the rocker; block 4 in the ram's vertical
        // slot; the ram on its horizontal guide (the reaction's line
        // through F = (x_D, y_F)).
        .prismatic(
            "23",
            "block 2",
            "rocker 3",
            "A",
            Guide::Angle("phi3".into()),
        )
        .prismatic(
            "45",
            "block 4",
            "ram 5",
            "D",
            Guide::Fixed(std::f64::consts::FRAC_PI_2),
        )
        .prismatic("50", "ram 5", "ground", "F", Guide::Fixed(0.0))
        .load_on("cutting", "ram 5")
        .load_on("friction", "ram 5")
        .rotor("crank 1", flywheel, -1.0)
        .driver("crank 1", -1.0)
        .build()
}
