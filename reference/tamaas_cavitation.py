#!/usr/bin/env python3
"""Independent reference for the solver's cavitated states (issue 10): the
Dugdale-Maugis wavy-cylinder contact solved with Tamaas (a BEM code by Frerot,
Anciaux, Rey and Molinari; PyPI `tamaas`, version printed into the CSV).

    python3 -m pip install tamaas numpy
    python3 reference/tamaas_cavitation.py            # lambda = 1/4, Fig. 4c roughness
    python3 reference/tamaas_cavitation.py --hertz    # check of units and datum: Hertz
                                                      # (approach within 2.8e-5 of Hertz's at loads 0.014-0.29)

It writes reference/data/tamaas_cavitation.csv, which
solver/tests/it/tamaas_reference.rs compares with maugis-solver state by state.

Method
------
Tamaas 1D (`model_type.basic_1d`, E = 1, nu = 0, so E* = 1: the normalised units
of the semi-analytical model and of solver/, lengths in l_h, heights in l_v,
traction in (E*^2 dgamma/R)^(1/3)) with `PolonskyKeerRey` on the gap (primal and
constraint), and `MaugisAdhesionFunctional` with range rho = delta_c = 1/lambda and
surface energy 1 (so the Dugdale stress is sigma0 = lambda, solver/src/profile.rs).
The indenter is h(x) = x^2/2 + alpha (1 - cos(2 pi x/beta)) on a periodic cell of
width P centred on the contact.

Periodic images. Tamaas's elastic operator is periodic: its displacement is that
of the kernel -(2/pi) ln|2 sin(pi t/P)| plus a constant, while solver/ and the
semi-analytical model use one contact on a half-plane, -(2/pi) ln(|t|/L_d). The
difference, corr(x) = u_T(x) - u_free(x), is smooth near the contact
(ln|2 sin y| - ln|2y| = -y^2/6 - y^4/180 - ..., y = pi t/P), about
(pi/(3P^2)) int p(s)(x-s)^2 ds: an image curvature that biases the load by about
2 pi L^2/(3 P^2) (0.08 at L = 5, P = 32). It is removed exactly, by a fixed
point: Tamaas solves with the indenter h - corr, corr taken from the previous
solve (computed from Tamaas's own pressure: u_free by the exact cell-integrated
log kernel, a zero-padded FFT convolution), until the load changes by less than
1e-7. At the fixed point Tamaas's gap is h + u_free + const: the free-space
problem. The constant is the approach; on the datum L_d = 1,
    Delta_1 = h(x) + u_free(x)  at every contact node
(its spread over the contact nodes is printed as a check, and written to the CSV).
A solver with datum L_d has Delta = Delta_1 + (2/pi) L ln L_d (elastic.rs).

The loading path is driven by Tamaas's mean gap, from first contact to
abar = 4.5, each solve warm-started from the previous one. Tamaas's displacement
has zero mean over the cell, so its mean gap fixes its periodic approach d_T;
as -(2/pi) ln|2 sin(pi t/P)| = -(2/pi) ln(|t|/(P/(2 pi))) + O(t^2), that is
displacement control with the datum L_d = P/(2 pi) (up to the slowly varying
image correction). The Rust test runs maugis-solver with that datum, so both
codes take the same branches through the jumps, and compares it state by state.

Run (default arguments, P = 64, 2^14 nodes, mean-gap step 0.1; about 7 minutes
on one core): 180 states, abar 1.15 to 4.51, 3 or 5 contact intervals at abar
1.15-1.41, 2.14-2.43, 3.24-3.47 and 4.34-4.51. A second run with P = 32 and 2^13
nodes (the same cell size; images of up to 0.27 removed instead of 0.07)
gives the same curve: at equal load and topology, the approaches differ by at
most 2.6e-3 (the contact edges sit on nodes 0.0039 apart).

Columns: delta_ld1 (approach on datum 1), load, abar (outermost contact nodes,
half-width to the outer cell edges), intervals (contact intervals), spread
(max - min of h + u_free over the contact nodes), image (max |corr - corr(0)| over
the contact, the size of what was removed), solves (Tamaas solves in the image
fixed point), mean_gap_step (the control). Tamaas's own stopping tolerance is
--tol 1e-8: its error stalls near 1e-9 at 2^14 nodes, so 1e-10 runs to max_iter.
"""

import argparse
import math
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent


def free_space_displacement(p, dx):
    """u_free at the nodes for nodal pressures p on cells of width dx: the exact
    integral of -(2/pi) ln|t| over each cell (solver/src/elastic.rs, L_d = 1),
    as a linear (zero-padded) convolution."""
    n = p.size
    k = np.arange(-(n - 1), n, dtype=float)

    def F(t):
        with np.errstate(divide="ignore", invalid="ignore"):
            v = t * np.log(np.abs(t)) - t
        return np.where(t == 0.0, 0.0, v)

    kern = -(2.0 / math.pi) * (F(k * dx + dx / 2) - F(k * dx - dx / 2))
    m = 1 << int(math.ceil(math.log2(3 * n)))
    conv = np.fft.irfft(np.fft.rfft(p, m) * np.fft.rfft(kern, m), m)
    return conv[n - 1 : 2 * n - 1]


