//! A kernel of a run-time mechanism ready to run: its tape, its place
//! among the kernels (the key of its register files), and the register
//! each entry of a phase's result is read from — the result laid out as
//! the views read it: each part's matrix column by column (nalgebra's
//! order), the points as (x, y) pairs, the parts of a phase end to end.
//! Worked out once per kernel, so that a call reads its matrices straight
//! from the registers, with no search and no copy in between; an entry no
//! output fills is a structural zero.

use linkage_symbolic::tape::{Form, Part, Registers, Tape, TapeError};
use nalgebra::SMatrix;

/// A kernel's tape and the layout of its results.
#[derive(Debug)]
pub(crate) struct KernelTape {
    /// Its index ([`Kernel::index`](linkage_symbolic::plan::Kernel::index)).
    pub(crate) index: usize,
    pub(crate) tape: Tape,
    phases: Vec<Layout>,
}

/// Where a phase's result is read from.
#[derive(Debug)]
struct Layout {
    /// The register of each entry of the result ([`ZERO`] for an entry no
    /// output fills).
    sources: Vec<u32>,
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

/// The source of a structural zero: no register (the registers' `get`
/// finds none there).
const ZERO: u32 = u32::MAX;

impl Layout {
    /// The layout of a phase's parts, whose outputs are in `outputs`.
    fn of(parts: &[Part], outputs: &[u32]) -> Layout {
        let len = parts.iter().map(|p| p.rows * p.cols).sum();
        let mut sources = vec![ZERO; len];
        let mut starts = Vec::with_capacity(parts.len());
        let mut start = 0;
        let mut registers = outputs.iter();
        for part in parts {
            starts.push(start);
            for (&entry, &register) in part.entries.iter().zip(registers.by_ref()) {
                // An entry outside its part is read by no one.
                if entry.0 < part.rows && entry.1 < part.cols {
                    sources[start + place(part, entry)] = register;
                }
            }
            start += part.rows * part.cols;
        }
        Layout {
            sources,
            starts,
            len,
        }
    }
}

impl KernelTape {
    pub(crate) fn new(index: usize, tape: Tape) -> KernelTape {
        let phases = (0..tape.phases())
            .map(|p| {
                let outputs = tape.phase(p).map_or(&[][..], |phase| &phase.outputs);
                Layout::of(tape.parts(p), outputs)
            })
            .collect();
        KernelTape {
            index,
            tape,
            phases,
        }
    }

    /// How long a phase's result is.
    pub(crate) fn len(&self, phase: usize) -> usize {
        self.phases.get(phase).map_or(0, |p| p.len)
    }

    /// Runs a phase on every lane; its result stays in the registers, read
    /// with [`KernelTape::block`] or [`KernelTape::read`].
    #[inline(always)]
    pub(crate) fn run<const L: usize>(
        &self,
        phase: usize,
        registers: &mut Registers<L>,
    ) -> Result<(), TapeError> {
        self.tape.run_phase(phase, registers)
    }

    /// The R × C matrix of the phase's result that starts at `start`, on
    /// lane `lane` (NaN where the result is shorter).
    #[inline(always)]
    pub(crate) fn block<const R: usize, const C: usize, const L: usize>(
        &self,
        registers: &Registers<L>,
        phase: usize,
        start: usize,
        lane: usize,
    ) -> SMatrix<f64, R, C> {
        match self.sources(phase, start, R * C) {
            Some(sources) => SMatrix::from_fn(|i, j| {
                registers
                    .get(sources[j * R + i])
                    .map_or(0.0, |lanes| lanes.get(lane).copied().unwrap_or(f64::NAN))
            }),
            None => SMatrix::repeat(f64::NAN),
        }
    }

    /// The `len` entries of the phase's result from `start` on every lane
    /// at once: `each(e, lanes)` for each entry e in order (zero on every
    /// lane for a structural zero, NaN if the result is shorter), each
    /// register found once for all the lanes.
    #[inline(always)]
    pub(crate) fn each_entry<const L: usize>(
        &self,
        registers: &Registers<L>,
        (phase, start, len): (usize, usize, usize),
        mut each: impl FnMut(usize, &[f64; L]),
    ) {
        let Some(sources) = self.sources(phase, start, len) else {
            (0..len).for_each(|e| each(e, &[f64::NAN; L]));
            return;
        };
        for (e, &source) in sources.iter().enumerate() {
            each(e, registers.get(source).unwrap_or(&[0.0; L]));
        }
    }

    /// The registers of the `len` entries of the phase's result from
    /// `start` (`None` if the result is shorter).
    #[inline(always)]
    fn sources(&self, phase: usize, start: usize, len: usize) -> Option<&[u32]> {
        (self.phases.get(phase))
            .and_then(|p| p.sources.get(start..))
            .and_then(|rest| rest.get(..len))
    }

    /// The phase's whole result on lane `lane`, into `out` (as long as
    /// [`KernelTape::len`]; an entry beyond `out` is left out).
    pub(crate) fn read<const L: usize>(
        &self,
        registers: &Registers<L>,
        phase: usize,
        lane: usize,
        out: &mut [f64],
    ) {
        let sources = self.phases.get(phase).map_or(&[][..], |p| &p.sources);
        for (o, &register) in out.iter_mut().zip(sources) {
            *o = registers
                .get(register)
                .map_or(0.0, |lanes| lanes.get(lane).copied().unwrap_or(f64::NAN));
        }
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
        let outputs: Vec<u32> = (100..110).collect();
        let layout = Layout::of(&parts, &outputs);
        assert_eq!(layout.starts, [0, 2, 6, 10]);
        assert_eq!(layout.len, 11);
        // Output k in register 100 + k; the matrix's (0, 0) is a
        // structural zero, and the last part's entry is outside it.
        assert_eq!(
            layout.sources,
            [100, 101, ZERO, 103, 102, 104, 105, 106, 107, 108, ZERO]
        );
    }
}
