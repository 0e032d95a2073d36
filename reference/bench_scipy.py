#!/usr/bin/env python3
"""Side-by-side timing and accuracy of 2F1 in f64: SciPy (vectorised) and maugis.

The points are the issue-8 domain a, b in [-3, 3], c in [0.5, 6], z in [-5, 0.9],
drawn from the same 64-bit LCG as `hyp2f1_bench_points` in benches/special.rs
(same seed, same order), so both sides see identical inputs.

Run `cargo bench --bench special -- hyp2f1_f64` first (criterion writes
target/criterion/hyp2f1_f64/...; the bench also prints maugis's MP-fallback count
and worst error against the certified 120-bit value), then

    python3 reference/bench_scipy.py [--points 1000]

It times scipy.special.hyp2f1 on the whole vector (best of 7), computes SciPy's
worst relative error against mpmath at 120 bits, and prints one table with the
maugis time per value read from criterion's estimates.
"""

import argparse
import json
import time
from pathlib import Path

import mpmath
import numpy as np
import scipy
import scipy.special

ROOT = Path(__file__).resolve().parent.parent
MASK = (1 << 64) - 1


def points(n, seed=0x2F15C1):
    state = seed
    out = []

    def uniform(lo, hi):
        nonlocal state
        state = (state * 6364136223846793005 + 1442695040888963407) & MASK
        return lo + (hi - lo) * ((state >> 11) / float(1 << 53))

    for _ in range(n):
        out.append((uniform(-3.0, 3.0), uniform(-3.0, 3.0), uniform(0.5, 6.0), uniform(-5.0, 0.9)))
    return np.array(out)


def criterion_ns(group, bench):
    path = ROOT / "target" / "criterion" / group / bench / "new" / "estimates.json"
    if not path.exists():
        return None
    est = json.loads(path.read_text())
    return est["median"]["point_estimate"]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--points", type=int, default=1000)
    args = ap.parse_args()
    p = points(args.points)
    a, b, c, z = p[:, 0], p[:, 1], p[:, 2], p[:, 3]
    best = float("inf")
    for _ in range(7):
        t0 = time.perf_counter()
        v = scipy.special.hyp2f1(a, b, c, z)
        best = min(best, time.perf_counter() - t0)
    mpmath.mp.prec = 120
    worst = 0.0
    for (ai, bi, ci, zi), vi in zip(p, v):
        ref = mpmath.hyp2f1(mpmath.mpf(ai), mpmath.mpf(bi), mpmath.mpf(ci), mpmath.mpf(zi))
        worst = max(worst, float(abs((mpmath.mpf(vi) - ref) / ref)) if ref != 0 else 0.0)
    scipy_us = best / args.points * 1e6
    print("points: %d (a, b in [-3, 3], c in [0.5, 6], z in [-5, 0.9]; scipy %s, numpy %s)"
          % (args.points, scipy.__version__, np.__version__))
    print("| function | time per value | worst rel. error (vs mpmath, 120 bits) |")
    print("|---|---|---|")
    print("| scipy.special.hyp2f1 (vectorised, best of 7) | %.3f us | %.1e |" % (scipy_us, worst))
    for bench in ("hyp2f1_1000 random points", "hyp2f1_bounded_1000 random points"):
        ns = criterion_ns("hyp2f1_f64", bench)
        if ns is None:
            print("| maugis %s | (run cargo bench --bench special -- hyp2f1_f64 first) | |" % bench.split("_1000")[0])
        else:
            print("| maugis %s (criterion median) | %.3f us | see the bench's printed line |"
                  % (bench.split("_1000")[0], ns / args.points / 1e3))


if __name__ == "__main__":
    main()
