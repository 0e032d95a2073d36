//! `J_n(x)` for `n + 1 <= x` in double-double with a **proven** bound: the
//! forward recurrence from `J_0`, `J_1`.
//!
//! # Method
//!
//! `y_{k+1} = c_k y_k - y_{k-1}`, `c_k = 2k/x` [DLMF 10.6.1], from
//! `y_0 = J_0(x)`, `y_1 = J_1(x)` with their bounds `e_0`, `e_1`
//! (`native_hankel.rs`), in *compensated* arithmetic: each `y_k` is an
//! unnormalised pair `h_k + l_k` (f64 head, f64 correction), like a
//! double-double but without renormalising, so that the dependency chain per
//! step is one product and one subtraction (Graillat, Langlois, Louvet,
//! "Algorithms for accurate, validated and fast polynomial evaluation", 2009,
//! do the same for Horner's scheme). The coefficient is split without a
//! product of its own: `ih` is `fl_dd(1/x).hi` with its low 15 bits cleared and
//! `il = fl((hi - ih) + lo)`, so `|1/x - ih - il| <= g_1 = 16 u^2 |1/x| + u |il|`,
//! `ch = 2k ih` is exact (`2k < 2^15`), `cl = fl(2k il)`, and
//! `|c_k - ch - cl| <= g_k = 2k g_1 + u |cl|`:
//!
//! ```text
//! p + pi = ch * h_k            (Dekker's exact product)
//! s + sigma = p - h_{k-1}      (Knuth's exact sum)
//! h_{k+1} = s,   l_{k+1} = fl(((pi + sigma) + cl h_k) + cf l_k - l_{k-1}),   cf = fl(ch + cl)
//! ```
//!
//! The exact step applied to `h + l` differs from `h_{k+1} + l_{k+1}` by the
//! rounding of the five-term f64 sum (`<= gamma_5 sum |terms|`, `gamma_5 <= 5.01 u`,
//! products included), `(ch + cl - cf) l_k` (`<= u |cf l_k|`), and
//! `(c_k - ch - cl)(h_k + l_k)`; with `|pi| <= u |p|`, `|sigma| <= u |s|`:
//!
//! `|delta_k| <= u (5.1 (u |p| + u |s| + |cl h_k| + |l_{k-1}|) + 6.1 |cf l_k|) + g_k (|h_k| + |l_k|)`.
//!
//! (`l_k` is not small like a double-double's low part: it collects the
//! `cl h` terms, `~2^-37` of the value, and it is carried exactly as above.)
//!
//! # Error bound: an energy norm instead of absolute values
//!
//! The errors `eps_k = y~_k - J_k` obey the same recurrence plus `delta_k`.
//! Adding absolute values, `E_{k+1} = c_k E_k + E_{k-1}`, would grow like a
//! Fibonacci sequence (`~e^{0.47 x}` at `n = x`, i.e. 100 bits at `x = 150`)
//! although the true error grows like `Y_n`. We use instead, for `|c| < 2`,
//! the norm `||(a, b)||_c = sqrt(a^2 - c a b + b^2)`:
//!
//! * the step matrix `M_k = [[c_k, -1], [1, 0]]` preserves
//!   `Q_{c_k}(a, b) = a^2 - c_k a b + b^2` (direct expansion), so
//!   `||(eps_{k+1}, eps_k)||_{c_k} <= ||(eps_k, eps_{k-1})||_{c_k} + |delta_k|`;
//! * changing `c` to `c' = c + 2/x`: `Q_{c'} = Q_c - (c' - c) a b` and
//!   `|a b| <= Q_c / (2 - c)` (from `a^2 + b^2 >= 2|ab|`), so
//!   `||.||_{c'} <= ||.||_c sqrt(1 + 1/(x - k)) <= ||.||_c (1 + 1/(2(x - k)))`;
//! * at the start `||(eps_1, eps_0)||_{c_1} <= e_1 + e_0`, and at the end
//!   `Q_c(a, b) >= (1 - c^2/4) a^2`, so
//!   `|eps_n| <= N x / sqrt((x - (n-1)) (x + (n-1)))`.
//!
//! The product of the norm changes is about `sqrt(x/(x - n))` (the growth of
//! `Y_n` in its oscillatory range) and the last factor is below
//! `sqrt(x/2)` for `n + 1 <= x`; both are harmless next to `u^2`. The bound is
//! evaluated in f64 (`x - k` and `x +- (n-1)` are single roundings) and inflated
//! by [`crate::ball::dd_bounded`]'s `1 + 2^-30` at the end.

use crate::ball::{div_f64_p, mag, two_sum, BoundedDd, Dd, ExactProduct, U, U2};

/// Most steps (beyond the issue-8 domain the MP path is used).
pub(crate) const MAX_RECURRENCE_ORDER: u64 = 10_000;

