//! Hodographs: the tips of force vectors over a cycle from one origin,
//! with equal scales on both axes.

use super::plot::*;
use super::{DiagramError, PALETTE};
use plotters::prelude::*;

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
        let (rows, rows_height) = grid(self.columns, self.panels.len(), side)?;
        let total_width = within(
            "the picture's width",
            "at most 20 000 pixels (columns × their side)",
            self.columns as u64 * u64::from(side),
            0..=MAX_PIXELS.into(),
        )?;
        let title_height = 40;
        page((total_width, title_height + rows_height), |root| {
            self.draw(root, title_height, rows)
        })
    }

    fn draw(
        &self,
        root: &Page<'_>,
        title_height: u32,
        rows: usize,
    ) -> Result<(), Box<dyn std::error::Error>> {
        let (top, body) = root.split_vertically(title_height);
        top.draw(&title_text(self.title.clone(), 11))?;
        let areas = body.split_evenly((rows, self.columns));
        let unit = &self.unit;
        for ((name, points, mark), area) in self.panels.iter().zip(areas.iter()) {
            // A square window about the origin holding every tip.
            let mut reach = points
                .iter()
                .fold(0.0_f64, |r, p| r.max(p.0.abs()).max(p.1.abs()));
            if let Some((x, y, _)) = mark {
                reach = reach.max(x.abs()).max(y.abs());
            }
            let reach = reach.max(f64::MIN_POSITIVE) * 1.12;
            let mut chart = ChartBuilder::on(area)
                .caption(name.clone(), ("serif", 16))
                .margin(10)
                .x_label_area_size(34)
                .y_label_area_size(58)
                .build_cartesian_2d(-reach..reach, -reach..reach)?;
            chart
                .configure_mesh()
                .light_line_style(WHITE)
                .bold_line_style(BLACK.mix(0.08))
                .axis_desc_style(("sans-serif", 12))
                .label_style(("sans-serif", 11))
                .x_desc(format!("Fx [{unit}]"))
                .y_desc(format!("Fy [{unit}]"))
                .x_label_formatter(&|x| trim(*x))
                .y_label_formatter(&|y| trim(*y))
                .draw()?;
            let axis = BLACK.mix(0.35).stroke_width(1);
            chart.draw_series([
                PathElement::new(vec![(-reach, 0.0), (reach, 0.0)], axis),
                PathElement::new(vec![(0.0, -reach), (0.0, reach)], axis),
            ])?;
            let mut closed = points.clone();
            if let Some(first) = points.first() {
                closed.push(*first);
            }
            chart.draw_series(LineSeries::new(closed, PALETTE[0].stroke_width(2)))?;
            if let Some((x, y, label)) = mark {
                let red = PALETTE[1];
                chart.draw_series(std::iter::once(PathElement::new(
                    vec![(0.0, 0.0), (*x, *y)],
                    red.stroke_width(2),
                )))?;
                chart.draw_series(std::iter::once(Circle::new((*x, *y), 4, red.filled())))?;
                chart.draw_series(std::iter::once(Text::new(
                    label.clone(),
                    (*x, *y),
                    ("sans-serif", 12).into_font().color(&red),
                )))?;
            }
        }
        Ok(())
    }
}
