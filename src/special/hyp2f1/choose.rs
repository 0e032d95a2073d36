//! Choosing the `2F1` algorithm: a pure function of cheap f64 estimates.
//!
//! # Method
//!
//! Within `-1 <= z <= 1/2` the same function is also
//! `(1-z)^{c-a-b} 2F1(c-a, c-b; c; z)` ([`Algorithm::Euler`], DLMF 15.8.1) and
//! `(1-z)^{-b} 2F1(c-a, b; c; w)` ([`Algorithm::PfaffSwapped`]); for `z < 0`
//! also `(1-z)^{-a} 2F1(a, c-b; c; w)` with `|w| < |z|`. [`choose_algorithm`]
//! simulates the term magnitudes of these series in f64 and takes the cheapest
//! (terms times precision plus cancellation, the direct series on ties). This
//! matters for large negative parameters: `2F1(-N+1/2, 2; 3; 1/2)` loses about
//! `0.6 N` bits to cancellation in the direct series, while the Euler transform
//! has positive terms (`N = 10^6` takes 0.2 s instead of minutes).
//!
//! With large parameters the two pieces of the 1-z formula can both be far
//! larger than their sum: for `2F1(1, k+1/2; k+2; y)` they are about
//! `y^{-k}`, so at `k = 1000`, `y = 0.6` some 740 bits cancel. For
//! `1/2 < z < 1` (and for `w` after Pfaff) [`choose_algorithm`] therefore
//! compares estimated costs: an f64 simulation of the term magnitudes of the
//! direct series in `z` and of the 1-z series, the cancellation between the
//! pieces from f64 log-Gamma estimates, and a fixed price for the Gamma
//! values. It takes the direct series (`|z| < 1` converges; the ratio test is
//! rigorous) when that is cheaper. The estimate only chooses; the certified
//! error bound never depends on it.

use std::f64::consts::LN_2;

use rug::Float;

use super::connection::{hyp2f1_connection, hyp2f1_gauss, hyp2f1_pfaff_connection};
use super::large_param::{hyp2f1_large_param, large_param_cheaper, large_param_loss, large_param_terms};
use super::log_case::hyp2f1_connection_log;
use super::polynomial::hyp2f1_polynomial;
use super::transform::{hyp2f1_direct, hyp2f1_euler, hyp2f1_pfaff};
use super::{one, terminating_degree, DIRECT_RADIUS, MAX_LOG_M};
use crate::ball::Ball;
use crate::error::Result;
use crate::special::gamma::{lgamma_est, xball};
use crate::special::{exact_sub, is_nonpositive_integer};

/// Cap on the f64 cost simulations (iterations).
const SIM_CAP: u64 = 200_000;

/// Price of the Gamma/digamma values of a connection formula, in series terms.
const GAMMA_COST_TERMS: f64 = 150.0;

/// Relative price of one logarithmic-series term (ball arithmetic, digammas).
const LOG_TERM_COST: f64 = 6.0;

/// The algorithms (see the module docs for the formulas).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Algorithm {
    /// `a` or `b` a non-positive integer: finite sum, any `z <= 1`.
    Polynomial,
    /// Power series in `z` (`|z| <= 1/2` unless a transformed series is cheaper;
    /// `1/2 < z < 1` when cheaper than the 1-z formula).
    Direct,
    /// Pfaff, then the power series in `w = z/(z-1)`: `(1-z)^{-a} 2F1(a, c-b; c; w)`
    /// (`-1 <= z < -1/2`; `-1/2 <= z < 0` when cheaper; `z < -1` when cheaper or when
    /// the transformed series terminates).
    Pfaff,
    /// Pfaff on `b`: `(1-z)^{-b} 2F1(c-a, b; c; w)`, same regions as [`Algorithm::Pfaff`].
    PfaffSwapped,
    /// Euler: `(1-z)^{c-a-b} 2F1(c-a, c-b; c; z)` [DLMF 15.8.1]: a polynomial times a
    /// power when `c - a` or `c - b` is a non-positive integer (any `z < 1`), else the
    /// series for `|z| <= 1/2` when cheaper than the direct one.
    Euler,
    /// 1-z connection formula, `c - a - b` not an integer, `1/2 < z < 1`.
    Connection,
    /// Logarithmic 1-z formula, `c - a - b` an integer, `1/2 < z < 1`.
    ConnectionLog,
    /// Pfaff then the 1-w formula, `b - a` not an integer, `z < -1`.
    PfaffConnection,
    /// Pfaff then the logarithmic 1-w formula, `b - a` an integer, `z < -1`.
    PfaffConnectionLog,
    /// Gauss's sum at `z = 1`, `c - a - b > 0`.
    Gauss,
    /// One large parameter (`large_param.rs`): the connection formula in
    /// `1/(1-z)` (`z < 0`) or `1-z` (`0 < z < 1`), series whose length does not
    /// grow with the parameter.
    LargeParam,
}

