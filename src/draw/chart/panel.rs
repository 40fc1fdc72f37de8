//! One panel of a [`Chart`](super::Chart): its axes and what is drawn in
//! them, as a builder.

use super::look::{Colour, Dash, Marker};

/// Whether an axis is linear or logarithmic.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scale {
    Linear,
    /// Base ten; every value on it must be positive.
    Log,
}

/// What a series draws.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Shape {
    /// Polylines (one legend entry for them all).
    Lines(Vec<Vec<(f64, f64)>>),
    /// A polyline with a marker at each point.
    LineAndPoints(Vec<(f64, f64)>),
    /// Markers.
    Points(Vec<(f64, f64)>),
    /// A filled polygon: a band between two curves, a region.
    Fill(Vec<(f64, f64)>),
    /// An arrow from the first point to the second, a dot at its tip.
    Arrow([(f64, f64); 2]),
}

/// What a user chose of a series' look; the rest comes from its place in
/// the chart.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Chosen {
    pub(crate) colour: Option<Colour>,
    pub(crate) dash: Option<Dash>,
    pub(crate) marker: Option<Marker>,
    pub(crate) open: bool,
    pub(crate) width: Option<f64>,
    pub(crate) opacity: Option<f64>,
}

/// One series: a name (its legend entry), what it draws and how.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Series {
    pub(crate) name: String,
    pub(crate) shape: Shape,
    pub(crate) chosen: Chosen,
    /// Whether it has a legend entry.
    pub(crate) listed: bool,
}

impl Series {
    /// Every point it draws.
    pub(crate) fn points(&self) -> Box<dyn Iterator<Item = (f64, f64)> + '_> {
        match &self.shape {
            Shape::Lines(lines) => Box::new(lines.iter().flatten().copied()),
            Shape::LineAndPoints(p) | Shape::Points(p) | Shape::Fill(p) => {
                Box::new(p.iter().copied())
            }
            Shape::Arrow(ends) => Box::new(ends.iter().copied()),
        }
    }
}

/// One panel of a [`Chart`](super::Chart): curves, points, bands and bars
/// against an abscissa, with vertical marks, horizontal reference levels,
/// shaded ranges and notes. Each series' colour, marker and dashes come
/// from its name's place in the chart (the same name looks the same in
/// every panel) unless chosen; [`Panel::colour`], [`Panel::marker`],
/// [`Panel::dash`], [`Panel::open`], [`Panel::width`], [`Panel::faint`]
/// and [`Panel::unlisted`] change the series added last.
#[derive(Clone, Debug, PartialEq)]
pub struct Panel {
    pub(crate) y_label: String,
    pub(crate) x_label: Option<String>,
    pub(crate) caption: Option<String>,
    pub(crate) scales: [Scale; 2],
    pub(crate) ranges: [Option<(f64, f64)>; 2],
    pub(crate) equal_scales: bool,
    pub(crate) series: Vec<Series>,
    pub(crate) marks: Vec<(f64, String)>,
    /// Reference levels: a label and the ordinates it is drawn at.
    pub(crate) levels: Vec<(String, Vec<f64>)>,
    /// Shaded ranges of the abscissa: a label, from, to.
    pub(crate) shades: Vec<(String, f64, f64)>,
    pub(crate) notes: Vec<((f64, f64), String)>,
    /// A bar chart's categories, and its groups of bars (one value per
    /// category each).
    pub(crate) categories: Vec<String>,
    pub(crate) groups: Vec<(String, Vec<f64>)>,
}

impl Panel {
    pub fn new(y_label: &str) -> Panel {
        Panel {
            y_label: y_label.into(),
            x_label: None,
            caption: None,
            scales: [Scale::Linear; 2],
            ranges: [None; 2],
            equal_scales: false,
            series: Vec::new(),
            marks: Vec::new(),
            levels: Vec::new(),
            shades: Vec::new(),
            notes: Vec::new(),
            categories: Vec::new(),
            groups: Vec::new(),
        }
    }

    /// A bar chart: one bar per category of each group (see
    /// [`Panel::group`]), from zero.
    pub fn bars(y_label: &str, categories: &[&str]) -> Panel {
        Panel {
            categories: categories.iter().map(|c| c.to_string()).collect(),
            ..Panel::new(y_label)
        }
    }

    /// A group of bars: `values` one per category.
    pub fn group(mut self, name: &str, values: &[f64]) -> Panel {
        self.groups.push((name.into(), values.to_vec()));
        self
    }

    /// A caption above the panel.
    pub fn caption(mut self, caption: &str) -> Panel {
        self.caption = Some(caption.into());
        self
    }

    /// This panel's own abscissa label (else the chart's, under the bottom
    /// row).
    pub fn x_label(mut self, label: &str) -> Panel {
        self.x_label = Some(label.into());
        self
    }

