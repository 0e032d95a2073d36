//! `u_w` and `du_w/dx` in f64 ([`WaveBessel`] and the free functions): the
//! Bessel form at one contact size with the `J_n(D)` sequence computed once,
//! the compensated value path, and the bounded path of
//! [`crate::contact::displacement::bounded`] with its counted MP fallback.
//!
//! Accuracy: the value paths are double-double sums rounded once (a few ulps,
//! tests/wave_value.rs); the `*_bounded` paths return a proven bound for the
//! f64 inputs as given (module docs of [`crate::contact::displacement::bounded`]).

use std::sync::OnceLock;

use crate::ball::{Bounded, Dd};
use crate::contact::displacement::bounded::{count_fallback, count_scratch_miss, CertifiedBessel};
use crate::error::{finite, Error, Result};
use crate::special::bessel_j::bessel_j_sequence_dd;
use crate::special::exact;

use super::bessel_mp::{du_wave_mp_up_to, u_wave_mp_up_to};
use super::geometry::check_wave_f64;

/// Number of Bessel terms for the f64 path: the tail `sum_{n>N} 2 n^2 (D/2)^{2n}/(2n)!`
/// below `1e-18` (estimate in f64).
fn bessel_terms_f64(d: f64) -> usize {
    let half = d / 2.0;
    let mut n = (half.ceil() as usize).max(1) + 2;
    loop {
        let m = (n + 1) as f64;
        // log of (D/2)^{2m}/(2m)! via lgamma-free Stirling upper bound
        let ln_t = 2.0 * m * half.max(1e-300).ln() - ln_factorial(2.0 * m);
        if ln_t + (2.0 * m * m).ln() < (1e-19f64).ln() {
            return n;
        }
        n += 2;
    }
}

/// `ln(n!)` for real `n >= 1` by Stirling with the 1/(12n) term (a lower bound of
/// the true value is not needed here: this only sizes the f64 sum).
fn ln_factorial(n: f64) -> f64 {
    n * n.ln() - n + 0.5 * (2.0 * std::f64::consts::PI * n).ln() + 1.0 / (12.0 * n)
}

/// [`WaveBessel::u_fast`] stops its sum once the terms left are at most this in
/// sum (`2^-64`, relative to `|A|`).
const TAIL_LIMIT: f64 = 1.0 / 18_446_744_073_709_551_616.0;

/// Placeholder entries of the batch outputs (every one is overwritten).
const UNSET_PAIR: (Bounded, Bounded) = (Bounded { value: 0.0, err: f64::INFINITY }, Bounded { value: 0.0, err: f64::INFINITY });

/// The Bessel form at one contact size: `D = 2 pi a/zeta` and the sequence
/// `J_n(D)` are computed once (double-double Miller recurrence), after which
/// `u_w(x)`, `du_w/dx` and the wave-traction integral cost one short sum each.
/// This is what the Maugis solver uses: `a` is fixed while the strip end moves.
///
/// Everything is evaluated in double-double (the geometry `q`, `g_n` and the
/// sums) and rounded once; `acosh(x/a)` is the f64 library value, whose
/// half-ulp error enters only through the `D J1(D) acosh(x/a)` term.
#[derive(Debug, Clone)]
pub struct WaveBessel {
    a: f64,
    zeta: f64,
    amp: f64,
    /// Certified Bessel data for the `*_bounded` evaluations, built on first use.
    cert: OnceLock<Option<CertifiedBessel>>,
    /// The native (double-double) certified data, built on first use by either
    /// path; `None` where they do not certify (`D` beyond about 60).
    native: OnceLock<Option<CertifiedBessel>>,
    d: Dd,
    n_terms: usize,
    j: Vec<Dd>,
    /// `S_n = 2 sum_{k>=0} (-1)^k J_{2n+2k+1}(D)`, `n = 0..=n_terms`.
    conv: Vec<Dd>,
    /// `J_{2n}(D)` rounded to f64, for [`WaveBessel::u_fast`].
    j_even_f64: Vec<f64>,
    /// `S_n` rounded to f64, for [`WaveBessel::traction_integral_fast`].
    conv_f64: Vec<f64>,
    /// Horner coefficients in `q^2` of the two sums (`horner_coefficients`).
    u_coef: Vec<Dd>,
    du_coef: Vec<Dd>,
}

