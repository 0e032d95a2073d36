//! The wave displacement by direct quadrature of Eq. 11a: an independent route
//! that uses neither Eq. 12 nor the Bessel form.
//!
//! # The integrals
//!
//! Eq. 11a, as corrected in docs/displacement.md, Route 3 (outer integral over
//! `t in [0, D]`, `D = 2 pi a/zeta`, prefactor `A/zeta`, `x = a/cos(phi)`):
//!
//! ```text
//! du_w/dx = (A/zeta) int_0^D J0(t) int_0^{2pi} cos(phi) sin^2(th) / (1 - cos(th) cos(phi))
//!                                               cos((t - D) cos(th)) dth dt.
//! ```
//!
//! Integrating in `x` from `a` to `x` under the integral signs (Fubini; the
//! kernel is bounded) and using the elementary antiderivative
//! `int a/(x' - a cos th) dx' = a ln(x' - a cos th)` gives
//!
//! ```text
//! u_w(x) - u_w(a) = (A a/zeta) int_0^D J0(t) int_0^{2pi} sin^2(th) cos((t - D) cos(th))
//!                                     ln((x/a - cos th)/(1 - cos th)) dth dt,
//! ```
//!
//! and `u_w(a) = A (1 - cos D)` (the substrate meets the profile at the edge).
//! Both inner integrands are even about `th = pi`, so `int_0^{2pi} = 2 int_0^pi`.
//!
//! # Numerics
//!
//! * Cancellation-free kernels: `1 - cos th cos phi = 2 sin^2(th/2) + cos th * (x-a)/x`
//!   and `ln((r - cos th)/(1 - cos th)) = ln1p((r-1)/(2 sin^2(th/2)))`, `r = x/a`.
//! * As `x -> a+` the kernels peak at `th = 0` with width `phi ~ sqrt(2(x/a-1))`:
//!   the inner interval is split at `th_s = min(phi, pi/2)` (gradient) or
//!   `min(2 sqrt(r-1), pi/2)` (displacement), and each piece is integrated by
//!   tanh-sinh (MP, the gradient), which clusters nodes at the piece ends, or
//!   (f64) composite Gauss–Legendre on panels graded geometrically away from `th = 0`.
//! * MP displacement: the inner integral in closed form, a Neumann series in
//!   `J_{2k}(t - D)` with exact coefficients (Jacobi–Anger and the Fourier series
//!   of the log kernel; `InnerNeumann`), evaluated at each outer node from one
//!   Bessel sequence. The nested tanh-sinh it replaced evaluated the kernel (a
//!   `sin_cos`, a `cos`, an `ln1p`) at every inner node of every outer node:
//!   `u_wave_quad_mp(29.208292368802887, 23.6293610310602, 24.46665687179133,
//!   212.75)` took 3.25 s at 146 bits and now 0.032 s, with the same 40 digits
//!   (dev profile; `examples/wave_quad_timing.rs`, docs/fuzzing.md).
//! * The outer integrand `J0(t) * inner(t)` is smooth on `[0, D]`; the call's
//!   time budget ([`crate::budget`]) is checked at every outer node.
//!
//! The results are quadrature *estimates* (see [`crate::quad`]), not certified
//! balls; they serve as the independent cross-check of the series routes.

use rug::float::Constant;
use rug::Float;

use crate::error::{finite, Error, Interval, Reached, Result};
use crate::quad::{gauss_legendre, tanh_sinh, QuadEstimate, QuadEstimateMp, TanhSinhOptions};
use crate::special::bessel_j::{bessel_j_mp, bessel_j_sequence, bessel_j_sequence_mp, bessel_j_sequence_three_term};
use crate::special::{check_finite, exact_sub};

/// Which quantity.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Quantity {
    /// `du_w/dx`
    Gradient,
    /// `u_w(x) - u_w(a)`
    Increment,
}

impl Quantity {
    /// The public function computing this quantity.
    fn name(self) -> &'static str {
        match self {
            Quantity::Gradient => "du_wave_quad",
            Quantity::Increment => "u_wave_quad",
        }
    }
}

