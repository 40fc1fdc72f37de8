//! A tape: a flat list of operations over f64 registers, run phase by
//! phase on a register file made for it, which it reuses for every call
//! (a call allocates nothing). The register file holds, in order, the
//! inputs ([`Slots`]), the constants and the temporaries; it has L lanes,
//! so that one pass of the tape evaluates it at L inputs at once, each
//! lane computing what a call of one lane computes, bit for bit.

use super::error::TapeError;
use super::op::{Code, Op};
use super::part::Part;
use super::slots::{Input, Slots};
use std::sync::atomic::{AtomicU64, Ordering};

/// One phase of a tape: where its operations end, and its outputs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Phase {
    /// The end of its operations in the tape's list (they start where the
    /// previous phase's end).
    pub end: usize,
    /// The register of each output, in order.
    pub outputs: Vec<u32>,
    /// The parts of the result the outputs fill, in order.
    pub parts: Vec<Part>,
}

/// A compiled kernel: operations over f64 registers, in phases.
#[derive(Clone, Debug)]
pub struct Tape {
    /// Tells the register files made for this tape from others.
    id: u64,
    slots: Slots,
    /// The values of the registers after the inputs.
    constants: Vec<f64>,
    ops: Vec<Op>,
    phases: Vec<Phase>,
    /// The size of the register file.
    registers: usize,
    /// The coordinates (indices into q = (u, v)) whose sine and cosine are
    /// read from `TrigU` and `TrigV`, ascending.
    trig_coords: Vec<usize>,
}

/// The registers of one tape on L lanes, made by [`Tape::registers`]; the
/// inputs are written with [`Registers::set`] (one lane) or
/// [`Registers::set_lane`].
#[derive(Clone, Debug)]
pub struct Registers<const L: usize = 1> {
    /// The id of the tape it was made for.
    tape: u64,
    slots: Slots,
    values: Vec<[f64; L]>,
}

static NEXT_ID: AtomicU64 = AtomicU64::new(0);

impl Tape {
    /// A tape from its parts, if they are consistent: every register
    /// inside the file, no operation writing an input or a constant or
    /// both its results to one register, the phases in order and their
    /// outputs as many as their parts' entries.
    pub fn new(
        slots: Slots,
        constants: Vec<f64>,
        ops: Vec<Op>,
        phases: Vec<Phase>,
        registers: usize,
        trig_coords: Vec<usize>,
    ) -> Result<Tape, TapeError> {
        let invalid = |why: &'static str| Err(TapeError::Invalid(why));
        let first_temporary = slots.total() + constants.len();
        if first_temporary > registers || u32::try_from(registers).is_err() {
            return invalid("the register file is smaller than its inputs and constants");
        }
        let inside = |r: u32| (r as usize) < registers;
        for op in &ops {
            if !op.reads().all(inside) {
                return invalid("an operation reads a register outside the file");
            }
            if !op
                .writes()
                .all(|w| inside(w) && w as usize >= first_temporary)
            {
                return invalid("an operation writes an input, a constant or outside the file");
            }
            if op.code == Code::SinCos && op.d == op.b {
                return invalid("a sine and cosine written to one register");
            }
        }
        let mut start = 0;
        for phase in &phases {
            let outputs: usize = phase.parts.iter().map(|p| p.entries.len()).sum();
            if phase.end < start || phase.end > ops.len() {
                return invalid("the phases' operations out of order");
            }
            if phase.outputs.len() != outputs {
                return invalid("a phase's outputs not as many as its parts' entries");
            }
            if !phase.outputs.iter().all(|&r| inside(r)) {
                return invalid("an output outside the register file");
            }
            start = phase.end;
        }
        if start != ops.len() {
            return invalid("operations after the last phase");
        }
        if trig_coords.iter().any(|&k| k >= slots.m + slots.f) {
            return invalid("a sine and cosine of a coordinate the mechanism does not have");
        }
        Ok(Tape {
            id: NEXT_ID.fetch_add(1, Ordering::Relaxed),
            slots,
            constants,
            ops,
            phases,
            registers,
            trig_coords,
        })
    }

    /// Its operations, all phases in order.
    pub fn ops(&self) -> &[Op] {
        &self.ops
    }

    /// The values of the registers after the inputs.
    pub fn constants(&self) -> &[f64] {
        &self.constants
    }

    /// A phase: where its operations end, its outputs and their parts.
    pub fn phase(&self, phase: usize) -> Option<&Phase> {
        self.phases.get(phase)
    }

    /// The sizes its inputs are laid out by.
    pub fn slots(&self) -> Slots {
        self.slots
    }