/// The Bessel-form sums as polynomials in `q^2`:
/// `sum_{n=1}^N (-1)^{n+1} J_{2n} q^{2n} = sum_m u_m q^{2m}`, `u_m = (-1)^{m+1} J_{2m}`, and
/// `sum_n (-1)^{n+1} n J_{2n} geo_n = (1 + q) sum_{m<N} T_m q^{2m}`,
/// `T_m = sum_{n=m+1}^{N} (-1)^{n+1} n J_{2n}` (the powers `q^{2m}`, `q^{2m+1}` of
/// `geo_n = sum_{j<2n} q^j` both occur for every `n > m`). Two Horner passes per `x`.
fn horner_coefficients(j: &[Dd], n_terms: usize) -> (Vec<Dd>, Vec<Dd>) {
    let sign = |n: usize| if n % 2 == 1 { 1.0 } else { -1.0 };
    let u_coef: Vec<Dd> = (0..=n_terms).map(|m| j[2 * m].mul_f64(sign(m))).collect();
    let mut du_coef = vec![Dd::ZERO; n_terms];
    let mut acc = Dd::ZERO;
    for m in (0..n_terms).rev() {
        acc = acc + j[2 * (m + 1)].mul_f64(sign(m + 1) * (m + 1) as f64);
        du_coef[m] = acc;
    }
    (u_coef, du_coef)
}

impl WaveBessel {
    /// Precomputes the Bessel data for contact half-width `a`, wavelength `zeta`,
    /// amplitude `amp`.
    pub fn new(a: f64, zeta: f64, amp: f64) -> Result<WaveBessel> {
        check_wave_f64(a, zeta, amp, a)?;
        let d = Dd::TWO_PI.mul_f64(a) / Dd::from_f64(zeta);
        let n_terms = bessel_terms_f64(d.hi);
        let top = 2 * n_terms + 3;
        let j = bessel_j_sequence_dd(top, d);
        if j.len() <= top {
            // D not finite in double-double at subnormal scales (found by
            // tests/fuzz.rs), or beyond the sequence's range
            return Err(Error::NonFiniteResult { function: "WaveBessel::new (2 pi a/zeta in double-double)" });
        }
        // S_n = J_{2n+1} - J_{2n+3} + ... (times 2): backward partial sums over the odd orders.
        let mut conv = vec![Dd::ZERO; n_terms + 1];
        // Start at the highest odd order available and accumulate downward;
        // the neglected orders are below the sums' truncation level.
        let mut tail = Dd::ZERO;
        let mut k = top as isize - if top % 2 == 1 { 0 } else { 1 };
        while k >= 1 {
            // tail_k = J_k - tail_{k+2}
            tail = j[k as usize] - tail;
            if (k - 1) % 2 == 0 {
                let idx = (k - 1) / 2;
                if idx <= n_terms as isize {
                    conv[idx as usize] = tail.mul_f64(2.0);
                }
            }
            k -= 2;
        }
        let j_even_f64 = (0..=n_terms).map(|n| j[2 * n].to_f64()).collect();
        let conv_f64 = conv.iter().map(|c| c.to_f64()).collect();
        let (u_coef, du_coef) = horner_coefficients(&j, n_terms);
        Ok(WaveBessel { a, zeta, amp, cert: OnceLock::new(), native: OnceLock::new(), d, n_terms, j, conv, j_even_f64, conv_f64, u_coef, du_coef })
    }

    /// `D = 2 pi a / zeta`.
    pub fn d(&self) -> f64 {
        self.d.to_f64()
    }

    /// `(u_w(x), du_w/dx)` for `x >= a`: the values of [`WaveBessel::eval_bounded`]
    /// (native double-double, rounded once; the certified data are built on the
    /// first call) up to `x/a = 25/7`, beyond it the double-double Miller data.
    /// An estimate: about `1e-16` of `max(|u_w|, |A|)`.
    ///
    /// Errors: `x` NaN or infinite, or `x < a` (the Bessel form is for the
    /// outside of the contact).
    pub fn eval(&self, x: f64) -> Result<(f64, f64)> {
        self.check_x(x)?;
        // The values of the proven-bound path where it runs natively (it is
        // also the faster one); beyond x/a = 25/7 the double-double Miller data.
        if let Some((u, du)) = self.native_data().and_then(|c| c.eval_bounded(self.a, self.amp, x)) {
            return Ok((u.value, du.value));
        }
        Ok(self.eval_unchecked(x))
    }