impl Algorithm {
    /// Whether the method takes Gamma values at the working precision.
    pub(crate) fn uses_gamma(self) -> bool {
        matches!(
            self,
            Algorithm::Connection
                | Algorithm::ConnectionLog
                | Algorithm::PfaffConnection
                | Algorithm::PfaffConnectionLog
                | Algorithm::Gauss
                | Algorithm::LargeParam
        )
    }
}

/// Result of [`simulate`]: term count and log2 of `sum |t_n|` and of `|sum t_n|`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Sim {
    terms: f64,
    log2_abs: f64,
    log2_val: f64,
    /// False when the cap was reached (then the other fields describe the partial sum).
    converged: bool,
}

impl Sim {
    fn lost(&self) -> f64 {
        let l = self.log2_abs - self.log2_val;
        if l.is_nan() {
            0.0
        } else {
            l.clamp(0.0, 1e6)
        }
    }
}

/// `x` in f64 for the cost model, a non-zero `x` below the f64 range kept
/// non-zero (`2F1(4e-8201, 1; 1e-191; w)` is not the terminating `2F1(0, ...)`:
/// read as 0, the simulation chose the direct series at `w = 1 - 2^-71`, which
/// ran its 5 million terms), and one above it kept finite (`c = 3.4e29217` read
/// as infinite made the ratio of `2F1(a, c-b; c; w)` `inf/inf`: the simulation
/// failed and the plan took a connection formula whose series in `1/(1-z)`
/// needs `c` terms, refused as TooExpensive where Pfaff's series ends after one).
fn est(x: &Float) -> f64 {
    let v = x.to_f64();
    let sign = if x.is_sign_negative() { -1.0 } else { 1.0 };
    if v == 0.0 && !x.is_zero() {
        f64::MIN_POSITIVE.copysign(sign)
    } else if v.is_infinite() && x.is_finite() {
        f64::MAX.copysign(sign)
    } else {
        v
    }
}

pub(super) fn f64_exponent(v: f64) -> i64 {
    ((v.abs().to_bits() >> 52) & 0x7ff) as i64 - 1023
}

