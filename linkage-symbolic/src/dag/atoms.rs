//! The vocabulary of the DAG: node handles, symbols, the named constants,
//! the functions of one and two arguments, exact numbers, and the nodes.

/// The handle of a node in the [`Dag`](super::Dag).
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub struct Id(pub(super) u32);

impl Id {
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// A leaf: a parameter, a coordinate or one of its time derivatives, or a
/// named mathematical constant.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub enum Symbol {
    /// The struct field with this index among the `f64` parameters.
    Param(u16),
    /// The coordinate `q[k]` (u first, then v).
    Coord(u16),
    /// Its velocity `q̇[k]`.
    Vel(u16),
    /// Its acceleration `q̈[k]`.
    Acc(u16),
    /// A constant of `core::f64::consts`.
    Constant(Constant),
}

/// The constants of `core::f64::consts` an expression may name.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub enum Constant {
    Pi,
    Tau,
    E,
    FracPi2,
    FracPi3,
    FracPi4,
    FracPi6,
    FracPi8,
    Frac1Pi,
    Frac2Pi,
    Frac2SqrtPi,
    Sqrt2,
    Frac1Sqrt2,
    Ln2,
    Ln10,
    Log2E,
    Log10E,
    Log2_10,
    Log10_2,
}

impl Constant {
    pub const ALL: [Constant; 19] = [
        Constant::Pi,
        Constant::Tau,
        Constant::E,
        Constant::FracPi2,
        Constant::FracPi3,
        Constant::FracPi4,
        Constant::FracPi6,
        Constant::FracPi8,
        Constant::Frac1Pi,
        Constant::Frac2Pi,
        Constant::Frac2SqrtPi,
        Constant::Sqrt2,
        Constant::Frac1Sqrt2,
        Constant::Ln2,
        Constant::Ln10,
        Constant::Log2E,
        Constant::Log10E,
        Constant::Log2_10,
        Constant::Log10_2,
    ];

    /// The name in `core::f64::consts`.
    pub fn name(self) -> &'static str {
        use Constant::*;
        match self {
            Pi => "PI",
            Tau => "TAU",
            E => "E",
            FracPi2 => "FRAC_PI_2",
            FracPi3 => "FRAC_PI_3",
            FracPi4 => "FRAC_PI_4",
            FracPi6 => "FRAC_PI_6",
            FracPi8 => "FRAC_PI_8",
            Frac1Pi => "FRAC_1_PI",
            Frac2Pi => "FRAC_2_PI",
            Frac2SqrtPi => "FRAC_2_SQRT_PI",
            Sqrt2 => "SQRT_2",
            Frac1Sqrt2 => "FRAC_1_SQRT_2",
            Ln2 => "LN_2",
            Ln10 => "LN_10",
            Log2E => "LOG2_E",
            Log10E => "LOG10_E",
            Log2_10 => "LOG2_10",
            Log10_2 => "LOG10_2",
        }
    }

    /// The constant's value.
    pub fn value(self) -> f64 {
        use Constant::*;
        use std::f64::consts as c;
        match self {
            Pi => c::PI,
            Tau => c::TAU,
            E => c::E,
            FracPi2 => c::FRAC_PI_2,
            FracPi3 => c::FRAC_PI_3,
            FracPi4 => c::FRAC_PI_4,
            FracPi6 => c::FRAC_PI_6,
            FracPi8 => c::FRAC_PI_8,
            Frac1Pi => c::FRAC_1_PI,
            Frac2Pi => c::FRAC_2_PI,
            Frac2SqrtPi => c::FRAC_2_SQRT_PI,
            Sqrt2 => c::SQRT_2,
            Frac1Sqrt2 => c::FRAC_1_SQRT_2,
            Ln2 => c::LN_2,
            Ln10 => c::LN_10,
            Log2E => c::LOG2_E,
            Log10E => c::LOG10_E,
            Log2_10 => c::LOG2_10,
            Log10_2 => c::LOG10_2,
        }
    }

    pub fn from_name(name: &str) -> Option<Constant> {
        Constant::ALL.into_iter().find(|c| c.name() == name)
    }
}

/// A function of one argument.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub enum Func {
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
    Ln,
    Abs,
    /// The derivative of `abs`; not callable from an attribute.
    Signum,
}

impl Func {
    /// The Rust method name (`x.sin()`).
    pub fn method(self) -> &'static str {
        use Func::*;
        match self {
            Sin => "sin",
            Cos => "cos",
            Tan => "tan",
            Asin => "asin",
            Acos => "acos",
            Atan => "atan",
            Sinh => "sinh",
            Cosh => "cosh",
            Tanh => "tanh",
            Sqrt => "sqrt",
            Exp => "exp",
            Ln => "ln",
            Abs => "abs",
            Signum => "signum",
        }
    }

    pub fn eval(self, x: f64) -> f64 {
        use Func::*;
        match self {
            Sin => x.sin(),
            Cos => x.cos(),
            Tan => x.tan(),
            Asin => x.asin(),
            Acos => x.acos(),
            Atan => x.atan(),
            Sinh => x.sinh(),
            Cosh => x.cosh(),
            Tanh => x.tanh(),
            Sqrt => x.sqrt(),
            Exp => x.exp(),
            Ln => x.ln(),
            Abs => x.abs(),
            Signum => {
                if x == 0.0 {
                    0.0
                } else {
                    x.signum()
                }
            }
        }
    }

    /// `f(−x) = −f(x)`.
    pub(super) fn is_odd(self) -> bool {
        use Func::*;
        matches!(self, Sin | Tan | Asin | Atan | Sinh | Tanh | Signum)
    }

    /// `f(−x) = f(x)`.
    pub(super) fn is_even(self) -> bool {
        use Func::*;
        matches!(self, Cos | Cosh | Abs)
    }
}

/// A function of two arguments.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub enum Func2 {
    /// `y.atan2(x)`: the first argument is `y`.
    Atan2,
    Hypot,
    Powf,
}

impl Func2 {
    pub fn method(self) -> &'static str {
        match self {
            Func2::Atan2 => "atan2",
            Func2::Hypot => "hypot",
            Func2::Powf => "powf",
        }
    }

    pub fn eval(self, a: f64, b: f64) -> f64 {
        match self {
            Func2::Atan2 => a.atan2(b),
            Func2::Hypot => a.hypot(b),
            Func2::Powf => a.powf(b),
        }
    }
}

/// A finite `f64` as a hashable key; `-0.0` is stored as `0.0`.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub struct Num(pub(super) u64);

impl Num {
    pub(super) fn new(x: f64) -> Num {
        debug_assert!(x.is_finite());
        Num(if x == 0.0 { 0 } else { x.to_bits() })
    }

    pub fn get(self) -> f64 {
        f64::from_bits(self.0)
    }
}

/// A node of the expression DAG.
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub enum Node {
    Const(Num),
    Sym(Symbol),
    /// `Σ cᵢ·tᵢ`; the constant term is the coefficient of [`Dag::ONE`](super::Dag::ONE).
    Sum(Vec<(Num, Id)>),
    /// `Π fᵢ^eᵢ`, no factor constant, coefficient 1.
    Prod(Vec<(Id, i32)>),
    Call(Func, Id),
    Call2(Func2, Id, Id),
}