/// `J_n(x)` from `(J_0, J_1)` for `n + 1 <= x`, `n <= MAX_RECURRENCE_ORDER`.
#[inline(always)]
pub(crate) fn forward<P: ExactProduct>(n: u64, x: f64, j0: BoundedDd, j1: BoundedDd) -> Option<BoundedDd> {
    forward_visit::<P, _>(n, x, j0, j1, |_, _| {})
}

/// `J_0(x), ..., J_n(x)` from `(J_0, J_1)` for `n + 1 <= x` into `out[0..=n]`,
/// each with the bound the module docs give for its own order (the norm at
/// step `k` bounds `eps_{k+1}` the same way it bounds the last one).
#[inline(always)]
pub(crate) fn forward_sequence<P: ExactProduct>(n: u64, x: f64, j0: BoundedDd, j1: BoundedDd, out: &mut [BoundedDd]) -> Option<()> {
    if out.len() <= n as usize {
        return None;
    }
    out[0] = j0;
    if n >= 1 {
        out[1] = j1;
    }
    let last = forward_visit::<P, _>(n, x, j0, j1, |k, v| out[k] = v)?;
    out[n as usize] = last;
    Some(())
}

/// The recurrence of [`forward`]; `visit(k, J_k)` receives the orders
/// `2..n` on the way (the last one is returned).
#[inline(always)]
fn forward_visit<P: ExactProduct, F: FnMut(usize, BoundedDd)>(n: u64, x: f64, j0: BoundedDd, j1: BoundedDd, mut visit: F) -> Option<BoundedDd> {
    if n == 0 {
        return Some(j0);
    }
    if n == 1 {
        return Some(j1);
    }
    if n > MAX_RECURRENCE_ORDER || !((n + 1) as f64 <= x) {
        return None;
    }
    let inv_x = div_f64_p::<P>(Dd::ONE, x);
    // ih: inv_x.hi with its low 15 bits cleared, so that 2k ih is exact for
    // 2k < 2^15; il: the rest (one rounding). |1/x - ih - il| <= g1.
    let ih = f64::from_bits(inv_x.hi.to_bits() & !((1u64 << 15) - 1));
    let il = (inv_x.hi - ih) + inv_x.lo;
    let g1 = 16.0 * U2 * mag(inv_x) + U * il.abs();
    let (mut h_prev, mut l_prev) = (j0.v.hi, j0.v.lo);
    let (mut h, mut l) = (j1.v.hi, j1.v.lo);
    let mut norm = j0.e + j1.e;
    for k in 1..n {
        let two_k = (2 * k) as f64;
        let (ch, cl) = (two_k * ih, two_k * il); // ch exact
        let cf = ch + cl;
        let (p, pi) = P::two_prod(ch, h);
        let (s, sigma) = two_sum(p, -h_prev);
        let l_next = (pi + sigma) + cl * h + cf * l - l_prev;
        // |c_k - ch - cl| <= 2k g1 + u |cl|
        let g = two_k * g1 + U * cl.abs();
        norm += U * (5.1 * (U * (p.abs() + s.abs()) + cl.abs() * h.abs() + l_prev.abs()) + 6.1 * cf.abs() * l.abs())
            + g * (h.abs() + l.abs());
        if k + 1 < n {
            let m = k as f64;
            visit(k as usize + 1, BoundedDd { v: Dd { hi: s, lo: l_next }, e: norm * x / ((x - m) * (x + m)).sqrt() });
            norm *= 1.0 + 0.5 / (x - k as f64);
        }
        (h_prev, l_prev) = (h, l);
        (h, l) = (s, l_next);
    }
    let m = (n - 1) as f64;
    let e = norm * x / ((x - m) * (x + m)).sqrt();
    e.is_finite().then_some(BoundedDd { v: Dd { hi: h, lo: l }, e })
}
#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::Dekker;
    use rug::Float;

    #[test]
    fn bound_holds_up_to_the_turning_point() {
        for &x in &[25.0, 61.5, 150.0, 149.99] {
            let (j0, j1) = super::super::native_hankel::bessel_j01::<Dekker>(x).unwrap();
            let top = (x - 1.0).floor() as u64;
            for n in [2, 7, top / 2, top - 1, top] {
                let b = forward::<Dekker>(n, x, j0, j1).unwrap();
                let e = super::super::bessel_j_mp(n as i64, &Float::with_val(53, x), 300).unwrap();
                let got = Float::with_val(300, b.v.hi) + b.v.lo;
                let diff = Float::with_val(300, got - e.mid()).abs();
                assert!(diff <= b.e, "J_{n}({x}): diff {} bound {:e}", diff.to_f64(), b.e);
                assert!(b.e < 1e-20, "J_{n}({x}): bound {:e}", b.e);
            }
            assert!(forward::<Dekker>(top + 2, x, j0, j1).is_none());
        }
    }
}