fn check(a: f64, zeta: f64, amp: f64, x: f64) -> Result<()> {
    finite(a, "a")?;
    finite(zeta, "zeta")?;
    finite(amp, "amp")?;
    finite(x, "x")?;
    Interval::above(0.0).check("a", a)?;
    Interval::above(0.0).check("zeta", zeta)?;
    if x < a {
        return Err(Error::OutOfRange { arg: "x (the wave displacement is for x >= a)", value: x, allowed: Interval::at_least(a) });
    }
    let d = 2.0 * std::f64::consts::PI * a / zeta;
    if !(d <= MAX_QUAD_D) {
        // the quadrature's cost grows like D^2
        return Err(Error::OutOfRange { arg: "2 pi a/zeta", value: d, allowed: Interval::left_open(0.0, MAX_QUAD_D) });
    }
    Ok(())
}

/// Largest `D = 2 pi a/zeta` the quadrature route accepts.
pub const MAX_QUAD_D: f64 = 1.0e3;

/// Inner-interval split point (f64 is enough: it only places nodes).
fn split_point(kind: Quantity, a: f64, x: f64) -> f64 {
    let rm1 = (x - a) / a;
    let s = match kind {
        Quantity::Gradient => (a / x).acos(),
        Quantity::Increment => 2.0 * rm1.sqrt(),
    };
    s.min(std::f64::consts::FRAC_PI_2)
}

// ---------------------------------------------------------------- MP

/// Geometry shared by all inner integrals at working precision.
struct MpGeometry {
    d: Float,
    cos_phi: Float,
    /// `(x-a)/x = 1 - cos(phi)`
    one_minus_cos_phi: Float,
    /// `r - 1 = (x-a)/a`
    rm1: Float,
}

/// The gradient's inner kernel `cos(phi) sin^2(th) cos((t - D) cos th) / (1 - cos th cos phi)`
/// (the increment's inner integral is [`InnerNeumann`]).
fn mp_kernel(g: &MpGeometry, t: &Float, th: &Float) -> Float {
    let p = t.prec().max(th.prec());
    // One sin_cos of th/2 gives everything: 1 - cos th = 2 s^2, cos th = 1 - 2 s^2,
    // sin th = 2 s c.
    let mut s_half = Float::with_val(p, th / 2u32);
    let mut c_half = Float::new(p);
    s_half.sin_cos_mut(&mut c_half);
    let two_s2 = Float::with_val(p, s_half.square_ref()) * 2u32; // 1 - cos th
    let c = Float::with_val(p, 1 - &two_s2);
    let sin_th = Float::with_val(p, &s_half * &c_half) * 2u32;
    let sin2 = Float::with_val(p, sin_th.square_ref());
    let arg = Float::with_val(p, t - &g.d) * &c;
    let osc = Float::with_val(p, arg.cos_ref());
    // cos(phi) sin^2 / (2 sin^2(th/2) + cos th (1 - cos phi))
    let den = Float::with_val(p, &two_s2 + Float::with_val(p, &c * &g.one_minus_cos_phi));
    Float::with_val(p, &g.cos_phi * &sin2) * &osc / den
}

/// `2 int_0^pi kernel(t, th) dth` by tanh-sinh on the two pieces.
fn mp_inner(g: &MpGeometry, t: &Float, split: f64, opts: &TanhSinhOptions) -> Result<Float> {
    let p = t.prec();
    let zero = Float::new(p);
    let pi = Float::with_val(p, Constant::Pi);
    let mut total = Float::new(p);
    let pieces: Vec<(Float, Float)> = if split > 0.0 {
        let s = Float::with_val(p, split);
        vec![(zero, s.clone()), (s, pi)]
    } else {
        vec![(zero, pi)]
    };
    for (lo, hi) in pieces {
        let r = tanh_sinh::integrate_with_complements(
            |th: &Float, from_lo: &Float, _to_hi: &Float| {
                // Near th = 0 use the accurate distance from 0 as the angle itself.
                let angle = if lo.is_zero() { from_lo } else { th };
                Ok(mp_kernel(g, t, angle))
            },
            &lo,
            &hi,
            opts,
        )?;
        total += r.value;
    }
    Ok(total * 2u32)
}

