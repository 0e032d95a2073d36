#!/usr/bin/env python3
"""Reference values of H^(1)_n(z) for the test of Hankel's expansion and its error bound.

Usage:  python3 reference/generate_hankel.py

Writes reference/data/hankel1.csv: n, re_z, im_z, re_h, im_h, with H^(1)_n(z) to
OUT_DIGITS significant digits.  The points z = x + i y have dyadic x > 0 and y (exact
in binary), from |z| = 1/2 to 45 and phases from about -pi/2 (x small, y < 0: the edge
of the sector -pi/2 <= ph z <= 0 where DLMF 10.17.15 has the factor chi(l)) to about
pi/2.  Each value is computed by mpmath's hankel1 at mp.dps = OUT_DIGITS + 20 and
OUT_DIGITS + 60 (plus 0.87 |y| digits, which J_n + i Y_n loses to cancellation) and kept only when the two agree to OUT_DIGITS + 5 digits; it is
cross-checked against J_n(z) + i Y_n(z) from mpmath's besselj and bessely.  The test
(tests/it/hankel_bound.rs) forms the true remainder R_l of Hankel's expansion from
these values, for l = 1..24, and checks it against the bound of DLMF 10.17.14-15 that
src/ball/complex/hankel.rs uses.  Depends only on mpmath (pinned in
requirements.txt); the output is byte-identical between runs.
"""

import csv
import os

import mpmath
from mpmath import mp, mpf

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "data", "hankel1.csv")
OUT_DIGITS = 120

ORDERS = [0, 1, 2, 3, 5, 10]
XS = ["0.5", "1", "2", "4", "8", "16", "32"]
YS = ["-32", "-8", "-2", "-0.5", "0", "0.5", "2", "8", "32"]


def value(n, z, dps):
    with mp.workdps(dps):
        return mpmath.hankel1(n, z)


def main():
    rows = []
    for n in ORDERS:
        for xs in XS:
            for ys in YS:
                z = mpmath.mpc(mpf(xs), mpf(ys))
                # J_n + i Y_n cancels by about e^{2 |y|} in the upper half-plane
                extra = int(abs(float(ys)) * 0.87) + 10
                h1 = value(n, z, OUT_DIGITS + 20 + extra)
                h2 = value(n, z, OUT_DIGITS + 60 + extra)
                with mp.workdps(OUT_DIGITS + 60):
                    if abs(h1 - h2) > abs(h2) * mpf(10) ** (-(OUT_DIGITS + 5)):
                        raise SystemExit(f"n {n} z {z}: {h1} and {h2} disagree")
                with mp.workdps(OUT_DIGITS + 20 + extra):
                    check = mpmath.besselj(n, z) + 1j * mpmath.bessely(n, z)
                    if abs(check - h1) > abs(h1) * mpf(10) ** (-OUT_DIGITS):
                        raise SystemExit(f"n {n} z {z}: J + iY = {check}, hankel1 = {h1}")
                with mp.workdps(OUT_DIGITS + 60):
                    re = mpmath.nstr(h2.real, OUT_DIGITS, strip_zeros=False, min_fixed=1, max_fixed=0)
                    im = mpmath.nstr(h2.imag, OUT_DIGITS, strip_zeros=False, min_fixed=1, max_fixed=0)
                rows.append([n, xs, ys, re, im])
    with open(OUT, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["n", "re_z", "im_z", "re_h", "im_h"])
        w.writerows(rows)
    print(f"wrote {len(rows)} rows to {OUT}")


if __name__ == "__main__":
    main()
