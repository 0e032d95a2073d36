#!/usr/bin/env python3
"""Side-by-side timing and accuracy in f64: SciPy (vectorised) and maugis, for 2F1
(default) and J_n (`--bessel`).

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

By band of z (`--regions`, 20000 points by default): build the example first
(`cargo build --release --example hyp2f1_regions`), then

    python3 reference/bench_scipy.py --regions [--write docs/performance.md]

In one run, on the same 20000 points (the example's LCG is this one, same seed
and order): scipy.special.hyp2f1 per band of z and on the whole vector in the
drawn order (best of 7 each), and the Rust example as a subprocess (maugis
hyp2f1 per band and in the drawn order, best of 5; hyp2f1_bounded beside it),
in one table with the ratio SciPy / maugis.

J_n (issue 8: integer n <= 60, x <= 150, uniform): build the example first
(`cargo build --release --example bessel_f64`), then

    python3 reference/bench_scipy.py --bessel [--points 100000] [--write docs/performance.md]

In one run, on the same points (the LCG of `points` in examples/bessel_f64.rs,
seed 0xB355E1): scipy.special.jv on the whole vector (best of 5, wall and CPU
time), the Python binding `maugis.bessel_j(n, x)` if it is importable (same),
and the Rust example as a subprocess (per value, wall and CPU, per method, MP
fallbacks, worst error and bound misses against the certified value); SciPy's
worst relative error against mpmath (53-bit inputs, 120 bits) on the first
`--accuracy-points` points. The load average is printed with the table: the
machine is shared, so compare the CPU-time columns, which were taken in one run.
"""

import argparse
import contextlib
import io
import math
import json
import os
import subprocess
import time
from pathlib import Path

import mpmath

from bench_table import footer, write_between_markers
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


def bessel_points(n, seed=0xB355E1):
    """The points of examples/bessel_f64.rs: n = min(floor(61 u), 60), x = 150 u'."""
    state = seed
    ns, xs = [], []

    def uniform():
        nonlocal state
        state = (state * 6364136223846793005 + 1442695040888963407) & MASK
        return (state >> 11) / float(1 << 53)

    for _ in range(n):
        ns.append(min(int(uniform() * 61.0), 60))
        xs.append(uniform() * 150.0)
    return np.array(ns, dtype=np.int64), np.array(xs)


def best_of(reps, f):
    """Best (wall, cpu) seconds of `reps` calls of f."""
    wall = cpu = float("inf")
    for _ in range(reps):
        w0, c0 = time.perf_counter(), time.process_time()
        f()
        wall = min(wall, time.perf_counter() - w0)
        cpu = min(cpu, time.process_time() - c0)
    return wall, cpu


def bench_bessel(points, accuracy_points, exe):
    n, x = bessel_points(points)
    load = os.getloadavg()
    rows = []
    wall, cpu = best_of(5, lambda: scipy.special.jv(n, x))
    v = scipy.special.jv(n, x)
    mpmath.mp.prec = 120
    worst = 0.0
    for ni, xi, vi in zip(n[:accuracy_points], x[:accuracy_points], v[:accuracy_points]):
        ref = mpmath.besselj(int(ni), mpmath.mpf(float(xi)))
        if ref != 0:
            worst = max(worst, float(abs((mpmath.mpf(float(vi)) - ref) / ref)))
    rows.append(("scipy.special.jv (vectorised)", wall, cpu, "%.1e (first %d points)" % (worst, accuracy_points)))
    try:
        import maugis  # the Python binding, `pip install ./python`

        wall, cpu = best_of(5, lambda: maugis.bessel_j(n, x))
        rows.append(("maugis.bessel_j (Python binding)", wall, cpu, ""))
        wall, cpu = best_of(5, lambda: maugis.bessel_j(n, x, bounded=True))
        rows.append(("maugis.bessel_j(bounded=True) (Python binding)", wall, cpu, ""))
    except ImportError:
        rows.append(("maugis.bessel_j (Python binding)", None, None, "not installed (pip install ./python)"))
    rust = None
    if exe.exists():
        rust = subprocess.run([str(exe), str(points)], capture_output=True, text=True, check=True).stdout
    print("points: %d (integer n <= 60, x <= 150, uniform); scipy %s, numpy %s; load average %.1f %.1f %.1f"
          % (points, scipy.__version__, np.__version__, *load))
    print("| J_n, f64 | wall per value | CPU per value | worst rel. error (vs mpmath, 120 bits) |")
    print("|---|---|---|---|")
    for name, wall, cpu, acc in rows:
        if wall is None:
            print("| %s | | | %s |" % (name, acc))
        else:
            print("| %s | %.3f us | %.3f us | %s |" % (name, wall / points * 1e6, cpu / points * 1e6, acc))
    if rust is None:
        print("(build the Rust side first: cargo build --release --example bessel_f64)")
    else:
        print("Rust, same points, same run (examples/bessel_f64):")
        print(rust.rstrip())


