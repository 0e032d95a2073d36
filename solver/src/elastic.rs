//! The elastic operator: surface displacement of a half-plane in plane strain
//! under a piecewise-constant normal traction, by zero-padded FFT convolution.
//!
//! # Method
//!
//! In the normalised units of the semi-analytical model (`E* = 1`, horizontal
//! lengths in `l_h`, vertical in `l_v`, traction in `(E*^2 dgamma/R)^(1/3)`)
//! the Flamant/Boussinesq line-load solution (Johnson, *Contact Mechanics*,
//! 1985, Eq. 2.25b) gives the surface displacement into the body, for a
//! compressive traction `p` (positive),
//!
//! ```text
//! u(x) = -(2/pi) int p(s) ln(|x - s| / L_d) ds .
//! ```
//!
//! A free half-plane has no absolute displacement in 2D: `u` is measured from
//! the **datum** `L_d`, i.e. relative to a surface point at distance `L_d` from
//! the load (for a single line load `u(x0 +- L_d) = 0`). The approach `Delta`
//! reported by the solver is relative to that datum; changing it to `L_d'`
//! changes `Delta` by `(2/pi) Lbar ln(L_d'/L_d)` and nothing else.
//!
//! For traction constant on cells of width `dx` the influence of cell `j` on the
//! centre of cell `i` is exact:
//!
//! ```text
//! K_k = -(2/pi) [F(k dx + dx/2) - F(k dx - dx/2)] + (2/pi) dx ln L_d,
//! F(t) = t ln|t| - t,  F(0) = 0,  k = i - j .
//! ```
//!
//! The Toeplitz product `u_i = sum_j K_{i-j} p_j` is a linear (not circular)
//! convolution: `p` is zero-padded to `2n` points and the circulant embedding of
//! `K` is applied with one real forward and one real inverse FFT (realfft /
//! rustfft). The plans, the kernel spectrum (real, as `K` is even) and the
//! scratch buffers are made once per operator and reused by every product, so
//! one product costs two real FFTs of length `2n`.
//!
//! # Periodic domain
//!
//! [`HalfPlane::periodic`] makes the domain `[-X, X]` one period `P = 2X` of a
//! periodic surface, the traction's images included. Summing the images of
//! `ln|t|` (the product `sin(pi z) = pi z prod (1 - z^2/m^2)`) gives the kernel
//! `ln|2 sin(pi t/P)|` up to a constant, so
//!
//! ```text
//! u(x) = -(2/pi) int_period p(s) [ln|2 sin(pi (x - s)/P)| - ln(2 pi L_d/P)] ds ,
//! ```
//!
//! which tends to the free kernel `ln(|t|/L_d)` as `P -> infinity` at fixed
//! `t`. In 2D a non-zero mean traction moves the surface without bound, so
//! the datum `L_d` again fixes the approach; `ln|2 sin|` has zero mean over a
//! period, so the mean traction `pbar` moves the surface by
//! `(2/pi) P pbar ln(2 pi L_d/P)` into the body, and the kernel is positive definite only if
//! `L_d > P/(2 pi)` (at `L_d = P/(2 pi)` the approach is the mean gap of
//! Tamaas's periodic BEM; `docs/solver.md`). The cell coefficients are the
//! exact integral of `ln|t|` plus the smooth remainder
//! `ln(|2 sin(pi t/P)|/|t|)` by 6-point Gauss-Legendre, at the nearest image's
//! offset; the product is a circular convolution of length `n` (no padding).
//!
//! # Positive definiteness
//!
//! The logarithmic kernel is positive definite on an interval of length `W`
//! only if `L_d > W/4` (the logarithmic capacity of the interval). The solver's
//! conjugate-gradient method needs it, so [`HalfPlane::new`] requires
//! `L_d >= W/2` (default `L_d = W`, the domain width).
//!
//! # Errors
//!
//! The product is exact for piecewise-constant traction up to FFT rounding
//! (about `1e-15 * log2(2n)` relative to `max |K| sum |p|`). The discretisation
//! error of the contact problem (traction that is not piecewise constant, edges
//! pinned to cell centres) is measured in the tests and in `docs/solver.md`.