/// f64 simulation of the series with term ratio `(p1+n)(p2+n) x / ((q1+n)(q2+n))`
/// until the terms fall `bits` below the sum; the partial sum (`converged =
/// false`) past `cap` terms; `None` at a pole or on overflow.
pub(super) fn simulate(p: [f64; 2], q: [f64; 2], x: f64, bits: f64, cap: u64) -> Option<Sim> {
    let is_nonpos_int = |v: f64| v <= 0.0 && v == v.floor();
    let deg = p.iter().filter(|v| is_nonpos_int(**v)).map(|v| (-v) as u64).min();
    let mut n_pos = 0u64;
    for v in p.iter().chain(q.iter()) {
        if *v <= 0.0 && !is_nonpos_int(*v) {
            n_pos = n_pos.max((-v).floor() as u64 + 1);
        }
    }
    if n_pos > cap {
        // At least n_pos terms (the tail bound needs every parameter positive).
        return Some(Sim { terms: n_pos as f64, log2_abs: 0.0, log2_val: 0.0, converged: false });
    }
    let bits = bits.min(1e6) as i64;
    let (mut t, mut s, mut abs) = (1.0f64, 1.0f64, 1.0f64);
    let mut scale = 0.0f64; // true values are 2^scale times these
    let big = 2f64.powi(500);
    let mut n = 0u64;
    loop {
        if deg == Some(n) {
            break;
        }
        let nf = n as f64;
        if (q[0] + nf) * (q[1] + nf) == 0.0 {
            return None;
        }
        // as two quotients, in the pairing that stays finite (parameters near
        // f64::MAX: `c - b` over `c`)
        let pair = |i: usize| (p[i] + nf) / (q[0] + nf) * ((p[1 - i] + nf) / (q[1] + nf));
        let r1 = pair(0);
        let r = if r1.is_finite() { r1 } else { pair(1) } * x;
        t *= r;
        n += 1;
        if !t.is_finite() {
            return None;
        }
        if deg.is_none() && n >= n_pos && r.abs() < 1.0 {
            let ref_mag = if s != 0.0 { s.abs() } else { abs * 2f64.powi(-(bits.min(1000) as i32)) };
            if t == 0.0 || f64_exponent(t) + bits < f64_exponent(ref_mag) {
                // The engine's tail bound |t_N| / (1 - rho_N) (see `ratio_bound`).
                let nf = n as f64;
                let pf = |a: f64, b: f64| ((a + nf) / (b + nf)).max(1.0);
                let rho = x.abs() * (pf(p[0], q[0]) * pf(p[1], q[1])).min(pf(p[1], q[0]) * pf(p[0], q[1]));
                if rho < 1.0 && (t == 0.0 || f64_exponent(t) + bits + 1 + (-(1.0 - rho).log2()).ceil() as i64 <= f64_exponent(ref_mag)) {
                    break;
                }
            }
        }
        s += t;
        abs += t.abs();
        if abs > big {
            t /= big;
            s /= big;
            abs /= big;
            scale += 500.0;
        }
        if n > cap {
            break;
        }
    }
    let log2_val = if s == 0.0 { f64::NEG_INFINITY } else { s.abs().log2() + scale };
    Some(Sim { terms: n as f64, log2_abs: abs.log2() + scale, log2_val, converged: n <= cap })
}

/// [`simulate`], converged runs only.
pub(super) fn simulate_converged(p: [f64; 2], q: [f64; 2], x: f64, bits: f64, cap: u64) -> Option<Sim> {
    simulate(p, q, x, bits, cap).filter(|s| s.converged)
}

/// Terms and log2 of the magnitude of `2F1(p1, p2; q; u)`, with the power shortcut.
pub(super) fn series_estimate(p1: f64, p2: f64, q: f64, u: f64, bits: f64) -> (f64, f64) {
    if p1 == q {
        return (0.0, -p2 * (1.0 - u).log2());
    }
    if p2 == q {
        return (0.0, -p1 * (1.0 - u).log2());
    }
    match simulate_converged([p1, p2], [q, 1.0], u, bits, SIM_CAP) {
        Some(s) => (s.terms, s.log2_abs),
        None => (f64::INFINITY, 0.0),
    }
}

