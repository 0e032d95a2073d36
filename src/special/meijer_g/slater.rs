//! A general `G^{2,2}_{3,3}(z)` for `-1 < z < 0` by Slater's theorem
//! [DLMF 16.17.2]: the sum of two 3F2 series in non-degenerate position. Tests
//! compare the degenerate family `G(k, y)` with it at perturbed parameters.
//!
//! Error bound: every factor is a ball (gamma, reciprocal gamma, the 3F2 series
//! with its rigorous tail from the pFq core), so the result encloses the value.

use rug::Float;

use crate::ball::Ball;
use crate::error::{Error, Interval, Result};
use crate::special::pfq::pfq_series;
use crate::special::{exact, exact_add, exact_sub};

/// Real and imaginary parts of `G^{2,2}_{3,3}(z | a1, a2, a3; b1, b2, b3)` for
/// `-1 < z < 0` by Slater's theorem [DLMF 16.17.2], at working precision `wp`.
///
/// Requires non-degenerate position: `b1 - b2` not an integer, and no Gamma
/// pole among `Gamma(1 + b_h - a_1), Gamma(1 + b_h - a_2)`. `z^{b_h}` is taken on
/// the principal branch, `(-y)^b = y^b e^{i pi b}` (mpmath's convention).
/// The parameters must be exactly representable (they are combined exactly).
pub fn meijer_g33_slater_mp(a: [f64; 3], b: [f64; 3], z: f64, wp: u32) -> Result<(Ball, Ball)> {
    crate::error::check_working_prec(wp)?;
    for &v in a.iter().chain(b.iter()).chain(std::iter::once(&z)) {
        crate::error::finite(v, "Meijer G argument")?;
    }
    if !(z > -1.0 && z < 0.0) {
        return Err(Error::OutOfRange { arg: "z (Slater's sum)", value: z, allowed: Interval { lo: -1.0, hi: 0.0, lo_closed: false, hi_closed: false } });
    }
    let ae: Vec<Float> = a.iter().map(|&v| exact(v)).collect();
    let be: Vec<Float> = b.iter().map(|&v| exact(v)).collect();
    if exact_sub(&be[0], &be[1]).is_integer() {
        return Err(Error::Degenerate { function: "meijer_g33_slater_mp (Slater's sum)", needs: "b1 - b2 not an integer" });
    }
    let y = Ball::from_f64(-z, wp)?;
    let ln_y = y.ln()?;
    let one = Float::with_val(2, 1);
    let mut re = Ball::zero(wp);
    let mut im = Ball::zero(wp);
    for h in 0..2 {
        let other = 1 - h;
        let bh = &be[h];
        let g = |x: Float| Ball::from_float(&x, wp.max(x.prec())).gamma();
        let rg = |x: Float| Ball::from_float(&x, wp.max(x.prec())).rgamma();
        let one_plus_bh = exact_add(&one, bh);
        let coef = g(exact_sub(&be[other], bh))?
            .mul(&g(exact_sub(&one_plus_bh, &ae[0]))?)
            .mul(&g(exact_sub(&one_plus_bh, &ae[1]))?)
            .mul(&rg(exact_sub(&one_plus_bh, &be[2]))?)
            .mul(&rg(exact_sub(&ae[2], bh))?)
            .set_prec(wp);
        let num: Vec<Ball> = (0..3).map(|i| Ball::from_float(&exact_sub(&one_plus_bh, &ae[i]), wp)).collect();
        let den: Vec<Ball> = vec![
            Ball::from_float(&exact_sub(&one_plus_bh, &be[other]), wp),
            Ball::from_float(&exact_sub(&one_plus_bh, &be[2]), wp),
        ];
        // argument (-1)^{p-m-n} z = -z = y
        let f = pfq_series(&num, &den, &y, wp)?.sum;
        let bh_ball = Ball::from_float(bh, wp);
        let ypow = ln_y.mul(&bh_ball).exp()?;
        let (s, c) = Ball::pi(wp).mul(&bh_ball).sin_cos();
        let common = coef.mul(&ypow).mul(&f);
        re = re.add(&common.mul(&c));
        im = im.add(&common.mul(&s));
    }
    Ok((re, im))
}

