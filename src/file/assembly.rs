//! Which assembly of the loops to start from: `[assembly]`.

use super::names::Name;
use super::quantity::{Accept, Quantity};
use super::reader::{Reader, Value};
use super::units::Unit;
use std::ops::Range;

/// How the file picks the assembly to start from (one way of three),
/// among the modes at the drivers' `at` (the pose one analysis takes; by
/// default `from`, where a sweep starts).
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum AssemblyChoice {
    /// `index = k`: the mode of this index among those found (counted from
    /// 0, in the order `linkage::assembly::modes` returns them).
    Index { index: usize, span: Range<usize> },
    /// `near = { theta3 = "20 deg", … }`: the mode nearest a sketch of the
    /// dependent coordinates (each of them).
    Near(Vec<(Name, Quantity)>),
    /// `points = { C = ["30 mm", "40 mm"], … }`: the mode nearest a sketch
    /// of named points.
    Points(Vec<(Name, [Quantity; 2])>),
}

/// The most modes an index may name.
const MOST_INDEX: u64 = 1 << 16;

impl Reader<'_> {
    /// The `[assembly]` table.
    pub(super) fn assembly(&mut self, value: &Value<'_>, length: Unit) -> Option<AssemblyChoice> {
        let mut table = self.table(
            "assembly",
            "a table with `index`, `near` or `points`",
            value,
        )?;
        let ways = [
            ("index", table.take("index")),
            ("near", table.take("near")),
            ("points", table.take("points")),
        ];
        table.finish(self);
        let mut written: Vec<_> = ways
            .iter()
            .filter_map(|(key, v)| v.map(|v| (*key, v)))
            .collect();
        // The first written is taken; the second is the mistake.
        written.sort_by_key(|(_, v)| v.span().start);
        let (key, value) = match written.as_slice() {
            [] => {
                self.error(
                    value.span(),
                    "`assembly` picks no assembly: give `index`, `near` or `points`",
                );
                return None;
            }
            [one] => *one,
            [(first, first_value), (second, second_value), ..] => {
                let message =
                    format!("`assembly` is picked one way: `{first}` or `{second}`, not both");
                let error = self
                    .mistake(second_value.span(), message)
                    .label(first_value.span(), format!("`{first}`"));
                self.push(error);
                return None;
            }
        };
        match key {
            "index" => {
                let index = self.count("assembly.index", value, 0, MOST_INDEX)?;
                Some(AssemblyChoice::Index {
                    index,
                    span: value.span(),
                })
            }
            "near" => self.near(value, length).map(AssemblyChoice::Near),
            _ => self.sketch(value, length).map(AssemblyChoice::Points),
        }
    }

    /// `near = { name = coordinate, … }`.
    fn near(&mut self, value: &Value<'_>, length: Unit) -> Option<Vec<(Name, Quantity)>> {
        let table = self.table("assembly.near", "a table of coordinate = value", value)?;
        let mut near = Vec::new();
        let mut ok = true;
        for (key, span, v) in table.all() {
            let name = self.identifier(key, span);
            let q = self.quantity(&table.place(key), v, Accept::COORDINATE, length);
            match (name, q) {
                (Some(name), Some(q)) => near.push((name, q)),
                _ => ok = false,
            }
        }
        self.not_empty("assembly.near", &table.span(), near.is_empty() && ok)?;
        ok.then_some(near)
    }

    /// `points = { name = [x, y], … }`.
    fn sketch(&mut self, value: &Value<'_>, length: Unit) -> Option<Vec<(Name, [Quantity; 2])>> {
        let table = self.table("assembly.points", "a table of point = [x, y]", value)?;
        let mut points = Vec::new();
        let mut ok = true;
        for (key, span, v) in table.all() {
            let name = self.identifier(key, span);
            let at = self.position(&table.place(key), v, length);
            match (name, at) {
                (Some(name), Some(at)) => points.push((name, at)),
                _ => ok = false,
            }
        }
        self.not_empty("assembly.points", &table.span(), points.is_empty() && ok)?;
        ok.then_some(points)
    }

    /// An error if `empty`.
    fn not_empty(&mut self, place: &str, span: &Range<usize>, empty: bool) -> Option<()> {
        if empty {
            self.error(
                span.clone(),
                format!("`{place}` is empty: name at least one"),
            );
            None
        } else {
            Some(())
        }
    }

    /// A position `[x, y]` of two lengths.
    pub(super) fn position(
        &mut self,
        place: &str,
        value: &Value<'_>,
        length: Unit,
    ) -> Option<[Quantity; 2]> {
        let expected = "a position [x, y]";
        let array = self.array(place, expected, value)?;
        if array.len() != 2 {
            self.error(
                value.span(),
                format!(
                    "`{place}` must be {expected}: two lengths, not {}",
                    array.len()
                ),
            );
            return None;
        }
        let x = self.quantity(&format!("{place}[0]"), &array[0], Accept::LENGTH, length);
        let y = self.quantity(&format!("{place}[1]"), &array[1], Accept::LENGTH, length);
        Some([x?, y?])
    }
}

impl AssemblyChoice {
    /// The pick this choice says, for a mechanism whose dependent
    /// coordinates are `u_names`: a sketch that leaves one of them out, or
    /// names one the mechanism does not have, is a mistake at its place.
    pub fn pick<const M: usize>(
        &self,
        u_names: &[&str],
    ) -> Result<crate::assembly::Pick<M>, crate::mechanism::Diagnostic> {
        use crate::assembly::Pick;
        use crate::mechanism::Diagnostic;
        match self {
            AssemblyChoice::Index { index, .. } => Ok(Pick::Index(*index)),
            AssemblyChoice::Near(sketch) => {
                if let Some((name, _)) = sketch
                    .iter()
                    .find(|(n, _)| !u_names.contains(&n.text.as_str()))
                {
                    return Err(Diagnostic::error(
                        format!(
                            "`{}` is not a dependent coordinate: `near` sketches u = [{}]",
                            name.text,
                            u_names.join(", ")
                        ),
                        Some(name.span.clone()),
                    ));
                }
                let mut u = nalgebra::SVector::<f64, M>::zeros();
                for (k, coordinate) in u_names.iter().enumerate().take(M) {
                    let Some((_, value)) = sketch.iter().find(|(n, _)| n.text == *coordinate)
                    else {
                        let at = sketch.first().map(|(n, _)| n.span.clone());
                        return Err(Diagnostic::error(
                            format!(
                                "`near` leaves out `{coordinate}`: it sketches every dependent coordinate, u = [{}]",
                                u_names.join(", ")
                            ),
                            at,
                        ));
                    };
                    u[k] = value.value;
                }
                Ok(Pick::NearestCoordinates(u))
            }
            AssemblyChoice::Points(sketch) => Ok(Pick::NearestPoints(
                sketch
                    .iter()
                    .map(|(n, [x, y])| (n.text.clone(), nalgebra::Vector2::new(x.value, y.value)))
                    .collect(),
            )),
        }
    }
}
