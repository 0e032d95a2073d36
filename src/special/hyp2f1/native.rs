//! Native f64 `2F1` with a proven error bound (running error analysis).
//!
//! # Method
//!
//! * `-1/2 <= z <= 9/10`, or `a`/`b` a non-positive integer (any `z <= 1`): the
//!   direct series `sum_n t_n z^n` [DLMF 15.2.1] in f64.
//! * `z < -1/2`: Pfaff [DLMF 15.8.1], `(1-z)^{-a} 2F1(a, c-b; c; w)` or
//!   `(1-z)^{-b} 2F1(c-a, b; c; w)`, `w = z/(z-1) in (1/3, 1)`; the candidate
//!   with fewer negative numerators first, the other if the first cannot certify.
//!   `c - b` is a double word (exact); the prefactor is
//!   [`pow_from_ln`](super::power_f64) for the f64 sums (a bound of a few `u`) and
//!   [`pow_dw`](super::power::pow_dw) for the double-word sums.
//! * `z <= -4`: the connection formula in `x = 1/(1-z)` [DLMF 15.8.3], two f64
//!   series in `x <= 1/5` and seven reciprocal Gammas
//!   ([`rgamma_batch`](super::rgamma_f64)), first (Pfaff's `w >= 4/5` needs
//!   more than 150 terms); not where `a - b` is within `0.05` of an integer
//!   (its two terms blow up). Its bound is derived at
//!   [`connection_inv_one_minus_z`]. Between `-4` and `-1/2`, Pfaff goes first
//!   (measured crossover, `hyp2f1_regions`), and below `-4` too when `a, b > 0`
//!   (the connection formula's two terms cancel at a third of those points,
//!   Pfaff's f64 sum certifies 98.6%); the connection formula is its fallback there.
//!
//! * `9/10 < z < 1`: the connection formula in `x = 1 - z` [DLMF 15.8.4], two
//!   f64 series in `x < 1/10` and six reciprocal Gammas (the direct series
//!   does not converge usefully beyond `9/10`; below, it costs less); not
//!   where `c - a - b` is within `0.05` of an integer (the log case). Its
//!   bound is derived at [`connection_one_minus_z`].
//!
//! When no f64 sum certifies (cancellation), the same series are summed in
//! double words. Anything else (`z = 1`, `z` in `(9/10, 1)` where the
//! connection formula does not apply, more than
//! [`MAX_NATIVE_TERMS`](super::native_series::MAX_NATIVE_TERMS) terms, a bound above the caller's tolerance, values
//! near the f64 range ends) returns `None`, and the callers fall back to the
//! certified MP path.
//!//! The proof of the f64 sums' bound is in [`super::native_series`], the
//! double-word sums in [`super::native_dw`], the connection formulas'
//! bounds in [`super::native_connection`]; this file chooses among them.

use super::native_connection::{connection_inv_one_minus_z, connection_one_minus_z};
use super::native_dw::{series_dw, series_hybrid};
use super::native_series::{series, stop_for, Param};
use super::power::{pow_dw, U};
use super::power_f64::{ln_f64, pow_from_ln};
use crate::ball::{Bounded, Dd};

/// Largest `z` for the native direct series (beyond it the terms decay too slowly).
pub(super) const NATIVE_Z_MAX: f64 = 0.9;

/// Where the direct series hands over to Pfaff.
const PFAFF_BELOW: f64 = -0.5;

/// Below this `z` the connection formula in `1/(1-z)` goes first: its two
/// series (argument at most `1/(1-z)`) and seven reciprocal Gammas cost less
/// than Pfaff's one series at `w = z/(z-1) = 1 - 1/(1-z)` (measured over the
/// benchmark domain: `-4` beats `-3` and `-4.5`).
const CONNECTION_FIRST_BELOW: f64 = -4.0;

/// Above this `z` the connection formula in `1 - z` goes first: there it is
/// the only f64 path ([`NATIVE_Z_MAX`]). Below, the direct series costs less
/// (measured with the two-lane loops over the benchmark domain: at
/// `0.75 <= z < 0.9`, 0.22 us a value against 0.30 us with the connection
/// formula first from `z = 0.7`).
const CONNECTION_ONE_MINUS_Z_ABOVE: f64 = 0.9;

