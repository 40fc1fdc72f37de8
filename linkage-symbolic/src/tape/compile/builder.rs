//! The operations of a tape as they are read, over virtual registers (one
//! per value, each written once): constants folded, and the forms LLVM
//! rewrites in optimised code (`powi`, `powf` with a constant operand)
//! rewritten the same way, so that the tape computes what the compiled
//! code computes.

use crate::hasher::FastMap;
use crate::tape::op::{Code, Op};

/// A value while compiling: a virtual register, or a constant known now.
#[derive(Clone, Copy, Debug)]
pub(super) enum Val {
    Reg(u32),
    Const(f64),
}

/// What a virtual register holds.
#[derive(Clone, Copy, Debug)]
pub(super) enum Virtual {
    /// An input slot (its index is the slot's).
    Input,
    /// A constant.
    Constant(f64),
    /// The result of an operation.
    Temporary,
}

/// The program read so far.
pub(super) struct Builder {
    /// What each virtual register holds; the inputs first, in slot order.
    pub(super) registers: Vec<Virtual>,
    /// The operations over virtual registers.
    pub(super) ops: Vec<Op>,
    /// Each finished phase: where its operations end, and its outputs.
    pub(super) phases: Vec<(usize, Vec<u32>)>,
    /// The register of each constant, by its bits.
    constants: FastMap<u64, u32>,
}

impl Builder {
    pub(super) fn new(inputs: usize) -> Builder {
        Builder {
            registers: vec![Virtual::Input; inputs],
            ops: Vec::new(),
            phases: Vec::new(),
            constants: FastMap::default(),
        }
    }

    fn fresh(&mut self, kind: Virtual) -> u32 {
        let r = self.registers.len() as u32;
        self.registers.push(kind);
        r
    }

    /// The register holding a value (a constant gets one, shared by every
    /// use of the same bits).
    pub(super) fn register(&mut self, v: Val) -> u32 {
        match v {
            Val::Reg(r) => r,
            Val::Const(c) => match self.constants.get(&c.to_bits()) {
                Some(&r) => r,
                None => {
                    let r = self.fresh(Virtual::Constant(c));
                    self.constants.insert(c.to_bits(), r);
                    r
                }
            },
        }
    }

    /// `code(a)` or `code(a, b)`; on constants, its value now, computed by
    /// the same operation the tape would run.
    pub(super) fn op(&mut self, code: Code, a: Val, b: Val) -> Val {
        // A unary operation ignores its second operand.
        let b = if code.is_binary() { b } else { Val::Const(0.0) };
        if let (Val::Const(x), Val::Const(y)) = (a, b) {
            return Val::Const(match code {
                // LLVM folds `exp2(x)` as `pow(2, x)`.
                Code::Exp2 => fold(Code::Powf, 2.0, x),
                _ => fold(code, x, y),
            });
        }
        let a = self.register(a);
        let b = match code.is_binary() {
            true => self.register(b),
            false => 0,
        };
        let d = self.fresh(Virtual::Temporary);
        self.ops.push(Op {
            code,
            d,
            a,
            b,
            c: 0,
        });
        Val::Reg(d)
    }

    pub(super) fn unary(&mut self, code: Code, a: Val) -> Val {
        self.op(code, a, Val::Const(0.0))
    }

    /// `(a.sin(), a.cos())`.
    pub(super) fn sin_cos(&mut self, a: Val) -> (Val, Val) {
        if let Val::Const(x) = a {
            return (
                Val::Const(fold(Code::Sin, x, 0.0)),
                Val::Const(fold(Code::Cos, x, 0.0)),
            );
        }
        let a = self.register(a);
        let (d, b) = (
            self.fresh(Virtual::Temporary),
            self.fresh(Virtual::Temporary),
        );
        self.ops.push(Op {
            code: Code::SinCos,
            d,
            a,
            b,
            c: 0,
        });
        (Val::Reg(d), Val::Reg(b))
    }