/// The inner integral of `u_w` as a function of `s = t - D`, in closed form:
///
/// ```text
/// 2 int_0^pi sin^2(th) L(th) cos(s cos th) dth = 2 M_0 J_0(s) + 4 sum_{k>=1} (-1)^k M_k J_{2k}(s),
/// ```
///
/// by the Jacobi-Anger expansion `cos(s cos th) = J_0(s) + 2 sum_k (-1)^k
/// J_{2k}(s) cos(2k th)` [DLMF 10.12.3], with the moments `M_k = int_0^pi
/// sin^2(th) L(th) cos(2k th) dth` of `L = ln((r - cos th)/(1 - cos th))`
/// exact: with `r = cosh(eta)`, `rho = e^-eta`, the Fourier series
/// `ln(1 - 2 rho cos th + rho^2) = -2 sum rho^n cos(n th)/n` gives
/// `L = eta + 2 sum_{n>=1} (1 - rho^n) cos(n th)/n`, so `Lam_n = int_0^pi L cos(n th)
/// = pi (1 - rho^n)/n` (`Lam_0 = pi eta`), and `sin^2 = (1 - cos 2th)/2` gives
/// `M_k = Lam_{2k}/2 - (Lam_{2k+2} + Lam_{|2k-2|})/4`. The series is cut where
/// `4 M_0 (|s|/2)^{2k}/(2k)!` (a bound of the term: `|M_k| <= M_0` as the
/// weight is positive, `|J_n(s)| <= (|s|/2)^n/n!` [DLMF 10.14.4]) and the tail
/// after it pass below `2^-wp M_0` for every `|s| <= D`.
struct InnerNeumann {
    /// `c_0 = 2 M_0`, `c_k = 4 (-1)^k M_k`.
    coeffs: Vec<Float>,
    wp: u32,
}

impl InnerNeumann {
    fn new(rm1: &Float, d: f64, wp: u32) -> InnerNeumann {
        let pi = Float::with_val(wp, Constant::Pi);
        // eta = acosh(1 + rm1) = ln1p(rm1 + sqrt(rm1 (2 + rm1))), cancellation-free
        let root = Float::with_val(wp, rm1 * Float::with_val(wp, rm1 + 2u32)).sqrt();
        let eta = Float::with_val(wp, rm1 + &root).ln_1p();
        let kmax = Self::terms(d, wp);
        // Lam_n for n = 0, 2, 4, ..., 2 kmax + 2
        let lam: Vec<Float> = (0..=kmax + 1)
            .map(|j| {
                let n = 2 * j as u32;
                if n == 0 {
                    return Float::with_val(wp, &pi * &eta);
                }
                // 1 - rho^n = -expm1(-n eta)
                let one_minus = -Float::with_val(wp, -Float::with_val(wp, &eta * n)).exp_m1();
                Float::with_val(wp, &pi * one_minus) / n
            })
            .collect();
        let coeffs = (0..=kmax)
            .map(|k| {
                let below = if k == 0 { &lam[1] } else { &lam[k - 1] };
                let quarter = Float::with_val(wp, &lam[k + 1] + below) / 4u32;
                let m = Float::with_val(wp, &lam[k] / 2u32) - quarter;
                match k {
                    0 => m * 2u32,
                    _ if k % 2 == 1 => -(m * 4u32),
                    _ => m * 4u32,
                }
            })
            .collect();
        InnerNeumann { coeffs, wp }
    }

    /// The last `k` kept: `(D/2)^{2k}/(2k)! <= 2^-(wp + 8)` with the ratio of
    /// the next terms below 1/4 (so the tail is at most a third more).
    fn terms(d: f64, wp: u32) -> usize {
        let h = (d / 2.0).max(1e-300);
        let mut log2_term = 0.0f64; // log2 of (D/2)^{2k}/(2k)!
        let mut k = 0usize;
        loop {
            let n = 2.0 * k as f64;
            let ratio = h * h / ((n + 1.0) * (n + 2.0));
            if log2_term <= -(f64::from(wp) + 8.0) && ratio <= 0.25 {
                return k;
            }
            log2_term += ratio.log2();
            k += 1;
        }
    }

    /// The inner integral at `s` (working precision of the series).
    fn at(&self, s: &Float) -> Result<Float> {
        let wp = self.wp;
        let mut sum = Float::with_val(wp, &self.coeffs[0]);
        if s.is_zero() {
            return Ok(sum); // J_0(0) = 1, J_n(0) = 0
        }
        // J_{2k}(s) = J_{2k}(|s|); the ball recurrence loses about 0.68 |s|
        // bits, the three-term sequence a few (its radii are not needed here)
        let x = Float::with_val(wp, s.abs_ref());
        let nmax = 2 * (self.coeffs.len() as u64 - 1);
        let seq = if x > 32 {
            bessel_j_sequence_three_term(nmax, &x, wp)?
        } else {
            bessel_j_sequence_mp(nmax, &x, wp)?
        };
        sum *= seq[0].mid();
        for (k, c) in self.coeffs.iter().enumerate().skip(1) {
            sum += Float::with_val(wp, c * seq[2 * k].mid());
        }
        Ok(sum)
    }
}

