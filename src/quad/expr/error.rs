//! What can be wrong with an expression, as typed errors whose messages say what to fix.

use std::fmt;

// Only the two leaf files of the parser: the crate's `Error` holds an `ExprError`,
// so nothing this file uses may depend on `Error` (no import cycle).
use super::function::Function;
use super::limits::{MAX_BESSEL_ORDER, MAX_DEPTH, MAX_LEN};

/// Why an expression was rejected ([`crate::Error::Expression`]).
///
/// Positions count characters (Unicode scalar values) from 0; the messages
/// print them from 1 ("at character 3").
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum ExprError {
    /// The text is empty or only white space.
    Empty,
    /// The text is longer than [`MAX_LEN`] characters.
    TooLong {
        /// Its length in characters.
        chars: usize,
    },
    /// Parentheses, calls and powers nest deeper than [`MAX_DEPTH`] levels.
    TooDeep {
        /// Where the level past the limit starts.
        position: usize,
    },
    /// Something other than what the grammar allows at this point.
    Syntax {
        /// Where.
        position: usize,
        /// What is there (a token, or "the end of the expression").
        found: String,
        /// What could stand there.
        expected: String,
    },
    /// A name followed by `(` that is not one of the functions.
    UnknownFunction {
        /// The name written.
        name: String,
        /// Where it starts.
        position: usize,
    },
    /// A name that is neither the variable `x` nor the constant `pi`.
    UnknownVariable {
        /// The name written.
        name: String,
        /// Where it starts.
        position: usize,
    },
    /// A function called with the wrong number of arguments.
    WrongArity {
        /// The function.
        name: String,
        /// How many it takes.
        expected: usize,
        /// How many were given.
        got: usize,
        /// Where the call starts.
        position: usize,
    },
    /// The order of `besselj(n, x)` is not an integer literal in
    /// `-MAX_BESSEL_ORDER ..= MAX_BESSEL_ORDER`.
    BadBesselOrder {
        /// The order as written.
        text: String,
        /// Where it starts.
        position: usize,
    },
    /// A decimal literal out of range (see [`crate::ball::Decimal`]).
    BadNumber {
        /// The literal.
        text: String,
        /// Where it starts.
        position: usize,
        /// Why.
        reason: String,
    },
}

/// The functions, listed for messages: `sqrt, exp, ..., atan and besselj(n, x)`.
fn known_functions() -> String {
    let names: Vec<&str> = Function::ALL.iter().map(|f| f.name()).collect();
    format!("{} and besselj(n, x)", names.join(", "))
}

impl fmt::Display for ExprError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ExprError::Empty => {
                write!(f, "the expression is empty: write an integrand in x, for example exp(-x^2) or sqrt(x)*cos(x)")
            }
            ExprError::TooLong { chars } => {
                write!(f, "the expression has {chars} characters; at most {MAX_LEN} are accepted")
            }
            ExprError::TooDeep { position } => write!(
                f,
                "the expression nests parentheses, calls and powers more than {MAX_DEPTH} levels deep \
                 (at character {}); simplify it",
                position + 1
            ),
            ExprError::Syntax { position, found, expected } => {
                write!(f, "syntax error at character {}: expected {expected}, found {found}", position + 1)
            }
            ExprError::UnknownFunction { name, position } => write!(
                f,
                "unknown function '{name}' at character {}; the functions are {}",
                position + 1,
                known_functions()
            ),
            ExprError::UnknownVariable { name, position } => write!(
                f,
                "unknown name '{name}' at character {}: the variable is x and the one constant is pi \
                 (write exp(1) for e; the functions are {})",
                position + 1,
                known_functions()
            ),
            ExprError::WrongArity { name, expected, got, position } => {
                let usage = if name == "besselj" { "besselj(n, x)".to_string() } else { format!("{name}(x)") };
                let plural = if *expected == 1 { "" } else { "s" };
                write!(
                    f,
                    "{name} at character {} takes {expected} argument{plural}, as in {usage}, but got {got}",
                    position + 1
                )
            }
            ExprError::BadBesselOrder { text, position } => write!(
                f,
                "the order of besselj at character {} must be an integer literal n with |n| <= {MAX_BESSEL_ORDER}, \
                 as in besselj(0, x) or besselj(-2, x); got '{text}'",
                position + 1
            ),
            ExprError::BadNumber { text, position, reason } => {
                write!(f, "bad number '{text}' at character {}: {reason}", position + 1)
            }
        }
    }
}

impl std::error::Error for ExprError {}
