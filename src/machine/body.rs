//! The bodies that carry mass: as described ([`Body`]) and as resolved
//! against the model's names ([`MassBody`]), with the one place the weight
//! m·g is computed.

use nalgebra::Vector2;

/// A body that carries mass.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    pub name: String,
    pub mass: f64,
    /// The moment of inertia about the centre of mass.
    pub inertia: f64,
    /// The point that is the centre of mass (none: the body does not
    /// translate, e.g. a rotor on a fixed axis).
    pub centre: Option<String>,
    /// The coordinate that is the body's angle (none: it does not turn).
    pub angle: Option<String>,
    /// The body's angle is `angle_factor` × the coordinate + a constant.
    pub angle_factor: f64,
}

impl Body {
    /// A massless, inertia-less body: add what it has.
    pub fn new(name: &str) -> Body {
        Body {
            name: name.into(),
            mass: 0.0,
            inertia: 0.0,
            centre: None,
            angle: None,
            angle_factor: 1.0,
        }
    }

    pub fn mass(mut self, mass: f64) -> Body {
        self.mass = mass;
        self
    }

    /// The moment of inertia about the centre of mass.
    pub fn inertia(mut self, inertia: f64) -> Body {
        self.inertia = inertia;
        self
    }

    /// The centre of mass is the model's point `point`.
    pub fn at(mut self, point: &str) -> Body {
        self.centre = Some(point.into());
        self
    }

    /// The body turns with the coordinate `coordinate` (its angle, up to a
    /// constant).
    pub fn angle(mut self, coordinate: &str) -> Body {
        self.angle = Some(coordinate.into());
        self
    }

    /// The body's angle is `factor` × `coordinate` + a constant: a crank
    /// turning clockwise as φ grows has factor −1 (angles positive
    /// counter-clockwise).
    pub fn angle_as(mut self, coordinate: &str, factor: f64) -> Body {
        self.angle = Some(coordinate.into());
        self.angle_factor = factor;
        self
    }
}

/// A body resolved against the model: its centre a point index, its angle
/// a coordinate index. The machine's dynamics and its kinetostatics both
/// read these.
pub(crate) struct MassBody {
    pub(crate) name: String,
    pub(crate) mass: f64,
    pub(crate) inertia: f64,
    pub(crate) centre: Option<usize>,
    pub(crate) angle: Option<usize>,
    pub(crate) angle_factor: f64,
}

impl MassBody {
    /// The body's weight m·g under the acceleration of gravity `g`.
    pub(crate) fn weight(&self, g: Vector2<f64>) -> Vector2<f64> {
        g * self.mass
    }
}