fn mp_quadrature(kind: Quantity, a: &Float, zeta: &Float, amp: &Float, x: &Float, prec: u32) -> Result<QuadEstimateMp> {
    crate::budget::ensure(|| mp_quadrature_in_budget(kind, a, zeta, amp, x, prec))
}

/// [`mp_quadrature`] under the call's time budget.
fn mp_quadrature_in_budget(kind: Quantity, a: &Float, zeta: &Float, amp: &Float, x: &Float, prec: u32) -> Result<QuadEstimateMp> {
    for (v, n) in [(a, "a"), (zeta, "zeta"), (amp, "amp"), (x, "x")] {
        check_finite(v, n)?;
    }
    check(a.to_f64(), zeta.to_f64(), amp.to_f64(), x.to_f64())?;
    if *x < *a {
        return Err(Error::OutOfRange {
            arg: "x (the wave displacement is for x >= a)",
            value: x.to_f64(),
            allowed: Interval::at_least(a.to_f64()),
        });
    }
    crate::error::check_prec(prec)?;
    let inner_opts = TanhSinhOptions::with_prec(prec + 24);
    let wp = inner_opts.prec + inner_opts.guard_bits;
    let d = Float::with_val(wp, Constant::Pi) * a * 2u32 / zeta;
    let xma = exact_sub(x, a);
    let g = MpGeometry {
        cos_phi: Float::with_val(wp, a / x),
        one_minus_cos_phi: Float::with_val(wp, &xma / x),
        rm1: Float::with_val(wp, &xma / a),
        d: d.clone(),
    };
    let split = split_point(kind, a.to_f64(), x.to_f64());
    let mut outer_opts = TanhSinhOptions::with_prec(prec);
    // The result may be small compared with its pieces: an absolute floor at the
    // natural scale (|A| for u, 2 pi |A|/zeta for du).
    outer_opts.abs_tol = Float::with_val(53, amp.abs_ref()) >> (prec as i32);
    let zero = Float::new(wp);
    // u_w: the inner integral in closed form as a Neumann series in s = t - D
    let neumann = (kind == Quantity::Increment).then(|| InnerNeumann::new(&g.rm1, d.to_f64(), wp));
    let mut evaluations = 0u64;
    let mut last = std::time::Instant::now();
    let outer = tanh_sinh::integrate(
        |t: &Float| {
            // the nested quadrature's length is not known in advance: the call's
            // time budget is checked at every outer node, with the last node's
            // time as the next one's estimate
            crate::budget::check_elapsed(kind.name(), crate::budget::since(last), Reached::Evaluations { count: evaluations })?;
            last = std::time::Instant::now();
            evaluations += 1;
            let j0 = bessel_j_mp(0, t, t.prec())?;
            let inner = match &neumann {
                Some(series) => series.at(&Float::with_val(wp, t - &g.d))?,
                None => mp_inner(&g, t, split, &inner_opts)?,
            };
            Ok(Float::with_val(t.prec(), j0.mid() * &inner))
        },
        &zero,
        &d,
        &outer_opts,
    )?;
    let factor = match kind {
        Quantity::Gradient => Float::with_val(wp, amp / zeta),
        Quantity::Increment => Float::with_val(wp, amp * a) / zeta,
    };
    let mut value = Float::with_val(prec, &outer.value * &factor);
    let err = Float::with_val(53, &outer.error_estimate * Float::with_val(53, factor.abs_ref()));
    if kind == Quantity::Increment {
        // + u_w(a) = A (1 - cos D) = 2 A sin^2(D/2)
        let half = Float::with_val(wp, &d / 2u32);
        let s = Float::with_val(wp, half.sin_ref());
        value += Float::with_val(wp, s.square_ref()) * amp * 2u32;
    }
    Ok(QuadEstimateMp { value, error_estimate: err, evaluations: outer.evaluations })
}