    /// How many phases it runs in.
    pub fn phases(&self) -> usize {
        self.phases.len()
    }

    /// The parts of the result a phase's outputs fill, in order (empty for
    /// a phase it does not have).
    pub fn parts(&self, phase: usize) -> &[Part] {
        self.phases.get(phase).map_or(&[], |p| &p.parts)
    }

    /// How many outputs a phase has (0 for a phase it does not have).
    pub fn outputs(&self, phase: usize) -> usize {
        self.phases.get(phase).map_or(0, |p| p.outputs.len())
    }

    /// How many operations it runs in all.
    pub fn len(&self) -> usize {
        self.ops.len()
    }

    /// Whether it runs no operation (every output an input or a constant).
    pub fn is_empty(&self) -> bool {
        self.ops.is_empty()
    }

    /// The size of its register file.
    pub fn register_count(&self) -> usize {
        self.registers
    }

    /// The coordinates (indices into q = (u, v)) whose sine and cosine it
    /// reads from [`Input::TrigU`] and [`Input::TrigV`], ascending (none
    /// unless it was compiled with the sines and cosines given).
    pub fn trig_coords(&self) -> &[usize] {
        &self.trig_coords
    }

    /// A register file for this tape on L lanes (L ≥ 1), the constants in
    /// place and every input zero.
    pub fn registers<const L: usize>(&self) -> Registers<L> {
        const { assert!(L > 0, "a register file has at least one lane") };
        let mut values = vec![[0.0; L]; self.registers];
        let first = self.slots.total();
        for (register, &c) in values[first..].iter_mut().zip(&self.constants) {
            *register = [c; L];
        }
        Registers {
            tape: self.id,
            slots: self.slots,
            values,
        }
    }

    /// Runs a phase on one lane and writes its outputs to `out`. Phases run
    /// in order: a phase reads what the phases before it computed, and the
    /// inputs the caller wrote in between.
    pub fn run(
        &self,
        phase: usize,
        registers: &mut Registers,
        out: &mut [f64],
    ) -> Result<(), TapeError> {
        let outputs = self.check(phase, registers.tape, out.len())?;
        self.execute(phase, &mut registers.values);
        for (o, &r) in out.iter_mut().zip(outputs) {
            *o = registers.values[r as usize][0];
        }
        Ok(())
    }

    /// Runs a phase on every lane: `out[k][l]` is output k of lane l.
    pub fn run_lanes<const L: usize>(
        &self,
        phase: usize,
        registers: &mut Registers<L>,
        out: &mut [[f64; L]],
    ) -> Result<(), TapeError> {
        let outputs = self.check(phase, registers.tape, out.len())?;
        self.execute(phase, &mut registers.values);
        for (o, &r) in out.iter_mut().zip(outputs) {
            *o = registers.values[r as usize];
        }
        Ok(())
    }

    /// The phase's output registers, if the call fits the tape.
    fn check(&self, phase: usize, tape: u64, out: usize) -> Result<&[u32], TapeError> {
        if tape != self.id {
            return Err(TapeError::ForeignRegisters);
        }
        let Some(p) = self.phases.get(phase) else {
            return Err(TapeError::Phase {
                phase,
                phases: self.phases.len(),
            });
        };
        if out != p.outputs.len() {
            return Err(TapeError::OutputLength {
                phase,
                expected: p.outputs.len(),
                found: out,
            });
        }
        Ok(&p.outputs)
    }

    /// The interpreter: the phase's operations, in order.
    fn execute<const L: usize>(&self, phase: usize, registers: &mut [[f64; L]]) {
        let start = match phase {
            0 => 0,
            _ => self.phases[phase - 1].end,
        };
        for op in &self.ops[start..self.phases[phase].end] {
            op.execute(registers);
        }
    }
}

impl<const L: usize> Registers<L> {
    /// Writes an input on one lane.
    pub fn set_lane(&mut self, input: Input, lane: usize, values: &[f64]) -> Result<(), TapeError> {
        let range = self.slots.range(input);
        if values.len() != range.len() {
            return Err(TapeError::InputLength {
                input,
                expected: range.len(),
                found: values.len(),
            });
        }
        if lane >= L {
            return Err(TapeError::Lane { lane, lanes: L });
        }
        for (register, &value) in self.values[range].iter_mut().zip(values) {
            register[lane] = value;
        }
        Ok(())
    }
}

impl Registers<1> {
    /// Writes an input.
    pub fn set(&mut self, input: Input, values: &[f64]) -> Result<(), TapeError> {
        self.set_lane(input, 0, values)
    }
}
