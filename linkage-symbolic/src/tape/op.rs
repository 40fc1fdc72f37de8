//! The operations of a tape over f64 registers, and what each computes:
//! exactly what optimised Rust computes for the emitted expression it
//! stands for, so that a tape gives the compiled code's bits.
//!
//! Every operation is one IEEE operation or one call of the same `f64`
//! method the emitted code calls (the same libm function), never fused
//! (Rust contracts no `a * b + c` into a fused multiply-add). The two forms
//! LLVM rewrites in optimised code have operations of their own:
//! `x.powf(0.5)` is `|√x|` with `−∞ ↦ +∞` ([`Code::PowfHalf`]) and
//! `2.0.powf(x)` is `x.exp2()` ([`Code::Exp2`]); `x.powi(n)` is a chain of
//! multiplications (see `compile`).
//!
//! Two arithmetic operations in a row, the first's result read by the
//! second alone, run as one fused operation ([`Code::fused`]): the same two
//! roundings in the same order, one dispatch instead of two.

/// What an operation computes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Code {
    Add,
    Sub,
    Mul,
    Div,
    Neg,
    /// sin into the result register, cos into the second operand's.
    SinCos,
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Sinh,
    Cosh,
    Tanh,
    Sqrt,
    Exp,
    Exp2,
    Ln,
    Abs,
    Signum,
    /// `x.powf(0.5)` as LLVM lowers it: `|√x|`, and `+∞` at `−∞`.
    PowfHalf,
    /// `y.atan2(x)`: the first operand is y.
    Atan2,
    Hypot,
    Powf,
    // Fused: t = a ∘ b, then d = t ∘ c (`…Then…`) or d = c ∘ t
    // (`…Into…`), each ∘ an addition, a subtraction or a multiplication.
    AddThenAdd,
    AddThenSub,
    AddThenMul,
    SubThenAdd,
    SubThenSub,
    SubThenMul,
    MulThenAdd,
    MulThenSub,
    MulThenMul,
    AddIntoAdd,
    AddIntoSub,
    AddIntoMul,
    SubIntoAdd,
    SubIntoSub,
    SubIntoMul,
    MulIntoAdd,
    MulIntoSub,
    MulIntoMul,
}

/// The fused codes, by first operation, second operation and whether the
/// first's result is the second's left operand (each operation's index:
/// addition 0, subtraction 1, multiplication 2).
const FUSED: [[[Code; 2]; 3]; 3] = {
    use Code::*;
    [
        [
            [AddThenAdd, AddIntoAdd],
            [AddThenSub, AddIntoSub],
            [AddThenMul, AddIntoMul],
        ],
        [
            [SubThenAdd, SubIntoAdd],
            [SubThenSub, SubIntoSub],
            [SubThenMul, SubIntoMul],
        ],
        [
            [MulThenAdd, MulIntoAdd],
            [MulThenSub, MulIntoSub],
            [MulThenMul, MulIntoMul],
        ],
    ]
};

impl Code {
    /// Whether it reads a second operand.
    pub fn is_binary(self) -> bool {
        matches!(
            self,
            Code::Add | Code::Sub | Code::Mul | Code::Div | Code::Atan2 | Code::Hypot | Code::Powf
        ) || self.is_fused()
    }

    /// Whether it is two operations fused, reading a third operand.
    pub fn is_fused(self) -> bool {
        FUSED.as_flattened().as_flattened().contains(&self)
    }

    /// The addition, subtraction and multiplication's index.
    fn arithmetic(self) -> Option<usize> {
        match self {
            Code::Add => Some(0),
            Code::Sub => Some(1),
            Code::Mul => Some(2),
            _ => None,
        }
    }

    /// `first` then `then` as one operation: t = a `first` b, then
    /// d = t `then` c if `left` (t the left operand), else d = c `then` t;
    /// `None` unless both are additions, subtractions or multiplications.
    pub fn fused(first: Code, then: Code, left: bool) -> Option<Code> {
        let (i, j) = (first.arithmetic()?, then.arithmetic()?);
        Some(FUSED[i][j][usize::from(!left)])
    }
}

/// One operation: `d = code(a, b)`, registers being indices into the
/// register file; a unary operation ignores `b`, except [`Code::SinCos`],
/// which writes the sine to `d` and the cosine to `b`; only a fused
/// operation reads `c`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Op {
    pub code: Code,
    pub d: u32,
    pub a: u32,
    pub b: u32,
    pub c: u32,
}

/// `x.powf(0.5)` in optimised code.
fn powf_half(x: f64) -> f64 {
    if x == f64::NEG_INFINITY {
        f64::INFINITY
    } else {
        x.sqrt().abs()
    }
}

/// `x.sin_cos()` in a function of its own, where LLVM makes the sine and
/// the cosine one call of libm's `sincos`, as it does in the compiled
/// kernels. The interpreter calls it through a pointer LLVM cannot see
/// through: in line, amid the interpreter's stores, LLVM calls `sin` and
/// `cos` apart (the same bits at twice the cost).
#[inline(never)]
fn sin_cos(x: f64) -> (f64, f64) {
    x.sin_cos()
}

/// `d = g(f(a, b), c)` on every lane: two roundings, in this order.
#[inline(always)]
fn fused<const L: usize>(
    r: &mut [[f64; L]],
    (d, a, b, c): (usize, usize, usize, usize),
    f: impl Fn(f64, f64) -> f64,
    g: impl Fn(f64, f64) -> f64,
) {
    let (x, y, z) = (r[a], r[b], r[c]);
    let out = &mut r[d];
    for l in 0..L {
        out[l] = g(f(x[l], y[l]), z[l]);
    }
}

