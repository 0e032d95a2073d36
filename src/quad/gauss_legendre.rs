//! Gauss–Legendre quadrature in f64, any order `n` in `1..=MAX_ORDER`.
//!
//! # Method
//!
//! The `n`-point rule `∫_{-1}^{1} f(x) dx ≈ Σ_i w_i f(x_i)` is exact for
//! polynomials of degree `<= 2n - 1` [DLMF 3.5.15]. Its nodes are the zeros of
//! the Legendre polynomial `P_n`, its weights
//! `w_i = 2 / ((1 - x_i^2) P_n'(x_i)^2)` [DLMF 3.5.19, A&S 25.4.29].
//!
//! * **Nodes.** Newton's method in the angle `θ` (`x = cos θ`) on
//!   `g(θ) = P_n(cos θ)`, started from Tricomi's approximation
//!   [A&S 22.16.6]
//!   `x_i ≈ (1 - 1/(8n^2) + 1/(8n^3)) cos(π (i - 1/4)/(n + 1/2))`,
//!   which is within `O(n^-4)` of the `i`-th largest zero and well inside
//!   Newton's basin for every `n`. `P_n` and `P_{n-1}` come from Bonnet's
//!   recurrence `k P_k = (2k-1) x P_{k-1} - (k-1) P_{k-2}` [DLMF 18.9.1] and
//!   `sin^2θ P_n'(x) = -n (x P_n - P_{n-1})` [DLMF 18.9.19].
//!   Working in `θ` keeps `1 - x^2 = sin^2 θ` free of cancellation near the
//!   ends, so the small outer weights are accurate to a few ulps *relative*.
//!   Newton stops one step after `|Δθ| <= 1e-10 θ` (quadratic convergence
//!   takes the last step to rounding level). Nodes and weights are symmetric
//!   and are computed for `x > 0` only; for odd `n` the middle node is exactly 0.
//! * **Cost.** `O(n)` per recurrence, about 3 Newton steps plus one final
//!   evaluation per node, so `O(n^2)` per rule: about 3 ms for `n = 1000`.
//!   Rules are cached per `n` (see [`rule`]).
//! * **Accuracy.** Nodes within a few ulps; the rule integrates
//!   polynomials of degree `<= 2n - 1` to about `n^{1/2}` ulps of `∫|f|`
//!   (tested up to `n = 1000`).
//!
//! A fixed rule has no error estimate of its own; compare two orders (or use
//! [`gauss_kronrod`](crate::quad::gauss_kronrod)) when one is needed.
//!
//! # Intervals
//!
//! `∫_a^b f = r Σ w_i f(c + r x_i)`, `c = (a+b)/2`, `r = (b-a)/2`, computed as
//! `a/2 + b/2` and `b/2 - a/2` so that finite bounds never overflow. `a > b`
//! gives the negated integral (`r < 0`), `a == b` gives 0.

use std::collections::HashMap;
use std::f64::consts::PI;
use std::sync::{Arc, Mutex, OnceLock};

use crate::error::{finite, Error, Invariant, Result};

/// Largest order accepted. Rule generation is `O(n^2)` (about 10 ms at the cap).
pub const MAX_ORDER: usize = 2000;

/// Largest number of panels accepted by the composite rule.
pub const MAX_PANELS: usize = 1 << 24;

/// Newton switches to its final polishing step once `|Δθ| <= NEWTON_SWITCH θ`:
/// with quadratic convergence the next step is at rounding level.
const NEWTON_SWITCH: f64 = 1e-10;

/// Newton step cap per node. From Tricomi's start 3–4 steps suffice for every
/// `n <= MAX_ORDER`; the cap only guards against a bug.
const MAX_NEWTON_STEPS: u32 = 20;

/// Most rules kept in the cache (the biggest, `n = 2000`, is 32 kB); once full,
/// further orders are computed on every call instead of cached.
const CACHE_CAPACITY: usize = 128;

/// An `n`-point Gauss–Legendre rule on `[-1, 1]`.
#[derive(Debug, Clone, PartialEq)]
pub struct GaussLegendreRule {
    nodes: Vec<f64>,
    weights: Vec<f64>,
}

impl GaussLegendreRule {
    /// Computes the `n`-point rule (uncached; prefer [`rule`]).
    pub fn new(n: usize) -> Result<GaussLegendreRule> {
        check_order(n)?;
        let mut nodes = vec![0.0; n];
        let mut weights = vec![0.0; n];
        let recurrence = BonnetCoefficients::new(n);
        for i in 1..=n / 2 {
            let (x, w) = positive_node(n, i, &recurrence)?;
            nodes[n - i] = x;
            nodes[i - 1] = -x;
            weights[n - i] = w;
            weights[i - 1] = w;
        }
        if n % 2 == 1 {
            // Middle node x = 0 (θ = π/2, sin θ = 1): w = 2 / (n P_{n-1}(0))^2.
            let (_, pm1) = recurrence.eval(0.0);
            let d = n as f64 * pm1;
            weights[n / 2] = 2.0 / (d * d);
        }
        Ok(GaussLegendreRule { nodes, weights })
    }

