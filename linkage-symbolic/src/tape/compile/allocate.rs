//! Registers for the virtual ones: the inputs keep their slots, the
//! constants follow them, and the temporaries share what is left, a
//! register reused once its value is dead (its last reader has run, or,
//! for an output, its phase has ended) — but a value of one phase that a
//! later phase reads keeps its register, so that a later phase can run
//! again on its own. Operations whose results nothing reads are dropped.

use super::builder::{Builder, Virtual};
use crate::tape::op::{Code, Op};
use crate::tape::program::Phase;

/// The physical program: the constants' values, the operations, each
/// phase's end and outputs, and the size of the register file.
pub(super) struct Allocated {
    pub(super) constants: Vec<f64>,
    pub(super) ops: Vec<Op>,
    pub(super) phases: Vec<(usize, Vec<u32>)>,
    pub(super) registers: usize,
}

pub(super) fn allocate(builder: Builder) -> Allocated {
    let Builder {
        registers: virtuals,
        ops,
        phases,
        ..
    } = builder;
    // Which operations something reads, backwards from the outputs.
    let mut live = vec![false; virtuals.len()];
    for (_, outputs) in &phases {
        for &r in outputs {
            live[r as usize] = true;
        }
    }
    let mut kept = vec![false; ops.len()];
    for (k, op) in ops.iter().enumerate().rev() {
        if op.writes().any(|w| live[w as usize]) {
            kept[k] = true;
            for r in op.reads() {
                live[r as usize] = true;
            }
        }
    }
    // The phase of each operation.
    let mut phase_of = vec![0; ops.len()];
    let mut start = 0;
    for (p, (end, _)) in phases.iter().enumerate() {
        for phase in &mut phase_of[start..*end] {
            *phase = p;
        }
        start = *end;
    }
    let mut defined_in: Vec<Option<usize>> = vec![None; virtuals.len()];
    for (k, op) in ops.iter().enumerate() {
        for w in op.writes() {
            defined_in[w as usize] = Some(phase_of[k]);
        }
    }
    // Positions: operation k at 2k + 1, the end of a phase ending before
    // operation e at 2e (after its last operation, before the next one).
    // A value a later phase reads stays for good: a later phase may run
    // again (with other late inputs) without the phases before it.
    let mut last_use: Vec<Option<usize>> = vec![None; virtuals.len()];
    let mut pinned = vec![false; virtuals.len()];
    let mut used = |r: u32, at: usize, phase: usize| {
        let r = r as usize;
        last_use[r] = Some(last_use[r].unwrap_or(0).max(at));
        if defined_in[r].is_some_and(|p| p < phase) {
            pinned[r] = true;
        }
    };
    for (k, op) in ops.iter().enumerate().filter(|(k, _)| kept[*k]) {
        for r in op.reads() {
            used(r, 2 * k + 1, phase_of[k]);
        }
    }
    for (p, (end, outputs)) in phases.iter().enumerate() {
        for &r in outputs {
            used(r, 2 * end, p);
        }
    }
    let mut deaths: Vec<Vec<u32>> = vec![Vec::new(); 2 * ops.len() + 2];
    for (r, kind) in virtuals.iter().enumerate() {
        if let (Virtual::Temporary, Some(at), false) = (kind, last_use[r], pinned[r]) {
            deaths[at].push(r as u32);
        }
    }

    // The inputs keep their slots; the constants follow.
    let inputs = virtuals
        .iter()
        .take_while(|v| matches!(v, Virtual::Input))
        .count();
    let mut physical: Vec<u32> = vec![u32::MAX; virtuals.len()];
    let mut constants = Vec::new();
    for (r, kind) in virtuals.iter().enumerate() {
        match kind {
            Virtual::Input => physical[r] = r as u32,
            Virtual::Constant(c) if live[r] => {
                physical[r] = (inputs + constants.len()) as u32;
                constants.push(*c);
            }
            _ => {}
        }
    }
    let first_temporary = inputs + constants.len();
    let mut registers = first_temporary;
    let mut free: Vec<u32> = Vec::new();
    // A free register: the last one freed, or a new one.
    let mut take = |free: &mut Vec<u32>| match free.pop() {
        Some(r) => r,
        None => {
            registers += 1;
            (registers - 1) as u32
        }
    };

    let mut out_ops = Vec::with_capacity(ops.len());
    let mut ends = phases.iter().map(|(end, _)| *end).peekable();
    let mut out_ends = Vec::with_capacity(phases.len());
    for (k, op) in ops.iter().enumerate() {
        // The phases that ended before this operation.
        while let Some(end) = ends.next_if(|&e| e <= k) {
            out_ends.push(out_ops.len());
            free.extend(deaths[2 * end].iter().map(|&r| physical[r as usize]));
        }
        if !kept[k] {
            continue;
        }
        let a = physical[op.a as usize];
        let mut b = match op.code.is_binary() {
            true => physical[op.b as usize],
            false => 0,
        };
        let c = match op.code.is_fused() {
            true => physical[op.c as usize],
            false => 0,
        };
        // The operands read last here free their registers for the result.
        free.extend(deaths[2 * k + 1].iter().map(|&r| physical[r as usize]));
        let d = take(&mut free);
        physical[op.d as usize] = d;
        if op.code == Code::SinCos {
            b = take(&mut free);
            physical[op.b as usize] = b;
        }
        out_ops.push(Op {
            code: op.code,
            d,
            a,
            b,
            c,
        });
        // A result nothing reads (the unused half of a sine and cosine).
        for w in op.writes() {
            if last_use[w as usize].is_none() {
                free.push(physical[w as usize]);
            }
        }
    }
    for end in ends {
        out_ends.push(out_ops.len());
        free.extend(deaths[2 * end].iter().map(|&r| physical[r as usize]));
    }
    let phases = phases
        .iter()
        .zip(out_ends)
        .map(|((_, outputs), end)| (end, outputs.iter().map(|&r| physical[r as usize]).collect()))
        .collect();
    Allocated {
        constants,
        ops: out_ops,
        phases,
        registers,
    }
}

/// The program's phases with their parts.
pub(super) fn phases(allocated: &Allocated, parts: Vec<Vec<crate::tape::Part>>) -> Vec<Phase> {
    allocated
        .phases
        .iter()
        .zip(parts)
        .map(|((end, outputs), parts)| Phase {
            end: *end,
            outputs: outputs.clone(),
            parts,
        })
        .collect()
}
