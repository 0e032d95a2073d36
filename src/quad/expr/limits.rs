//! The limits of the expression language: how long, how deep and how large an
//! order [`Expr::parse`](super::Expr::parse) accepts, so that no input can
//! exhaust the stack or the time budget.
//!
//! A file of its own, with no reference to the rest of the crate, for the same
//! reason as `function.rs`: the parser's error messages quote these limits.

/// Longest expression accepted, in characters.
pub const MAX_LEN: usize = 4096;

/// Deepest nesting of parentheses, calls and exponents accepted.
pub const MAX_DEPTH: usize = 100;

/// Largest `|n|` accepted in `besselj(n, x)`.
pub const MAX_BESSEL_ORDER: u64 = 10_000;
