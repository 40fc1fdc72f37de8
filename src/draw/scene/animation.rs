//! Animation of a scene: a cycle's frames as SMIL animations of every
//! drawn element, looping.

use super::layout::Placed;
use super::motion::Motion;
use super::symbols::{ground_symbol, guide_symbol};
use super::{Frame, Scene, SceneError, positive, resolve};

impl Scene {
    /// An animation of `cycle` (its frames at equal time steps, looping
    /// over `seconds`), as SVG with SMIL animations: self-contained, played
    /// by any browser. Titled by [`Scene::animation_title`] (not by
    /// [`Scene::title`] and [`Scene::subtitle`], which name a pose);
    /// automatic arrow scales are chosen over the whole cycle, as
    /// [`Scene::render`] chooses them. The ghost poses, curves, markers
    /// and notes stay still behind and over the moving mechanism.
    pub fn animate(&self, cycle: &[Frame], seconds: f64) -> Result<String, SceneError> {
        if cycle.len() < 2 {
            return Err(SceneError::TooFewFrames {
                frames: cycle.len(),
            });
        }
        positive("the animation's duration", seconds)?;
        let layout = self.layout(cycle, cycle, self.animation_title.as_deref(), None)?;
        let mut w = layout.open();
        let overlay = self.overlay(&layout)?;
        self.draw_ghosts(&mut w, &overlay.ghosts);
        let traces = self.trace_paths(&layout, cycle)?;
        self.draw_traces(&mut w, &traces);
        self.draw_curves(&mut w, &overlay.curves);
        let guides = self.guides(&layout, cycle, cycle)?;
        for guide in &guides {
            guide_symbol(&mut w, guide);
        }
        for (name, _) in &self.ground {
            let at = resolve(&cycle[0], name, &self.ground)?;
            ground_symbol(&mut w, layout.screen(at));
        }
        let frames: Vec<Placed> = cycle
            .iter()
            .map(|f| self.place(&layout, f))
            .collect::<Result<_, _>>()?;
        let motion = Motion {
            frames: &frames,
            seconds,
        };
        self.draw_links(&mut w, &frames[0], Some(&motion));
        self.draw_sliders(&mut w, &frames[0], Some(&motion));
        self.draw_points(&mut w, &frames[0], Some(&motion));
        self.draw_markers(&mut w, &overlay.markers);
        self.draw_arrows(&mut w, &layout, &cycle[0], Some((cycle, seconds)))?;
        self.draw_notes(&mut w, &overlay.notes);
        if self.labels {
            let arrows = self.arrows(&layout, &cycle[0])?;
            let obstacles =
                self.obstacles(&layout, &frames[0], &arrows, &guides, &traces, &overlay);
            self.draw_labels(&mut w, &frames[0], Some(&motion), &obstacles, &overlay);
        }
        self.draw_legend(&mut w, &layout, true);
        Ok(w.finish())
    }
}