/// `u_w(x)` from the Eq. 11a quadrature (tanh-sinh), to about `prec` bits
/// (estimate). The nested quadrature's length is not known in advance: the
/// call's time budget ([`crate::budget`], default 30 s) is checked at every
/// outer node ([`Error::BudgetSpent`] past it).
pub fn u_wave_quad_mp(a: &Float, zeta: &Float, amp: &Float, x: &Float, prec: u32) -> Result<QuadEstimateMp> {
    mp_quadrature(Quantity::Increment, a, zeta, amp, x, prec)
}

/// `du_w/dx` from the Eq. 11a double integral (tanh-sinh), to about `prec` bits
/// (estimate), under the call's time budget (as [`u_wave_quad_mp`]).
pub fn du_wave_quad_mp(a: &Float, zeta: &Float, amp: &Float, x: &Float, prec: u32) -> Result<QuadEstimateMp> {
    mp_quadrature(Quantity::Gradient, a, zeta, amp, x, prec)
}

// ---------------------------------------------------------------- f64

/// Gauss–Legendre order per panel of the f64 route.
const GL_ORDER: usize = 24;

/// Widest panel (radians in `th`, units in `t`): with at most ~75 rad of phase
/// per unit (`|t - D| <= D <= 75` in the tested range) a 24-point rule per panel
/// resolves the oscillation to f64 accuracy.
const MAX_PANEL: f64 = 0.25;

/// Panels of `[0, pi]` for the inner integral: `[0, th_s]`, then geometrically
/// growing panels from `th_s` (resolving the `phi`-scale feature at the left
/// end), each at most [`MAX_PANEL`] wide.
fn inner_panels(split: f64) -> Vec<(f64, f64)> {
    let pi = std::f64::consts::PI;
    let mut panels = Vec::new();
    let mut lo = 0.0;
    if split > 0.0 {
        // [0, split] itself graded towards 0 for the log kernel.
        let mut edges = vec![split];
        let mut e = split;
        for _ in 0..12 {
            e *= 0.25;
            edges.push(e);
        }
        edges.push(0.0);
        edges.reverse();
        for w in edges.windows(2) {
            panels.push((w[0], w[1]));
        }
        lo = split;
    }
    let mut width = if split > 0.0 { split } else { MAX_PANEL };
    while lo < pi {
        let hi = (lo + width.min(MAX_PANEL)).min(pi);
        panels.push((lo, hi));
        lo = hi;
        width *= 2.0;
    }
    // No panel wider than MAX_PANEL (the oscillation needs it).
    panels
        .into_iter()
        .flat_map(|(lo, hi)| {
            let pieces = ((hi - lo) / MAX_PANEL).ceil().max(1.0) as usize;
            let w = (hi - lo) / pieces as f64;
            (0..pieces).map(move |i| (lo + i as f64 * w, if i + 1 == pieces { hi } else { lo + (i + 1) as f64 * w }))
        })
        .collect()
}

/// Inner Gauss–Legendre nodes on the graded panels of `[0, pi]`, with the
/// `t`-independent part of the kernel folded into the weight: `(w geom(th), cos th)`.
fn inner_nodes(kind: Quantity, a: f64, x: f64, rule: &gauss_legendre::GaussLegendreRule) -> Vec<(f64, f64)> {
    let cos_phi = a / x;
    let one_minus_cos_phi = (x - a) / x;
    let rm1 = (x - a) / a;
    let mut nodes = Vec::new();
    for (lo, hi) in inner_panels(split_point(kind, a, x)) {
        let half = 0.5 * (hi - lo);
        let mid = 0.5 * (hi + lo);
        for (xi, wi) in rule.nodes().iter().zip(rule.weights()) {
            let th = mid + half * xi;
            let s_half = (0.5 * th).sin();
            let two_s2 = 2.0 * s_half * s_half;
            let c = 1.0 - two_s2;
            let sin2 = th.sin().powi(2);
            let geom = match kind {
                Quantity::Gradient => cos_phi * sin2 / (two_s2 + c * one_minus_cos_phi),
                Quantity::Increment => {
                    if two_s2 == 0.0 {
                        0.0
                    } else {
                        sin2 * (rm1 / two_s2).ln_1p()
                    }
                }
            };
            nodes.push((wi * half * geom, c));
        }
    }
    nodes
}