def intervals_of(mask):
    """Contiguous runs of True: (first, last) index pairs."""
    idx = np.flatnonzero(mask)
    if idx.size == 0:
        return []
    breaks = np.flatnonzero(np.diff(idx) > 1)
    starts = np.concatenate(([idx[0]], idx[breaks + 1]))
    ends = np.concatenate((idx[breaks], [idx[-1]]))
    return list(zip(starts, ends))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--lam", type=float, default=0.25)
    ap.add_argument("--alpha", type=float, default=math.sqrt(2.0) / 4.0)
    ap.add_argument("--beta", type=float, default=1.125)
    ap.add_argument("--period", type=float, default=64.0, help="periodic cell width (its effective datum P/(2 pi) must be >= the solver test's domain half-width)")
    ap.add_argument("--nodes", type=int, default=2**14, help="nodes per cell (P/n = 0.0039 by default)")
    ap.add_argument("--step", type=float, default=0.1, help="mean-gap step of the loading path")
    ap.add_argument("--abar-max", type=float, default=4.5)
    ap.add_argument("--tol", type=float, default=1e-8, help="Tamaas's stopping tolerance (its error stalls near 1e-9 at 2^14 nodes)")
    ap.add_argument("--hertz", action="store_true", help="no adhesion, smooth cylinder: compare with Hertz")
    ap.add_argument("--out", default=str(ROOT / "reference/data/tamaas_cavitation.csv"))
    args = ap.parse_args()

    import tamaas as tm

    P, n = args.period, args.nodes
    dx = P / n
    x = np.arange(n) * dx - P / 2
    alpha = 0.0 if args.hertz else args.alpha
    h = 0.5 * x * x + alpha * (1.0 - np.cos(2.0 * math.pi * x / args.beta))
    centre = n // 2

    model = tm.ModelFactory.createModel(tm.model_type.basic_1d, [P], [n])
    model.E = 1.0
    model.nu = 0.0
    surface = np.ascontiguousarray(-h)  # Tamaas: gap = u - surface; updated in place
    solver = tm.PolonskyKeerRey(model, surface, args.tol, tm.PolonskyKeerRey.gap, tm.PolonskyKeerRey.gap)
    if not args.hertz:
        adhesion = tm.MaugisAdhesionFunctional(surface)
        adhesion.parameters = {"rho": 1.0 / args.lam, "surface_energy": 1.0}
        solver.addFunctionalTerm(adhesion)
    solver.max_iter = 20000
    solver.dump_freq = 10**9  # no per-iteration table

    corr = np.zeros(n)
    rows = []
    d = -0.2 if not args.hertz else 0.05
    while True:
        load_prev = None
        for it in range(30):
            surface[:] = -(h - corr)
            solver.solve(float(np.mean(h - corr) - d))
            p = np.array(model.traction).ravel()
            u = np.array(model.displacement).ravel()
            u_free = free_space_displacement(p, dx)
            c = u - u_free
            corr = c - c[centre]
            load = float(p.sum() * dx)
            if load_prev is not None and abs(load - load_prev) <= 1e-7:
                break
            load_prev = load
        else:
            sys.exit(f"image fixed point did not converge at mean-gap step {d}")
        gap = u - surface
        contact = gap <= 1e-9 * max(1.0, float(np.max(np.abs(u))))
        runs = intervals_of(contact)
        if runs:
            tot = h + u_free
            delta = float(np.mean(tot[contact]))
            spread = float(np.ptp(tot[contact]))
            image = float(np.max(np.abs(corr[contact])))
            abar = float(x[runs[-1][1]] - x[runs[0][0]] + dx) / 2
            residual = float(solver.computeError()) if hasattr(solver, "computeError") else float("nan")
            rows.append((delta, load, abar, len(runs), spread, image, it + 1, float(d)))
            line = f"d {d:7.3f}  Delta_1 {delta: .6f}  L {load: .6f}  abar {abar:.4f}  intervals {len(runs)}  spread {spread:.1e}  image {image:.1e}  solves {it + 1}"
            if args.hertz:
                a = math.sqrt(4 * load / math.pi)  # Hertz: L = pi a^2/4
                hertz = 0.5 * a * a * (math.log(2 / a) + 0.5)
                line += f"  | Hertz at this L: a {a:.4f}, Delta_1 {hertz:.6f} (rel. diff {delta / hertz - 1:+.1e})"
            print(line, flush=True)
            if abar >= args.abar_max:
                break
        d += args.step
        if args.hertz and len(rows) >= 8:
            break

    if args.hertz:
        return
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    with open(out, "w") as f:
        f.write(f"# Tamaas {tm.__version__} Dugdale-Maugis wavy cylinder, loading path; written by reference/tamaas_cavitation.py\n")
        f.write(f"# lambda={args.lam!r} alpha={args.alpha!r} beta={args.beta!r} period={P!r} nodes={n} step={args.step!r}\n")
        f.write("# delta_ld1: approach on datum L_d = 1 (free space, images removed); load, abar in normalised units\n")
        f.write("delta_ld1,load,abar,intervals,spread,image,solves,mean_gap_step\n")
        for r in rows:
            f.write(f"{r[0]!r},{r[1]!r},{r[2]!r},{r[3]},{r[4]:.3e},{r[5]:.3e},{r[6]},{r[7]:.3f}\n")
    print(f"wrote {out} ({len(rows)} states)")


if __name__ == "__main__":
    main()
