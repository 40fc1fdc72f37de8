//! A file's drawing as a [`Scene`].

use super::MechanismFile;
use super::drawing::{DrawingSpec, Guide};
use crate::draw::scene::Scene;

impl DrawingSpec {
    /// The scene this spec describes (its ground pivots, links, plates,
    /// sliders, arrows and traces; the scales if written), added to
    /// `scene`.
    pub fn scene(&self, scene: Scene) -> Scene {
        let mut scene = scene;
        for (name, [x, y]) in &self.ground {
            scene = scene.ground(&name.text, [x.value, y.value]);
        }
        for [a, b] in &self.links {
            scene = scene.link([a.text.as_str(), b.text.as_str()]);
        }
        for plate in &self.plates {
            scene = scene.plate(plate.iter().map(|n| n.text.as_str()));
        }
        for slider in &self.sliders {
            let point = slider.point.text.as_str();
            scene = match &slider.guide {
                Guide::Ground(angle) => scene.slider(point, angle.value),
                Guide::Along([a, b]) => scene.slider_on(point, [a.text.as_str(), b.text.as_str()]),
                Guide::Slot(angle) => scene.block(point, angle.value),
            };
        }
        scene = scene
            .velocities(self.velocities.iter().map(|n| n.text.as_str()))
            .accelerations(self.accelerations.iter().map(|n| n.text.as_str()))
            .trace(self.trace.iter().map(|n| n.text.as_str()));
        if let Some(scale) = &self.velocity_scale {
            scene = scene.velocity_scale(scale.value);
        }
        if let Some(scale) = &self.acceleration_scale {
            scene = scene.acceleration_scale(scale.value);
        }
        scene
    }
}

impl MechanismFile {
    /// The picture the file describes: its drawing (an empty scene if it
    /// has none), titled with its title, its legend in the file's length
    /// unit and seconds.
    ///
    /// ```
    /// use linkage::draw::scene::Frame;
    /// use linkage::file::MechanismFile;
    /// use linkage::mechanisms::FourBar;
    /// use linkage::prelude::*;
    ///
    /// let file = MechanismFile::parse(include_str!("../../mechanisms/four_bar.toml"))?;
    /// // Drawn at a pose of the file's compiled twin.
    /// let bar = FourBar::WORKSHEET;
    /// let theta2 = file.driver("theta2").unwrap();
    /// let pose = bar.analyze(
    ///     &vector![1.2, -0.9],
    ///     &vector![theta2.at.value],
    ///     &vector![theta2.rate.value],
    ///     &vector![theta2.acceleration.value],
    ///     &Options::default(),
    /// )?;
    /// let svg = file.scene().render(&Frame::from_analysis(&bar, &pose), &[])?;
    /// assert!(svg.contains("The four-bar of the Maple worksheet"));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn scene(&self) -> Scene {
        let mut scene = Scene::new().units(&self.length_unit, "s");
        if let Some(title) = &self.title {
            scene = scene.title(title);
        }
        match &self.drawing {
            Some(drawing) => drawing.scene(scene),
            None => scene,
        }
    }
}

impl MechanismFile {
    /// [`MechanismFile::scene`], and for a file without `[drawing]` the
    /// paths of `points` (the mechanism's named points) over the drive
    /// range: a file says how its bodies look, but every mechanism has its
    /// points' paths to show.
    pub fn scene_of(&self, points: &[&str]) -> Scene {
        let scene = self.scene();
        match &self.drawing {
            Some(_) => scene,
            None => scene.trace(points.iter().copied()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const FILE: &str = "name = \"Crank\"\nequations = '''\nu = [x], v = [t],\npoints = [P = (x, t)],\nclosure = [x - t.sin()],\n'''\n[drive.t]\nfrom = 0\nto = 1\n";

    /// Without `[drawing]`, the points' paths are drawn; with one, what it
    /// says.
    #[test]
    fn a_file_without_a_drawing_traces_its_points() {
        let file = MechanismFile::parse(FILE).unwrap();
        let traced = Scene::new().units("m", "s").trace(["P"]);
        assert_eq!(file.scene_of(&["P"]), traced);
        let drawn = format!("{FILE}[drawing]\ntrace = []\n");
        let file = MechanismFile::parse(&drawn).unwrap();
        assert_eq!(file.scene_of(&["P"]), file.scene());
        assert_ne!(file.scene_of(&["P"]), traced);
    }
}
