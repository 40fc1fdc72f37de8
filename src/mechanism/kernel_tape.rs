//! A kernel of a run-time mechanism ready to run: its tape, its place
//! among the kernels (the key of its register files), and where each of
//! its outputs goes in the result the views read — each part's matrix
//! column by column (nalgebra's order), the points as (x, y) pairs, the
//! parts of a phase end to end. Worked out once per kernel, so that a call
//! writes its outputs straight into place and reads its matrices as
//! slices, with no search and no zeroing: the entries no output fills are
//! structural zeros, written once when the result's buffer is made.

use linkage_symbolic::tape::{Form, Part, Registers, Tape, TapeError};

/// A kernel's tape and the layout of its results.
#[derive(Debug)]
pub(crate) struct KernelTape {
    /// Its place in [`Kernel::ALL`](linkage_symbolic::plan::Kernel::ALL).
    pub(crate) index: usize,
    pub(crate) tape: Tape,
    phases: Vec<Layout>,
}

/// Where a phase's outputs go.
#[derive(Debug)]
struct Layout {
    /// The place of each output, in order.
    places: Vec<u32>,
    /// Where each part starts.
    starts: Vec<usize>,
    /// How long the result is: every entry of every part.
    len: usize,
}

/// Where entry (i, j) of a part goes, from the part's start: a matrix's
/// column by column, a point's coordinates together.
fn place(part: &Part, (i, j): (usize, usize)) -> usize {
    match part.form {
        Form::Matrix | Form::PointColumns => j * part.rows + i,
        Form::Points => i * part.cols + j,
    }
}

impl Layout {
    fn of(parts: &[Part]) -> Layout {
        let mut places = Vec::new();
        let mut starts = Vec::with_capacity(parts.len());
        let mut len = 0;
        for part in parts {
            starts.push(len);
            for &entry in &part.entries {
                let inside = entry.0 < part.rows && entry.1 < part.cols;
                let at = (len + place(part, entry)) as u32;
                // An entry outside its part goes nowhere (`run_to` skips
                // places outside the result).
                places.push(if inside { at } else { u32::MAX });
            }
            len += part.rows * part.cols;
        }
        Layout {
            places,
            starts,
            len,
        }
    }
}

impl KernelTape {
    pub(crate) fn new(index: usize, tape: Tape) -> KernelTape {
        let phases = (0..tape.phases())
            .map(|p| Layout::of(tape.parts(p)))
            .collect();
        KernelTape {
            index,
            tape,
            phases,
        }
    }

    /// A buffer for each phase's result on `lanes` lanes (their results
    /// end to end), every entry zero.
    pub(crate) fn results(&self, lanes: usize) -> Vec<Vec<f64>> {
        self.phases
            .iter()
            .map(|p| vec![0.0; p.len * lanes])
            .collect()
    }

    /// How long a phase's result is on one lane.
    pub(crate) fn len(&self, phase: usize) -> usize {
        self.phases.get(phase).map_or(0, |p| p.len)
    }

    /// Runs a phase, its outputs written into their places in `result`
    /// (a buffer of [`KernelTape::results`]).
    pub(crate) fn run(
        &self,
        phase: usize,
        registers: &mut Registers,
        result: &mut [f64],
    ) -> Result<(), TapeError> {
        let places = self.phases.get(phase).map_or(&[][..], |p| &p.places);
        self.tape.run_to(phase, registers, result, places)
    }

    /// [`KernelTape::run`] on every lane: lane l's result is the l-th of
    /// `results`, each [`KernelTape::len`] long.
    pub(crate) fn run_lanes<const L: usize>(
        &self,
        phase: usize,
        registers: &mut Registers<L>,
        results: &mut [f64],
    ) -> Result<(), TapeError> {
        let places = self.phases.get(phase).map_or(&[][..], |p| &p.places);
        let stride = self.len(phase);
        self.tape
            .run_lanes_to(phase, registers, results, stride, places)
    }

    /// Where part `part` of a phase's result starts (`usize::MAX` if it
    /// has no such part).
    pub(crate) fn start(&self, phase: usize, part: usize) -> usize {
        (self.phases.get(phase))
            .and_then(|p| p.starts.get(part).copied())
            .unwrap_or(usize::MAX)
    }

    /// Whether the parts of each phase have these names, in this order.
    pub(crate) fn has_parts(&self, names: &[&[&str]]) -> bool {
        self.tape.phases() == names.len()
            && names.iter().enumerate().all(|(phase, names)| {
                let parts = self.tape.parts(phase);
                parts.len() == names.len() && parts.iter().zip(*names).all(|(p, n)| p.name == *n)
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn part(form: Form, rows: usize, cols: usize, entries: Vec<(usize, usize)>) -> Part {
        Part {
            name: "x",
            form,
            rows,
            cols,
            entries,
        }
    }

    #[test]
    fn matrices_go_column_by_column_and_points_in_pairs() {
        let parts = [
            part(Form::Matrix, 2, 1, vec![(0, 0), (1, 0)]),
            part(Form::Matrix, 2, 2, vec![(0, 1), (1, 0), (1, 1)]),
            part(Form::Points, 2, 2, vec![(0, 0), (0, 1), (1, 0), (1, 1)]),
            part(Form::Matrix, 1, 1, vec![(3, 0)]),
        ];
        let layout = Layout::of(&parts);
        assert_eq!(layout.starts, [0, 2, 6, 10]);
        assert_eq!(layout.len, 11);
        assert_eq!(
            layout.places,
            [0, 1, 2 + 2, 2 + 1, 2 + 3, 6, 7, 8, 9, u32::MAX]
        );
    }
}