    /// The order `n`.
    pub fn order(&self) -> usize {
        self.nodes.len()
    }

    /// Nodes in `(-1, 1)`, increasing.
    pub fn nodes(&self) -> &[f64] {
        &self.nodes
    }

    /// Weights, in the order of [`nodes`](Self::nodes); they sum to 2.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }
}

fn check_order(n: usize) -> Result<()> {
    if n == 0 || n > MAX_ORDER {
        let value = i64::try_from(n).unwrap_or(i64::MAX);
        return Err(Error::IntegerOutOfRange { arg: "the Gauss-Legendre order n", value, min: 1, max: MAX_ORDER as i64 });
    }
    Ok(())
}

/// Bonnet's recurrence with its coefficients precomputed:
/// `P_k = α_k x P_{k-1} - β_k P_{k-2}`, `α_k = (2k-1)/k`, `β_k = (k-1)/k`.
struct BonnetCoefficients {
    n: usize,
    alpha: Vec<f64>,
    beta: Vec<f64>,
}

impl BonnetCoefficients {
    fn new(n: usize) -> BonnetCoefficients {
        let alpha = (2..=n).map(|k| (2 * k - 1) as f64 / k as f64).collect();
        let beta = (2..=n).map(|k| (k - 1) as f64 / k as f64).collect();
        BonnetCoefficients { n, alpha, beta }
    }

    /// `(P_n(x), P_{n-1}(x))`.
    fn eval(&self, x: f64) -> (f64, f64) {
        if self.n == 0 {
            return (1.0, 0.0);
        }
        let (mut p_prev, mut p) = (1.0, x);
        for (a, b) in self.alpha.iter().zip(&self.beta) {
            let next = a * x * p - b * p_prev;
            p_prev = p;
            p = next;
        }
        (p, p_prev)
    }
}

/// The `i`-th largest zero of `P_n` (`1 <= i <= n/2`, so `x > 0`) and its weight.
fn positive_node(n: usize, i: usize, rec: &BonnetCoefficients) -> Result<(f64, f64)> {
    let nf = n as f64;
    let phi = PI * (i as f64 - 0.25) / (nf + 0.5);
    let tricomi = 1.0 - 1.0 / (8.0 * nf * nf) + 1.0 / (8.0 * nf * nf * nf);
    let mut theta = (tricomi * phi.cos()).clamp(-1.0, 1.0).acos();
    let mut polish = false;
    let mut converged = false;
    for _ in 0..MAX_NEWTON_STEPS {
        let (s, x) = theta.sin_cos();
        let (p, pm1) = rec.eval(x);
        // g(θ) = P_n(cos θ), g'(θ) = -sin θ P_n'(x) = n (x P_n - P_{n-1}) / sin θ.
        let d = nf * (x * p - pm1);
        let step = p * s / d;
        theta -= step;
        if polish {
            converged = true;
            break;
        }
        if step.abs() <= NEWTON_SWITCH * theta {
            polish = true;
        }
    }
    if !converged || !theta.is_finite() {
        return Err(Error::Invariant(Invariant::GaussLegendreNewton { degree: n, node: i }));
    }
    let (s, x) = theta.sin_cos();
    let (p, pm1) = rec.eval(x);
    // w = 2 / (sin^2 θ P_n'^2) = 2 sin^2 θ / (n (x P_n - P_{n-1}))^2.
    let d = nf * (x * p - pm1);
    let w = 2.0 * s * s / (d * d);
    Ok((x, w))
}

fn cache() -> &'static Mutex<HashMap<usize, Arc<GaussLegendreRule>>> {
    static CACHE: OnceLock<Mutex<HashMap<usize, Arc<GaussLegendreRule>>>> = OnceLock::new();
    CACHE.get_or_init(|| Mutex::new(HashMap::new()))
}

