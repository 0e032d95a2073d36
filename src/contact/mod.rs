//! The application layer: the wavy Maugis line-contact model of the seed paper.
//!
//! * [`displacement`]: substrate displacements outside the contact, dimensional
//!   form: Hertz (Eq. 10), wave (Eq. 12, its gradient Eq. 11b, the
//!   cancellation-free Bessel form) and adhesive (Box I / A.5a), plus the
//!   profile depth (Eq. 1). Its submodules hold every route to `u_w`:
//!   [`displacement::bounded`] (`u_w` and `du_w/dx` in f64 with a proven error
//!   bound), [`displacement::quadrature`] (the independent Eq. 11a quadrature
//!   route) and [`displacement::quadrature_ball`] (Eq. 11a and the traction
//!   integral as certified balls). Their old paths `wave_bounded`,
//!   `wave_quadrature` and `wave_certified` are re-exported here.
//! * [`traction_mp`]: the traction (Eq. 16) as a certified ball.
//! * [`model`]: the normalised Maugis model at one contact size: the
//!   adhesive-strip equation (15b corrected), its first root, the load (Eq. 14),
//!   traction (Eq. 16), displacement, gap and the validity checks.
//! * [`model_mp`]: the strip residual, a certified enclosure of the strip end `m`
//!   and the load in arbitrary precision, on request (the solver works in f64).
//! * [`curve`]: the load-area response, turning points, pull-off.
//! * [`paths`]: load- and displacement-controlled paths, the jumps they meet,
//!   hysteresis loops and the dissipated energy.
//! * [`summary`]: a run of curves over lambda and its summary, the output schema
//!   of `maugis curve` (summary.json, `--format json`) and Python's `run_summary`.
//! * [`sweep`]: regime maps over grids of lambda and alpha, beta or the Johnson parameter, sharded.
//! * [`limits`]: Appendix E (JKR, M-DMT) and the Eq. 17 envelope, one by one and
//!   as the rows of `maugis limits`.
//! * [`multiscale`]: what bounds the response of a profile of many waves: the envelope
//!   constants (triangle sum, phase-locked `M+` and `M-`) and the model's excursion
//!   outside them (docs/multiscale.md).
//! * [`jkr_line`]: the JKR limit of the line contact for any wavy profile, from the
//!   energy-release-rate balance and the profile's slope (an independent reference
//!   for the model at large lambda).
//! * [`units`]: SI inputs and outputs (scales of Eq. 13a with two length scales).
//! * [`state_profile`]: the profiles of one state sampled over x (traction, displacement, gap).
//! * [`located`]: the error of a profile, a run of curves or a table of limits, and where it arose.
//!
//! Sign convention (docs/displacement.md): compressive traction is negative,
//! `u` is positive "downward" like the profile depth
//! `h(x) = x^2/(2R) + A (1 - cos(2 pi x/zeta))`, so that the substrate meets the
//! profile at the contact edge: `u_H(a) = a^2/(2R)`, `u_w(a) = A (1 - cos(2 pi a/zeta))`.
//! The gap is `g(x) = h(x) - u_H(x) - u_w(x) - u_a(x)` for `|x| >= a`.

pub mod displacement;
/// Old path of [`displacement::bounded`] (the certified f64 wave displacement), kept
/// so that code written against it still compiles.
pub use displacement::bounded as wave_bounded;
/// Old path of [`displacement::quadrature`] (the Eq. 11a quadrature estimates).
pub use displacement::quadrature as wave_quadrature;
/// Old path of [`displacement::quadrature_ball`] (the certified Eq. 11a/11b balls).
pub use displacement::quadrature_ball as wave_certified;
pub mod traction_mp;
pub mod model;
pub mod profile;
pub mod paper;
pub mod curve;
pub mod curve_state;
pub mod limits;
pub mod model_mp;
pub mod paths;
pub mod summary;
pub mod sweep;
pub mod units;
pub mod state_profile;
pub mod located;
pub mod jkr_line;
pub mod multiscale;