    /// The native certified Bessel data, built on first use (never MP, so
    /// that the estimate path stays cheap at any `D`).
    fn native_data(&self) -> Option<&CertifiedBessel> {
        self.native.get_or_init(|| CertifiedBessel::native_only(self.a, self.zeta)).as_ref()
    }

    /// The certified Bessel data: native where they certify, else built in MP
    /// on first use.
    fn certified(&self) -> Option<&CertifiedBessel> {
        self.native_data().or_else(|| self.cert.get_or_init(|| CertifiedBessel::new_mp_counted(self.a, self.zeta).ok()).as_ref())
    }

    /// [`WaveBessel::eval`] over a slice of `x` (one contact, many points: the
    /// solver's case), the same values as one call per point, computed in one
    /// loop. Fails on the first invalid `x`, naming it.
    pub fn eval_many(&self, xs: &[f64]) -> Result<Vec<(f64, f64)>> {
        xs.iter().try_for_each(|&x| self.check_x(x))?;
        let Some(c) = self.native_data() else {
            return Ok(xs.iter().map(|&x| self.eval_unchecked(x)).collect());
        };
        let mut out = vec![UNSET_PAIR; xs.len()];
        let mut refused = Vec::new();
        c.eval_bounded_batch(self.a, self.amp, xs, &mut out, &mut refused);
        let mut values: Vec<(f64, f64)> = out.iter().map(|(u, du)| (u.value, du.value)).collect();
        for i in refused {
            values[i] = self.eval_unchecked(xs[i]);
        }
        Ok(values)
    }

    /// `(u_w(x), du_w/dx)` with proven error bounds for the f64 inputs as given
    /// ([`crate::contact::displacement::bounded`]). The certified Bessel data are computed
    /// on the first call (MP, once per contact); each later call costs one short
    /// double-double sum. Falls back to the MP Bessel form for `x/a > 25/7`
    /// (counted by [`wave_bounded_fallbacks`](crate::contact::displacement::bounded::wave_bounded_fallbacks)).
    pub fn eval_bounded(&self, x: f64) -> Result<(Bounded, Bounded)> {
        self.check_x(x)?;
        if let Some(r) = self.certified().and_then(|c| c.eval_bounded(self.a, self.amp, x)) {
            return Ok(r);
        }
        wave_bounded_fallback(self.a, self.zeta, self.amp, x)
    }

    /// [`WaveBessel::eval_bounded`] over a slice of `x` (one contact, many
    /// points: the solver's case), the same values and bounds as one call per
    /// point, computed in one loop. Fails on the first invalid `x`, naming it.
    pub fn eval_bounded_many(&self, xs: &[f64]) -> Result<Vec<(Bounded, Bounded)>> {
        let mut out = vec![UNSET_PAIR; xs.len()];
        self.eval_bounded_into(xs, &mut out)?;
        Ok(out)
    }

    /// [`WaveBessel::eval_bounded_many`] into the caller's slice, without
    /// allocating (`out.len()` must equal `xs.len()`). Every `x` is checked
    /// before anything is written; an error from the MP fallback (`x/a > 25/7`)
    /// can leave `out` partly written.
    pub fn eval_bounded_into(&self, xs: &[f64], out: &mut [(Bounded, Bounded)]) -> Result<()> {
        if out.len() != xs.len() {
            return Err(Error::LengthMismatch { inputs: xs.len(), outputs: out.len() });
        }
        xs.iter().try_for_each(|&x| self.check_x(x))?;
        let Some(c) = self.certified() else {
            for (o, &x) in out.iter_mut().zip(xs) {
                *o = wave_bounded_fallback(self.a, self.zeta, self.amp, x)?;
            }
            return Ok(());
        };
        let mut refused = Vec::new();
        c.eval_bounded_batch(self.a, self.amp, xs, out, &mut refused);
        for i in refused {
            out[i] = wave_bounded_fallback(self.a, self.zeta, self.amp, xs[i])?;
        }
        Ok(())
    }

    fn check_x(&self, x: f64) -> Result<()> {
        finite(x, "x")?;
        if x < self.a {
            return Err(Error::InsideContact { x, a: self.a });
        }
        Ok(())
    }