/// The `n`-point rule, computed once per `n` and shared (thread safe).
///
/// The cache holds up to 128 orders; a poisoned lock is recovered (the map is
/// only ever extended with complete rules).
pub fn rule(n: usize) -> Result<Arc<GaussLegendreRule>> {
    check_order(n)?;
    if let Some(r) = cache().lock().unwrap_or_else(|e| e.into_inner()).get(&n) {
        return Ok(Arc::clone(r));
    }
    // Computed outside the lock: another thread may do the same work, harmlessly.
    let fresh = Arc::new(GaussLegendreRule::new(n)?);
    let mut map = cache().lock().unwrap_or_else(|e| e.into_inner());
    if map.len() >= CACHE_CAPACITY && !map.contains_key(&n) {
        return Ok(fresh);
    }
    Ok(Arc::clone(map.entry(n).or_insert(fresh)))
}

/// `∫_a^b f` by the `n`-point Gauss–Legendre rule.
pub fn integrate<F>(mut f: F, a: f64, b: f64, n: usize) -> Result<f64>
where
    F: FnMut(f64) -> f64,
{
    try_integrate(|x| Ok(f(x)), a, b, n)
}

/// [`integrate`] for a fallible integrand; its errors are passed through.
pub fn try_integrate<F>(mut f: F, a: f64, b: f64, n: usize) -> Result<f64>
where
    F: FnMut(f64) -> Result<f64>,
{
    check_order(n)?;
    finite(a, "lower bound a")?;
    finite(b, "upper bound b")?;
    let r = rule(n)?;
    apply(&r, &mut f, a, b)
}

/// `∫_a^b f` by the `n`-point rule on each of `panels` equal sub-intervals
/// (`n * panels` evaluations).
pub fn integrate_composite<F>(mut f: F, a: f64, b: f64, n: usize, panels: usize) -> Result<f64>
where
    F: FnMut(f64) -> f64,
{
    try_integrate_composite(|x| Ok(f(x)), a, b, n, panels)
}

/// [`integrate_composite`] for a fallible integrand.
pub fn try_integrate_composite<F>(mut f: F, a: f64, b: f64, n: usize, panels: usize) -> Result<f64>
where
    F: FnMut(f64) -> Result<f64>,
{
    check_order(n)?;
    finite(a, "lower bound a")?;
    finite(b, "upper bound b")?;
    if panels == 0 || panels > MAX_PANELS {
        let value = i64::try_from(panels).unwrap_or(i64::MAX);
        return Err(Error::IntegerOutOfRange { arg: "the number of panels", value, min: 1, max: MAX_PANELS as i64 });
    }
    let r = rule(n)?;
    let m = panels as f64;
    // Panel ends by interpolation a (1 - t) + b t: exact at both ends, no overflow.
    let end = |j: usize| -> f64 {
        if j == panels {
            b
        } else {
            let t = j as f64 / m;
            a * (1.0 - t) + b * t
        }
    };
    let mut total = 0.0;
    let mut lo = a;
    for j in 1..=panels {
        let hi = end(j);
        total += apply(&r, &mut f, lo, hi)?;
        lo = hi;
    }
    if !total.is_finite() {
        return Err(Error::Overflow { what: "Gauss-Legendre sum".into() });
    }
    Ok(total)
}

