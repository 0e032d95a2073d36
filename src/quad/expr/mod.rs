//! Integrand expressions in one variable `x`: parse once, evaluate at any precision.
//!
//! ```
//! use maugis::quad::expr::Expr;
//!
//! let f = Expr::parse("x^(-1/2) * cos(x) + besselj(-1, 2.5e-1*x)").unwrap();
//! assert!(f.depends_on_x());
//! let v = f.eval_f64(0.25);
//! assert!((v - (2.0 * 0.25f64.cos() - maugis::special::bessel_j::bessel_j(1, 0.0625).unwrap())).abs() < 1e-15);
//! ```
//!
//! # The language
//!
//! * the variable `x`, the constant `pi` (or `π`), decimal literals (`2`, `0.1`,
//!   `.5`, `2.`, `2.5e-3`, `1E6`);
//! * `+ - * / ^` with the usual precedence; `^` is right-associative
//!   (`2^3^2 = 2^9`) and a unary minus binds more loosely than `^`, as in
//!   mathematics (`-x^2 = -(x^2)`, `2^-x*3 = (2^(-x))*3`);
//! * the functions `sqrt exp log sin cos tan sinh cosh tanh sech atan` of one argument
//!   and `besselj(n, expr)`, the Bessel function `J_n`, whose order `n` is an
//!   integer literal (possibly negative, `|n| <=` [`MAX_BESSEL_ORDER`]).
//!
//! Decimals are kept exact ([`Decimal`](crate::ball::Decimal)) and become, at each
//! evaluation, a ball that contains the decimal as typed at the working precision
//! (never an f64 rounding). An exponent written as an integer literal (`x^3`,
//! `x^-2`, `x^(2)`) is an [`Expr::PowInt`]: integer powering, defined on the
//! whole complex plane, without the branch cut of the general power.
//!
//! # Evaluation
//!
//! [`Expr::eval`] computes the tree in any [`ExprValue`]: `f64` (plain floating
//! point) and [`CBall`](crate::ball::CBall) (certified complex balls). In complex
//! balls the functions with a branch cut (`log`, `sqrt`, the general power,
//! `atan`) are taken in their *analytic* forms, which return a non-finite ball
//! when the argument touches the cut, so the certified integrator sees that the
//! integrand is not holomorphic there instead of integrating across the cut.
//!
//! # Integrals without declarations
//!
//! [`integrate_range`] reads the tree to find what the certified integrator would
//! otherwise ask for: a tail bound at `+-inf` (decay classes, `decay.rs`), the
//! oscillatory factor of an integral to infinity and a class of the rest on a sector,
//! which licenses moving the tail onto rotated rays (`oscillatory.rs`), and the
//! singular points of a finite range with their local classes (`local.rs`,
//! `finite.rs`). Each rule is proven in the method block of its file; the overview and
//! the timings are in `docs/quadrature.md`.
//!
//! # Errors
//!
//! [`Expr::parse`] returns [`crate::Error::Expression`] with an [`ExprError`]
//! that names the problem and its position: empty text, a syntax error (what was
//! expected and what was found), an unknown function or name (the message lists
//! the functions), a wrong number of arguments, a `besselj` order that is not an
//! integer literal, a decimal out of range, and text longer than [`MAX_LEN`]
//! characters or nested deeper than [`MAX_DEPTH`] levels (so that no input can
//! exhaust the stack). No input panics.
//!
//! # Why `winnow`, not `exmex`
//!
//! The issue asked for a parser crate made for expressions, `exmex` if it can
//! carry a custom value type. It can (a value type that is a tree node, its
//! operators functions that build nodes, literals parsed by `FromStr`), but
//! exmex 0.21 falls short on three points of this language, each checked:
//!
//! * its unary operators bind more tightly than every binary one, by design
//!   (its docs: `-2^2 = 4`); so `-x^2` is `(-x)^2`, and the tree it hands to the
//!   operators keeps no trace of parentheses, so `-x^2` and `(-x)^2` cannot be
//!   told apart afterwards;
//! * two-argument functions exist only as binary operators in call syntax, and
//!   nesting them fails (`besselj(1, besselj(2, x))` gives "parentheses
//!   mismatch"), while the infix form `1 besselj x` is accepted;
//! * errors are strings without positions (`"we have 0 ops and 2 node..."` for
//!   `1e5` with the default literal pattern), where the front ends need typed
//!   errors that say what to fix.
//!
//! So the parser is written with [`winnow`](https://docs.rs/winnow) (the parser
//! combinator crate behind `toml_edit`, already in the dependency tree), using
//! its Pratt [`expression`](winnow::combinator::expression) combinator for
//! `+ - * /` and a small grammar for signs, powers and calls (see `parse.rs`).

mod decay;
// `pub(crate)`: `crate::Error::Expression` names the parser's error by its own
// file, a leaf of the parser (no import cycle through `crate::Error`).
pub(crate) mod error;
mod eval;
mod finite;
mod function;
mod integrate;
mod limits;
mod local;
mod mapped;
mod oscillatory;
mod oscillatory_sum;
mod parse;
mod removable;
mod substitute;
mod tree;

#[cfg(test)]
mod tests;

use std::str::FromStr;

pub use error::ExprError;
pub use eval::ExprValue;
pub use function::Function;
pub use integrate::{integrate_expr, integrate_range, abs_tol_text, shortfall, significant_imaginary, DecaySpec, End, UpperLimit, WeightSpec};
pub use limits::{MAX_BESSEL_ORDER, MAX_DEPTH, MAX_LEN};
pub use tree::Expr;

impl Expr {
    /// Parses an integrand in `x` (see the module docs for the language).
    pub fn parse(text: &str) -> crate::Result<Expr> {
        parse::parse(text).map_err(crate::Error::Expression)
    }
}

impl FromStr for Expr {
    type Err = crate::Error;

    fn from_str(text: &str) -> crate::Result<Expr> {
        Expr::parse(text)
    }
}
