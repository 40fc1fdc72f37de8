//! What a picture of the mechanism shows: `[drawing]`, read into a
//! [`DrawingSpec`] (drawn as a `linkage::draw::scene::Scene`).

use super::names::Name;
use super::quantity::{Accept, Quantity};
use super::reader::{Reader, Value};
use super::units::Unit;
use toml::de::DeValue;

/// What a picture shows: ground pivots, links and plates between named
/// points, sliders, arrows and traced paths. Names are the equations'
/// points or the ground pivots'.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DrawingSpec {
    /// `ground = { A = [0, 0], … }`: fixed pivots, drawn hatched.
    pub ground: Vec<(Name, [Quantity; 2])>,
    /// `links = [["A", "B"], …]`: binary links.
    pub links: Vec<[Name; 2]>,
    /// `plates = [["B", "C", "E"], …]`: links of three or more joints.
    pub plates: Vec<Vec<Name>>,
    /// `sliders = [{ point = "C", angle = "0 deg" }, …]`.
    pub sliders: Vec<SliderSpec>,
    /// `velocities = ["B", …]`: velocity arrows.
    pub velocities: Vec<Name>,
    /// `accelerations = ["C", …]`: acceleration arrows.
    pub accelerations: Vec<Name>,
    /// `trace = ["E", …]`: paths over a cycle.
    pub trace: Vec<Name>,
    /// `velocity_scale`: drawn length per unit of velocity (s), automatic
    /// if not written.
    pub velocity_scale: Option<Quantity>,
    /// `acceleration_scale`: drawn length per unit of acceleration (s²),
    /// automatic if not written.
    pub acceleration_scale: Option<Quantity>,
}

/// A slider block at a point, and what it slides on.
#[derive(Clone, Debug, PartialEq)]
pub struct SliderSpec {
    pub point: Name,
    pub guide: Guide,
}

/// What a slider block slides on: one of `angle`, `along`, `slot`.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Guide {
    /// `angle = "0 deg"`: a fixed straight guide at this angle, drawn
    /// hatched.
    Ground(Quantity),
    /// `along = ["C", "D"]`: the link through these two points; the block
    /// turns with it.
    Along([Name; 2]),
    /// `slot = "90 deg"`: a slot at this fixed angle in a translating body
    /// (a ram); no ground guide is drawn.
    Slot(Quantity),
}

/// A scale of arrows: a positive plain number.
const SCALE: Accept = Accept {
    kinds: &[],
    what: "a positive plain number",
};