/// One rule on one interval (bounds already validated).
fn apply<F>(rule: &GaussLegendreRule, f: &mut F, a: f64, b: f64) -> Result<f64>
where
    F: FnMut(f64) -> Result<f64>,
{
    if a == b {
        return Ok(0.0);
    }
    let c = 0.5 * a + 0.5 * b;
    let r = 0.5 * b - 0.5 * a;
    let mut sum = 0.0;
    for (x, w) in rule.nodes.iter().zip(&rule.weights) {
        let y = f(c + r * x)?;
        if !y.is_finite() {
            return Err(Error::NonFinite { what: "integrand value" });
        }
        sum += w * y;
    }
    let v = r * sum;
    if !v.is_finite() {
        return Err(Error::Overflow { what: "Gauss-Legendre sum".into() });
    }
    Ok(v)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::{Float, Rational};

    #[test]
    fn small_rules_match_closed_forms() {
        // n = 1: x = 0, w = 2. n = 2: x = ±1/sqrt(3), w = 1. n = 3: x = 0, ±sqrt(3/5), w = 8/9, 5/9.
        let r1 = GaussLegendreRule::new(1).unwrap();
        assert_eq!(r1.nodes(), &[0.0]);
        assert!((r1.weights()[0] - 2.0).abs() < 1e-15);
        let r2 = GaussLegendreRule::new(2).unwrap();
        let s = 1.0 / 3f64.sqrt();
        assert!((r2.nodes()[1] - s).abs() < 2e-16 && (r2.nodes()[0] + s).abs() < 2e-16);
        assert!((r2.weights()[0] - 1.0).abs() < 4e-16);
        let r3 = GaussLegendreRule::new(3).unwrap();
        assert_eq!(r3.nodes()[1], 0.0);
        assert!((r3.nodes()[2] - 0.6f64.sqrt()).abs() < 2e-16);
        assert!((r3.weights()[1] - 8.0 / 9.0).abs() < 4e-16);
        assert!((r3.weights()[0] - 5.0 / 9.0).abs() < 4e-16);
    }

    #[test]
    fn nodes_sorted_and_weights_sum_to_two() {
        for n in [1usize, 2, 5, 16, 63, 64, 200, 1000, MAX_ORDER] {
            let r = rule(n).unwrap();
            assert_eq!(r.order(), n);
            assert!(r.nodes().windows(2).all(|p| p[0] < p[1]), "n={n}");
            assert!(r.nodes().iter().all(|x| x.abs() < 1.0));
            assert!(r.weights().iter().all(|w| *w > 0.0));
            let s: f64 = r.weights().iter().sum();
            assert!((s - 2.0).abs() < 1e-13, "n={n}: {s}");
        }
    }

    #[test]
    fn exact_for_degree_2n_minus_1() {
        // ∫_{-1}^{1} x^k dx = 2/(k+1) for even k, 0 for odd k.
        for n in 1usize..=40 {
            let r = rule(n).unwrap();
            for k in 0..2 * n {
                let v: f64 = r.nodes().iter().zip(r.weights()).map(|(x, w)| w * x.powi(k as i32)).sum();
                let exact = if k % 2 == 0 { 2.0 / (k as f64 + 1.0) } else { 0.0 };
                assert!((v - exact).abs() < 4e-15, "n={n} k={k}: {v} vs {exact}");
            }
        }
    }

    #[test]
    fn nodes_are_zeros_of_p_n_in_mp() {
        // P_n at the f64 node, evaluated in 200-bit arithmetic, is within a few
        // ulps of the node times |P_n'|.
        for n in [7usize, 100, 1000] {
            let r = rule(n).unwrap();
            for (i, &x) in r.nodes().iter().enumerate().step_by(n / 7 + 1) {
                let xm = Float::with_val(200, x);
                let (mut p0, mut p1) = (Float::with_val(200, 1), xm.clone());
                for k in 2..=n as u32 {
                    let p2 = (Float::with_val(200, 2 * k - 1) * &xm * &p1 - Float::with_val(200, k - 1) * &p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                // Newton correction δ = P_n / P_n' with P_n' = n (x P_n - P_{n-1}) / (x^2 - 1).
                let dp = Float::with_val(200, &xm * &p1 - &p0) * n as u32 / (Float::with_val(200, &xm * &xm) - 1u32);
                let delta = Float::with_val(200, &p1 / &dp).to_f64().abs();
                // θ is accurate to a few ulps, so x = cos θ to a few ulps of 1.
                assert!(delta <= 3.0 * f64::EPSILON, "n={n} i={i} x={x}: {delta:e}");
            }
        }
    }

    #[test]
    fn intervals_reversed_and_empty() {
        let exact = Float::with_val(100, Rational::from((1u32, 3u32))).to_f64();
        assert!((integrate(|x| x * x, 0.0, 1.0, 3).unwrap() - exact).abs() < 4e-16);
        assert!((integrate(|x| x * x, 1.0, 0.0, 3).unwrap() + exact).abs() < 4e-16);
        assert_eq!(integrate(|x| x * x, 2.5, 2.5, 3).unwrap(), 0.0);
        let c = integrate_composite(|x| x.cos(), 0.0, 10.0, 8, 16).unwrap();
        assert!((c - 10f64.sin()).abs() < 1e-14);
    }

    #[test]
    fn bad_input_is_an_error() {
        assert!(matches!(rule(0), Err(Error::IntegerOutOfRange { value: 0, .. })));
        assert!(matches!(rule(MAX_ORDER + 1), Err(Error::IntegerOutOfRange { .. })));
        assert!(integrate(|x| x, 0.0, 1.0, 0).is_err());
        assert!(matches!(integrate(|x| x, f64::NAN, 1.0, 4), Err(Error::NonFinite { .. })));
        assert!(matches!(integrate(|x| x, 0.0, f64::INFINITY, 4), Err(Error::NonFinite { .. })));
        assert!(matches!(integrate(|_| f64::NAN, 0.0, 1.0, 4), Err(Error::NonFinite { .. })));
        assert!(integrate_composite(|x| x, 0.0, 1.0, 4, 0).is_err());
        assert!(try_integrate(|_| Err(Error::DivisionByZero), 0.0, 1.0, 4) == Err(Error::DivisionByZero));
        // Extreme but finite bounds: no overflow in c and r.
        let v = integrate(|_| 0.0, -f64::MAX, f64::MAX, 4).unwrap();
        assert_eq!(v, 0.0);
    }
}
