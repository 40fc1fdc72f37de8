//! Compiling a kernel of a built model into a tape: its plan's statements
//! emitted as the attribute emits them ([`crate::plan`]), read back as
//! rustc reads them, and turned into register operations.

mod allocate;
mod builder;
mod fuse;
mod read;

use super::program::Tape;
use super::slots::{Input, Slots};
use crate::dag::Symbol;
use crate::derivatives::Derivatives;
use crate::emit::Mode;
use crate::names::SymbolNames;
use crate::plan::{Kernel, Plan, PlannedPart, free_name};
use builder::Builder;
use read::Reader;
use std::fmt;

/// A kernel whose emitted code the tape compiler does not read: the
/// emitter wrote a form the compiler does not know (an internal error).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CompileError {
    /// The kernel's name, once known.
    pub kernel: &'static str,
    pub message: String,
}

impl CompileError {
    fn new(message: String) -> CompileError {
        CompileError {
            kernel: "",
            message,
        }
    }
}

impl fmt::Display for CompileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "the tape of `{}` cannot be compiled: {}",
            self.kernel, self.message
        )
    }
}

impl std::error::Error for CompileError {}

/// The tape of one kernel of a model.
pub fn compile(model: &Derivatives, kernel: Kernel) -> Result<Tape, CompileError> {
    compile_named(model, &model.lowered.names(), kernel, true)
}

/// The tapes of every kernel of a model ([`Kernel::every`]).
#[derive(Clone, Debug)]
pub struct Tapes {
    tapes: Vec<Tape>,
}

impl Tapes {
    pub fn build(model: &Derivatives) -> Result<Tapes, CompileError> {
        let names = model.lowered.names();
        let tapes = Kernel::every()
            .map(|kernel| compile_named(model, &names, kernel, true))
            .collect::<Result<_, _>>()?;
        Ok(Tapes { tapes })
    }

    /// The tape of a kernel.
    pub fn get(&self, kernel: Kernel) -> &Tape {
        &self.tapes[kernel.index().unwrap_or(0)]
    }
}