/// Above this `z` the connection formula in `1 - z` is the fallback when the
/// direct series cannot certify (before the double-word head): at
/// `hyp2f1_bounded`'s `1e-14` that happens often near `z = 0.9`.
const CONNECTION_ONE_MINUS_Z_FALLBACK_ABOVE: f64 = 0.7;

/// `2F1(a, b; c; z)` natively with a proven bound, accepted only when
/// `err <= rel_tol |value|`; `None` where the native path cannot certify that
/// (the caller then uses MP). Arguments are validated by the caller.
pub(super) fn hyp2f1_native(a: f64, b: f64, c: f64, z: f64, rel_tol: f64) -> Option<Bounded> {
    let accept = |v: f64, err: f64| -> Option<Bounded> {
        (v.is_finite() && v.abs() > 1e-290 && v.abs() < 1e290 && err <= rel_tol * v.abs()).then_some(Bounded { value: v, err })
    };
    let stop = stop_for(rel_tol);
    let terminating = Param::exact(a).nonpos_degree().is_some() || Param::exact(b).nonpos_degree().is_some();
    if !terminating && z > CONNECTION_ONE_MINUS_Z_ABOVE {
        if let Some(r) = connection_one_minus_z(a, b, c, z, stop).and_then(|(v, err)| accept(v, err)) {
            return Some(r);
        }
    }
    if terminating || (PFAFF_BELOW..=NATIVE_Z_MAX).contains(&z) {
        let (pa, pb, pc) = (Param::exact(a), Param::exact(b), Param::exact(c));
        if let Some(r) = series(pa, pb, pc, z, 0.0, stop).and_then(|(v, err)| accept(v, err)) {
            return Some(r);
        }
        // Above 0.7 the connection formula in 1 - z (its series in 1 - z < 0.3
        // are short, and its cancellation a different one) ...
        if !terminating && z > CONNECTION_ONE_MINUS_Z_FALLBACK_ABOVE {
            if let Some(r) = connection_one_minus_z(a, b, c, z, stop).and_then(|(v, err)| accept(v, err)) {
                return Some(r);
            }
        }
        // ... a double-word head where the first terms cancel, then f64 ...
        if let Some(r) = series_hybrid(Dd::from_f64(a), Dd::from_f64(b), Dd::from_f64(c), Dd::from_f64(z), 0.0, stop).and_then(|(v, err)| accept(v, err)) {
            return Some(r);
        }
        // ... then double words throughout (cancellation, many terms).
        let (s, err) = series_dw(Dd::from_f64(a), Dd::from_f64(b), Dd::from_f64(c), Dd::from_f64(z), 0.0)?;
        let v = s.hi + s.lo;
        return accept(v, (err + U * v.abs()) * (1.0 + 2.0 * U));
    }
    if z >= PFAFF_BELOW {
        return None;
    }
    // Below -4 the connection formula goes first, except for a, b > 0: there
    // it fails to certify a third of the points (its two terms cancel), and
    // Pfaff's f64 sum certifies 98.6% (measured over z in [-5, -4)); it is
    // Pfaff's fallback then.
    let connection_first = z <= CONNECTION_FIRST_BELOW && !(a > 0.0 && b > 0.0);
    if connection_first {
        if let Some(r) = connection_inv_one_minus_z(a, b, c, z, stop).and_then(|(v, err)| accept(v, err)) {
            return Some(r);
        }
    }
    // Pfaff: w = z/(z-1) = -z / (1 - z); 1 - z exact as a double word.
    let omz = Dd::diff(1.0, z);
    let ca = Dd::diff(c, a);
    let cb = Dd::diff(c, b);
    let neg = |x: f64| (x < 0.0) as u8;
    let first_a = neg(a) + neg(cb.hi) <= neg(b) + neg(ca.hi);
    let candidates = if first_a { [(a, cb), (b, ca)] } else { [(b, ca), (a, cb)] };
    // f64 sums first (w rounded twice: relative error <= 2.01 u) ...
    let w = -z / omz.hi;
    // |P - P~| <= pre_rel |P~| (power_f64); one more rounding for the product.
    let pfaff = |(pre, pre_rel): (f64, f64), (s, err_s): (f64, f64)| -> Option<Bounded> {
        let v = pre * s;
        let pr = pre_rel * 1.0001;
        accept(v, (pre.abs() * err_s * (1.0 + 2.0 * pr) + (1.01 * pr + U) * v.abs()) * (1.0 + 4.0 * U))
    };
    // ln(1 - z) once; each power before its sum (independent work the CPU
    // overlaps with the sum's start)
    let ln_omz = ln_f64(omz.hi, omz.lo);
    for (p, q) in candidates {
        let pre = ln_omz.and_then(|l| pow_from_ln(l, -p));
        let sum = series(Param::exact(p), Param::from_dw(q), Param::exact(c), w, 2.01 * U, stop);
        if let Some(r) = pre.zip(sum).and_then(|(pre, sum)| pfaff(pre, sum)) {
            return Some(r);
        }
    }
    if z <= CONNECTION_FIRST_BELOW && !connection_first {
        if let Some(r) = connection_inv_one_minus_z(a, b, c, z, stop).and_then(|(v, err)| accept(v, err)) {
            return Some(r);
        }
    }
    // ... then a double-word head (w to 32 u^2) where the first terms cancel
    // (not the connection formula where it did not go first: over random
    // points where the first f64 sum fails, it certifies only 23% of those the
    // second one does not, at the cost of two series and seven Gammas) ...
    let w = Dd::from_f64(-z).div_accurate(omz);
    for (p, q) in candidates {
        let pre = ln_omz.and_then(|l| pow_from_ln(l, -p));
        if let Some(r) = pre.zip(series_hybrid(Dd::from_f64(p), q, Dd::from_f64(c), w, 32.0 * U * U, stop)).and_then(|(pre, sum)| pfaff(pre, sum)) {
            return Some(r);
        }
    }
    // ... then double words throughout.
    let (p, q) = candidates[0];
    let (s, err_s) = series_dw(Dd::from_f64(p), q, Dd::from_f64(c), w, 32.0 * U * U)?;
    let (pre, pre_rel) = pow_dw(omz, Dd::from_f64(-p), 0.0)?;
    let prod = pre.mul_accurate(s);
    let v = prod.hi + prod.lo;
    let s_abs = s.hi.abs() * (1.0 + 2.0 * U);
    let pre_abs = pre.hi.abs() * (1.0 + 2.0 * U);
    // |P S - v| <= |P| err_s + |P~ - P| |s~| + 7u^2 |P~ s~| + u |v|
    let err = (pre_abs * (1.0 + 1.01 * pre_rel) * err_s + 1.01 * pre_rel * pre_abs * s_abs + 8.0 * U * U * pre_abs * s_abs)
        * 1.0001
        + U * v.abs();
    accept(v, err * (1.0 + 4.0 * U))
}

