//! Property test of the certified integrator: random analytic integrands with known
//! antiderivatives, `p(x) e^(alpha x + beta)` and `p(x) sin(alpha x + beta)` with a
//! random cubic `p`, random dyadic `alpha`, `beta` and a random range. The
//! antiderivative (integration by parts, `int p g = p G1 - p' G2 + p'' G3 - p''' G4`,
//! `G_j` the j-th antiderivative of `g`) is evaluated in MPFR at 4x the precision.
//! Every ball must contain it and meet the goal.

use maugis::ball::Ball;
use maugis::quad::certified::{integrate, HoloBall, Options};
use maugis::rug::ops::Pow;
use maugis::rug::Float;
use proptest::prelude::*;

/// `p^(k)(x)` for `p = c0 + c1 x + c2 x^2 + c3 x^3`.
fn poly_deriv(c: &[i64; 4], k: usize, x: &Float) -> Float {
    let p = x.prec();
    let mut s = Float::with_val(p, 0);
    for (j, &cj) in c.iter().enumerate().skip(k) {
        // d^k/dx^k x^j = j!/(j-k)! x^(j-k)
        let fall: i64 = ((j - k + 1)..=j).map(|v| v as i64).product();
        s += Float::with_val(p, x.clone().pow((j - k) as u32)) * (cj * fall);
    }
    s
}

/// The j-th antiderivative of `g` at `x` (`j = 1..=4`).
fn g_anti(sin: bool, j: usize, alpha: &Float, beta: &Float, x: &Float) -> Float {
    let p = x.prec();
    let t = Float::with_val(p, alpha * x) + beta;
    let aj = Float::with_val(p, alpha.clone().pow(j as u32));
    if !sin {
        return t.exp() / aj;
    }
    // G1 = -cos/a, G2 = -sin/a^2, G3 = cos/a^3, G4 = sin/a^4
    let v = match j % 4 {
        1 => -t.cos(),
        2 => -t.sin(),
        3 => t.cos(),
        _ => t.sin(),
    };
    v / aj
}

fn antiderivative(c: &[i64; 4], sin: bool, alpha: &Float, beta: &Float, x: &Float) -> Float {
    let mut s = Float::with_val(x.prec(), 0);
    for k in 0..4 {
        let term = poly_deriv(c, k, x) * g_anti(sin, k + 1, alpha, beta, x);
        if k % 2 == 0 {
            s += term;
        } else {
            s -= term;
        }
    }
    s
}

fn dyadic(n: i64, shift: i32, p: u32) -> Float {
    Float::with_val(p, n) >> shift
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, .. ProptestConfig::default() })]
    #[test]
    fn random_analytic_integrands_are_enclosed(
        c in prop::array::uniform4(-5i64..=5),
        alpha_n in prop_oneof![-24i64..=-1, 1i64..=24],
        beta_n in -16i64..=16,
        a_n in -24i64..=24,
        len_n in 1i64..=32,
        sin in any::<bool>(),
        prec in prop_oneof![Just(64u32), Just(128u32)],
    ) {
        let rp = 4 * prec;
        let alpha = dyadic(alpha_n, 3, rp);
        let beta = dyadic(beta_n, 3, rp);
        let (a, b) = (dyadic(a_n, 3, rp), dyadic(a_n + len_n, 3, rp));
        let exact = antiderivative(&c, sin, &alpha, &beta, &b) - antiderivative(&c, sin, &alpha, &beta, &a);
        let f = |x: &HoloBall| {
            let mut poly = x.int(c[3]);
            for &cj in c[..3].iter().rev() {
                poly = poly * x + x.int(cj);
            }
            let t = x * x.real(Ball::from_float(&alpha, prec)) + x.real(Ball::from_float(&beta, prec));
            poly * if sin { t.sin() } else { t.exp() }
        };
        let r = integrate(f, &Ball::from_float(&a, prec), &Ball::from_float(&b, prec), prec, &Options::new()).unwrap();
        prop_assert!(r.real().contains(&exact), "{:?} vs {}", r.real(), exact.to_string_radix(10, Some(25)));
        // A zero polynomial gives exactly 0 (no relative goal to meet).
        if c.iter().any(|&v| v != 0) && !exact.is_zero() {
            prop_assert!(r.goal_met || r.value.rad_mag().le(&maugis::ball::Mag::pow2(-(prec as i64) + 8)), "goal: {:?}", r.value);
        }
    }
}