impl Reader<'_> {
    /// The `[drawing]` table.
    pub(super) fn drawing(&mut self, value: &Value<'_>, length: Unit) -> Option<DrawingSpec> {
        let mut table = self.table("drawing", "a table", value)?;
        let ground = table.take("ground");
        let links = table.take("links");
        let plates = table.take("plates");
        let sliders = table.take("sliders");
        let velocities = table.take("velocities");
        let accelerations = table.take("accelerations");
        let trace = table.take("trace");
        let velocity_scale = table.take("velocity_scale");
        let acceleration_scale = table.take("acceleration_scale");
        table.finish(self);
        let mut spec = DrawingSpec::default();
        let mut ok = true;
        if let Some(v) = ground {
            ok &= self.ground(v, length, &mut spec.ground).is_some();
        }
        if let Some(v) = links {
            ok &= self
                .polygons("drawing.links", v, 2, 2)
                .map(|all| {
                    spec.links = all
                        .into_iter()
                        .filter_map(|ends| <[Name; 2]>::try_from(ends).ok())
                        .collect();
                })
                .is_some();
        }
        if let Some(v) = plates {
            ok &= self
                .polygons("drawing.plates", v, 3, usize::MAX)
                .map(|all| spec.plates = all)
                .is_some();
        }
        if let Some(v) = sliders {
            ok &= self
                .sliders(v, length)
                .map(|all| spec.sliders = all)
                .is_some();
        }
        for (key, value, into) in [
            ("velocities", velocities, &mut spec.velocities),
            ("accelerations", accelerations, &mut spec.accelerations),
            ("trace", trace, &mut spec.trace),
        ] {
            if let Some(v) = value {
                ok &= self
                    .point_list(&format!("drawing.{key}"), v)
                    .map(|all| *into = all)
                    .is_some();
            }
        }
        for (key, value, into) in [
            ("velocity_scale", velocity_scale, &mut spec.velocity_scale),
            (
                "acceleration_scale",
                acceleration_scale,
                &mut spec.acceleration_scale,
            ),
        ] {
            if let Some(v) = value {
                ok &= self
                    .scale(&format!("drawing.{key}"), v, length)
                    .map(|q| *into = Some(q))
                    .is_some();
            }
        }
        ok.then_some(spec)
    }

    /// `ground = { name = [x, y], … }`.
    fn ground(
        &mut self,
        value: &Value<'_>,
        length: Unit,
        into: &mut Vec<(Name, [Quantity; 2])>,
    ) -> Option<()> {
        let table = self.table("drawing.ground", "a table of pivot = [x, y]", value)?;
        let mut ok = true;
        for (key, span, v) in table.all() {
            let name = self.identifier(key, span);
            let at = self.position(&table.place(key), v, length);
            match (name, at) {
                (Some(name), Some(at)) => into.push((name, at)),
                _ => ok = false,
            }
        }
        ok.then_some(())
    }

    /// Point names, as strings, each a name the equations can use.
    fn point_names(&mut self, place: &str, value: &Value<'_>) -> Option<Vec<Name>> {
        let names = self.names(place, value)?;
        let mut ok = true;
        let mut all = Vec::new();
        for (text, span) in names {
            match self.identifier(&text, span) {
                Some(name) => all.push(name),
                None => ok = false,
            }
        }
        ok.then_some(all)
    }

    /// A list of points, each once.
    fn point_list(&mut self, place: &str, value: &Value<'_>) -> Option<Vec<Name>> {
        let names = self.point_names(place, value)?;
        let mut ok = true;
        for (k, name) in names.iter().enumerate() {
            if let Some(first) = names[..k].iter().find(|n| n.text == name.text) {
                let error = self
                    .mistake(
                        name.span.clone(),
                        format!("`{}` is listed twice in `{place}`", name.text),
                    )
                    .label(first.span.clone(), "first here");
                self.push(error);
                ok = false;
            }
        }
        ok.then_some(names)
    }

    /// An array of polygons, each of `least` to `most` points.
    fn polygons(
        &mut self,
        place: &str,
        value: &Value<'_>,
        least: usize,
        most: usize,
    ) -> Option<Vec<Vec<Name>>> {
        let shape = if most == 2 {
            "an array of links, each [\"A\", \"B\"]".to_owned()
        } else {
            format!("an array of plates, each of {least} or more points")
        };
        let array = self.array(place, &shape, value)?;
        let mut all = Vec::new();
        let mut ok = true;
        for (k, item) in array.iter().enumerate() {
            let place = format!("{place}[{k}]");
            let Some(points) = self.point_list(&place, item) else {
                ok = false;
                continue;
            };
            if points.len() < least || points.len() > most {
                let count = if least == most {
                    format!("{least} points")
                } else {
                    format!("{least} or more points")
                };
                self.error(
                    item.span(),
                    format!("`{place}` must join {count}, not {}", points.len()),
                );
                ok = false;
                continue;
            }
            all.push(points);
        }
        ok.then_some(all)
    }

    /// `sliders = [{ point = "C", angle | along | slot = … }, …]`.
    fn sliders(&mut self, value: &Value<'_>, length: Unit) -> Option<Vec<SliderSpec>> {
        let place = "drawing.sliders";
        let array = self.array(
            place,
            "an array of sliders, each { point = \"C\", angle = \"0 deg\" }",
            value,
        )?;
        let mut all = Vec::new();
        let mut ok = true;
        for item in array.iter() {
            match self.slider(item, length) {
                Some(slider) => all.push(slider),
                None => ok = false,
            }
        }
        ok.then_some(all)
    }

    /// One slider's table.
    fn slider(&mut self, value: &Value<'_>, length: Unit) -> Option<SliderSpec> {
        let place = "drawing.sliders";
        let mut table = self.table(place, "a table { point = \"C\", angle = \"0 deg\" }", value)?;
        let point = table.require(self, "point", "the slider block's point");
        let guides = [
            ("angle", table.take("angle")),
            ("along", table.take("along")),
            ("slot", table.take("slot")),
        ];
        table.finish(self);
        let point = point.and_then(|p| match p.get_ref() {
            DeValue::String(s) => self.identifier(s, p.span()),
            _ => {
                self.wrong_type("drawing.sliders.point", "a point's name", p);
                None
            }
        });
        let mut written: Vec<_> = guides
            .iter()
            .filter_map(|(key, v)| v.map(|v| (*key, v)))
            .collect();
        // The first written is taken; the second is the mistake.
        written.sort_by_key(|(_, v)| v.span().start);
        let guide = match written.as_slice() {
            [] => {
                self.error(
                    value.span(),
                    "a slider needs its guide: `angle` (a fixed guide), `along` (a link) or `slot` (a slot in a translating body)",
                );
                None
            }
            [("angle", v)] => self
                .quantity("drawing.sliders.angle", v, Accept::ANGLE, length)
                .map(Guide::Ground),
            [("slot", v)] => self
                .quantity("drawing.sliders.slot", v, Accept::ANGLE, length)
                .map(Guide::Slot),
            [(_, v)] => self.line("drawing.sliders.along", v).map(Guide::Along),
            [(first, first_value), (second, second_value), ..] => {
                let message = format!("a slider has one guide: `{first}` or `{second}`, not both");
                let error = self
                    .mistake(second_value.span(), message)
                    .label(first_value.span(), format!("`{first}`"));
                self.push(error);
                None
            }
        };
        Some(SliderSpec {
            point: point?,
            guide: guide?,
        })
    }

    /// Two points of a line.
    fn line(&mut self, place: &str, value: &Value<'_>) -> Option<[Name; 2]> {
        let points = self.point_list(place, value)?;
        let count = points.len();
        match <[Name; 2]>::try_from(points) {
            Ok(line) => Some(line),
            Err(_) => {
                self.error(
                    value.span(),
                    format!("`{place}` must name the two points of a line, not {count}"),
                );
                None
            }
        }
    }

    /// A scale of arrows: positive.
    fn scale(&mut self, place: &str, value: &Value<'_>, length: Unit) -> Option<Quantity> {
        let q = self.quantity(place, value, SCALE, length)?;
        if q.value > 0.0 {
            Some(q)
        } else {
            self.error(
                value.span(),
                format!("`{place}` must be positive, not {}", q.value),
            );
            None
        }
    }
}
