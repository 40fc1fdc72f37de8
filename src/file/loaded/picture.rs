//! A loaded file's picture where its mechanism now is: the drawing's
//! ground pivots at the mechanism's values. A topology's pivot J is its
//! parameters `x_J` and `y_J`, which may be set after the file was read (a
//! pivot dragged in the page): drawn, and turned about by its links, where
//! those values put it, not where the text wrote it.

use super::Loaded;
use crate::Kernels;
use crate::draw::scene::Scene;
use crate::mechanism::Fixed;

impl Loaded {
    /// The drawing's ground pivots, by name: a topology's at its
    /// parameters `x_J`, `y_J` in `model`, any other where the drawing
    /// puts it (none without `[drawing]`).
    pub fn pivots<const M: usize, const F: usize, const N: usize, const K: usize>(
        &self,
        model: &Fixed<M, F, N, K>,
    ) -> Vec<(String, [f64; 2])> {
        let Some(drawing) = &self.file().drawing else {
            return Vec::new();
        };
        let names = model.parameter_names();
        let value = |name: String, written: f64| match self.topology() {
            Some(_) => (names.iter().position(|n| *n == name))
                .and_then(|k| model.parameters().get(k).copied())
                .unwrap_or(written),
            None => written,
        };
        (drawing.ground.iter())
            .map(|(name, [x, y])| {
                let at = [
                    value(format!("x_{}", name.text), x.value),
                    value(format!("y_{}", name.text), y.value),
                ];
                (name.text.clone(), at)
            })
            .collect()
    }

    /// The file's picture of `model` ([`MechanismFile::scene_of`] of its
    /// points), its pivots where [`Loaded::pivots`] puts them.
    ///
    /// [`MechanismFile::scene_of`]: crate::file::MechanismFile::scene_of
    pub fn scene_of<const M: usize, const F: usize, const N: usize, const K: usize>(
        &self,
        model: &Fixed<M, F, N, K>,
    ) -> Scene {
        let scene = self.file().scene_of(model.point_names());
        (self.pivots(model).iter()).fold(scene, |scene, (name, at)| scene.ground(name, *at))
    }
}