/// For `2F1(a, b; c; x)` with `1/2 < x < 1`, `u = 1 - x`, `s = c - a - b`
/// (exact): whether the direct series is cheaper than the 1-x formula, and the
/// estimated bits lost by the chosen one.
pub(super) fn near_one_choice(a: &Float, b: &Float, c: &Float, s: &Float, x: f64, u: f64, bits: f64) -> (bool, f64) {
    let (af, bf, cf) = (est(a), est(b), est(c));
    // `c - a` and `c - b` formed exactly, then estimated: past the f64 range
    // `est` clamps to f64::MAX, and `cf - bf` was 0 at `c = 3.4e29217`,
    // `b = c - 22.96` (Pfaff's `c - b`), so the connection's series
    // `2F1(c - a, 22.96; 1 + s; u)` looked empty where it runs to about `c`
    // terms (refused TooExpensive, issue 37's scan; the direct series ends at once)
    let (caf, cbf) = (est(&exact_sub(c, a)), est(&exact_sub(c, b)));
    let lg2 = |v: f64| lgamma_est(v) / LN_2;
    let (n_conn, log2_big, fixed) = if (s.is_integer() && s.clone().abs() > MAX_LOG_M) || !s.to_f64().is_finite() {
        // no connection: the logarithmic formula refuses such an integer `m`
        // (OutOfRange), and `Gamma(+-s)` past the f64 range overflows. The
        // majorant of a decimal `c = 3.4e29217` has `s` about `-2^96800`, which the
        // estimates below read as a connection of 0 terms: the direct series of
        // 195 terms lost to Euler's polynomial of degree 2^96800 (TooExpensive)
        (f64::INFINITY, 0.0, 0.0)
    } else if s.is_integer() {
        let m = s.to_f64();
        let (pa, pb, mm, shift) = if m >= 0.0 { (af, bf, m, 0.0) } else { (caf, cbf, -m, m * u.log2()) };
        let (nl, sl) = match simulate_converged([pa + mm, pb + mm], [mm + 1.0, 1.0], u, bits, SIM_CAP) {
            Some(sim) => (sim.terms, sim.log2_abs),
            None => (f64::INFINITY, 0.0),
        };
        let t1 = if mm >= 1.0 { lg2(cf) + lg2(mm) - lg2(cf - pa) - lg2(cf - pb) } else { f64::NEG_INFINITY };
        let t2 = lg2(cf) - lg2(pa) - lg2(pb) + mm * u.log2() + (u.ln().abs() + 2.0).log2() + sl;
        (mm + LOG_TERM_COST * nl, t1.max(t2) + shift, 2.0 * GAMMA_COST_TERMS)
    } else {
        let sf = est(s);
        let (n1, l1) = series_estimate(af, bf, 1.0 - sf, u, bits);
        let (n2, l2) = series_estimate(caf, cbf, 1.0 + sf, u, bits);
        let t1 = lg2(cf) + lg2(sf) - lg2(caf) - lg2(cbf) + l1;
        let t2 = lg2(cf) + lg2(-sf) - lg2(af) - lg2(bf) + sf * u.log2() + l2;
        (n1 + n2, t1.max(t2), GAMMA_COST_TERMS)
    };
    let conn_base = n_conn + fixed;
    let cap = if conn_base.is_finite() { (8.0 * conn_base + 100.0).min(SIM_CAP as f64) as u64 } else { SIM_CAP };
    match simulate([af, bf], [cf, 1.0], x, bits, cap) {
        None => (false, 0.0),
        Some(d) => {
            let lost_d = d.lost();
            if !conn_base.is_finite() && d.converged {
                return (true, lost_d);
            }
            // |f| from the (partial) direct sum: for 0 < x < 1 its terms end up of
            // one sign, so a partial sum errs on the side of more guard bits.
            let lost_c = if log2_big.is_finite() && d.log2_val.is_finite() {
                (log2_big - d.log2_val).clamp(0.0, 1e6)
            } else {
                0.0
            };
            if !d.converged {
                return (false, lost_c);
            }
            let cost_d = d.terms * (bits + lost_d);
            let cost_c = n_conn * (1.0 + lost_c / bits) * (bits + lost_c) + fixed * bits;
            if cost_d <= cost_c {
                (true, lost_d)
            } else {
                (false, lost_c)
            }
        }
    }
}

/// Price of a power prefactor (Euler, Pfaff), in series terms.
const PREFACTOR_COST_TERMS: f64 = 30.0;

