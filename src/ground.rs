//! A machine's fixed geometry, described once: the named ground points
//! (pivots) that both its picture ([`Scene::with_ground`]) and its force
//! analysis ([`KinetostaticsBuilder::with_ground`]) take.
//!
//! [`Scene::with_ground`]: crate::draw::scene::Scene::with_ground
//! [`KinetostaticsBuilder::with_ground`]: crate::machine::kinetostatics::KinetostaticsBuilder::with_ground

use nalgebra::Vector2;

/// The ground: named fixed points, in the model's coordinates.
///
/// ```
/// use linkage::ground::Ground;
///
/// let ground = Ground::new().point("A", [0.0, 0.0]).point("D", [80.0, 0.0]);
/// assert_eq!(ground.get("D").map(|p| p.x), Some(80.0));
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Ground {
    points: Vec<(String, Vector2<f64>)>,
}

impl Ground {
    /// No points yet.
    pub fn new() -> Ground {
        Ground::default()
    }

    /// A fixed point named `name` at `at` (checked where it is used: a
    /// scene or a force analysis rejects a non-finite one).
    pub fn point(mut self, name: &str, at: [f64; 2]) -> Ground {
        self.points.push((name.into(), Vector2::new(at[0], at[1])));
        self
    }

    /// The points, in the order given.
    pub fn points(&self) -> impl Iterator<Item = (&str, Vector2<f64>)> {
        self.points.iter().map(|(n, p)| (n.as_str(), *p))
    }

    /// The point named `name`.
    pub fn get(&self, name: &str) -> Option<Vector2<f64>> {
        self.points.iter().find(|(n, _)| n == name).map(|(_, p)| *p)
    }
}