    fn eval_unchecked(&self, x: f64) -> (f64, f64) {
        let (a, amp, d, j) = (self.a, self.amp, self.d, &self.j);
        let ad = Dd::from_f64(a);
        let rm1 = Dd::diff(x, a) / ad; // x/a - 1
        let rp1 = (Dd::from_f64(x) + ad) / ad; // x/a + 1
        let r = Dd::from_f64(x) / ad;
        let sq = (rm1 * rp1).sqrt(); // sqrt((x/a)^2 - 1)
        let q = (r + sq).recip();
        let acosh_r = (rm1 + sq).to_f64().ln_1p();
        let one_minus_q_over_s = Dd::ONE - (rm1 / rp1).sqrt();
        let q2 = q * q;
        // Horner in q^2 (see `horner_coefficients`).
        // One loop, two independent chains (they overlap in the pipeline).
        let n = self.n_terms;
        let (mut su, mut sdu) = (self.u_coef[n], self.du_coef[n - 1]);
        for m in (0..n - 1).rev() {
            su = su * q2 + self.u_coef[m + 1];
            sdu = sdu * q2 + self.du_coef[m];
        }
        let su = su * q2;
        let sdu = sdu * (Dd::ONE + q);
        let inner = (Dd::ONE - j[0]) + (d * j[1]).mul_f64(acosh_r) + su.mul_f64(2.0);
        let u = inner.mul_f64(amp).to_f64();
        let du = (one_minus_q_over_s * sdu).mul_f64(4.0 * amp / a).to_f64();
        (u, du)
    }

    /// `u_w(x)` in plain f64 arithmetic (from the double-double Bessel values):
    /// about 4x faster than [`WaveBessel::eval`], with an error of a few ulps of
    /// the largest term (`~ 1e-15 |A| D`) instead of one rounding (its sum
    /// stops once the terms left are below `2^-64 |A|` in sum, so its cost
    /// falls from `D/2` terms next to the edge to a few hundred away from it:
    /// tests/it/wave_value.rs measures it against the certified form). The Maugis
    /// solver uses it in its scans; the public `u_wave` uses [`WaveBessel::eval`].
    pub fn u_fast(&self, x: f64) -> f64 {
        let a = self.a;
        let rm1 = (x - a) / a;
        let (q, acosh_r) = if rm1 < 1e100 {
            let sq = (rm1 * (rm1 + 2.0)).sqrt();
            (1.0 / (1.0 + rm1 + sq), (rm1 + sq).ln_1p())
        } else {
            // far from a tiny contact (r = x/a up to overflow): with p = sqrt(x^2 - a^2),
            // q = a/(x + p) and acosh r = ln r + ln1p(p/x), no r^2 formed
            let p = (x - a).sqrt() * (x + a).sqrt();
            let ln_r = if rm1.is_finite() { rm1.ln_1p() } else { x.ln() - a.ln() };
            (a / (x + p), ln_r + (p / x).ln_1p())
        };
        let q2 = q * q;
        // |J_2n(D)| <= 1 (DLMF 10.14.1), so the terms past n are at most
        // q^(2n+2)/(1 - q^2) in sum: once that is below TAIL_LIMIT the rest of the
        // n_terms sum changes `su` by less than its own rounding (the documented
        // error is a few ulps of the largest term, which is at least q^2 |J_2|).
        // Far from the edge (x/a - 1 = 1e-3: q^2 = 1 - 0.18) that is a few hundred
        // terms where D/2 can be tens of thousands (the strip scan of a fine wave).
        let tail_scale = TAIL_LIMIT * (1.0 - q2);
        let mut q_pow = 1.0f64;
        let mut su = 0.0f64;
        for n in 1..=self.n_terms {
            q_pow *= q2;
            let t = self.j_even_f64[n] * q_pow;
            su += if n % 2 == 1 { t } else { -t };
            if q_pow <= tail_scale {
                break;
            }
        }
        let j1 = self.j[1].to_f64();
        let one_minus_j0 = (Dd::ONE - self.j[0]).to_f64();
        self.amp * (one_minus_j0 + self.d.to_f64() * j1 * acosh_r + 2.0 * su)
    }

