//! Compiling a kernel of a built model into a tape: its plan's statements
//! emitted as the attribute emits them ([`crate::plan`]), read back as
//! rustc reads them, and turned into register operations.

mod allocate;
mod builder;
mod read;

use super::program::Tape;
use super::slots::{Input, Slots};
use crate::dag::Symbol;
use crate::derivatives::Derivatives;
use crate::emit::Mode;
use crate::names::SymbolNames;
use crate::plan::{Kernel, Plan, free_name};
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
    compile_named(model, &model.lowered.names(), kernel)
}

/// The tapes of every kernel of a model ([`Kernel::ALL`]).
#[derive(Clone, Debug)]
pub struct Tapes {
    tapes: Vec<Tape>,
}

impl Tapes {
    pub fn build(model: &Derivatives) -> Result<Tapes, CompileError> {
        let names = model.lowered.names();
        let tapes = Kernel::ALL
            .iter()
            .map(|&kernel| compile_named(model, &names, kernel))
            .collect::<Result<_, _>>()?;
        Ok(Tapes { tapes })
    }

    /// The tape of a kernel.
    pub fn get(&self, kernel: Kernel) -> &Tape {
        let k = Kernel::ALL.iter().position(|&k| k == kernel).unwrap_or(0);
        &self.tapes[k]
    }
}

fn compile_named(
    model: &Derivatives,
    names: &SymbolNames,
    kernel: Kernel,
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
    for (statements, values) in &phased.phases {
        for statement in statements {
            reader.statement(statement).map_err(named)?;
        }
        reader.end_phase(values).map_err(named)?;
    }
    let allocated = allocate::allocate(builder);
    let parts = plan
        .phases
        .into_iter()
        .map(|parts| parts.into_iter().map(|p| p.part).collect())
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
