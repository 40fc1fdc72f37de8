//! The loads on a machine: forces at points, moments on coordinates, and
//! the usual kinds ready-made (process forces, friction, gravity); and what
//! they apply at a pose.

use super::{MachineError, Pose, Table};
use nalgebra::Vector2;
use std::sync::Arc;

type ForceFn = Arc<dyn Fn(&Pose) -> Vector2<f64> + Send + Sync>;
type MomentFn = Arc<dyn Fn(&Pose) -> f64 + Send + Sync>;
type KinksFn = Arc<dyn Fn(&Pose) -> Vec<f64> + Send + Sync>;

/// What a load is.
#[derive(Clone)]
pub(crate) enum LoadKind {
    Force {
        point: String,
        force: ForceFn,
    },
    Moment {
        coordinate: String,
        moment: MomentFn,
    },
    Gravity {
        g: Vector2<f64>,
    },
    Process {
        point: String,
        direction: Vector2<f64>,
        table: Table,
    },
    Friction {
        point: String,
        direction: Vector2<f64>,
        magnitude: f64,
    },
}

/// A load on the machine (see the constructors).
#[derive(Clone)]
pub struct Load {
    pub name: String,
    pub(crate) kind: LoadKind,
    pub(crate) kinks: Option<KinksFn>,
}

impl std::fmt::Debug for Load {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let kind = match &self.kind {
            LoadKind::Force { point, .. } => format!("force at {point}"),
            LoadKind::Moment { coordinate, .. } => format!("moment on {coordinate}"),
            LoadKind::Gravity { g } => format!("gravity {g:?}"),
            LoadKind::Process {
                point, direction, ..
            } => format!("process force at {point} along {direction:?}"),
            LoadKind::Friction {
                point,
                direction,
                magnitude,
            } => format!("friction {magnitude} at {point} along {direction:?}"),
        };
        write!(f, "Load {{ {}: {kind} }}", self.name)
    }
}

impl Load {
    /// A force at `point`, any function of the pose. Where it jumps or
    /// kinks, say so with [`Load::kinks`] so that the work integral splits
    /// there.
    pub fn force(
        name: &str,
        point: &str,
        force: impl Fn(&Pose) -> Vector2<f64> + Send + Sync + 'static,
    ) -> Load {
        Load {
            name: name.into(),
            kind: LoadKind::Force {
                point: point.into(),
                force: Arc::new(force),
            },
            kinks: None,
        }
    }

    /// A moment on the body whose angle is `coordinate` (positive in the
    /// coordinate's sense).
    pub fn moment(
        name: &str,
        coordinate: &str,
        moment: impl Fn(&Pose) -> f64 + Send + Sync + 'static,
    ) -> Load {
        Load {
            name: name.into(),
            kind: LoadKind::Moment {
                coordinate: coordinate.into(),
                moment: Arc::new(moment),
            },
            kinks: None,
        }
    }

    /// The weights m·g of every body, at their centres of mass.
    pub fn gravity(name: &str, g: Vector2<f64>) -> Load {
        Load {
            name: name.into(),
            kind: LoadKind::Gravity { g },
            kinks: None,
        }
    }

    /// A process force — cutting, pressing, pumping — against the motion of
    /// `point` along `direction` (any finite nonzero vector: its unit vector
    /// is taken), while the point moves that way as φ grows (the working
    /// stroke), of the magnitude `table` gives for the point's displacement
    /// along `direction` since φ = 0.
    pub fn process(name: &str, point: &str, direction: Vector2<f64>, table: Table) -> Load {
        Load {
            name: name.into(),
            kind: LoadKind::Process {
                point: point.into(),
                direction,
                table,
            },
            kinks: None,
        }
    }

    /// Coulomb friction of constant magnitude against the motion of `point`
    /// along `direction` (a guide; any finite nonzero vector), zero at rest.
    pub fn friction(name: &str, point: &str, direction: Vector2<f64>, magnitude: f64) -> Load {
        Load {
            name: name.into(),
            kind: LoadKind::Friction {
                point: point.into(),
                direction,
                magnitude,
            },
            kinks: None,
        }
    }

    /// Functions of the pose whose sign changes mark where this load jumps
    /// or kinks (for [`Load::force`] and [`Load::moment`]; the other kinds
    /// know theirs).
    pub fn kinks(mut self, kinks: impl Fn(&Pose) -> Vec<f64> + Send + Sync + 'static) -> Load {
        self.kinks = Some(Arc::new(kinks));
        self
    }
}

/// A load or a weight applied at a pose: a force at a point or a moment on
/// a coordinate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Applied {
    Force { point: usize, force: Vector2<f64> },
    Moment { coordinate: usize, moment: f64 },
}

/// The unit vector of a process or friction load's direction, checked:
/// finite and nonzero.
pub(crate) fn unit_direction(direction: Vector2<f64>) -> Result<Vector2<f64>, MachineError> {
    let length = direction.x.hypot(direction.y);
    if length > 0.0 && length.is_finite() {
        Ok(direction / length)
    } else {
        Err(MachineError::BadSetting {
            what: "the direction of a process or friction load",
            must: "finite and nonzero",
            value: length,
        })
    }
}

pub(crate) struct ResolvedLoad {
    pub(crate) load: Load,
    /// The point or coordinate index.
    pub(crate) target: usize,
    /// The point's position at φ = 0 (process loads).
    pub(crate) origin: Vector2<f64>,
}