    /// `a.powi(n)` as LLVM expands a constant exponent (and as
    /// compiler-builtins' `__powidf2` computes any): square and multiply,
    /// the result so far times the next square, `1 / x^|n|` for n < 0; of
    /// a constant, as LLVM folds it.
    pub(super) fn powi(&mut self, a: Val, n: i32) -> Val {
        // LLVM folds `powi` of a constant as `pow(x, n)` (C++'s
        // `std::pow(double, int)`), rounded once.
        if let Val::Const(x) = a {
            return Val::Const(fold(Code::Powf, x, f64::from(n)));
        }
        let mut bits = n.unsigned_abs();
        let mut result: Option<Val> = None;
        let mut square = a;
        while bits != 0 {
            if bits & 1 == 1 {
                result = Some(match result {
                    Some(r) => self.op(Code::Mul, r, square),
                    None => square,
                });
            }
            bits >>= 1;
            if bits != 0 {
                square = self.op(Code::Mul, square, square);
            }
        }
        let result = result.unwrap_or(Val::Const(1.0));
        if n < 0 {
            self.op(Code::Div, Val::Const(1.0), result)
        } else {
            result
        }
    }

    /// `a.powf(b)` as optimised code computes it: folded when both are
    /// constants; with a constant operand, rewritten as LLVM's library-call
    /// simplifier rewrites it (`1^y = 1`, `(2^k)^y = exp2(k·y)`,
    /// `x^−1 = 1/x`, `x^0 = 1`, `x^1 = x`, `x^2 = x·x`, `x^0.5 = |√x|`).
    pub(super) fn powf(&mut self, a: Val, b: Val) -> Val {
        match (a, b) {
            (Val::Const(_), Val::Const(_)) => self.op(Code::Powf, a, b),
            (Val::Const(base), _) => {
                if base == 1.0 {
                    return Val::Const(1.0);
                }
                let exponent = match exp2_scale(base) {
                    None => return self.op(Code::Powf, a, b),
                    Some(1) => b,
                    Some(-1) => self.unary(Code::Neg, b),
                    Some(k) => self.op(Code::Mul, b, Val::Const(f64::from(k))),
                };
                self.unary(Code::Exp2, exponent)
            }
            (_, Val::Const(y)) => {
                if y == -1.0 {
                    self.op(Code::Div, Val::Const(1.0), a)
                } else if y == 0.0 {
                    Val::Const(1.0)
                } else if y == 1.0 {
                    a
                } else if y == 2.0 {
                    self.op(Code::Mul, a, a)
                } else if y == 0.5 {
                    self.unary(Code::PowfHalf, a)
                } else {
                    self.op(Code::Powf, a, b)
                }
            }
            _ => self.op(Code::Powf, a, b),
        }
    }

    /// Ends a phase whose outputs are these values.
    pub(super) fn end_phase(&mut self, outputs: Vec<Val>) {
        let outputs = outputs.into_iter().map(|v| self.register(v)).collect();
        self.phases.push((self.ops.len(), outputs));
    }
}

#[cfg(test)]
impl Builder {
    /// The value of `v` when the inputs are `inputs` (a test's evaluator
    /// of the virtual program).
    pub(super) fn evaluate(&self, inputs: &[f64], v: Val) -> f64 {
        let mut r: Vec<[f64; 1]> = self
            .registers
            .iter()
            .enumerate()
            .map(|(k, kind)| match kind {
                Virtual::Input => [inputs[k]],
                Virtual::Constant(c) => [*c],
                Virtual::Temporary => [f64::NAN],
            })
            .collect();
        r.resize(r.len().next_power_of_two(), [f64::NAN]);
        let mask = r.len() - 1;
        for op in &self.ops {
            op.execute(&mut r, mask);
        }
        match v {
            Val::Reg(k) => r[k as usize][0],
            Val::Const(c) => c,
        }
    }
}

/// The value of an operation on constants, computed by the operation the
/// tape would run (the libm call optimised code makes at run time, and
/// LLVM when it folds the call while compiling).
fn fold(code: Code, x: f64, y: f64) -> f64 {
    let mut scratch = [[x], [y], [0.0], [0.0]];
    Op {
        code,
        d: 2,
        a: 0,
        b: 1,
        c: 0,
    }
    .execute(&mut scratch, 3);
    scratch[2][0]
}

/// k with `base = 2^k` (k ≠ 0; `2^k` or `2^−k` a whole number that fits 64
/// bits, as LLVM requires), the bases whose `powf` becomes `exp2`.
fn exp2_scale(base: f64) -> Option<i32> {
    if base.is_nan() || base <= 0.0 || base == 1.0 {
        return None;
    }
    let whole = if base.fract() == 0.0 {
        base
    } else if (1.0 / base).fract() == 0.0 {
        1.0 / base
    } else {
        return None;
    };
    let k = whole.log2();
    let fits = whole < 2f64.powi(64) && k.fract() == 0.0 && 2f64.powi(k as i32) == whole;
    let k = k as i32;
    match (fits, base > 1.0) {
        (true, true) => Some(k),
        (true, false) => Some(-k),
        (false, _) => None,
    }
}

