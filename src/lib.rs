//! # maugis
//!
//! Certified high-precision special functions and quadrature for the wavy
//! Maugis line-contact model ("Instabilities and cavitation in cylindrical
//! wavy line contact: A Maugis analysis").
//!
//! The modules, bottom up:
//!
//! * [`error`]: the one error type, [`Error`], a typed variant with fields for
//!   every way a call can be refused.
//! * [`ball`]: ball arithmetic over MPFR (`rug::Float` midpoint, radius rounded
//!   upward), complex balls, exact decimal inputs ([`ball::Decimal`]) and the
//!   double-double type of the fast f64 paths. Everything certified is built on it.
//! * [`special`]: one folder per function, arbitrary precision and f64 side by
//!   side, one file per method: [`bessel_j`](special::bessel_j),
//!   [`hyp1f2`](special::hyp1f2), [`hyp2f1`](special::hyp2f1), the
//!   [`pFq` core](special::pfq) and the Eq. 12 Meijer-G family
//!   [`meijer_g_k`](special::meijer_g).
//! * [`quad`]: [certified integration](quad::certified) in complex ball arithmetic
//!   (adaptive Gauss-Legendre with Bernstein-ellipse bounds, endpoint weights,
//!   semi-infinite ranges, integrand [expressions](quad::expr)), and the estimating
//!   rules beside it: tanh-sinh (MP), Gauss-Legendre and Gauss-Kronrod (f64).
//! * [`roots`]: root finding and minimisation in one variable for the model.
//! * [`contact`]: the application: the displacements (Eqs. 10, 11a, 11b, 12,
//!   A.5a), the normalised Maugis model (Eqs. 14, 15b, 16) in f64 and in balls,
//!   the load-area response and its stability, paths, jumps, pull-off and
//!   dissipation, regime sweeps, physical units, the limits of Appendix E and the
//!   paper's roughnesses.
//! * [`registry`]: one table from a function's name to the calls behind it, which
//!   the command line's `eval` and the Python package dispatch through.
//!
//! Outside this crate, each depending on it as any user would:
//!
//! * `maugis-solver` (`solver/`): a numerical Dugdale-Maugis solver (FFT boundary
//!   elements) for the states the semi-analytical model cannot reach.
//! * `maugis-cli` (`cli/`), the `maugis` command: `curve` (the main job: load-area
//!   curves, jumps, pull-off), `profile`, `limits`, `sweep` and `merge` (regime
//!   maps, sharded), `simulate` (the numerical solver), `figures` and `paper` (the
//!   paper's figures and numbers), `multiscale` (multi-scale roughness studies),
//!   `eval` (a JSON Lines calculator), `integrate`
//!   (a certified integral of an expression) and `demo`.
//! * `maugis-python` (`python/`): the Python package `maugis`.
//!
//! ## Three kinds of answers
//!
//! * `*_mp(.., prec)` returns a [`Ball`]: a midpoint and a radius such that the
//!   exact value of the function at the given binary inputs is provably inside,
//!   and `rad <= 2^-prec |mid|`. Working precision rises automatically (Ziv)
//!   until that holds, up to [`MAX_WORKING_PREC`] bits.
//! * `*_bounded(..)` returns a [`Bounded`]: an `f64` value and a proven bound on
//!   its distance to the exact value at the f64 inputs as given.
//! * the plain functions return an `f64` within a documented, tested tolerance
//!   (see `docs/special-functions.md`): an estimate, not a bound.
//!
//! ## Example
//!
//! ```
//! use maugis::special::bessel_j::{bessel_j, bessel_j_mp};
//! use rug::Float;
//!
//! // certified, 200 bits: the exact J_5(2.5) lies within rad of mid
//! let ball = bessel_j_mp(5, &Float::with_val(53, 2.5), 200).unwrap();
//! assert!(ball.meets_rel(200));
//!
//! // f64: within one ulp of the certified value
//! let j = bessel_j(5, 2.5).unwrap();
//! assert!((j - ball.to_f64()).abs() <= f64::EPSILON * j.abs());
//! ```
//!
//! The wave displacement of the seed's Eq. 12, certified three ways, lives in
//! [`contact::displacement`]; the semi-analytical model in [`contact::model`] and
//! [`contact::curve`]; quadrature rules in [`quad`].
//!
//! No public function panics: bad input returns an [`Error`].

// The house idiom for argument checks is `!(x > 0.0)`: unlike `x <= 0.0` it is
// true for NaN, so one comparison rejects both (clippy would have `partial_cmp`).
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod ball;
pub mod budget;
pub mod contact;
pub mod error;
pub mod quad;
pub mod registry;
pub mod roots;
pub mod special;

/// `rug` is in the public API (`Float` arguments, [`Ball`] midpoints); this is the
/// version the crate was built with, so users need no separate, matching dependency.
pub use rug;

pub use ball::{Ball, Bounded};
pub use budget::Budget;
pub use error::{Error, Log2Magnitude, Log2Relation, Result};

/// Largest output precision (bits) a caller may request.
pub const MAX_PREC: u32 = 1 << 16;

/// Largest working precision (bits) the Ziv loops may reach before giving up
/// with [`Error::PrecisionExhausted`].
pub const MAX_WORKING_PREC: u32 = 1 << 20;

/// The README's Rust example, compiled and run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