fn f64_quadrature(kind: Quantity, a: f64, zeta: f64, amp: f64, x: f64) -> Result<QuadEstimate> {
    check(a, zeta, amp, x)?;
    let d = 2.0 * std::f64::consts::PI * a / zeta;
    let rule = gauss_legendre::rule(GL_ORDER)?;
    let nodes = inner_nodes(kind, a, x, &rule);
    let n_outer_panels = ((d / MAX_PANEL).ceil() as usize).max(1);
    let mut evaluations = 0u64;
    let mut outer = 0.0f64;
    let mut comp = 0.0f64;
    let width = d / n_outer_panels as f64;
    for p in 0..n_outer_panels {
        let mid = (p as f64 + 0.5) * width;
        for (xi, wi) in rule.nodes().iter().zip(rule.weights()) {
            let t = mid + 0.5 * width * xi;
            let j0 = bessel_j_sequence(0, t).first().copied().unwrap_or(f64::NAN);
            let inner: f64 = nodes.iter().map(|&(w, c)| w * ((t - d) * c).cos()).sum();
            evaluations += nodes.len() as u64;
            let term = 0.5 * width * wi * 2.0 * j0 * inner;
            // Neumaier summation
            let new = outer + term;
            comp += if outer.abs() >= term.abs() { (outer - new) + term } else { (term - new) + outer };
            outer = new;
        }
    }
    let outer = outer + comp;
    let factor = match kind {
        Quantity::Gradient => amp / zeta,
        Quantity::Increment => amp * a / zeta,
    };
    let mut value = outer * factor;
    if kind == Quantity::Increment {
        let s = (0.5 * d).sin();
        value += 2.0 * amp * s * s;
    }
    // A fixed rule has no built-in estimate; report the rounding level of the sums.
    let error_estimate = 1e-15 * (1.0 + d) * factor.abs().max(amp.abs());
    if !(value.is_finite() && error_estimate.is_finite()) {
        // extreme scales (found by tests/fuzz.rs: a = x = 5e-324, zeta = 5.5e-222)
        return Err(Error::NonFiniteResult { function: kind.name() });
    }
    Ok(QuadEstimate { value, error_estimate, evaluations })
}

/// `u_w(x)` from the Eq. 11a quadrature in f64 (nested adaptive Gauss–Kronrod).
pub fn u_wave_quad(a: f64, zeta: f64, amp: f64, x: f64) -> Result<QuadEstimate> {
    f64_quadrature(Quantity::Increment, a, zeta, amp, x)
}

/// `du_w/dx` from the Eq. 11a double integral in f64 (nested adaptive Gauss–Kronrod).
pub fn du_wave_quad(a: f64, zeta: f64, amp: f64, x: f64) -> Result<QuadEstimate> {
    f64_quadrature(Quantity::Gradient, a, zeta, amp, x)
}

/// The printed (garbled) Eq. 11a, kept only so a test can pin the erratum:
/// outer integral over `t in [0, 2 pi]` with the factor `2 pi a/zeta` in front of
/// `J0(t)` and prefactor `A/zeta`, f64. Do not use it for anything else.
pub fn du_wave_quad_as_printed(a: f64, zeta: f64, amp: f64, x: f64) -> Result<f64> {
    check(a, zeta, amp, x)?;
    let d = 2.0 * std::f64::consts::PI * a / zeta;
    let rule = gauss_legendre::rule(GL_ORDER)?;
    let nodes = inner_nodes(Quantity::Gradient, a, x, &rule);
    let inner = |t: f64| -> f64 { 2.0 * nodes.iter().map(|&(w, c)| w * ((t - d) * c).cos()).sum::<f64>() };
    let two_pi = 2.0 * std::f64::consts::PI;
    let panels = (two_pi / MAX_PANEL).ceil() as usize;
    let width = two_pi / panels as f64;
    let mut total = 0.0;
    for p in 0..panels {
        let mid = (p as f64 + 0.5) * width;
        for (xi, wi) in rule.nodes().iter().zip(rule.weights()) {
            let t = mid + 0.5 * width * xi;
            let j0 = bessel_j_sequence(0, t).first().copied().unwrap_or(f64::NAN);
            total += 0.5 * width * wi * d * j0 * inner(t);
        }
    }
    Ok(amp / zeta * total)
}