/// For `-1 <= z <= 1/2` (non-terminating): the cheapest of the direct series, its
/// Euler transform (both in `z`, for `|z| <= 1/2`) and the two Pfaff transforms
/// (in `w = z/(z-1)`, `|w| < |z|`, for `z < 0`), by simulated terms times
/// (precision + cancellation). The direct series wins ties; `-1 <= z < -1/2` is
/// always Pfaff (`|w| <= 1/2`).
pub(super) fn small_z_choice(af: f64, bf: f64, cf: f64, caf: f64, cbf: f64, zf: f64, bits: f64) -> (Algorithm, u32) {
    let w = zf / (zf - 1.0);
    // log2 of the prefactors (1-z)^e that turn each transformed sum into f.
    let l1z = (1.0 - zf).log2();
    let mut cands: Vec<(Algorithm, [f64; 2], f64, f64, f64)> = Vec::with_capacity(4);
    if zf >= -DIRECT_RADIUS {
        cands.push((Algorithm::Direct, [af, bf], zf, 0.0, 0.0));
        cands.push((Algorithm::Euler, [caf, cbf], zf, PREFACTOR_COST_TERMS, (cf - af - bf) * l1z));
    }
    if zf < 0.0 {
        cands.push((Algorithm::Pfaff, [af, cbf], w, PREFACTOR_COST_TERMS, -af * l1z));
        cands.push((Algorithm::PfaffSwapped, [caf, bf], w, PREFACTOR_COST_TERMS, -bf * l1z));
    }
    let sims: Vec<Option<Sim>> = cands.iter().map(|c| simulate(c.1, [cf, 1.0], c.2, bits, SIM_CAP)).collect();
    // All candidates sum the same f: take log2|f| from the converged run with the
    // least cancellation (an f64 sum says nothing once ~50 bits cancel), then charge
    // every candidate log2(sum |t| * prefactor / |f|). A run cut at the cap gives
    // only a partial sum: `2F1(24.1, -34.875; 1000001; 1/2)`'s Euler series (terms
    // growing to `n ~ 5e5`, prefactor `2^-1000012`) read as log2|f| = -65 000 made
    // the two-term direct series plan 65 560 guard bits (issue 37's scan).
    let mut log2_f = f64::NAN;
    let mut least = f64::INFINITY;
    for (c, sim) in cands.iter().zip(&sims) {
        if let Some(sim) = sim.as_ref().filter(|s| s.converged) {
            if sim.log2_val.is_finite() && sim.lost() < least {
                least = sim.lost();
                log2_f = sim.log2_val + c.4;
            }
        }
    }
    let mut best = (cands[0].0, f64::INFINITY, 0u32);
    for (c, sim) in cands.iter().zip(&sims) {
        let Some(sim) = sim else { continue };
        let mut lost = sim.lost();
        if log2_f.is_finite() {
            lost = lost.max((sim.log2_abs + c.4 - log2_f).clamp(0.0, 1e6));
        }
        // A run cut at the cap is at least that expensive: count it double.
        let penalty = if sim.converged { 1.0 } else { 2.0 };
        let cost = (sim.terms * penalty + c.3) * (bits + lost);
        if cost < best.1 {
            best = (c.0, cost, (lost + sim.terms.max(1.0).log2()).clamp(0.0, 65536.0) as u32);
        }
    }
    (best.0, best.2)
}

