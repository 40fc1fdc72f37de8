//! A name → its index, for every analysis: each lookup fails with the one
//! [`UnknownName`] error, which says who named what and lists the names it
//! could have meant.

use crate::error::{NameKind, UnknownName};
use crate::runtime::Linkage;

/// The index of `name` among `known`; if it is not there, the error of
/// `owner` naming the `kind` `name`.
pub(crate) fn find<'a, I>(
    kind: NameKind,
    owner: &str,
    name: &str,
    known: I,
) -> Result<usize, UnknownName>
where
    I: IntoIterator<Item = &'a str>,
    I::IntoIter: Clone,
{
    let known = known.into_iter();
    known
        .clone()
        .position(|n| n == name)
        .ok_or_else(|| UnknownName::new(kind, owner, name, known))
}

/// The index of the parameter `name` among a model's `params`
/// (`PARAM_NAMES`), which `owner` names.
pub(crate) fn parameter(params: &[&str], owner: &str, name: &str) -> Result<usize, UnknownName> {
    find(NameKind::Parameter, owner, name, params.iter().copied())
}

/// The index of the body `name`, which `owner` names, among the ground
/// (index 0) and `bodies` (from index 1).
pub(crate) fn body<'a, I>(bodies: I, owner: &str, name: &str) -> Result<usize, UnknownName>
where
    I: IntoIterator<Item = &'a str>,
    I::IntoIter: Clone,
{
    find(
        NameKind::Body,
        owner,
        name,
        std::iter::once("ground").chain(bodies),
    )
}

/// A model's point and coordinate names, to resolve what a description
/// names.
#[derive(Clone, Debug, PartialEq)]
pub struct Names {
    points: &'static [&'static str],
    /// u, then v.
    coordinates: Vec<&'static str>,
    /// How many of the coordinates are u.
    solved: usize,
}

impl Names {
    /// The names of the model `L`.
    pub fn of<L: Linkage<M, F>, const M: usize, const F: usize>(model: &L) -> Names {
        Names {
            points: model.point_names(),
            coordinates: model
                .u_names()
                .iter()
                .chain(&model.v_names())
                .copied()
                .collect(),
            solved: M,
        }
    }

    /// The points' names, in the order of `POINT_NAMES`.
    pub fn points(&self) -> &'static [&'static str] {
        self.points
    }

    /// The coordinates' names: u, then v.
    pub fn coordinates(&self) -> &[&'static str] {
        &self.coordinates
    }

    /// The index of the point `name`, which `owner` names.
    pub fn point(&self, owner: &str, name: &str) -> Result<usize, UnknownName> {
        find(NameKind::Point, owner, name, self.points.iter().copied())
    }

    /// The index of the coordinate `name` of u or v, which `owner` names,
    /// in the order of [`Names::coordinates`]: u's index i, or v's M + i.
    pub fn coordinate(&self, owner: &str, name: &str) -> Result<usize, UnknownName> {
        find(
            NameKind::Coordinate,
            owner,
            name,
            self.coordinates.iter().copied(),
        )
    }

    /// The index in u of the solved coordinate `name`, which `owner` names
    /// (a driver's name is not among them).
    pub fn solved(&self, owner: &str, name: &str) -> Result<usize, UnknownName> {
        find(
            NameKind::Coordinate,
            owner,
            name,
            self.coordinates[..self.solved].iter().copied(),
        )
    }

    /// Whether the coordinate at `index` (of [`Names::coordinate`]) is a
    /// driver's, and its index in u or in v.
    pub(crate) fn split(&self, index: usize) -> (bool, usize) {
        if index < self.solved {
            (false, index)
        } else {
            (true, index - self.solved)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names() -> Names {
        Names {
            points: &["A", "B"],
            coordinates: vec!["theta3", "theta4", "theta2"],
            solved: 2,
        }
    }

    #[test]
    fn each_kind_finds_its_index_and_names_what_it_could_have_meant() {
        let names = names();
        assert_eq!(names.point("load", "B"), Ok(1));
        assert_eq!(names.coordinate("load", "theta2"), Ok(2));
        assert_eq!(names.split(2), (true, 0));
        assert_eq!(names.split(1), (false, 1));
        assert_eq!(names.solved("task", "theta4"), Ok(1));
        let driver = names.solved("task", "theta2").unwrap_err();
        assert_eq!(driver.kind, NameKind::Coordinate);
        assert_eq!(driver.known, "theta3, theta4");
        let point = names.point("the scene", "C").unwrap_err();
        assert_eq!(
            point.to_string(),
            "`the scene` names the point `C`, which is not defined (the points: A, B)"
        );
        assert_eq!(parameter(&["l1", "l2"], "the tolerances", "l2"), Ok(1));
        let param = parameter(&["l1", "l2"], "the tolerances", "l3").unwrap_err();
        assert_eq!(
            (param.kind, param.owner.as_str()),
            (NameKind::Parameter, "the tolerances")
        );
    }

    #[test]
    fn the_ground_is_body_zero_and_the_others_follow() {
        let bodies = ["crank", "rod"];
        assert_eq!(body(bodies, "joint A", "ground"), Ok(0));
        assert_eq!(body(bodies, "joint A", "rod"), Ok(2));
        let e = body(bodies, "joint A", "slider").unwrap_err();
        assert_eq!(e.kind, NameKind::Body);
        assert_eq!(e.known, "ground, crank, rod");
    }
}