/// `d = f(a)` on every lane.
#[inline(always)]
fn unary<const L: usize>(r: &mut [[f64; L]], d: usize, a: usize, f: impl Fn(f64) -> f64) {
    let x = r[a];
    let out = &mut r[d];
    for l in 0..L {
        out[l] = f(x[l]);
    }
}

/// `d = f(a, b)` on every lane.
#[inline(always)]
fn binary<const L: usize>(
    r: &mut [[f64; L]],
    d: usize,
    a: usize,
    b: usize,
    f: impl Fn(f64, f64) -> f64,
) {
    let (x, y) = (r[a], r[b]);
    let out = &mut r[d];
    for l in 0..L {
        out[l] = f(x[l], y[l]);
    }
}

impl Op {
    /// The registers it writes.
    pub fn writes(self) -> impl Iterator<Item = u32> {
        let cos = (self.code == Code::SinCos).then_some(self.b);
        std::iter::once(self.d).chain(cos)
    }

    /// The registers it reads.
    pub fn reads(self) -> impl Iterator<Item = u32> {
        let second = self.code.is_binary().then_some(self.b);
        let third = self.code.is_fused().then_some(self.c);
        std::iter::once(self.a).chain(second).chain(third)
    }

    /// Runs the operation on L lanes of registers (the operands read before
    /// the result is written, so a result may reuse an operand's register).
    /// The register file's size is a power of two, `mask` one less: its
    /// registers are indexed through the mask, which spares the bounds
    /// checks (a tape's registers are inside its file, checked once when it
    /// was made).
    #[inline(always)]
    pub(crate) fn execute<const L: usize>(self, r: &mut [[f64; L]], mask: usize) {
        let (d, a, b, c) = (
            self.d as usize & mask,
            self.a as usize & mask,
            self.b as usize & mask,
            self.c as usize & mask,
        );
        let add = |x: f64, y: f64| x + y;
        let sub = |x: f64, y: f64| x - y;
        let mul = |x: f64, y: f64| x * y;
        let operands = (d, a, b, c);
        match self.code {
            Code::Add => binary(r, d, a, b, |x, y| x + y),
            Code::Sub => binary(r, d, a, b, |x, y| x - y),
            Code::Mul => binary(r, d, a, b, |x, y| x * y),
            Code::Div => binary(r, d, a, b, |x, y| x / y),
            Code::Neg => unary(r, d, a, |x| -x),
            Code::SinCos => {
                let x = r[a];
                let sin_cos = std::hint::black_box(sin_cos as fn(f64) -> (f64, f64));
                let mut sin = [0.0; L];
                let mut cos = [0.0; L];
                for l in 0..L {
                    (sin[l], cos[l]) = sin_cos(x[l]);
                }
                r[d] = sin;
                r[b] = cos;
            }
            Code::Sin => unary(r, d, a, f64::sin),
            Code::Cos => unary(r, d, a, f64::cos),
            Code::Tan => unary(r, d, a, f64::tan),
            Code::Asin => unary(r, d, a, f64::asin),
            Code::Acos => unary(r, d, a, f64::acos),
            Code::Atan => unary(r, d, a, f64::atan),
            Code::Sinh => unary(r, d, a, f64::sinh),
            Code::Cosh => unary(r, d, a, f64::cosh),
            Code::Tanh => unary(r, d, a, f64::tanh),
            Code::Sqrt => unary(r, d, a, f64::sqrt),
            Code::Exp => unary(r, d, a, f64::exp),
            Code::Exp2 => unary(r, d, a, f64::exp2),
            Code::Ln => unary(r, d, a, f64::ln),
            Code::Abs => unary(r, d, a, f64::abs),
            Code::Signum => unary(r, d, a, f64::signum),
            Code::PowfHalf => unary(r, d, a, powf_half),
            Code::Atan2 => binary(r, d, a, b, f64::atan2),
            Code::Hypot => binary(r, d, a, b, f64::hypot),
            Code::Powf => binary(r, d, a, b, f64::powf),
            Code::AddThenAdd => fused(r, operands, add, add),
            Code::AddThenSub => fused(r, operands, add, sub),
            Code::AddThenMul => fused(r, operands, add, mul),
            Code::SubThenAdd => fused(r, operands, sub, add),
            Code::SubThenSub => fused(r, operands, sub, sub),
            Code::SubThenMul => fused(r, operands, sub, mul),
            Code::MulThenAdd => fused(r, operands, mul, add),
            Code::MulThenSub => fused(r, operands, mul, sub),
            Code::MulThenMul => fused(r, operands, mul, mul),
            Code::AddIntoAdd => fused(r, operands, add, |t, z| z + t),
            Code::AddIntoSub => fused(r, operands, add, |t, z| z - t),
            Code::AddIntoMul => fused(r, operands, add, |t, z| z * t),
            Code::SubIntoAdd => fused(r, operands, sub, |t, z| z + t),
            Code::SubIntoSub => fused(r, operands, sub, |t, z| z - t),
            Code::SubIntoMul => fused(r, operands, sub, |t, z| z * t),
            Code::MulIntoAdd => fused(r, operands, mul, |t, z| z + t),
            Code::MulIntoSub => fused(r, operands, mul, |t, z| z - t),
            Code::MulIntoMul => fused(r, operands, mul, |t, z| z * t),
        }
    }
}
