//! Numerical quadrature on a finite interval `[a, b]`.
//!
//! | rule | arithmetic | use it for |
//! |---|---|---|
//! | [`tanh_sinh`] | `rug::Float`, any precision | high precision; analytic integrands, also with integrable endpoint singularities (`x^-1/2`, `ln x`, `(1-x)^-3/4`) |
//! | [`gauss_legendre`] | f64, fixed order `n` (1..=[`MAX_ORDER`](gauss_legendre::MAX_ORDER)) | smooth integrands where the order is chosen by the caller; inner loops (cached rules) |
//! | [`gauss_kronrod`] | f64, adaptive G7-K15 | everyday f64 integrals to a tolerance, moderate endpoint singularities, kinks |
//!
//! Certified integrals, whose balls provably contain the integral, are in
//! [`certified`] (method and guarantees there and in `docs/quadrature.md`).
//!
//! # Estimates, not bounds
//!
//! The three rules in the table are **not certified**. The
//! `error_estimate` of a [`QuadEstimate`] / [`QuadEstimateMp`] is a heuristic
//! (difference of successive tanh-sinh levels, QUADPACK's Kronrod-Gauss
//! formula): reliable for the integrands each rule is made for, but it can
//! under-estimate the error for integrands with features the nodes never see
//! (a narrow spike between nodes, an interior singularity). Where a proof is
//! needed, cross-check two rules or compare with a closed form.
//!
//! # Conventions (all rules)
//!
//! * Bounds must be finite ([`Error::NonFinite`](crate::Error::NonFinite) otherwise).
//! * Reversed intervals are supported: `∫_a^b f = -∫_b^a f`; the integrand is
//!   always sampled inside `[min(a,b), max(a,b)]`.
//! * `a == b` gives exactly `0` with error estimate `0` and no evaluation.
//! * An integrand value that is NaN or infinite is an
//!   [`Error::NonFinite`](crate::Error::NonFinite); an `Err` returned by a
//!   fallible integrand is passed through unchanged.
//! * Failing to meet the requested accuracy within the refinement cap is an
//!   error ([`Error::NoConvergence`](crate::Error::NoConvergence); for
//!   tanh-sinh also [`Error::PrecisionExhausted`](crate::Error::PrecisionExhausted)
//!   when cancellation exceeds the guard bits), never a silently inaccurate
//!   value. [`gauss_kronrod::integrate_report`] returns the best estimate with
//!   a flag instead.
//! * Integrands are `FnMut` closures, so they may cache (e.g. a Bessel value
//!   shared by several integrals on the same nodes). f64 rules take
//!   `FnMut(f64) -> f64`, with `try_*` variants for `FnMut(f64) -> Result<f64>`;
//!   tanh-sinh always takes a fallible integrand.

pub mod certified;
pub mod expr;
pub mod gauss_kronrod;
pub mod gauss_legendre;
pub mod tanh_sinh;

use rug::Float;

pub use gauss_kronrod::GaussKronrodOptions;
pub use gauss_legendre::GaussLegendreRule;
pub use tanh_sinh::TanhSinhOptions;

/// An f64 quadrature result with its error *estimate* (not a bound).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuadEstimate {
    /// The approximation of the integral.
    pub value: f64,
    /// Estimated absolute error of `value` (a heuristic, see the module docs).
    pub error_estimate: f64,
    /// Number of integrand evaluations.
    pub evaluations: u64,
}

/// An arbitrary-precision quadrature result with its error *estimate* (not a bound).
#[derive(Debug, Clone, PartialEq)]
pub struct QuadEstimateMp {
    /// The approximation of the integral, rounded to the requested precision.
    pub value: Float,
    /// Estimated absolute error of `value` (a heuristic, see the module docs),
    /// a 53-bit float rounded upward.
    pub error_estimate: Float,
    /// Number of integrand evaluations.
    pub evaluations: u64,
}
