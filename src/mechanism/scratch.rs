//! The register files a thread evaluates tapes in: made once per tape and
//! thread, then reused, so that evaluating a kernel allocates nothing.
//! A small direct-mapped cache: each (program, kernel) has one slot; a
//! program that meets another in its slot makes its file again.

use crate::mechanism::kernel_tape::KernelTape;
use linkage_symbolic::tape::Registers;
use std::cell::RefCell;

const SLOTS: usize = 128;

struct Slot {
    key: u64,
    registers: Registers,
    /// One buffer per phase for its result (see [`KernelTape::results`]).
    results: Vec<Vec<f64>>,
}

thread_local! {
    static FILES: RefCell<Vec<Option<Slot>>> = RefCell::new((0..SLOTS).map(|_| None).collect());
}

/// Runs `work` on this thread's register file for `kernel` of the program
/// `program`, with a buffer for each phase's result. `work` must not
/// evaluate another kernel.
pub(crate) fn with_registers<R>(
    program: u64,
    kernel: &KernelTape,
    work: impl FnOnce(&mut Registers, &mut [Vec<f64>]) -> R,
) -> R {
    let key = program.wrapping_mul(64).wrapping_add(kernel.index as u64);
    FILES.with(|files| {
        let mut files = files.borrow_mut();
        let slot = &mut files[(key.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 57) as usize % SLOTS];
        if slot.as_ref().is_none_or(|s| s.key != key) {
            *slot = Some(Slot {
                key,
                registers: kernel.tape.registers::<1>(),
                results: kernel.results(),
            });
        }
        match slot {
            Some(s) => work(&mut s.registers, &mut s.results),
            // Just filled.
            None => work(&mut kernel.tape.registers::<1>(), &mut kernel.results()),
        }
    })
}