/// Whether the large-parameter route (`large_param.rs`) applies at exact
/// arguments and is estimated cheaper than the series in `z`: no Gamma argument
/// of its formula at a pole, `b - a` (for `z < 0`) or `c - a - b` (for
/// `0 < z < 1`) not an integer. The planned loss is `log2` of the largest parameter.
pub(super) fn large_param_plan(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> Option<(Algorithm, u32)> {
    let (af, bf, cf, zf) = (est(a), est(b), est(c), est(z));
    let terms = large_param_terms(af, bf, cf, zf, wp as f64)?;
    if !large_param_cheaper(af, bf, zf, terms) {
        return None;
    }
    let (ca, cb) = (exact_sub(c, a), exact_sub(c, b));
    let pole = [a, b, c, &ca, &cb].iter().any(|x| is_nonpositive_integer(x));
    let integer = if *z < 0 { exact_sub(b, a).is_integer() } else { exact_sub(&ca, b).is_integer() };
    let lost = if af.abs() >= bf.abs() { large_param_loss(bf, af, cf, zf) } else { large_param_loss(af, bf, cf, zf) };
    (!pole && !integer).then_some((Algorithm::LargeParam, lost))
}

/// Largest degree of Euler's terminating form (`c - a` or `c - b` a non-positive
/// integer, `0 < z < 1`) taken without comparing it with the direct series.
const EULER_DEGREE_ALWAYS: u64 = 4096;

/// The algorithm and an estimate of the bits it loses (first Ziv guard).
pub(super) fn plan(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> (Algorithm, u32) {
    if terminating_degree(a, b).is_none() && *z != 1 {
        if let Some(p) = large_param_plan(a, b, c, z, wp) {
            return p;
        }
    }
    plan_regions(a, b, c, z, wp)
}

/// [`plan`] without the large-parameter route: the region's series and connection formulas.
pub(super) fn plan_regions(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> (Algorithm, u32) {
    let bits = wp as f64;
    let guard = |lost: f64, terms: f64| -> u32 { (lost + terms.max(1.0).log2()).clamp(0.0, 65536.0) as u32 };
    let sim_guard = |p: [f64; 2], q: [f64; 2], x: f64| -> u32 {
        match simulate_converged(p, q, x, bits, SIM_CAP) {
            Some(s) => guard(s.lost(), s.terms),
            None => 0,
        }
    };
    let (af, bf, cf, zf) = (est(a), est(b), est(c), est(z));
    if let Some(d) = terminating_degree(a, b) {
        // an exact rational sum needs no guard, but long arguments go to the series engine
        let g = if d == 0 { 0 } else { sim_guard([af, bf], [cf, 1.0], zf) };
        return (Algorithm::Polynomial, g);
    }
    if *z == 1 {
        return (Algorithm::Gauss, 0);
    }
    let ca = exact_sub(c, a);
    let cb = exact_sub(c, b);
    if *z >= -1 && *z <= DIRECT_RADIUS {
        return small_z_choice(af, bf, cf, est(&ca), est(&cb), zf, bits);
    }
    if *z > 0 {
        let s = exact_sub(&ca, b);
        let u = exact_sub(&one(), z).to_f64();
        if let Some(d) = terminating_degree(&ca, &cb) {
            // Euler's polynomial, unless its degree is long and the direct series
            // converges sooner: `c - b` a huge negative integer (the majorant
            // `2F1(A, B; C; R)` of a decimal `c = 3.4e29217`, where `C - B` is minus
            // twice the radius of `c`, about `2^96800`) was a polynomial of that
            // degree, refused TooExpensive, where the direct series takes 900 terms
            if d <= EULER_DEGREE_ALWAYS {
                return (Algorithm::Euler, 0);
            }
            return match near_one_choice(a, b, c, &s, zf, u, bits) {
                (true, lost) => (Algorithm::Direct, guard(lost, bits)),
                (false, _) => (Algorithm::Euler, 0),
            };
        }
        let (direct, lost) = near_one_choice(a, b, c, &s, zf, u, bits);
        let g = guard(lost, bits);
        return match (direct, s.is_integer()) {
            (true, _) => (Algorithm::Direct, g),
            (false, true) => (Algorithm::ConnectionLog, g),
            (false, false) => (Algorithm::Connection, g),
        };
    }
    // z < -1
    if terminating_degree(&ca, &cb).is_some() {
        return (Algorithm::Pfaff, 0);
    }
    let s = exact_sub(b, a);
    let u = 1.0 / (1.0 - zf);
    let (direct, lost) = near_one_choice(a, &cb, c, &s, 1.0 - u, u, bits);
    let g = guard(lost, bits);
    match (direct, s.is_integer()) {
        (true, _) => (Algorithm::Pfaff, g),
        (false, true) => (Algorithm::PfaffConnectionLog, g),
        (false, false) => (Algorithm::PfaffConnection, g),
    }
}

/// Picks the algorithm for validated arguments (finite, `z <= 1`, see
/// [`hyp2f1_mp`]) at working precision `wp` (the module docs list the regions).
#[cfg(test)]
pub(crate) fn choose_algorithm(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> Algorithm {
    plan(a, b, c, z, wp).0
}

/// Runs one algorithm at working precision `wp`.
pub(crate) fn evaluate(alg: Algorithm, a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> Result<Ball> {
    match alg {
        Algorithm::Polynomial => hyp2f1_polynomial(a, b, c, z, wp),
        Algorithm::Direct => hyp2f1_direct(a, b, c, z, wp),
        Algorithm::Pfaff => hyp2f1_pfaff(a, b, c, z, wp),
        Algorithm::PfaffSwapped => hyp2f1_pfaff(b, a, c, z, wp),
        Algorithm::Euler => hyp2f1_euler(a, b, c, z, wp),
        Algorithm::Connection => hyp2f1_connection(a, b, c, z, wp),
        Algorithm::ConnectionLog => hyp2f1_connection_log(a, b, c, z, wp),
        Algorithm::PfaffConnection | Algorithm::PfaffConnectionLog => hyp2f1_pfaff_connection(a, b, c, z, wp),
        Algorithm::Gauss => hyp2f1_gauss(a, b, c, wp),
        Algorithm::LargeParam => hyp2f1_large_param(&xball(a, wp), &xball(b, wp), &xball(c, wp), &xball(z, wp), wp),
    }
}
