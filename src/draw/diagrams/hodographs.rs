//! Hodographs: the tips of force vectors over a cycle from one origin,
//! with equal scales on both axes.

use crate::draw::chart::{
    Chart, Colour, DiagramError, MAX_PIXELS, Panel, check_plottable, grid, height, within,
};

/// A hodograph's name, its points, and the vector marked with its label.
type HodographPanel = (String, Vec<(f64, f64)>, Option<(f64, f64, String)>);

/// Hodographs: the tips of force vectors over a cycle drawn from a common
/// origin, one panel per force, each panel with equal scales on both axes
/// (so directions and magnitudes read true) — the polar diagrams of joint
/// reactions.
#[derive(Clone, Debug, PartialEq)]
pub struct Hodographs {
    title: String,
    unit: String,
    panels: Vec<HodographPanel>,
    columns: usize,
    size: u32,
}

impl Hodographs {
    /// Forces in `unit` (e.g. "N").
    pub fn new(title: &str, unit: &str) -> Hodographs {
        Hodographs {
            title: title.into(),
            unit: unit.into(),
            panels: Vec::new(),
            columns: 2,
            size: 420,
        }
    }

    /// A force's components over the cycle, and optionally one vector
    /// marked (drawn as an arrow from the origin) with its label.
    pub fn panel(
        mut self,
        name: &str,
        points: Vec<(f64, f64)>,
        mark: Option<(f64, f64, &str)>,
    ) -> Hodographs {
        self.panels.push((
            name.into(),
            points,
            mark.map(|(x, y, l)| (x, y, l.to_string())),
        ));
        self
    }

    /// Panels per row (default 2; 1 to 20) and each panel's side in pixels
    /// (160 to 20 000, the whole picture too); checked when it is drawn.
    pub fn layout(mut self, columns: usize, size: u32) -> Hodographs {
        self.columns = columns;
        self.size = size;
        self
    }

    pub fn render(&self) -> Result<String, DiagramError> {
        for (name, points, mark) in &self.panels {
            check_plottable("force", name, points.iter().flat_map(|p| [p.0, p.1]), 2)?;
            if let Some((x, y, label)) = mark {
                check_plottable("marked force", label, [*x, *y], 2)?;
            }
        }
        let side = height(self.size, 160)?;
        // The columns (1 to 20) and the rows' height checked first.
        grid(self.columns, self.panels.len(), side)?;
        let total_width = within(
            "the picture's width",
            "at most 20 000 pixels (columns × their side)",
            (self.columns as u64).saturating_mul(u64::from(side)),
            0..=MAX_PIXELS.into(),
        )?;
        let unit = &self.unit;
        let x_label = format!("F_x [{unit}]");
        let mut chart = Chart::new(&self.title, "")
            .columns(self.columns)
            .size(total_width.max(200), side);
        for (name, points, mark) in &self.panels {
            let mut closed = points.clone();
            if let Some(first) = points.first() {
                closed.push(*first);
            }
            let mut panel = Panel::new(&format!("F_y [{unit}]"))
                .caption(name)
                .x_label(&x_label)
                .equal_scales()
                .line("", closed)
                .colour(crate::draw::chart::look::COLOURS[0])
                .unlisted();
            if let Some((x, y, label)) = mark {
                let red = Colour(213, 94, 0);
                panel = panel
                    .arrow(label, (0.0, 0.0), (*x, *y))
                    .colour(red)
                    .unlisted()
                    .note((*x, *y), &format!(" {label}"));
            }
            chart = chart.panel(panel);
        }
        chart.render()
    }
}
