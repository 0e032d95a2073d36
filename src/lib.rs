//! # maugis
//!
//! Certified high-precision special functions and quadrature for the wavy
//! Maugis line-contact model ("Instabilities and cavitation in cylindrical
//! wavy line contact: A Maugis analysis").
//!
//! The layers, bottom up:
//!
//! * [`ball`]: ball arithmetic over MPFR (`rug::Float` midpoint, radius rounded
//!   upward) and a double-double type for fast f64 paths. Everything certified
//!   is built from it.
//! * [`special`]: one module per function, arbitrary precision and f64 side by
//!   side: [`bessel_j`](special::bessel_j), [`hyp1f2`](special::hyp1f2),
//!   [`hyp2f1`](special::hyp2f1), the [`pFq` core](special::pfq) and the Eq. 12
//!   Meijer-G family [`meijer_g_k`](special::meijer_g).
//! * [`quad`]: [certified integration](quad::certified) in complex ball arithmetic
//!   (adaptive Gauss-Legendre with Bernstein-ellipse bounds, endpoint weights,
//!   semi-infinite ranges, integrand [expressions](quad::expr)), and the estimating
//!   rules beside it: tanh-sinh (MP), Gauss-Legendre and Gauss-Kronrod (f64).
//! * [`contact`]: the application: displacements (Eqs. 10, 11a, 11b, 12, A.5a),
//!   the normalised Maugis model (Eqs. 14, 15b, 16), the load-area response and
//!   the limits of Appendix E.
//! * the `maugis` command line (its own crate, `cli/`): `curve` (the main job),
//!   `profile`, `limits`, and `eval`, a JSON Lines calculator.
//!
//! ## Two kinds of answers
//!
//! * `*_mp(.., prec)` returns a [`Ball`]: a midpoint and a radius such that the
//!   exact value of the function at the given binary inputs is provably inside,
//!   and `rad <= 2^-prec |mid|`. Working precision rises automatically (Ziv)
//!   until that holds, up to [`MAX_WORKING_PREC`] bits.
//! * the plain functions return an `f64` within a documented tolerance (see
//!   `docs/special-functions.md`), falling back to the MP path where the fast f64
//!   algorithm cannot promise it.
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
//! [`contact::displacement`]; the Maugis solver in [`contact::model`] and
//! [`contact::curve`]; quadrature rules in [`quad`].
//!
//! No public function panics: bad input returns an [`Error`].

// The house idiom for argument checks is `!(x > 0.0)`: unlike `x <= 0.0` it is
// true for NaN, so one comparison rejects both (clippy would have `partial_cmp`).
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod ball;
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
pub use error::{Error, Result};

/// Largest output precision (bits) a caller may request.
pub const MAX_PREC: u32 = 1 << 16;

/// Largest working precision (bits) the Ziv loops may reach before giving up
/// with [`Error::PrecisionExhausted`].
pub const MAX_WORKING_PREC: u32 = 1 << 20;

/// The README's Rust example, compiled and run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