#[cfg(test)]
mod tests {
    use super::super::native_connection::*;
    use super::super::native_dw::*;
    use super::super::native_series::*;
    use super::*;
    use crate::ball::Dekker;
    use crate::special::exact;
    use crate::special::hyp2f1::hyp2f1_mp;
    use rug::Float;

    use super::super::tests::Lcg;

    /// Over the benchmark domain (a, b in [-3, 3], c in [0.5, 6], z in [-5, 0.9]):
    /// the bound holds at every point against the certified 120-bit ball, the
    /// accepted values are within 1e-14, and the MP fallback stays rare.
    #[test]
    fn bound_holds_on_the_benchmark_domain() {
        let mut rng = Lcg(0x2f1);
        let (mut accepted, mut total) = (0u32, 0u32);
        let (mut worst, mut worst_bound) = (0.0f64, 0.0f64);
        for _ in 0..10000 {
            let (a, b, c, z) = (rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0), rng.uniform(0.5, 6.0), rng.uniform(-5.0, 0.9));
            total += 1;
            let Some(r) = hyp2f1_native(a, b, c, z, super::super::NATIVE_VALUE_REL) else { continue };
            let m = hyp2f1_mp(&exact(a), &exact(b), &exact(c), &exact(z), 120).unwrap();
            let diff = Float::with_val(200, m.mid() - r.value).abs();
            let diff_up = diff.to_f64() + m.rad().to_f64();
            assert!(diff_up <= r.err, "2F1({a}, {b}; {c}; {z}): |error| {diff_up:e} > bound {:e}", r.err);
            if r.err <= super::super::NATIVE_VALUE_REL * r.value.abs() {
                accepted += 1;
                worst = worst.max(diff_up / r.value.abs());
                worst_bound = worst_bound.max(r.err / r.value.abs());
            }
        }
        eprintln!("native accepted {accepted}/{total}, worst rel error {worst:e}, worst rel bound {worst_bound:e}");
        assert!(worst <= 1e-14, "{worst:e}");
        assert!(accepted as f64 >= 0.97 * total as f64, "{accepted}/{total}");
    }

    /// A connection formula on its own over 3000 random points (a, b in [-3, 3],
    /// c in [0.5, 6], z from `z_of`): its bound holds at every point against
    /// the certified 120-bit ball, and it answers at least 85% of them.
    fn check_connection(form: fn(f64, f64, f64, f64, f64) -> Option<(f64, f64)>, seed: u64, z_of: fn(&mut Lcg, u32) -> f64) {
        let mut rng = Lcg(seed);
        let (mut answered, mut total, mut worst_bound) = (0u32, 0u32, 0.0f64);
        for i in 0..3000 {
            let (a, b, c) = (rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0), rng.uniform(0.5, 6.0));
            let z = z_of(&mut rng, i);
            total += 1;
            let stop = if i % 2 == 0 { 1.3877787807814457e-17 } else { 1.4210854715202004e-14 };
            let Some((v, err)) = form(a, b, c, z, stop) else { continue };
            answered += 1;
            let m = hyp2f1_mp(&exact(a), &exact(b), &exact(c), &exact(z), 120).unwrap();
            let diff_up = Float::with_val(200, m.mid() - v).abs().to_f64() + m.rad().to_f64();
            assert!(diff_up <= err, "connection form of 2F1({a}, {b}; {c}; {z}): |error| {diff_up:e} > bound {err:e}");
            if v != 0.0 {
                worst_bound = worst_bound.max(err / v.abs());
            }
        }
        eprintln!("connection answered {answered}/{total}, worst rel bound {worst_bound:e}");
        assert!(answered as f64 >= 0.85 * total as f64, "{answered}/{total}");
    }

    /// The stops are powers of two, and `1/(4 stop)` is exact without a division.
    #[test]
    fn stops_are_powers_of_two() {
        for e in -60..-1 {
            let s = 2f64.powi(e);
            assert_eq!(quarter_over(s), 0.25 / s);
            assert_eq!(pow2_floor(s * 1.7), s);
        }
        assert_eq!(quarter_over(3e-17), 0.25 / 3e-17);
        for rel in [super::super::NATIVE_ACCEPT_REL, super::super::NATIVE_VALUE_REL, 1e-20, 1.0] {
            let stop = stop_for(rel);
            assert_eq!(pow2_floor(stop), stop);
            assert!(stop <= (rel / 256.0).max(1.3877787807814457e-17), "{rel:e}: {stop:e}");
        }
    }

    /// The double-word series with fused products (where the CPU has them) is
    /// bit-identical to the portable one.
    #[test]
    fn double_word_series_fused_equals_portable() {
        let mut rng = Lcg(0xf0a);
        for _ in 0..500 {
            let (a, b, c, x) = (rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0), rng.uniform(0.5, 6.0), rng.uniform(-0.9, 0.9));
            let args = (Dd::from_f64(a), Dd::diff(c, b), Dd::from_f64(c), Dd::from_f64(x));
            let fast = series_dw(args.0, args.1, args.2, args.3, 0.0);
            let portable = series_dw_with::<Dekker>(args.0, args.1, args.2, args.3, 0.0);
            assert_eq!(fast, portable, "2F1({a}, {c} - {b}; {c}; {x})");
        }
    }

    /// The hybrid sum (double-word head, f64 rest) where the f64 sum cannot
    /// certify 1e-13: Pfaff forms `2F1(a, c-b; c; w)` and direct series with
    /// exact f64 parameters and argument, `w in [1/3, 0.85]`. Its bound holds
    /// at every point against the certified 120-bit ball, at the stops of
    /// both entry points; it certifies most of them, within 1e-14.
    #[test]
    fn hybrid_series_bound_holds_where_f64_cancels() {
        let mut rng = Lcg(0x4b1d);
        let (mut cancelling, mut certified, mut worst) = (0u32, 0u32, 0.0f64);
        for i in 0..20000 {
            let (a, b, c) = (rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0), rng.uniform(0.5, 6.0));
            let x = if i % 2 == 0 { rng.uniform(1.0 / 3.0, 0.85) } else { rng.uniform(-0.5, 0.85) };
            let p2 = if i % 2 == 0 { c - b } else { b };
            // the stops of hyp2f1_bounded and hyp2f1
            let stop = stop_for(if i % 4 < 2 { super::super::NATIVE_ACCEPT_REL } else { super::super::NATIVE_VALUE_REL });
            let f64_sum = series(Param::exact(a), Param::exact(p2), Param::exact(c), x, 0.0, stop);
            if f64_sum.is_some_and(|(v, err)| err <= 1e-13 * v.abs()) {
                continue;
            }
            cancelling += 1;
            let Some((v, err)) = series_hybrid(Dd::from_f64(a), Dd::from_f64(p2), Dd::from_f64(c), Dd::from_f64(x), 0.0, stop) else { continue };
            let m = hyp2f1_mp(&exact(a), &exact(p2), &exact(c), &exact(x), 120).unwrap();
            let diff_up = Float::with_val(200, m.mid() - v).abs().to_f64() + m.rad().to_f64();
            assert!(diff_up <= err, "hybrid 2F1({a}, {p2}; {c}; {x}): |error| {diff_up:e} > bound {err:e}");
            if err <= 1e-13 * v.abs() {
                certified += 1;
                worst = worst.max(diff_up / v.abs());
            }
        }
        eprintln!("hybrid certified {certified} of {cancelling} points where f64 did not, worst rel error {worst:e}");
        assert!(cancelling >= 100, "{cancelling}");
        assert!(worst <= 1e-14, "{worst:e}");
        assert!(certified as f64 >= 0.9 * cancelling as f64, "{certified}/{cancelling}");
    }

    /// DLMF 15.8.3, z in [-1000, -1].
    #[test]
    fn connection_bound_holds() {
        check_connection(connection_inv_one_minus_z, 0x1f2, |rng, i| {
            if i % 3 == 0 {
                -10f64.powf(rng.uniform(0.0, 3.0))
            } else {
                rng.uniform(-5.0, -1.0)
            }
        });
    }

    /// DLMF 15.8.4, z in (1/2, 1), up to `1 - 10^-12`.
    #[test]
    fn connection_one_minus_z_bound_holds() {
        check_connection(connection_one_minus_z, 0x1a2, |rng, i| {
            if i % 3 == 0 {
                1.0 - 10f64.powf(-rng.uniform(0.31, 12.0))
            } else {
                rng.uniform(0.5, 1.0)
            }
        });
    }

    #[test]
    fn terminating_and_edges() {
        // 2F1(-2, b; c; z) = 1 - 2 b z / c + b (b+1) z^2 / (c (c+1)), also for z < -1.
        for &(b, c, z) in &[(0.7, 2.5, -30.0), (1.5, 0.25, 1.0), (-1.5, 3.0, -4.5)] {
            let r = hyp2f1_native(-2.0, b, c, z, 1e-13).unwrap();
            let want = 1.0 - 2.0 * b * z / c + b * (b + 1.0) * z * z / (c * (c + 1.0));
            assert!((r.value - want).abs() <= r.err + 4.0 * f64::EPSILON * want.abs(), "{r:?} vs {want}");
        }
        // Beyond 9/10 only the connection formula: native unless c - a - b is
        // (near) an integer (the log case); z = 1 is Gauss's sum in MP.
        assert!(hyp2f1_native(0.3, 0.4, 1.5, 0.95, 1e-13).is_some());
        assert!(hyp2f1_native(0.3, 0.7, 2.0, 0.95, 1e-13).is_none());
        assert!(hyp2f1_native(0.3, 0.4, 1.5, 1.0, 1e-13).is_none());
    }
}