REGION_BANDS = [(-5.0, -4.0), (-4.0, -3.0), (-3.0, -2.0), (-2.0, -1.0), (-1.0, -0.5), (-0.5, 0.0), (0.0, 0.5),
                (0.5, 0.75), (0.75, 0.9)]


def bench_regions(n_points, exe):
    """SciPy and maugis (examples/hyp2f1_regions) per band of z, in one run."""
    if not exe.exists():
        raise SystemExit("build the Rust side first: cargo build --release --example hyp2f1_regions")
    if n_points != 20000:
        raise SystemExit("--regions uses the example's 20000 points")
    p = points(n_points)
    points_array = p
    load = os.getloadavg()
    scipy_us = {}
    for key in REGION_BANDS + ["all"]:
        sel = points_array if key == "all" else p[(p[:, 3] >= key[0]) & (p[:, 3] < key[1])]
        a, b, c, z = (np.ascontiguousarray(sel[:, i]) for i in range(4))
        wall, _ = best_of(7, lambda: scipy.special.hyp2f1(a, b, c, z))
        scipy_us[key] = wall / len(sel) * 1e6
    rust = subprocess.run([str(exe)], capture_output=True, text=True, check=True).stdout
    ours = {}
    for line in rust.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) != 4 or not cells[1].isdigit():
            continue
        if cells[0].startswith("["):
            lo, hi = (float(v) for v in cells[0].strip("[)").split(","))
            ours[(lo, hi)] = (float(cells[2]), float(cells[3]), int(cells[1]))
        elif cells[0] == "all, drawn order":
            ours["all"] = (float(cells[2]), float(cells[3]), int(cells[1]))
    print("points: %d (a, b in [-3, 3], c in [0.5, 6], z in [-5, 0.9]); scipy %s, numpy %s; load average %.1f %.1f %.1f"
          % (n_points, scipy.__version__, np.__version__, *load))
    print("| z band | points | scipy.special.hyp2f1 | maugis hyp2f1 | SciPy / maugis | maugis hyp2f1_bounded |")
    print("|---|---|---|---|---|---|")
    for key in REGION_BANDS + ["all"]:
        v, bounded, n = ours[key]
        name = "all, drawn order" if key == "all" else "[%g, %g)" % key
        print("| %s | %d | %.3f us | %.3f us | %.2f | %.3f us |" % (name, n, scipy_us[key], v, scipy_us[key] / v, bounded))


def wave_points():
    """The 64 points of benches/displacement.rs (domain_points): a = 0.5 + 5.5 u,
    x = a (1 + 2 v), u, v the fractional parts of i phi and i 0.7548776662466927."""
    pts = []
    for i in range(64):
        u = math.modf(i * 0.618033988749895)[0]
        v = math.modf(i * 0.754877666246693)[0]
        a = 0.5 + 5.5 * u
        pts.append((a, a * (1.0 + 2.0 * v)))
    return pts


