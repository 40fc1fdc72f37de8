//! Mechanisms built the way engineers draw them: joints at drawn
//! positions, links listing the joints they carry, and drivers — no
//! equations written by hand.
//!
//! A [`Topology`] is checked (names, every joint on a link, sliders on
//! two links, every link connected to the frame, two links never joined
//! by two pins, the degrees of freedom by Grübler–Kutzbach against the
//! drivers), then its closure equations are generated: one vector loop
//! per joint that a spanning tree of the links does not cross, each
//! moving link's angle or each slider's travel a coordinate, every length
//! and fixed angle a named parameter read from the drawing (so that
//! sensitivities, tolerances and synthesis work on them). The result is
//! an ordinary mechanism file ([`Topology::mechanism_text`]), which
//! starts from the drawn assembly; nothing downstream is special.
//!
//! ```
//! use linkage::topology::Topology;
//!
//! // The four-bar of the Maple worksheet, as drawn at θ2 = 20° (mm).
//! let four_bar = Topology::new("FourBar")
//!     .length_unit("mm")
//!     .revolute("A", [0.0, 0.0])
//!     .revolute("B", [18.79385241571817, 6.840402866513374])
//!     .revolute("C", [35.44242865, 54.00760042])
//!     .revolute("D", [80.0, 0.0])
//!     .link("ground", &["A", "D"])
//!     .link("crank", &["A", "B"])
//!     .link("coupler", &["B", "C"])
//!     .link("rocker", &["D", "C"])
//!     .drive_angle("A", "B");
//! let file = four_bar.mechanism_file()?;
//! let mechanism = file.mechanism()?;
//! assert_eq!((mechanism.m(), mechanism.f()), (2, 1));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod check;
pub mod dxf;
mod error;
mod generate;
mod model;
pub mod pylinkage;
pub mod pyslvs;
mod save;
mod write;

pub use error::{TopologyError, TopologyErrors};
pub use model::{Driven, Driver, Joint, JointKind, Link, Topology};

use crate::file::MechanismFile;

impl Topology {
    /// Every mistake of the topology, or none.
    pub fn check(&self) -> Result<(), TopologyErrors> {
        check::check(self).map(|_| ())
    }

    /// The mechanism file of this topology: its generated equations,
    /// parameters read from the drawing, drivers, the drawn assembly and
    /// a drawing.
    pub fn mechanism_text(&self) -> Result<String, TopologyErrors> {
        let checked = check::check(self)?;
        let generated = generate::generate(&checked);
        if generated.u.is_empty() {
            return Err(TopologyError::NothingDepends.into());
        }
        // A joint's name is its point's: no generated name may be one.
        let generated_names = (generated.u.iter())
            .chain(generated.v.iter().map(|(v, _)| v))
            .chain(&generated.parameters)
            .map(|value| &value.name);
        let clashes: Vec<TopologyError> = generated_names
            .filter(|name| self.joints.iter().any(|j| j.name == **name))
            .map(|name| TopologyError::NameClash { name: name.clone() })
            .collect();
        if !clashes.is_empty() {
            return Err(TopologyErrors { errors: clashes });
        }
        // Every driver a coordinate of v (the checks make it so).
        if generated.v.len() != self.drivers.len() {
            return Err(TopologyError::Generated {
                why: "a driver moves no coordinate".to_owned(),
            }
            .into());
        }
        Ok(write::mechanism_file(&checked, &generated))
    }

    /// The topology file of this topology ([`crate::file::TopologyFile`]),
    /// which reads back to it.
    pub fn topology_text(&self) -> String {
        save::topology_file(self)
    }

    /// How far the drawing is from closing each loop, with the lengths
    /// given: for each joint where a loop closes, the largest residual of
    /// its equations at the drawn pose (0 to rounding when the drawing
    /// gives every length), largest first. Where a mechanism does not
    /// assemble, the first names the loop that the given lengths open.
    pub fn sketch_gaps(&self) -> Result<Vec<(String, f64)>, TopologyErrors> {
        let checked = check::check(self)?;
        let generated = generate::generate(&checked);
        let text = write::mechanism_file(&checked, &generated);
        let fault = |why: String| TopologyErrors::from(TopologyError::Generated { why });
        let file = MechanismFile::parse(&text).map_err(|e| fault(e.to_string()))?;
        let mechanism = file.mechanism().map_err(|e| fault(e.to_string()))?;
        let u: Vec<f64> = generated.u.iter().map(|c| c.value).collect();
        let v: Vec<f64> = generated.v.iter().map(|(c, _)| c.value).collect();
        let residual = mechanism
            .residual(&u, &v)
            .map_err(|e| fault(e.to_string()))?;
        let mut gaps: Vec<(String, f64)> = Vec::new();
        for (joint, r) in generated.closes_at.iter().zip(residual) {
            match gaps.iter_mut().find(|(j, _)| j == joint) {
                Some((_, gap)) => *gap = gap.max(r.abs()),
                None => gaps.push((joint.clone(), r.abs())),
            }
        }
        gaps.sort_by(|a, b| b.1.total_cmp(&a.1));
        Ok(gaps)
    }

    /// [`Topology::mechanism_text`], read.
    pub fn mechanism_file(&self) -> Result<MechanismFile, TopologyErrors> {
        let text = self.mechanism_text()?;
        MechanismFile::parse(&text).map_err(|errors| {
            // The generator's own mistake, never the user's: said whole.
            TopologyErrors::from(TopologyError::Generated {
                why: format!("{errors}\n{text}"),
            })
        })
    }
}

#[cfg(test)]
mod tests;
