//! Two arithmetic operations in a row made one ([`Code::fused`]): an
//! addition, subtraction or multiplication whose result is no output and is
//! read once, by an addition, subtraction or multiplication of the same
//! phase, runs inside its reader. The same two roundings in the same order,
//! so the tape's numbers do not change; its dispatches, which bound an
//! interpreter's speed, fall.

use super::builder::Builder;
use crate::tape::op::{Code, Op};

/// Fuses the builder's operations in pairs (a fused operation is no first
/// half of another), over its virtual registers, each written once.
pub(super) fn fuse(builder: &mut Builder) {
    let ops = &mut builder.ops;
    let mut reads = vec![0usize; builder.registers.len()];
    for op in ops.iter() {
        for r in op.reads() {
            reads[r as usize] += 1;
        }
    }
    // An output is read after its phase: never fused away.
    for (_, outputs) in &builder.phases {
        for &r in outputs {
            reads[r as usize] += 2;
        }
    }
    let mut writer = vec![usize::MAX; builder.registers.len()];
    for (k, op) in ops.iter().enumerate() {
        for w in op.writes() {
            writer[w as usize] = k;
        }
    }
    let mut phase_of = vec![builder.phases.len(); ops.len()];
    let mut start = 0;
    for (p, (end, _)) in builder.phases.iter().enumerate() {
        for phase in phase_of.iter_mut().take(*end).skip(start) {
            *phase = p;
        }
        start = *end;
    }
    let mut absorbed = vec![false; ops.len()];
    for j in 0..ops.len() {
        let reader = ops[j];
        if !reader.code.is_binary() {
            continue;
        }
        for (left, t, other) in [(true, reader.a, reader.b), (false, reader.b, reader.a)] {
            let k = writer[t as usize];
            let alone = k < j && !absorbed[k] && reads[t as usize] == 1;
            if !alone || phase_of[k] != phase_of[j] {
                continue;
            }
            let first = ops[k];
            if let Some(code) = Code::fused(first.code, reader.code, left) {
                ops[j] = Op {
                    code,
                    d: reader.d,
                    a: first.a,
                    b: first.b,
                    c: other,
                };
                absorbed[k] = true;
                break;
            }
        }
    }
    // The absorbed operations dropped, the phases' ends moved back.
    let mut before = Vec::with_capacity(ops.len() + 1);
    let mut count = 0;
    for &gone in &absorbed {
        before.push(count);
        count += usize::from(gone);
    }
    before.push(count);
    for (end, _) in &mut builder.phases {
        *end -= before[*end];
    }
    let mut k = 0;
    ops.retain(|_| {
        k += 1;
        !absorbed[k - 1]
    });
}
