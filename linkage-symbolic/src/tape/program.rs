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
    /// How many registers it uses (its file has the next power of two).
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
    /// How many of its registers are inputs ([`Slots::total`]).
    inputs: usize,
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

    /// How many registers it uses (inputs, constants and temporaries).
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
    /// place and every input zero; its size is the power of two at or
    /// above the registers the tape uses.
    pub fn registers<const L: usize>(&self) -> Registers<L> {
        const { assert!(L > 0, "a register file has at least one lane") };
        let mut values = vec![[0.0; L]; self.registers.next_power_of_two()];
        let first = self.slots.total();
        for (register, &c) in values[first..].iter_mut().zip(&self.constants) {
            *register = [c; L];
        }
        Registers {
            tape: self.id,
            slots: self.slots,
            inputs: first,
            values,
        }
    }

    /// Runs a phase on one lane and writes its outputs to `out`. Phases run
    /// in order: a phase reads what the phases before it computed, and the
    /// inputs the caller wrote in between; a later phase may run again on
    /// its own (γ at another u̇), the registers it reads of earlier phases
    /// kept.
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

    /// Runs a phase on every lane and leaves its outputs in the registers
    /// (those of [`Phase::outputs`], read with [`Registers::get`]).
    #[inline]
    pub fn run_phase<const L: usize>(
        &self,
        phase: usize,
        registers: &mut Registers<L>,
    ) -> Result<(), TapeError> {
        if registers.tape != self.id {
            return Err(TapeError::ForeignRegisters);
        }
        if phase >= self.phases.len() {
            return Err(TapeError::Phase {
                phase,
                phases: self.phases.len(),
            });
        }
        self.execute(phase, &mut registers.values);
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

    /// The interpreter: the phase's operations, in order, on a file whose
    /// size is a power of two (every file this tape made).
    fn execute<const L: usize>(&self, phase: usize, registers: &mut [[f64; L]]) {
        let start = match phase {
            0 => 0,
            _ => self.phases[phase - 1].end,
        };
        let size = registers.len();
        if !size.is_power_of_two() {
            return;
        }
        for op in &self.ops[start..self.phases[phase].end] {
            op.execute(registers, size - 1);
        }
    }
}

impl<const L: usize> Registers<L> {
    /// Writes an input on one lane.
    #[inline]
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
        self.set_at(range.start, lane, values);
        Ok(())
    }
}

impl<const L: usize> Registers<L> {
    /// Writes `values` to lane `lane` of the input registers from `start`
    /// on (laid out by [`Slots::range`]), unchecked against the inputs'
    /// sizes: for a caller that knows the offsets ahead (a view of fixed m
    /// and f) and the values' lengths. Nothing outside the inputs is
    /// within its reach: a write that would leave them writes nothing, and
    /// a lane the file lacks is not written.
    #[inline(always)]
    pub fn set_at(&mut self, start: usize, lane: usize, values: &[f64]) {
        let inputs = self.inputs.min(self.values.len());
        let inputs = &mut self.values[..inputs];
        if let Some(registers) = inputs.get_mut(start..start + values.len()) {
            for (register, &value) in registers.iter_mut().zip(values) {
                if let Some(x) = register.get_mut(lane) {
                    *x = value;
                }
            }
        }
    }

    /// The value of a register on every lane (`None` outside the file).
    #[inline(always)]
    pub fn get(&self, register: u32) -> Option<&[f64; L]> {
        self.values.get(register as usize)
    }
}

