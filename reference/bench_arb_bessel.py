#!/usr/bin/env python3
"""J_n(x) side by side: maugis (bessel_j_mp) and Arb (python-flint), same points.

Usage:
    cargo build --release --example bessel_grid
    python3 reference/bench_arb_bessel.py [--write docs/bessel.md] [prec ...]

The grid is issue 13's: n in {0, 1, 7, 60, 500, 2000, 10000} x x in {0.001, 1.5,
30.25, 150.5, 999.5, 5000.25, 20000.5, 99999.5, 1000000.5}, plus J_500(30000),
J_-1200(50000.25) and issue 8's J_0(2.5), J_5(30.25), J_40(150.5); at 53, 128
and 512 bits unless precisions are given.

Timing: each point is called in a loop until 20 ms have passed (at least once),
in one process per library (python-flint's call overhead, ~1 us, is included
for Arb). maugis' figures come from target/release/examples/bessel_grid, run
by this script in the same session. "bits" is the certified relative accuracy
log2(|mid|/rad) of the returned ball (Arb's rel_accuracy_bits; maugis'
rel_accuracy_bits), capped at 99999 for an exact ball.
"""

import argparse
import os
import subprocess
import sys
import time

import flint

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXAMPLE = os.path.join(ROOT, "target", "release", "examples", "bessel_grid")
MIN_TIME = 0.02


def arb_point(n, x, prec):
    flint.ctx.prec = prec
    xa = flint.arb(repr(x))
    t0 = time.perf_counter()
    calls = 0
    while True:
        v = xa.bessel_j(n)
        calls += 1
        if time.perf_counter() - t0 >= MIN_TIME:
            break
    us = (time.perf_counter() - t0) * 1e6 / calls
    bits = v.rel_accuracy_bits()
    return (min(bits, 99999) if bits > -10**6 else float("-inf")), us


def maugis_rows(precs):
    out = subprocess.run([EXAMPLE] + [str(p) for p in precs], check=True, capture_output=True, text=True).stdout
    rows = []
    for line in out.strip().splitlines()[1:]:
        prec, n, x, alg, bits, us = line.split(",")
        rows.append((int(prec), int(n), float(x), alg, bits, float(us)))
    return rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--write", default=None, help="markdown file to write the table to")
    ap.add_argument("precs", nargs="*", type=int)
    args = ap.parse_args()
    precs = args.precs or [53, 128, 512]
    rows = maugis_rows(precs)
    lines = [
        "| prec | n | x | maugis method | maugis bits | maugis us | Arb bits | Arb us |",
        "|---:|---:|---:|---|---:|---:|---:|---:|",
    ]
    worst = {}
    for prec, n, x, alg, bits, us in rows:
        abits, aus = arb_point(n, x, prec)
        ab = "%.1f" % abits if abits != float("-inf") else "0 (no bits)"
        lines.append("| %d | %d | %s | %s | %s | %.1f | %s | %.1f |" % (prec, n, repr(x), alg, bits, us, ab, aus))
        w = worst.setdefault(prec, [0.0, 0.0, 0, 0])
        w[0] = max(w[0], us)
        w[1] = max(w[1], aus)
        try:
            w[2] += float(bits) < prec
        except ValueError:
            w[2] += 1
        w[3] += abits < prec - 10
        sys.stderr.write(lines[-1] + "\n")
    summary = ["", "| prec | maugis worst us | Arb worst us | maugis points < prec bits | Arb points < prec - 10 bits |", "|---:|---:|---:|---:|---:|"]
    for prec, (mw, aw, mb, ab) in sorted(worst.items()):
        summary.append("| %d | %.0f | %.0f | %d | %d |" % (prec, mw, aw, mb, ab))
    text = "\n".join(lines + summary) + "\n"
    if args.write:
        with open(args.write, "w") as fh:
            fh.write(text)
    print(text)


if __name__ == "__main__":
    main()
