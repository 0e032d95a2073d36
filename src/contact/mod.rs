//! The application layer: the wavy Maugis line-contact model of the seed paper.
//!
//! * [`displacement`]: substrate displacements outside the contact, dimensional
//!   form: Hertz (Eq. 10), wave (Eq. 12, its gradient Eq. 11b, the
//!   cancellation-free Bessel form, and the Eq. 11a quadrature) and adhesive
//!   (Box I / A.5a), plus the profile depth (Eq. 1).
//!
//! Sign convention (notes/model.md, sec. 1): compressive traction is negative,
//! `u` is positive "downward" like the profile depth
//! `h(x) = x^2/(2R) + A (1 - cos(2 pi x/zeta))`, so that the substrate meets the
//! profile at the contact edge: `u_H(a) = a^2/(2R)`, `u_w(a) = A (1 - cos(2 pi a/zeta))`.
//! The gap is `g(x) = h(x) - u_H(x) - u_w(x) - u_a(x)` for `|x| >= a`.

pub mod displacement;
pub mod wave_quadrature;
