#!/usr/bin/env python3
"""Numerical check of the modulus bounds used by src/special/bessel_j/three_term.rs.

The recurrence's error bound rests on two facts about M_nu(x) = (J_nu^2 + Y_nu^2)^(1/2):
  (a) M_0(x) <= M_1(x)          (Nicholson's integral, DLMF 10.9.30, increases with nu)
  (b) for nu >= 1/2, x > nu: (x^2 - nu^2)^(1/2) M_nu^2(x) increases in x to 2/pi
      (Watson 1944, section 13.74), so M_nu^2(x) <= 2 / (pi (x^2 - nu^2)^(1/2)).
Both are theorems; this script only checks them numerically with mpmath over
nu in [1/2, 60], x/nu in (1, 70), and x in (0, 100] for (a), as a guard against a
misquoted direction.  Usage: python3 reference/check_modulus.py (exit 1 on a violation).
"""

import sys

import mpmath
from mpmath import mp, mpf

mp.dps = 30


def modulus_sq(nu, x):
    return mpmath.besselj(nu, x) ** 2 + mpmath.bessely(nu, x) ** 2


def main():
    bad = 0
    for nu in (mpf(1) / 2, mpf(3) / 4, 1, 2, 3, 5, 7, 20, 60):
        prev = None
        for i in range(1, 400):
            x = nu * (1 + i * mpf("0.002")) if i < 200 else nu * mpf("1.4") * mpf("1.02") ** (i - 200)
            v = mpmath.sqrt(x * x - nu * nu) * modulus_sq(nu, x) * mp.pi / 2
            if v > 1 + mpf(10) ** -25:
                print("bound (b) violated: nu=%s x=%s value %s" % (nu, x, v))
                bad += 1
            if prev is not None and v < prev - mpf(10) ** -25:
                print("monotonicity (b) violated: nu=%s x=%s" % (nu, x))
                bad += 1
            prev = v
    for i in range(1, 200):
        x = mpf(i) / 2
        if modulus_sq(0, x) > modulus_sq(1, x):
            print("(a) violated at x=%s" % x)
            bad += 1
    print("modulus checks: %d violations" % bad)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