use std::f64::consts::PI;
use std::sync::Arc;

use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};

use crate::error::{finite, Interval, Result, SolverError};
use crate::grid::Grid;

/// The half-plane influence operator on a grid, FFT plans and buffers included.
pub struct HalfPlane {
    grid: Grid,
    datum: f64,
    /// Periodic of period `2X` (circular convolution) rather than free.
    periodic: bool,
    /// Influence coefficients `K_k`, `k = 0..n` (the kernel is even).
    coeffs: Vec<f64>,
    /// Spectrum of the circulant embedding, divided by `2n` (the FFT normalisation).
    spectrum: Vec<f64>,
    /// Its reciprocal (divided by `2n` likewise): the circulant preconditioner.
    inverse_spectrum: Vec<f64>,
    /// Products done (operator and preconditioner), for profiling.
    products: usize,
    forward: Arc<dyn RealToComplex<f64>>,
    inverse: Arc<dyn ComplexToReal<f64>>,
    padded: Vec<f64>,
    freq: Vec<Complex<f64>>,
    scratch_fwd: Vec<Complex<f64>>,
    scratch_inv: Vec<Complex<f64>>,
}

/// `F(t) = t ln|t| - t`, the antiderivative of `ln|t|`, with `F(0) = 0`.
pub(crate) fn log_antiderivative(t: f64) -> f64 {
    if t == 0.0 {
        0.0
    } else {
        t * t.abs().ln() - t
    }
}

/// The kernel `G` of `u(x) = -(2/pi) int p(s) G(x - s) ds`: free,
/// `G(t) = ln(|t|/L_d)`; periodic of period `P`,
/// `G(t) = ln|2 sin(pi t/P)| - ln(2 pi L_d/P)`.
#[derive(Debug, Clone, Copy)]
struct Kernel {
    period: f64,
    ln_datum: f64,
    periodic: bool,
}

/// Gauss-Legendre nodes and weights on `[-1, 1]`, 6 points (even: no node at
/// the midpoint, where the periodic remainder's formula would divide 0 by 0).
const GAUSS6: [(f64, f64); 6] = [
    (-0.932_469_514_203_152, 0.171_324_492_379_170),
    (-0.661_209_386_466_265, 0.360_761_573_048_139),
    (-0.238_619_186_083_197, 0.467_913_934_572_691),
    (0.238_619_186_083_197, 0.467_913_934_572_691),
    (0.661_209_386_466_265, 0.360_761_573_048_139),
    (0.932_469_514_203_152, 0.171_324_492_379_170),
];

impl Kernel {
    /// `-(2/pi) int_a^b G(t) dt` for `b - a` at most a cell and, periodic,
    /// `|a|, |b| <= P/2 + b - a`. The logarithm's part is exact (`F`); the
    /// periodic remainder `R(t) = ln(|2 sin(pi t/P)|/|t|)`, analytic on
    /// `|t| < P`, is integrated by 6-point Gauss-Legendre (error about
    /// `((b - a)/P)^12`, far below rounding).
    fn influence(&self, a: f64, b: f64) -> f64 {
        let log_part = log_antiderivative(b) - log_antiderivative(a);
        if !self.periodic {
            return -2.0 / PI * (log_part - (b - a) * self.ln_datum);
        }
        let p = self.period;
        let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
        let remainder: f64 = GAUSS6
            .iter()
            .map(|&(z, w)| {
                let t = mid + half * z;
                let r = if t == 0.0 { (2.0 * PI / p).ln() } else { ((2.0 * (PI * t / p).sin()).abs() / t.abs()).ln() };
                w * r
            })
            .sum::<f64>()
            * half;
        -2.0 / PI * (log_part + remainder - (b - a) * (2.0 * PI / p).ln() - (b - a) * self.ln_datum)
    }
}

impl HalfPlane {
    /// The free-space operator on `grid` with datum distance `datum` (`None`:
    /// the domain width `2X`). `datum` must be at least half the domain width.
    pub fn new(grid: Grid, datum: Option<f64>) -> Result<HalfPlane> {
        HalfPlane::build(grid, datum, false)
    }