    /// The wave-traction integral of Eq. 7 / Eq. 16,
    /// `K(c) = int_0^D J0(t) cos((t - D) c) dt` for `|c| <= 1` (`c = x/a = cos(theta)`).
    ///
    /// Jacobi–Anger, `cos(z c) = J0(z) + 2 sum_n (-1)^n J_{2n}(z) T_{2n}(c)` [DLMF 10.12.3],
    /// and the convolution `int_0^D J0(t) J_{2n}(D-t) dt = 2 sum_k (-1)^k J_{2n+2k+1}(D)`
    /// [DLMF 10.22.31] give `K(c) = sum_n eps_n (-1)^n S_n T_{2n}(c)`; the Chebyshev
    /// polynomials by their recurrence. Same truncation as the displacement sums.
    pub fn traction_integral(&self, c: f64) -> f64 {
        let c = c.clamp(-1.0, 1.0);
        let x2 = 2.0 * c * c - 1.0; // T_2(c)
        // T_{2n}(c) = T_n(T_2(c)); recurrence in n on T_2
        let (mut t_prev, mut t_cur) = (1.0f64, x2); // T_0(x2), T_1(x2)
        let mut sum = self.conv[0];
        for n in 1..=self.n_terms {
            let coeff = self.conv[n].mul_f64(2.0 * t_cur);
            sum = if n % 2 == 1 { sum - coeff } else { sum + coeff };
            let t_next = 2.0 * x2 * t_cur - t_prev;
            t_prev = t_cur;
            t_cur = t_next;
        }
        sum.to_f64()
    }

    /// [`WaveBessel::traction_integral`] in plain f64 arithmetic (from the rounded
    /// `S_n`): one f64 multiply-add a term instead of a double-double one (not timed on
    /// its own; its effect on whole curves is in docs/performance.md), with an error of a
    /// few ulps of the largest term
    /// instead of one rounding. For scans that only locate candidates (the model's
    /// validity rescan), which then evaluate [`WaveBessel::traction_integral`].
    pub fn traction_integral_fast(&self, c: f64) -> f64 {
        let c = c.clamp(-1.0, 1.0);
        let x2 = 2.0 * c * c - 1.0;
        let (mut t_prev, mut t_cur) = (1.0f64, x2);
        let mut sum = self.conv_f64[0];
        for n in 1..=self.n_terms {
            let coeff = self.conv_f64[n] * (2.0 * t_cur);
            sum = if n % 2 == 1 { sum - coeff } else { sum + coeff };
            let t_next = 2.0 * x2 * t_cur - t_prev;
            t_prev = t_cur;
            t_cur = t_next;
        }
        sum
    }
}

fn wave_bessel_f64(a: f64, zeta: f64, amp: f64, x: f64) -> Result<(f64, f64)> {
    WaveBessel::new(a, zeta, amp)?.eval(x)
}

/// The MP fallback of the bounded f64 wave functions: both Bessel-form balls
/// at [`F64_FALLBACK_PREC`](crate::special::F64_FALLBACK_PREC) bits (counted).
fn wave_bounded_fallback(a: f64, zeta: f64, amp: f64, x: f64) -> Result<(Bounded, Bounded)> {
    count_fallback();
    let (a, zeta, amp, x) = (exact(a), exact(zeta), exact(amp), exact(x));
    // Capped like every f64 fallback: an argument that needs more than
    // F64_FALLBACK_MAX_WP bits (tests/fuzz.rs found a = 1e-296, zeta = 1e-300,
    // x = 29.6: 58 335 bits, minutes) is refused at once; the MP functions remain.
    let (p, max_wp) = (crate::special::F64_FALLBACK_PREC, crate::special::F64_FALLBACK_MAX_WP);
    let u = crate::special::bounded_from_ball("u_wave", &u_wave_mp_up_to(&a, &zeta, &amp, &x, p, max_wp)?)?;
    let du = crate::special::bounded_from_ball("du_wave", &du_wave_mp_up_to(&a, &zeta, &amp, &x, p, max_wp)?)?;
    Ok((u, du))
}

