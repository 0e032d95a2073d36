//! `J_n(x)` by Hankel's asymptotic expansion [DLMF 10.17.3] with the remainder
//! bounds of DLMF 10.17(iii) (see the module docs of [`super`]).

use rug::Float;

use crate::ball::Ball;
use crate::error::{Error, Result};

/// `J_n(x)` by Hankel's expansion at working precision `wp` (`x > 0`);
/// `None` if the expansion cannot reach `2^-wp` (terms stop decreasing).
pub fn bessel_j_hankel(n: u64, x: &Float, wp: u32) -> Result<Option<Ball>> {
    let xb = Ball::from_float(x, wp);
    let four_n2 = Ball::from_i64(4, wp).mul(&Ball::from_i64(n as i64, wp).sqr());
    let eight_x = xb.mul_i64(8);
    let mut term = Ball::one(wp); // a_k x^-k
    let mut p = Ball::one(wp);
    let mut q = Ball::zero(wp);
    let mut prev_abs = term.abs_upper();
    let min_k = (n as u64).max(2);
    let mut k: u64 = 0;
    loop {
        // term_{k+1} = term_k (4n^2 - (2k+1)^2) / (8 (k+1) x)
        let odd = Ball::from_i64(2 * k as i64 + 1, wp).sqr();
        let factor = four_n2.sub(&odd).div(&eight_x.mul_i64(k as i64 + 1))?;
        term = term.mul(&factor);
        k += 1;
        let t_abs = term.abs_upper();
        if k >= min_k && k % 2 == 0 {
            // Candidate stop at K = k: the remainders are bounded by |u_K| (for P)
            // and |u_{K+1}| (for Q).
            let next = term.mul(&four_n2.sub(&Ball::from_i64(2 * k as i64 + 1, wp).sqr()).div(&eight_x.mul_i64(k as i64 + 1))?);
            let n_abs = next.abs_upper();
            let mut target = Float::with_val(crate::ball::MAG_PREC, 1);
            target >>= wp as i32;
            if t_abs <= target && n_abs <= target {
                p.add_error(&t_abs);
                q.add_error(&n_abs);
                break;
            }
        }
        if k > min_k && t_abs > prev_abs {
            return Ok(None);
        }
        prev_abs = t_abs;
        // (-1)^j a_{2j} x^{-2j} into P (k = 2j), (-1)^j a_{2j+1} x^{-2j-1} into Q (k = 2j+1).
        let j = k / 2;
        let signed = if j % 2 == 1 { term.neg() } else { term.clone() };
        if k % 2 == 0 {
            p = p.add(&signed);
        } else {
            q = q.add(&signed);
        }
        if k > 10_000_000 {
            return Err(Error::NoConvergence { function: "bessel_j (Hankel)", terms: k });
        }
    }
    // w = x - (2n+1) pi / 4
    let pi = Ball::pi(wp);
    let w = xb.sub(&pi.mul_i64(2 * n as i64 + 1).mul_pow2(-2));
    let (s, c) = w.sin_cos();
    let amp = Ball::from_i64(2, wp).div(&pi.mul(&xb))?.sqrt()?;
    Ok(Some(amp.mul(&c.mul(&p).sub(&s.mul(&q)))))
}