def scipy_wave(a, x, zeta=1.125, amp=1.0):
    """u_w and du_w/dx by the Bessel form (docs/displacement.md, Route 2) with SciPy's
    J_n: the orders 0..2N+1, N = D/2 + 20 (the tail is below 1e-17 at D <= 34), in one
    vectorised jv call, then the two sums in NumPy. No error bound."""
    d = 2.0 * math.pi * a / zeta
    n_terms = int(d / 2) + 20
    j = scipy.special.jv(np.arange(2 * n_terms + 2), d)
    r = x / a
    s = math.sqrt((r - 1.0) * (r + 1.0))
    q = r - s if r < 2.0 else 1.0 / (r + s)
    n = np.arange(1, n_terms + 1)
    sign = np.where(n % 2 == 1, 1.0, -1.0)
    q2n = q ** (2 * n)
    u = amp * (1.0 - j[0] + d * j[1] * math.acosh(r) + 2.0 * np.sum(sign * j[2 * n] * q2n))
    t = math.sqrt((x - a) / (x + a))
    geo = (1.0 - q2n) / (1.0 - q) if q < 1.0 else 2.0 * n  # sum_{j<2n} q^j
    du = (4.0 * amp / a) * (1.0 - t) * np.sum(sign * n * j[2 * n] * geo)
    return u, du


def bench_wave(reps=7):
    """SciPy's u_w (Bessel form) over the 64 domain points against maugis' criterion
    medians of wave_f64_domain (run `cargo bench --bench displacement -- wave_f64_domain`
    first), per value."""
    pts = wave_points()
    wall, cpu = best_of(reps, lambda: [scipy_wave(a, x) for a, x in pts])
    print("u_w and du_w/dx over the 64 points of wave_f64_domain (a in [0.5, 6], zeta = 9/8, x/a in [1, 3]);"
          " scipy %s, numpy %s" % (scipy.__version__, np.__version__))
    print("| per value | time | ratio to SciPy |")
    print("|---|---:|---:|")
    scipy_us = wall / len(pts) * 1e6
    print("| SciPy Bessel form, u_w and du_w together (jv vectorised, best of %d; no bound) | %.2f us | 1.00 |"
          % (reps, scipy_us))
    for bench in ("u_wave_scratch", "du_wave_scratch", "u_wave_bounded_scratch", "du_wave_bounded_scratch"):
        ns = criterion_ns("wave_f64_domain", bench)
        if ns is None:
            print("| maugis %s | (run cargo bench --bench displacement -- wave_f64_domain first) | |" % bench)
        else:
            us = ns / len(pts) / 1e3
            print("| maugis `%s` from scratch (criterion median) | %.3f us | %.4f |"
                  % (bench.replace("_scratch", ""), us, us / scipy_us))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--points", type=int, default=None)
    ap.add_argument("--bessel", action="store_true", help="J_n instead of 2F1")
    ap.add_argument("--regions", action="store_true", help="2F1 by band of z, both sides in one run")
    ap.add_argument("--regions-example", type=Path, default=ROOT / "target" / "release" / "examples" / "hyp2f1_regions",
                    help="the built examples/hyp2f1_regions binary")
    ap.add_argument("--wave", action="store_true", help="u_w and du_w/dx (Bessel form) against wave_f64_domain")
    ap.add_argument("--accuracy-points", type=int, default=20000)
    ap.add_argument("--rust-example", type=Path, default=ROOT / "target" / "release" / "examples" / "bessel_f64",
                    help="the built examples/bessel_f64 binary")
    ap.add_argument("--write", default=None,
                    help="with --bessel or --regions: markdown file whose block between that mode's markers is replaced")
    args = ap.parse_args()
    if args.wave:
        bench_wave()
        return
    if args.bessel or args.regions:
        mode = "bessel" if args.bessel else "regions"
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            if args.bessel:
                bench_bessel(args.points or 100000, args.accuracy_points, args.rust_example)
            else:
                bench_regions(args.points or 20000, args.regions_example)
            print()
            print(footer("bench_scipy.py --%s" % mode, "SciPy and the Rust example in one run"))
        print(out.getvalue(), end="")
        if args.write:
            begin = "<!-- begin scipy %s: generated by reference/bench_scipy.py --%s, do not edit -->" % (mode, mode)
            end = "<!-- end scipy %s -->" % mode
            write_between_markers(args.write, begin, end, out.getvalue())
        return
    args.points = args.points or 1000
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