/// One bounded value from scratch (`du`: `du_w/dx`, else `u_w`): the one-pass
/// bounded Miller route (`crate::contact::displacement::bounded::wave_scratch_bounded`,
/// which forms only the sums that value needs) where it applies and its bound is
/// within `2^-50` of the value's scale (the model domain), else certified Bessel
/// data, then the native sum, else MP (counted).
fn wave_bounded_one(a: f64, zeta: f64, amp: f64, x: f64, du: bool) -> Result<Bounded> {
    use crate::contact::displacement::bounded::wave_scratch_bounded;
    check_wave_f64(a, zeta, amp, x)?;
    let scratch = if du { wave_scratch_bounded::<true>(a, zeta, amp, x) } else { wave_scratch_bounded::<false>(a, zeta, amp, x) };
    if let Some(r) = scratch {
        const TIGHT: f64 = 1.0 / (1u64 << 50) as f64;
        let scale = if du { 2.0 * std::f64::consts::PI * amp.abs() / zeta } else { amp.abs() };
        if r.err <= TIGHT * r.value.abs().max(scale) {
            return Ok(r);
        }
    }
    count_scratch_miss();
    let pair = match CertifiedBessel::new(a, zeta).ok().and_then(|c| c.eval_bounded(a, amp, x)) {
        Some(r) => r,
        None => wave_bounded_fallback(a, zeta, amp, x)?,
    };
    Ok(if du { pair.1 } else { pair.0 })
}

/// Both f64 values from scratch: the fast value path
/// (`crate::contact::displacement::bounded::wave_value`: one compensated Miller
/// recurrence with both sums in the same loop, an estimate enforced by
/// tests/wave_value.rs) where it applies (FMA, `x/a <= 25/7`, `D <= 64`), else
/// the native proven-bound path's values where it runs without MP, else the
/// double-double Miller route of [`WaveBessel`].
fn wave_f64_pair(a: f64, zeta: f64, amp: f64, x: f64) -> Result<(f64, f64)> {
    check_wave_f64(a, zeta, amp, x)?;
    if let Some(r) = crate::contact::displacement::bounded::wave_value(a, zeta, amp, x) {
        return Ok(r);
    }
    if let Some((u, du)) = CertifiedBessel::native_only(a, zeta).and_then(|c| c.eval_bounded(a, amp, x)) {
        return Ok((u.value, du.value));
    }
    let (u, du) = wave_bessel_f64(a, zeta, amp, x)?;
    if u.is_finite() && du.is_finite() {
        return Ok((u, du));
    }
    // the double-double route under- or overflows at extreme scales (found by
    // tests/fuzz.rs: a = x = 5e-324, zeta = 3.6e-217): the certified MP values
    let (u, du) = wave_bounded_fallback(a, zeta, amp, x)?;
    Ok((u.value, du.value))
}

/// Wave displacement `u_w(x)` in f64 (Bessel form), from scratch in about
/// 0.2-0.4 us on the model domain (compensated Miller recurrence, module docs
/// of [`crate::contact::displacement::bounded`]).
///
/// Accuracy: within `1e-15` of `max(|u_w|, |A|)`, measured worst `1.1e-16` on a
/// dense grid of `a in [0.5, 6]`, `zeta = 9/8`, `x/a in [1, 3]` (tests/wave_value.rs;
/// an estimate: [`u_wave_bounded`] returns a proven bound).
pub fn u_wave(a: f64, zeta: f64, amp: f64, x: f64) -> Result<f64> {
    Ok(wave_f64_pair(a, zeta, amp, x)?.0)
}

/// Wave-displacement gradient `du_w/dx` in f64 (Bessel form), computed with
/// `u_w` by the same path as [`u_wave`]; within `1e-15` of
/// `max(|du_w/dx|, 2 pi |A|/zeta)` on the same grid (an estimate:
/// [`du_wave_bounded`] returns a proven bound).
pub fn du_wave(a: f64, zeta: f64, amp: f64, x: f64) -> Result<f64> {
    Ok(wave_f64_pair(a, zeta, amp, x)?.1)
}

/// `u_w(x)` in f64 with a proven error bound for the f64 inputs as given:
/// one compensated Miller pass with its running error bound, forming only the
/// sums `u_w` needs (2.6k-5.5k instructions per call over the model domain;
/// method block of
/// `contact/displacement/bounded/value.rs`), else the per-contact double-double
/// data of [`crate::contact::displacement::bounded`], else MP (both counted).
/// For many `x` at one contact use [`WaveBessel::eval_bounded`], which
/// computes the Bessel data once.
pub fn u_wave_bounded(a: f64, zeta: f64, amp: f64, x: f64) -> Result<Bounded> {
    wave_bounded_one(a, zeta, amp, x, false)
}

/// `du_w/dx` in f64 with a proven error bound for the f64 inputs as given.
pub fn du_wave_bounded(a: f64, zeta: f64, amp: f64, x: f64) -> Result<Bounded> {
    wave_bounded_one(a, zeta, amp, x, true)
}

