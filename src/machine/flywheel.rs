//! Reductions between shafts and the flywheel's rim, as in the course
//! project. Each checks its numbers: finite, and of the sign the formula
//! needs.

use super::MachineError;

fn check(
    what: &'static str,
    must: &'static str,
    value: f64,
    ok: bool,
) -> Result<f64, MachineError> {
    if ok && value.is_finite() {
        Ok(value)
    } else {
        Err(MachineError::BadSetting { what, must, value })
    }
}

/// J of a rotor from its mD² (kg·m², ≥ 0): J = mD²/4 (D its diameter).
pub fn from_md2(md2: f64) -> Result<f64, MachineError> {
    Ok(check("mD²", "finite and ≥ 0", md2, md2 >= 0.0)? / 4.0)
}

/// The flywheel on the motor shaft for a constant reduced inertia
/// `required` at the crank, a transmission ratio `ratio` (motor speed /
/// crank speed, nonzero), the motor's rotor `motor` (at its shaft) and
/// the gears `gears` (already reduced to the crank), inertias ≥ 0:
/// J_fw = (J_required − J_motor·u² − J_gears)/u². Negative when the
/// rotors already exceed what is required.
pub fn on_motor_shaft(
    required: f64,
    ratio: f64,
    motor: f64,
    gears: f64,
) -> Result<f64, MachineError> {
    let must = "finite and ≥ 0";
    check("the required inertia", must, required, required >= 0.0)?;
    check("the motor rotor's inertia", must, motor, motor >= 0.0)?;
    check("the gears' inertia", must, gears, gears >= 0.0)?;
    check(
        "the transmission ratio",
        "finite and nonzero",
        ratio,
        ratio != 0.0,
    )?;
    let u2 = ratio * ratio;
    let flywheel = (required - motor * u2 - gears) / u2;
    check(
        "the flywheel's inertia",
        "finite (the numbers overflow)",
        flywheel,
        true,
    )
}

/// A rim flywheel by the course's rules of thumb: outer diameter D2 =
/// 0.437·J^(1/5) (m, J in kg·m²), inner D1 = 0.8·D2, width b = 0.2·D2,
/// mass m = 6123·(D2² − D1²)·b (6123 ≈ ρπ/4 for steel, ρ = 7.8 t/m³).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rim {
    pub outer: f64,
    pub inner: f64,
    pub width: f64,
    pub mass: f64,
}

impl Rim {
    /// The rim for a moment of inertia `inertia` (kg·m², finite and
    /// ≥ 0).
    pub fn course_rule(inertia: f64) -> Result<Rim, MachineError> {
        let inertia = check(
            "the flywheel's inertia",
            "finite and ≥ 0",
            inertia,
            inertia >= 0.0,
        )?;
        let outer = 0.437 * inertia.powf(0.2);
        let inner = 0.8 * outer;
        let width = 0.2 * outer;
        let rim = Rim {
            outer,
            inner,
            width,
            mass: 6123.0 * (outer * outer - inner * inner) * width,
        };
        check(
            "the flywheel's inertia",
            "small enough that the rim's mass and inertia stay finite",
            inertia,
            rim.mass.is_finite() && rim.inertia().is_finite(),
        )?;
        Ok(rim)
    }

    /// The rim's own moment of inertia, m(D2² + D1²)/8 (without hub
    /// and spokes, which the rule's coefficient allows for).
    pub fn inertia(&self) -> f64 {
        self.mass * (self.outer * self.outer + self.inner * self.inner) / 8.0
    }
}