#[cfg(test)]
mod tests {
    use super::{Builder, Val, exp2_scale};
    use std::hint::black_box;

    fn xs() -> impl Iterator<Item = f64> {
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        (0..2000).map(move |_| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let unit = (state >> 11) as f64 / (1u64 << 53) as f64;
            (unit - 0.5) * 7.0
        })
    }

    /// `powi` with a literal exponent, as optimised code computes it.
    macro_rules! literal_powi {
        ($x:expr, $n:expr, [$($k:literal),*]) => {
            match $n {
                $($k => $x.powi($k),)*
                _ => f64::NAN,
            }
        };
    }

    #[test]
    fn powi_gives_the_bits_of_f64_powi() {
        for n in -9..=12 {
            let mut b = Builder::new(1);
            let v = b.powi(Val::Reg(0), n);
            for x in xs() {
                let tape = b.evaluate(&[x], v);
                let runtime = x.powi(black_box(n));
                let literal = literal_powi!(
                    x,
                    n,
                    [
                        -9, -8, -7, -6, -5, -4, -3, -2, -1, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11,
                        12
                    ]
                );
                assert_eq!(
                    tape.to_bits(),
                    runtime.to_bits(),
                    "{x}^{n} (run-time exponent)"
                );
                assert_eq!(
                    tape.to_bits(),
                    literal.to_bits(),
                    "{x}^{n} (literal exponent)"
                );
            }
        }
    }

    #[test]
    fn powf_by_a_constant_is_what_optimised_code_computes() {
        for y in [-1.0, 0.0, 1.0, 2.0, 0.5, 1.5, -0.5] {
            let mut b = Builder::new(1);
            let v = b.powf(Val::Reg(0), Val::Const(y));
            for x in xs().chain([f64::NEG_INFINITY, -0.0, 0.0, f64::INFINITY]) {
                let tape = b.evaluate(&[x], v);
                let compiled = match y {
                    -1.0 => x.powf(-1.0),
                    0.0 => x.powf(0.0),
                    1.0 => x.powf(1.0),
                    2.0 => x.powf(2.0),
                    0.5 => x.powf(0.5),
                    1.5 => x.powf(1.5),
                    _ => x.powf(-0.5),
                };
                let same =
                    tape.to_bits() == compiled.to_bits() || tape.is_nan() && compiled.is_nan();
                assert!(
                    same,
                    "{x}.powf({y}): {tape} on the tape, {compiled} compiled"
                );
            }
        }
        for base in [2.0, 4.0, 0.5, 0.125, 3.0, 10.0] {
            let mut b = Builder::new(1);
            let v = b.powf(Val::Const(base), Val::Reg(0));
            for x in xs() {
                let tape = b.evaluate(&[x], v);
                let compiled = match base {
                    2.0 => 2f64.powf(x),
                    4.0 => 4f64.powf(x),
                    0.5 => 0.5f64.powf(x),
                    0.125 => 0.125f64.powf(x),
                    3.0 => 3f64.powf(x),
                    _ => 10f64.powf(x),
                };
                assert_eq!(tape.to_bits(), compiled.to_bits(), "{base}.powf({x})");
            }
        }
    }

    #[test]
    fn constants_fold_as_llvm_folds_them() {
        let mut b = Builder::new(0);
        let c = std::f64::consts::SQRT_2;
        let Val::Const(folded) = b.powi(Val::Const(c), 5) else {
            panic!("a constant's power is a constant");
        };
        assert_eq!(folded.to_bits(), c.powf(5.0).to_bits());
        assert_eq!(folded.to_bits(), std::f64::consts::SQRT_2.powi(5).to_bits());
        assert!(b.ops.is_empty());
    }

    #[test]
    fn the_bases_llvm_turns_into_exp2() {
        assert_eq!(exp2_scale(2.0), Some(1));
        assert_eq!(exp2_scale(8.0), Some(3));
        assert_eq!(exp2_scale(0.25), Some(-2));
        assert_eq!(exp2_scale(2f64.powi(63)), Some(63));
        for no in [1.0, 3.0, 0.3, -2.0, 0.0, 10.0, 2f64.powi(64), f64::NAN] {
            assert_eq!(exp2_scale(no), None, "{no}");
        }
    }
}
