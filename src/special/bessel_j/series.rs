//! `J_n(x)` by the power series [DLMF 10.2.2]: `(x/2)^n / n! * 0F1(; n+1; -x^2/4)`,
//! summed by the pFq core with its rigorous tail bound (see the module docs of
//! [`super`] for the cancellation estimate).

use rug::Float;

use crate::ball::Ball;
use crate::error::{Error, Result};
use crate::special::pfq::pfq_series;

/// `J_n(x)` by the power series at working precision `wp` (`x > 0`).
pub fn bessel_j_series(n: u64, x: &Float, wp: u32) -> Result<Ball> {
    let xb = Ball::from_float(x, wp);
    let half_x = xb.mul_pow2(-1);
    let z = half_x.sqr().neg();
    let b = [Ball::from_i64(n as i64 + 1, wp)];
    let sum = pfq_series(&[], &b, &z, wp)?.sum;
    // (x/2)^n / n!, n! correctly rounded by MPFR.
    let order = u32::try_from(n).map_err(|_| Error::Domain { what: "Bessel order too large".into() })?;
    let fact = Ball::factorial(order, wp);
    let pre = half_x.pow_u64(n).div(&fact)?;
    Ok(pre.mul(&sum))
}
