//! The one-argument functions of the expression language, by name.
//!
//! A file of its own, with no reference to the rest of the crate, so that the
//! parser's error type ([`ExprError`](super::ExprError)), which lists the names,
//! depends on nothing that depends on the crate's [`Error`](crate::Error).

/// A one-argument function of the expression language.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Function {
    /// `sqrt`, the square root (analytic form in [`CBall`](crate::ball::CBall)s).
    Sqrt,
    /// `exp`.
    Exp,
    /// `log`, the natural logarithm (analytic form in complex balls).
    Log,
    /// `sin`.
    Sin,
    /// `cos`.
    Cos,
    /// `tan`.
    Tan,
    /// `sinh`.
    Sinh,
    /// `cosh`.
    Cosh,
    /// `tanh`.
    Tanh,
    /// `sech = 1/cosh` (enclosed tightly on wide boxes, see [`crate::ball::CBall::sech`]).
    Sech,
    /// `atan` (analytic form in complex balls).
    Atan,
}

impl Function {
    /// Every one-argument function, in the order the messages list them.
    pub const ALL: [Function; 11] = [
        Function::Sqrt,
        Function::Exp,
        Function::Log,
        Function::Sin,
        Function::Cos,
        Function::Tan,
        Function::Sinh,
        Function::Cosh,
        Function::Tanh,
        Function::Sech,
        Function::Atan,
    ];

    /// The name written in expressions.
    pub fn name(self) -> &'static str {
        match self {
            Function::Sqrt => "sqrt",
            Function::Exp => "exp",
            Function::Log => "log",
            Function::Sin => "sin",
            Function::Cos => "cos",
            Function::Tan => "tan",
            Function::Sinh => "sinh",
            Function::Cosh => "cosh",
            Function::Tanh => "tanh",
            Function::Sech => "sech",
            Function::Atan => "atan",
        }
    }

    /// The function written `name`, if any.
    pub fn from_name(name: &str) -> Option<Function> {
        Function::ALL.into_iter().find(|f| f.name() == name)
    }
}