    /// The periodic operator (period `P = 2X`, see the module docs) on `grid`
    /// with datum distance `datum` (`None`: `P`). `datum` must be at least
    /// `P/4` (the kernel is positive definite for `datum > P/(2 pi)`).
    pub fn periodic(grid: Grid, datum: Option<f64>) -> Result<HalfPlane> {
        HalfPlane::build(grid, datum, true)
    }

    fn build(grid: Grid, datum: Option<f64>, periodic: bool) -> Result<HalfPlane> {
        let width = 2.0 * grid.half_width();
        let datum = datum.unwrap_or(width);
        finite(datum, "the datum distance")?;
        // at least this much for the kernel to be positive definite
        let (least, arg) = if periodic {
            (0.25 * width, "the datum distance (at least a quarter of the period)")
        } else {
            (0.5 * width, "the datum distance (at least half the domain width)")
        };
        if !(datum >= least && datum <= 1e12) {
            return Err(SolverError::OutOfRange { arg, value: datum, allowed: Interval::closed(least, 1e12) });
        }
        let n = grid.cells();
        let dx = grid.dx();
        let op_kernel = Kernel { period: width, ln_datum: datum.ln(), periodic };
        let coeffs: Vec<f64> = (0..n)
            .map(|k| {
                // The periodic kernel's offsets past half a period are the
                // nearest image's.
                let t = if periodic && k > n / 2 { (k as f64 - n as f64) * dx } else { k as f64 * dx };
                op_kernel.influence(t - 0.5 * dx, t + 0.5 * dx)
            })
            .collect();
        let m = if periodic { n } else { 2 * n };
        let mut planner = RealFftPlanner::<f64>::new();
        let forward = planner.plan_fft_forward(m);
        let inverse = planner.plan_fft_inverse(m);
        // Free: the circulant embedding c[k] = K_k, c[2n-k] = K_k (k = 1..n-1),
        // c[n] = 0. Periodic: the circulant itself, c[k] = K_k.
        let mut circ = vec![0.0; m];
        if periodic {
            circ.copy_from_slice(&coeffs);
        } else {
            circ[0] = coeffs[0];
            for k in 1..n {
                circ[k] = coeffs[k];
                circ[2 * n - k] = coeffs[k];
            }
        }
        let mut freq = forward.make_output_vec();
        let mut scratch_fwd = forward.make_scratch_vec();
        forward
            .process_with_scratch(&mut circ, &mut freq, &mut scratch_fwd)
            .map_err(|e| SolverError::Internal { what: format!("FFT: {e}") })?;
        let scale = 1.0 / m as f64;
        let spectrum: Vec<f64> = freq.iter().map(|z| z.re * scale).collect();
        // The eigenvalues of the embedding are positive (checked in the tests);
        // a floor keeps the preconditioner finite if rounding made one tiny.
        let floor = spectrum.iter().fold(0.0f64, |m, v| m.max(*v)) * 1e-14;
        let inverse_spectrum = spectrum.iter().map(|&v| scale * scale / v.max(floor)).collect();
        let scratch_inv = inverse.make_scratch_vec();
        Ok(HalfPlane {
            grid,
            datum,
            periodic,
            coeffs,
            spectrum,
            inverse_spectrum,
            products: 0,
            forward,
            inverse,
            padded: vec![0.0; m],
            freq,
            scratch_fwd,
            scratch_inv,
        })
    }

    /// Whether the operator is periodic.
    pub fn is_periodic(&self) -> bool {
        self.periodic
    }

    /// The displacement at `x` from a unit traction on `[s0, s1]` (exact; on
    /// the periodic operator the traction's images included).
    pub fn segment_influence(&self, x: f64, s0: f64, s1: f64) -> f64 {
        let width = 2.0 * self.grid.half_width();
        let kernel = Kernel { period: width, ln_datum: self.datum.ln(), periodic: self.periodic };
        let mut d = x - 0.5 * (s0 + s1);
        if self.periodic {
            d -= width * (d / width).round();
        }
        let w = s1 - s0;
        kernel.influence(d - 0.5 * w, d + 0.5 * w)
    }