fn compile_named(
    model: &Derivatives,
    names: &SymbolNames,
    kernel: Kernel,
    fusing: bool,
) -> Result<Tape, CompileError> {
    let named = |mut e: CompileError| {
        e.kernel = kernel.name();
        e
    };
    let plan = kernel.plan(model);
    let slots = Slots {
        m: model.m(),
        f: model.f(),
        fields: model.lowered.fields.len(),
    };
    let trig = Plan::trig_names(names);
    // The names the generated function binds itself, as the generator
    // reserves them: its results', and the sine-and-cosine arrays'.
    let mut reserved: Vec<String> = plan
        .phases
        .iter()
        .flatten()
        .map(|p| free_name(names, p.part.name))
        .collect();
    reserved.extend(trig.iter().cloned());
    let phased = plan.emit(model.dag(), names, &reserved, Mode::F64);

    let mut builder = Builder::new(slots.total());
    let start = |input: Input| slots.range(input).start as u32;
    let inputs = Input::ALL.map(|i| (i, start(i), slots.len(i)));
    let fields = (0..slots.fields).map(|k| {
        let name = names.code(Symbol::Param(k as u16));
        (name, start(Input::Fields) + k as u32)
    });
    let late = plan.late.iter().filter_map(|&s| match s {
        Symbol::Vel(k) if (k as usize) < slots.m => {
            Some((names.code(s), start(Input::Udot) + u32::from(k)))
        }
        _ => None,
    });
    let mut reader = Reader::new(&mut builder, inputs, trig, fields, late);
    for statement in &phased.prologue {
        reader.statement(statement).map_err(named)?;
    }
    // Each phase's outputs: its parts' roots in order, of the parts the
    // kernel keeps (the operations the others alone need are dropped).
    let kept = |part: &PlannedPart| {
        kernel
            .kept_parts()
            .is_none_or(|k| k.contains(&part.part.name))
    };
    for ((statements, values), parts) in phased.phases.iter().zip(&plan.phases) {
        for statement in statements {
            reader.statement(statement).map_err(named)?;
        }
        let mut outputs = Vec::with_capacity(values.len());
        let mut rest = values.as_slice();
        for part in parts {
            let (these, after) = rest.split_at(part.roots.len().min(rest.len()));
            if kept(part) {
                outputs.extend_from_slice(these);
            }
            rest = after;
        }
        reader.end_phase(&outputs).map_err(named)?;
    }
    if fusing {
        fuse::fuse(&mut builder);
    }
    let allocated = allocate::allocate(builder);
    let parts = plan
        .phases
        .into_iter()
        .map(|parts| parts.into_iter().filter(kept).map(|p| p.part).collect())
        .collect();
    let phases = allocate::phases(&allocated, parts);
    Tape::new(
        slots,
        allocated.constants,
        allocated.ops,
        phases,
        allocated.registers,
        phased.trig_coords,
    )
    .map_err(|e| named(CompileError::new(e.to_string())))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tape::{Form, Registers};

    /// The worksheet's four-bar, built from its text.
    fn fourbar() -> Derivatives {
        let attr = "u = [theta3, theta4], v = [theta2],
            points = [
                B = (l2 * theta2.cos(), l2 * theta2.sin()),
                C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
            ],
            closure = [
                l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
                l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
            ]";
        let item = "pub struct FourBar { pub l1: f64, pub l2: f64, pub l3: f64, pub l4: f64 }";
        let mut errors = crate::errors::Errors::default();
        let input = crate::ast::Input::parse(
            attr.parse().expect("tokens"),
            item.parse().expect("tokens"),
            &mut errors,
        )
        .expect("a struct");
        match crate::build(&input, &mut errors) {
            Ok(model) => model,
            Err(_) => panic!("{:?}", errors.combined()),
        }
    }

    #[test]
    fn kinematics_runs_in_two_phases_sharing_its_registers() {
        let model = fourbar();
        let tapes = Tapes::build(&model).expect("every kernel compiles");
        for kernel in Kernel::every() {
            let phases = tapes.get(kernel).phases();
            let expected = if matches!(kernel, Kernel::Kinematics { .. }) {
                2
            } else {
                1
            };
            assert_eq!(phases, expected, "{}", kernel.name());
        }
        let tape = tapes.get(Kernel::Kinematics { with_trig: false });
        let names =
            |phase: usize| -> Vec<&str> { tape.parts(phase).iter().map(|p| p.name).collect() };
        assert_eq!(names(0), ["psi", "psi_u", "psi_v"]);
        assert_eq!(names(1), ["gamma"]);
        assert!(tape.parts(0).iter().all(|p| p.form == Form::Matrix));
        // γ = −l3·cos θ3·θ̇3² − …: it reads the u̇ written between phases.
        let mut r: Registers = tape.registers();
        r.set(Input::U, &[0.3, 1.2]).unwrap();
        r.set(Input::V, &[0.5]).unwrap();
        r.set(Input::Vdot, &[1.0]).unwrap();
        r.set(Input::Fields, &[4.0, 1.0, 3.0, 2.5]).unwrap();
        let mut first = vec![0.0; tape.outputs(0)];
        tape.run(0, &mut r, &mut first).unwrap();
        // Phase 1 twice, at two velocities, after one phase 0: the
        // registers of phase 0 it reads stay.
        let mut gamma = [[0.0; 2]; 2];
        for (k, udot) in [[0.0, 0.0], [2.0, -1.0]].iter().enumerate() {
            r.set(Input::Udot, udot).unwrap();
            tape.run(1, &mut r, &mut gamma[k]).unwrap();
        }
        assert_ne!(gamma[0], gamma[1]);
        let expected = -3.0 * 0.3_f64.cos() * 4.0 - 2.5 * 1.2_f64.cos() - 0.5_f64.cos();
        assert!((gamma[1][0] - expected).abs() < 1e-12, "{gamma:?}");
    }

    #[test]
    fn the_sines_and_cosines_given_replace_the_calls() {
        let model = fourbar();
        let computed = compile(&model, Kernel::Kinematics { with_trig: false }).unwrap();
        let given = compile(&model, Kernel::Kinematics { with_trig: true }).unwrap();
        let calls = |t: &Tape| {
            t.ops()
                .iter()
                .filter(|op| op.code == crate::tape::Code::SinCos)
                .count()
        };
        assert_eq!(calls(&computed), 3);
        assert_eq!(calls(&given), 0);
        assert_eq!(given.trig_coords(), [0, 1, 2]);
        assert!(computed.trig_coords().is_empty());
    }

    /// Fused operations give the bits of the two they replace, on every
    /// kernel, every phase and every lane, and the kinematics of the
    /// four-bar runs fewer of them.
    #[test]
    fn fusing_changes_the_dispatches_not_the_bits() {
        let model = fourbar();
        let names = model.lowered.names();
        let mut fewer = 0;
        for kernel in Kernel::every() {
            let fused = compile_named(&model, &names, kernel, true).unwrap();
            let plain = compile_named(&model, &names, kernel, false).unwrap();
            let count = |t: &Tape| t.ops().iter().filter(|op| op.code.is_fused()).count();
            assert_eq!(count(&plain), 0);
            assert_eq!(
                fused.len() + count(&fused),
                plain.len(),
                "{}",
                kernel.name()
            );
            fewer += plain.len() - fused.len();
            let slots = fused.slots();
            // Inputs of every sign and size, a different set per lane.
            let value = |k: usize, lane: usize| {
                let x = ((k * 7 + lane * 13) % 23) as f64 - 11.0;
                x * 0.37 + 0.01 * lane as f64
            };
            let mut a = fused.registers::<4>();
            let mut b = plain.registers::<4>();
            for input in Input::ALL {
                for lane in 0..4 {
                    let values: Vec<f64> = (0..slots.len(input)).map(|k| value(k, lane)).collect();
                    a.set_lane(input, lane, &values).unwrap();
                    b.set_lane(input, lane, &values).unwrap();
                }
            }
            for phase in 0..fused.phases() {
                let mut x = vec![[0.0; 4]; fused.outputs(phase)];
                let mut y = vec![[0.0; 4]; plain.outputs(phase)];
                fused.run_lanes(phase, &mut a, &mut x).unwrap();
                plain.run_lanes(phase, &mut b, &mut y).unwrap();
                let bits = |v: &[[f64; 4]]| -> Vec<u64> {
                    v.iter().flatten().map(|x| x.to_bits()).collect()
                };
                assert_eq!(bits(&x), bits(&y), "{} phase {phase}", kernel.name());
            }
        }
        assert!(fewer > 0);
        let kinematics = compile(&model, Kernel::Kinematics { with_trig: true }).unwrap();
        assert!(kinematics.ops().iter().any(|op| op.code.is_fused()));
    }

    #[test]
    fn registers_are_reused_and_nothing_unread_is_computed() {
        let model = fourbar();
        let tape = compile(&model, Kernel::SensitivityTerms { with_trig: false }).unwrap();
        let first_temporary = tape.slots().total() + tape.constants().len();
        let temporaries = tape.register_count() - first_temporary;
        assert!(
            temporaries < tape.len(),
            "{temporaries} registers for {} operations",
            tape.len()
        );
        // Every result is read by a later operation or is an output.
        let outputs: Vec<u32> = (0..tape.phases())
            .flat_map(|p| tape.phase(p).map(|p| p.outputs.clone()).unwrap_or_default())
            .collect();
        for (k, op) in tape.ops().iter().enumerate() {
            for w in op.writes() {
                let read_later = tape.ops()[k + 1..]
                    .iter()
                    .any(|later| later.reads().any(|r| r == w));
                assert!(
                    read_later || outputs.contains(&w),
                    "operation {k} ({op:?}) unread"
                );
            }
        }
    }
}
