#!/usr/bin/env python3
"""2F1 with one large parameter (issue 37 item 2): Arb and mpmath on the grid of
reference/data/hyp2f1_large_param.csv, beside maugis (examples/hyp2f1_large_grid).

Usage:
    cargo run --release --features maugis/gmp-no-check --example hyp2f1_large_grid
    python3 reference/bench_hyp2f1_large_param.py [prec ...]     (default 64 256)

Per precision: how many points each library answers, and how. Arb:
python-flint's arb.hypgeom_2f1 (arb_hypgeom_2f1) at the decimals rounded to the
precision; a NaN or a ball with no correct bit counts as a failure, an answer
that misses the reference as wrong. mpmath: mpmath.hyp2f1 at the precision
(default maxterms); an exception (NoConvergence) counts as a failure, a value
off the reference by more than 2^-(prec-8) relative as wrong. CPU time per
point (process time, best of 3, capped at 2 s a call for mpmath by its own
maxterms). The reference is the table's value (mpmath through the connection
formulas at 700 and 1100 bits, reference/hyp2f1_large_param.py).
"""
import csv
import os
import sys
import time

import flint
import mpmath
from mpmath import mp, mpf

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "reference", "data", "hyp2f1_large_param.csv")


def rows():
    with open(DATA) as fh:
        return list(csv.DictReader(line for line in fh if not line.startswith("#")))


def cpu(f):
    best = float("inf")
    out = None
    for _ in range(3):
        t = time.process_time()
        try:
            out = f()
        except Exception as e:  # mpmath.NoConvergence and friends
            out = e
        best = min(best, time.process_time() - t)
    return out, best


def arb_point(r, prec):
    flint.ctx.prec = prec
    a, b, c, z = (flint.arb(r[k]) for k in "abcz")
    return z.hypgeom_2f1(a, b, c)


def mpmath_point(r, prec):
    mp.prec = prec
    return mpmath.hyp2f1(mpf(r["a"]), mpf(r["b"]), mpf(r["c"]), mpf(r["z"]))


def main():
    precs = [int(p) for p in sys.argv[1:]] or [64, 256]
    data = rows()
    for prec in precs:
        stats = {"arb": [0, 0, 0, 0.0], "mpmath": [0, 0, 0, 0.0]}  # ok, failed, wrong, max time
        for r in data:
            mp.prec = 1200
            ref = mpf(r["value"])
            v, t = cpu(lambda: arb_point(r, prec))
            s = stats["arb"]
            s[3] = max(s[3], t)
            if isinstance(v, Exception) or not v.is_finite() or v.rad() >= abs(v.mid()):
                s[1] += 1
            else:
                mp.prec = 1200
                lo, hi = mpf(v.lower().str(60, radius=False)), mpf(v.upper().str(60, radius=False))
                if min(lo, hi) - abs(ref) * mpf(10) ** -38 <= ref <= max(lo, hi) + abs(ref) * mpf(10) ** -38:
                    s[0] += 1
                else:
                    s[2] += 1
            v, t = cpu(lambda: mpmath_point(r, prec))
            s = stats["mpmath"]
            s[3] = max(s[3], t)
            if isinstance(v, Exception):
                s[1] += 1
            else:
                mp.prec = 1200
                if abs(v - ref) <= abs(ref) * mpf(2) ** -(prec - 8):
                    s[0] += 1
                else:
                    s[2] += 1
        for lib, (ok, failed, wrong, tmax) in stats.items():
            print("%4d bits  %-7s %d points: %d answered, %d failed (NaN, no digits or an exception), %d wrong; slowest %.1f ms"
                  % (prec, lib, len(data), ok, failed, wrong, tmax * 1e3), flush=True)


if __name__ == "__main__":
    main()