    /// The grid.
    pub fn grid(&self) -> Grid {
        self.grid
    }

    /// The datum distance `L_d`.
    pub fn datum(&self) -> f64 {
        self.datum
    }

    /// Influence coefficient `K_k` (displacement at distance `k` cells from a
    /// unit traction on one cell), `k < n`.
    pub fn coefficient(&self, k: usize) -> f64 {
        self.coeffs[k]
    }

    /// `u = K p` (surface displacement into the body for compressive traction
    /// `p`, both of length `n`). Two real FFTs of length `2n`.
    pub fn apply(&mut self, p: &[f64], u: &mut [f64]) {
        self.convolve(p, u, false);
    }

    /// `z = C r` with `C` the inverse of the circulant embedding of `K`
    /// (spectrum `1/K_hat`), zero-padded like [`HalfPlane::apply`]: an
    /// approximate inverse of `K` (symmetric positive definite), the FFT
    /// preconditioner of Vollebregt (J. Comput. Phys. 257, 2014, 333). The
    /// symbol of `K` is about `2/|k|`, so `C` is about `|k|/2`, a half
    /// derivative: it removes the growth of the condition number with the grid.
    /// Two real FFTs of length `2n`.
    pub fn precondition(&mut self, r: &[f64], z: &mut [f64]) {
        self.convolve(r, z, true);
    }

    /// Operator and preconditioner products done so far.
    pub fn products(&self) -> usize {
        self.products
    }

    fn convolve(&mut self, p: &[f64], u: &mut [f64], inverse: bool) {
        let n = self.grid.cells();
        // Free: zero-padded to 2n (linear convolution); periodic: n (circular).
        debug_assert!(p.len() == n && u.len() == n);
        self.products += 1;
        self.padded[..n].copy_from_slice(p);
        self.padded[n..].iter_mut().for_each(|v| *v = 0.0);
        // Lengths match the plans by construction, so these cannot fail.
        let _ = self.forward.process_with_scratch(&mut self.padded, &mut self.freq, &mut self.scratch_fwd);
        let spectrum = if inverse { &self.inverse_spectrum } else { &self.spectrum };
        for (z, k) in self.freq.iter_mut().zip(spectrum) {
            *z *= *k;
        }
        // realfft requires exactly real DC and Nyquist bins.
        self.freq[0].im = 0.0;
        if let Some(last) = self.freq.last_mut() {
            last.im = 0.0;
        }
        let _ = self.inverse.process_with_scratch(&mut self.freq, &mut self.padded, &mut self.scratch_inv);
        u.copy_from_slice(&self.padded[..n]);
    }