impl Registers<1> {
    /// Writes an input.
    #[inline]
    pub fn set(&mut self, input: Input, values: &[f64]) -> Result<(), TapeError> {
        self.set_lane(input, 0, values)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tape::part::Form;

    fn column(name: &'static str, rows: usize) -> Part {
        Part {
            name,
            form: Form::Matrix,
            rows,
            cols: 1,
            entries: (0..rows).map(|i| (i, 0)).collect(),
        }
    }

    fn op(code: Code, d: u32, a: u32, b: u32) -> Op {
        Op {
            code,
            d,
            a,
            b,
            c: 0,
        }
    }

    /// m = 1, f = 0, one field: the inputs u, u̇, ü, (sin u, cos u) and
    /// the field in registers 0–5, the constant 2 in 6. Phase 0 gives
    /// (u·l + 2, sin u, cos u), phase 1 u̇ times the first.
    fn example() -> Tape {
        let slots = Slots {
            m: 1,
            f: 0,
            fields: 1,
        };
        let ops = vec![
            op(Code::Mul, 7, 0, 5),
            op(Code::Add, 7, 7, 6),
            op(Code::SinCos, 8, 0, 9),
            op(Code::Mul, 8, 1, 7),
        ];
        let phases = vec![
            Phase {
                end: 3,
                outputs: vec![7, 8, 9],
                parts: vec![column("first", 3)],
            },
            Phase {
                end: 4,
                outputs: vec![8],
                parts: vec![column("second", 1)],
            },
        ];
        Tape::new(slots, vec![2.0], ops, phases, 10, Vec::new()).expect("a consistent tape")
    }

    /// Inputs of every length up to beyond those copied in line land in
    /// their registers, on their lane only.
    #[test]
    fn an_input_of_any_length_is_written_to_its_lane() {
        for fields in 1..=12 {
            let slots = Slots { m: 1, f: 0, fields };
            let tape = Tape::new(
                slots,
                Vec::new(),
                Vec::new(),
                Vec::new(),
                slots.total(),
                Vec::new(),
            )
            .expect("a tape of no operation");
            let values: Vec<f64> = (0..fields).map(|k| k as f64 + 0.5).collect();
            let mut lanes = tape.registers::<3>();
            lanes.set_lane(Input::Fields, 1, &values).unwrap();
            let range = slots.range(Input::Fields);
            for (k, register) in range.clone().enumerate() {
                assert_eq!(lanes.get(register as u32), Some(&[0.0, values[k], 0.0]));
            }
            let mut one = tape.registers::<1>();
            one.set(Input::Fields, &values).unwrap();
            for (k, register) in range.enumerate() {
                assert_eq!(one.get(register as u32), Some(&[values[k]]));
            }
            assert!(one.set(Input::Fields, &values[1..]).is_err());
            // Written at the offset the layout gives: the same registers,
            // and none beyond the inputs within reach.
            let mut direct = tape.registers::<1>();
            direct.set_at(slots.range(Input::Fields).start, 0, &values);
            let mut beyond = tape.registers::<1>();
            beyond.set_at(slots.total() - 1, 0, &[1.0, 2.0]);
            assert!((0..slots.total() as u32).all(|r| beyond.get(r) == Some(&[0.0])));
            for register in 0..slots.total() as u32 {
                assert_eq!(direct.get(register), one.get(register));
            }
        }
    }

    #[test]
    fn phases_run_in_order_on_the_registers_they_share() {
        let tape = example();
        let mut r = tape.registers::<1>();
        r.set(Input::U, &[0.7]).unwrap();
        r.set(Input::Fields, &[3.0]).unwrap();
        let mut first = [0.0; 3];
        tape.run(0, &mut r, &mut first).unwrap();
        assert_eq!(first, [0.7 * 3.0 + 2.0, 0.7_f64.sin(), 0.7_f64.cos()]);
        r.set(Input::Udot, &[-1.5]).unwrap();
        let mut second = [0.0];
        tape.run(1, &mut r, &mut second).unwrap();
        assert_eq!(second, [-1.5 * (0.7 * 3.0 + 2.0)]);
    }

    #[test]
    fn a_phase_run_leaves_its_outputs_in_their_registers() {
        let tape = example();
        let mut r = tape.registers::<1>();
        r.set(Input::U, &[0.7]).unwrap();
        r.set(Input::Fields, &[3.0]).unwrap();
        let mut listed = [0.0; 3];
        tape.run(0, &mut r, &mut listed).unwrap();
        // On two lanes, the first as above.
        let mut lanes = tape.registers::<2>();
        for (l, u) in [0.7, -0.2].into_iter().enumerate() {
            lanes.set_lane(Input::U, l, &[u]).unwrap();
            lanes.set_lane(Input::Fields, l, &[3.0]).unwrap();
        }
        tape.run_phase(0, &mut lanes).unwrap();
        let outputs = &tape.phase(0).unwrap().outputs;
        for (k, &register) in outputs.iter().enumerate() {
            let value = lanes.get(register).unwrap();
            assert_eq!(value[0].to_bits(), listed[k].to_bits());
        }
        assert_ne!(lanes.get(outputs[0]).unwrap()[1], listed[0]);
        assert_eq!(lanes.get(u32::MAX), None);
        assert_eq!(
            tape.run_phase(2, &mut lanes),
            Err(TapeError::Phase {
                phase: 2,
                phases: 2
            })
        );
        let mut foreign = example().registers::<2>();
        assert_eq!(
            tape.run_phase(0, &mut foreign),
            Err(TapeError::ForeignRegisters)
        );
    }

    #[test]
    fn each_lane_computes_what_one_lane_does() {
        let tape = example();
        let mut lanes = tape.registers::<4>();
        let us = [0.1, -2.0, 3.5, 1e-9];
        let udots = [1.0, 2.0, -3.0, 0.5];
        for (l, (&u, &udot)) in us.iter().zip(&udots).enumerate() {
            lanes.set_lane(Input::U, l, &[u]).unwrap();
            lanes.set_lane(Input::Udot, l, &[udot]).unwrap();
            lanes.set_lane(Input::Fields, l, &[0.3]).unwrap();
        }
        let mut out = [[0.0; 4]; 3];
        tape.run_lanes(0, &mut lanes, &mut out).unwrap();
        let mut second = [[0.0; 4]; 1];
        tape.run_lanes(1, &mut lanes, &mut second).unwrap();
        for (l, (&u, &udot)) in us.iter().zip(&udots).enumerate() {
            let mut one = tape.registers::<1>();
            one.set(Input::U, &[u]).unwrap();
            one.set(Input::Udot, &[udot]).unwrap();
            one.set(Input::Fields, &[0.3]).unwrap();
            let mut first = [0.0; 3];
            tape.run(0, &mut one, &mut first).unwrap();
            let mut next = [0.0];
            tape.run(1, &mut one, &mut next).unwrap();
            for k in 0..3 {
                assert_eq!(out[k][l].to_bits(), first[k].to_bits());
            }
            assert_eq!(second[0][l].to_bits(), next[0].to_bits());
        }
    }

    #[test]
    fn a_call_that_does_not_fit_is_an_error() {
        let tape = example();
        let mut r = tape.registers::<1>();
        assert_eq!(
            r.set(Input::U, &[1.0, 2.0]),
            Err(TapeError::InputLength {
                input: Input::U,
                expected: 1,
                found: 2
            })
        );
        assert_eq!(
            r.set(Input::V, &[1.0]),
            Err(TapeError::InputLength {
                input: Input::V,
                expected: 0,
                found: 1
            })
        );
        let mut lanes = tape.registers::<2>();
        assert_eq!(
            lanes.set_lane(Input::U, 2, &[1.0]),
            Err(TapeError::Lane { lane: 2, lanes: 2 })
        );
        assert_eq!(
            tape.run(2, &mut r, &mut []),
            Err(TapeError::Phase {
                phase: 2,
                phases: 2
            })
        );
        assert_eq!(
            tape.run(0, &mut r, &mut [0.0; 2]),
            Err(TapeError::OutputLength {
                phase: 0,
                expected: 3,
                found: 2
            })
        );
        // Another tape, identical but for its identity.
        let mut foreign = example().registers::<1>();
        assert_eq!(
            tape.run(0, &mut foreign, &mut [0.0; 3]),
            Err(TapeError::ForeignRegisters)
        );
    }

    #[test]
    fn an_inconsistent_tape_is_refused() {
        let slots = Slots {
            m: 1,
            f: 0,
            fields: 1,
        };
        let phase = |end, outputs: Vec<u32>| Phase {
            end,
            parts: vec![column("x", outputs.len())],
            outputs,
        };
        let cases = [
            // Writes the input u.
            (vec![op(Code::Neg, 0, 1, 0)], vec![phase(1, vec![0])], 8),
            // Writes the constant.
            (vec![op(Code::Neg, 6, 1, 0)], vec![phase(1, vec![6])], 8),
            // Reads outside the file.
            (vec![op(Code::Add, 7, 1, 8)], vec![phase(1, vec![7])], 8),
            // Sine and cosine into one register.
            (vec![op(Code::SinCos, 7, 0, 7)], vec![phase(1, vec![7])], 8),
            // An output outside the file.
            (vec![op(Code::Neg, 7, 0, 0)], vec![phase(1, vec![9])], 8),
            // Operations after the last phase.
            (vec![op(Code::Neg, 7, 0, 0)], vec![phase(0, vec![7])], 8),
            // A file smaller than its inputs and constants.
            (Vec::new(), vec![phase(0, vec![0])], 6),
        ];
        for (ops, phases, registers) in cases {
            let tape = Tape::new(slots, vec![2.0], ops.clone(), phases, registers, Vec::new());
            assert!(
                matches!(tape, Err(TapeError::Invalid(_))),
                "{ops:?} accepted"
            );
        }
        let mismatched = Phase {
            end: 0,
            outputs: vec![0, 1],
            parts: vec![column("x", 1)],
        };
        let tape = Tape::new(
            slots,
            Vec::new(),
            Vec::new(),
            vec![mismatched],
            6,
            Vec::new(),
        );
        assert!(matches!(tape, Err(TapeError::Invalid(_))));
    }
}
