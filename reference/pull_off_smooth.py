#!/usr/bin/env python3
"""Smooth Maugis pull-off (alpha = 0) at large lambda, for tests/it/large_lambda.rs.

Usage:  python3 reference/pull_off_smooth.py   (writes reference/data/pull_off_smooth.csv)

The normalised smooth strip equation and load (docs/model.md, "Equations"; z = m - 1,
s = sqrt(z (2 + z))):

    F(a, z) = (4/pi) lambda^2 a A(z) + (lambda/2) a^2 H(z) - 1 = 0,
    A(z) = s acosh(1+z) - (1+z) ln(1+z),   H(z) = (1+z) s - acosh(1+z),
    L(a, z) = pi a^2/4 - 2 lambda a s.

Pull-off is the minimum of L along F = 0: G = L_a F_z - L_z F_a = 0, with the
analytic partials A' = (1+z) acosh(1+z)/s - ln(1+z), H' = 2 s. The system
(F, G) = 0 is solved with mpmath's multidimensional Newton in (a, ln z) at two
precisions (dps 60 and 90); a point is written only if both agree to 45 digits.
Values are written with 40 significant digits. mpmath 1.3.0.
"""
import os
import sys

import mpmath as mp

LAMBDAS = ["100", "10000", "1000000"]


def solve(lam_s, dps):
    mp.mp.dps = dps
    lam = mp.mpf(lam_s)

    def parts(a, z):
        s = mp.sqrt(z * (2 + z))
        ac = mp.acosh(1 + z)
        A = s * ac - (1 + z) * mp.log1p(z)
        H = (1 + z) * s - ac
        dA = (1 + z) * ac / s - mp.log1p(z)
        dH = 2 * s
        F = 4 / mp.pi * lam**2 * a * A + lam / 2 * a**2 * H - 1
        Fa = 4 / mp.pi * lam**2 * A + lam * a * H
        Fz = 4 / mp.pi * lam**2 * a * dA + lam / 2 * a**2 * dH
        La = mp.pi * a / 2 - 2 * lam * s
        Lz = -2 * lam * a * (1 + z) / s
        L = mp.pi * a**2 / 4 - 2 * lam * a * s
        return F, La * Fz - Lz * Fa, L

    def eqs(a, lz):
        F, G, _ = parts(a, mp.exp(lz))
        # scale G to order one: F_z ~ lambda^2 a
        return [F, G / (lam**2)]

    a0 = mp.cbrt(2 / mp.pi)
    z0 = mp.pi / (4 * lam**2 * a0)
    a, lz = mp.findroot(eqs, (a0, mp.log(z0)), tol=mp.mpf(10) ** (-dps + 10), maxsteps=200)
    _, _, L = parts(a, mp.exp(lz))
    return a, L


def main():
    rows = []
    for lam in LAMBDAS:
        a1, l1 = solve(lam, 60)
        a2, l2 = solve(lam, 90)
        if abs(l1 - l2) > mp.mpf(10) ** -45 * abs(l2) or abs(a1 - a2) > mp.mpf(10) ** -45 * a2:
            print(f"lambda = {lam}: precisions disagree, rejected", file=sys.stderr)
            continue
        mp.mp.dps = 90
        rows.append((lam, mp.nstr(a2, 40, strip_zeros=False), mp.nstr(l2, 40, strip_zeros=False)))
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "pull_off_smooth.csv")
    with open(out, "w") as f:
        f.write("lambda,abar,load\n")
        for r in rows:
            f.write(",".join(r) + "\n")
    print(f"wrote {len(rows)} rows to {out}")


if __name__ == "__main__":
    main()
