//! The register files a thread evaluates tapes in: made once per tape and
//! thread, then reused, so that evaluating a kernel allocates nothing.
//! A small direct-mapped cache: each (program, kernel) has one slot; a
//! program that meets another in its slot makes its file again. Files of
//! one lane serve single evaluations, files of [`LANES`] lanes the
//! evaluations a batch asks for together.

use crate::mechanism::kernel_tape::KernelTape;
use linkage_symbolic::tape::Registers;
use std::cell::RefCell;

const SLOTS: usize = 128;

/// How many evaluations run together on a file of lanes.
pub(crate) const LANES: usize = 8;

struct Slot<const L: usize> {
    key: u64,
    registers: Registers<L>,
    /// A buffer a result may be read into.
    buffer: Vec<f64>,
}

type Files<const L: usize> = RefCell<Vec<Option<Slot<L>>>>;

thread_local! {
    static FILES: Files<1> = RefCell::new((0..SLOTS).map(|_| None).collect());
    static LANE_FILES: Files<LANES> = RefCell::new((0..SLOTS).map(|_| None).collect());
}

/// Runs `work` on this thread's register file for `kernel` of the program
/// `program`, with a buffer to read a result into (its length as the last
/// call left it). `work` must not evaluate another kernel.
#[inline(always)]
pub(crate) fn with_registers<R>(
    program: u64,
    kernel: &KernelTape,
    work: impl FnOnce(&mut Registers, &mut Vec<f64>) -> R,
) -> R {
    FILES.with(|files| in_slot(files, program, kernel, work))
}

/// [`with_registers`] on a file of [`LANES`] lanes.
pub(crate) fn with_lanes<R>(
    program: u64,
    kernel: &KernelTape,
    work: impl FnOnce(&mut Registers<LANES>, &mut Vec<f64>) -> R,
) -> R {
    LANE_FILES.with(|files| in_slot(files, program, kernel, work))
}

#[inline(always)]
fn in_slot<const L: usize, R>(
    files: &Files<L>,
    program: u64,
    kernel: &KernelTape,
    work: impl FnOnce(&mut Registers<L>, &mut Vec<f64>) -> R,
) -> R {
    let key = program.wrapping_mul(64).wrapping_add(kernel.index as u64);
    let mut files = files.borrow_mut();
    let slot = &mut files[(key.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 57) as usize % SLOTS];
    if slot.as_ref().is_none_or(|s| s.key != key) {
        *slot = Some(Slot {
            key,
            registers: kernel.tape.registers::<L>(),
            buffer: Vec::new(),
        });
    }
    match slot {
        Some(s) => work(&mut s.registers, &mut s.buffer),
        // Just filled.
        None => work(&mut kernel.tape.registers::<L>(), &mut Vec::new()),
    }
}