    /// Logarithmic abscissa.
    pub fn x_log(mut self) -> Panel {
        self.scales[0] = Scale::Log;
        self
    }

    /// Logarithmic ordinate.
    pub fn y_log(mut self) -> Panel {
        self.scales[1] = Scale::Log;
        self
    }

    /// The abscissa's range (else the data's, with a margin).
    pub fn x_range(mut self, from: f64, to: f64) -> Panel {
        self.ranges[0] = Some((from, to));
        self
    }

    /// The ordinate's range (else the data's, with a margin).
    pub fn y_range(mut self, from: f64, to: f64) -> Panel {
        self.ranges[1] = Some((from, to));
        self
    }

    /// One scale for both axes, so that lengths and directions read true.
    pub fn equal_scales(mut self) -> Panel {
        self.equal_scales = true;
        self
    }

    fn push(mut self, name: &str, shape: Shape) -> Panel {
        self.series.push(Series {
            name: name.into(),
            shape,
            chosen: Chosen::default(),
            listed: true,
        });
        self
    }

    /// A curve.
    pub fn line(self, name: &str, points: Vec<(f64, f64)>) -> Panel {
        self.push(name, Shape::Lines(vec![points]))
    }

    /// A dashed curve.
    pub fn dashed(self, name: &str, points: Vec<(f64, f64)>) -> Panel {
        self.line(name, points).dash(Dash::Dashed)
    }

    /// Several curves under one name (the samples of a Monte Carlo run,
    /// say): one legend entry.
    pub fn lines(self, name: &str, lines: Vec<Vec<(f64, f64)>>) -> Panel {
        self.push(name, Shape::Lines(lines))
    }

    /// Markers at points.
    pub fn points(self, name: &str, points: Vec<(f64, f64)>) -> Panel {
        self.push(name, Shape::Points(points))
    }

    /// A curve with a marker at each of its points.
    pub fn line_and_points(self, name: &str, points: Vec<(f64, f64)>) -> Panel {
        self.push(name, Shape::LineAndPoints(points))
    }

    /// A filled region, its outline given in order (a band: one curve
    /// forward and the other back).
    pub fn fill(self, name: &str, outline: Vec<(f64, f64)>) -> Panel {
        self.push(name, Shape::Fill(outline))
    }

    /// An arrow from `from` to `to`, with a dot at its tip.
    pub fn arrow(self, name: &str, from: (f64, f64), to: (f64, f64)) -> Panel {
        self.push(name, Shape::Arrow([from, to]))
    }

    fn last(mut self, change: impl FnOnce(&mut Series)) -> Panel {
        if let Some(series) = self.series.last_mut() {
            change(series);
        }
        self
    }

    /// The last series' colour.
    pub fn colour(self, colour: Colour) -> Panel {
        self.last(|s| s.chosen.colour = Some(colour))
    }

    /// The last series' dashes.
    pub fn dash(self, dash: Dash) -> Panel {
        self.last(|s| s.chosen.dash = Some(dash))
    }

    /// The last series' markers.
    pub fn marker(self, marker: Marker) -> Panel {
        self.last(|s| s.chosen.marker = Some(marker))
    }

    /// The last series' markers outlined, not filled.
    pub fn open(self) -> Panel {
        self.last(|s| s.chosen.open = true)
    }

    /// The last series' line width, in points at a 16 cm column.
    pub fn width(self, points: f64) -> Panel {
        self.last(|s| s.chosen.width = Some(points))
    }

    /// The last series drawn faint (thin and translucent): many curves
    /// behind the ones that matter.
    pub fn faint(self) -> Panel {
        self.last(|s| {
            s.chosen.opacity = Some(0.35);
            s.chosen.width = Some(super::look::points::THIN);
        })
    }

    /// The last series without a legend entry.
    pub fn unlisted(self) -> Panel {
        self.last(|s| s.listed = false)
    }

    /// A vertical dashed mark at x, labelled (an empty label: none).
    pub fn mark(mut self, x: f64, label: &str) -> Panel {
        self.marks.push((x, label.into()));
        self
    }

    /// Horizontal reference lines at each of `ys` across the panel — one
    /// limit or target (±35°, say) — in one style, with one legend entry.
    pub fn levels(mut self, label: &str, ys: &[f64]) -> Panel {
        self.levels.push((label.into(), ys.to_vec()));
        self
    }

    /// The abscissa from `from` to `to` shaded, with a legend entry.
    pub fn shade(mut self, label: &str, from: f64, to: f64) -> Panel {
        self.shades.push((label.into(), from, to));
        self
    }

    /// A text at (x, y), in the axes' units, written from there rightwards.
    pub fn note(mut self, at: (f64, f64), text: &str) -> Panel {
        self.notes.push((at, text.into()));
        self
    }
}