    /// The same product by the direct `O(n^2)` sum: the slow, obviously
    /// correct reference the FFT route is tested against.
    pub fn apply_direct(&self, p: &[f64], u: &mut [f64]) {
        let n = self.grid.cells();
        for i in 0..n {
            u[i] = (0..n)
                .map(|j| {
                    let k = if self.periodic { (i + n - j) % n } else { i.abs_diff(j) };
                    self.coeffs[k] * p[j]
                })
                .sum();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fft_product_matches_direct_sum() {
        let grid = Grid::new(256, 3.0).unwrap();
        let mut op = HalfPlane::new(grid, None).unwrap();
        // A fixed pseudo-random traction (LCG, seed 7).
        let mut s: u64 = 7;
        let p: Vec<f64> = (0..256)
            .map(|_| {
                s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5
            })
            .collect();
        let (mut u1, mut u2) = (vec![0.0; 256], vec![0.0; 256]);
        op.apply(&p, &mut u1);
        op.apply_direct(&p, &mut u2);
        let scale = u2.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (a, b) in u1.iter().zip(&u2) {
            assert!((a - b).abs() <= 1e-12 * scale, "{a} vs {b}");
        }
    }

    #[test]
    fn embedding_and_preconditioner_are_positive_definite() {
        for n in [64usize, 1024, 16384] {
            let op = HalfPlane::new(Grid::new(n, 4.0).unwrap(), None).unwrap();
            assert!(op.spectrum.iter().all(|&v| v > 0.0), "n = {n}");
        }
        // C is symmetric positive definite: a.Cb = b.Ca and r.Cr > 0.
        let grid = Grid::new(1024, 4.0).unwrap();
        let mut op = HalfPlane::new(grid, None).unwrap();
        let mut seed: u64 = 11;
        let mut rand = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let a: Vec<f64> = (0..1024).map(|_| rand()).collect();
        let b: Vec<f64> = (0..1024).map(|_| rand()).collect();
        let (mut ca, mut cb) = (vec![0.0; 1024], vec![0.0; 1024]);
        op.precondition(&a, &mut ca);
        op.precondition(&b, &mut cb);
        let dot = |x: &[f64], y: &[f64]| x.iter().zip(y).map(|(u, v)| u * v).sum::<f64>();
        assert!((dot(&a, &cb) - dot(&b, &ca)).abs() <= 1e-12 * dot(&a, &ca).abs());
        assert!(dot(&a, &ca) > 0.0 && dot(&b, &cb) > 0.0);
        assert_eq!(op.products(), 2);
    }

    #[test]
    fn periodic_operator_sums_the_images() {
        let (n, x) = (256usize, 2.0);
        let grid = Grid::new(n, x).unwrap();
        let mut op = HalfPlane::periodic(grid, None).unwrap();
        assert!(op.spectrum.iter().all(|&v| v > 0.0));
        // A traction with no net load: +1 on cell 40, -1 on cell 200. Its
        // images' free-space displacements converge (as 1/m^2).
        let mut p = vec![0.0; n];
        p[40] = 1.0;
        p[200] = -1.0;
        let (mut u, mut direct) = (vec![0.0; n], vec![0.0; n]);
        op.apply(&p, &mut u);
        op.apply_direct(&p, &mut direct);
        let free = HalfPlane::new(grid, None).unwrap();
        let period = 2.0 * x;
        for i in [0usize, 40, 41, 128, 199, 255] {
            assert!((u[i] - direct[i]).abs() < 1e-12, "{i}");
            let xi = grid.x(i);
            let mut images = 0.0;
            for m in -20_000i32..=20_000 {
                let shift = f64::from(m) * period;
                for (j, sign) in [(40usize, 1.0), (200, -1.0)] {
                    let s0 = grid.x(j) - 0.5 * grid.dx() + shift;
                    images += sign * free.segment_influence(xi, s0, s0 + grid.dx());
                }
            }
            assert!((u[i] - images).abs() < 1e-6, "cell {i}: {} vs image sum {images}", u[i]);
            // The point influence agrees with the cell coefficients.
            let s0 = grid.x(40) - 0.5 * grid.dx();
            let at = op.segment_influence(xi, s0, s0 + grid.dx()) - op.segment_influence(xi, grid.x(200) - 0.5 * grid.dx(), grid.x(200) + 0.5 * grid.dx());
            assert!((at - u[i]).abs() < 1e-12, "cell {i}");
        }
        // The mean traction moves the surface by (2/pi) P pbar ln(2 pi L_d/P).
        let ones = vec![1.0; n];
        op.apply(&ones, &mut u);
        let expected = 2.0 / PI * period * (2.0 * PI * period / period).ln();
        assert!(u.iter().all(|v| (v - expected).abs() < 1e-10 * expected), "{} vs {expected}", u[0]);
        assert!(HalfPlane::periodic(grid, Some(0.2 * period)).is_err());
    }

    #[test]
    fn datum_below_capacity_is_rejected() {
        let grid = Grid::new(64, 1.0).unwrap();
        assert!(HalfPlane::new(grid, Some(0.9)).is_err());
        assert!(HalfPlane::new(grid, Some(f64::NAN)).is_err());
        assert!(HalfPlane::new(grid, Some(1.0)).is_ok());
    }
}
