#!/usr/bin/env python3
"""Golden values for finite integrals with singular points found from the expression
(issue 40): removable singularities, algebraic and logarithmic endpoint singularities,
with no declared weight.

Usage:  python3 reference/generate_finite_singular.py

Writes reference/data/integrals_singular.csv: id, description, expression, a, b,
value.  Each value is its closed form (or a fast convergent series) at mp.dps =
OUT_DIGITS + 20 and OUT_DIGITS + 60, kept only when the two agree to OUT_DIGITS + 5
digits, then cross-checked against mpmath.quad (tanh-sinh) at CHECK_DPS digits, an
estimate that only guards against a mistyped closed form.  Byte-identical between
runs (mpmath pinned in requirements.txt).
"""

import csv
import os
import sys

import mpmath
from mpmath import mp, mpf

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "data", "integrals_singular.csv")
OUT_DIGITS = 400
CHECK_DPS = 30

def series(term, n):
    """sum_{m>=n} term(m), summed until a term is below 10^-(dps+10) (the terms fall
    factorially)."""
    total = mpf(0)
    while True:
        t = term(n)
        total += t
        if abs(t) < mpf(10) ** -(mp.dps + 10):
            return total
        n += 1


def cos_taylor4_series():
    """sum_{n>=2} (-1)^n / ((2n)! (2n-3))."""
    return series(lambda n: mpf(-1) ** n / (mpmath.factorial(2 * n) * (2 * n - 3)), 2)


def sin_pi_taylor2_series():
    """sum_{n>=1} (-1)^n pi^(2n+1) / ((2n+1)! (2n-1))."""
    return series(lambda n: mpf(-1) ** n * mp.pi ** (2 * n + 1) / (mpmath.factorial(2 * n + 1) * (2 * n - 1)), 1)


INTEGRALS = [
    ("sinc_sym", "int_-1^1 sin(x)/x dx = 2 Si(1)", "sin(x)/x", "-1", "1",
     lambda: 2 * mpmath.si(1), lambda: mpmath.quad(lambda x: mpmath.sinc(x), [-1, 0, 1])),
    ("expm1_over_x", "int_0^1 (exp(x)-1)/x dx = Ei(1) - gamma", "(exp(x)-1)/x", "0", "1",
     lambda: mpmath.ei(1) - mp.euler, lambda: mpmath.quad(lambda x: mpmath.expm1(x) / x, [0, 1])),
    ("log", "int_0^1 log(x) dx = -1", "log(x)", "0", "1",
     lambda: mpf(-1), lambda: mpmath.quad(mpmath.log, [0, 1])),
    ("x_pow_x", "int_0^1 x^x dx = sum_n (-1)^(n+1) n^-n", "x^x", "0", "1",
     lambda: mpmath.nsum(lambda n: (-1) ** (n + 1) * n ** (-n), [1, mpmath.inf]),
     lambda: mpmath.quad(lambda x: x ** x, [0, 1])),
    ("rsqrt", "int_0^1 x^(-1/2) dx = 2", "x^(-1/2)", "0", "1",
     lambda: mpf(2), lambda: mpmath.quad(lambda x: 1 / mpmath.sqrt(x), [0, 1])),
    ("sqrt", "int_0^1 sqrt(x) dx = 2/3", "sqrt(x)", "0", "1",
     lambda: mpf(2) / 3, lambda: mpmath.quad(mpmath.sqrt, [0, 1])),
    ("log_log1m", "int_0^1 log(x) log(1-x) dx = 2 - pi^2/6", "log(x)*log(1-x)", "0", "1",
     lambda: 2 - mp.pi ** 2 / 6, lambda: mpmath.quad(lambda x: mpmath.log(x) * mpmath.log(1 - x), [0, 1])),
    ("rsqrt_cos", "int_0^1 x^(-1/2) cos(x) dx = sqrt(2 pi) C(sqrt(2/pi))", "x^(-1/2)*cos(x)", "0", "1",
     lambda: mpmath.sqrt(2 * mp.pi) * mpmath.fresnelc(mpmath.sqrt(2 / mp.pi)),
     lambda: mpmath.quad(lambda x: mpmath.cos(x) / mpmath.sqrt(x), [0, 1])),
    ("atan_recip", "int_0^1 atan(1/x) dx = pi/4 + log(2)/2", "atan(1/x)", "0", "1",
     lambda: mp.pi / 4 + mpmath.log(2) / 2, lambda: mpmath.quad(lambda x: mpmath.atan(1 / x), [0, 1])),
    ("rsqrt_both", "int_0^1 x^(-1/2) (1-x)^(-1/2) dx = pi", "x^(-1/2)*(1-x)^(-1/2)", "0", "1",
     lambda: +mp.pi, lambda: mpmath.quad(lambda x: 1 / mpmath.sqrt(x * (1 - x)), [0, 0.5, 1])),
    ("sinc_mid", "int_0^1 sin(x-1/2)/(x-1/2) dx = 2 Si(1/2) (removable point inside)", "sin(x-0.5)/(x-0.5)", "0", "1",
     lambda: 2 * mpmath.si(mpf(1) / 2), lambda: mpmath.quad(lambda x: mpmath.sinc(x - mpf(1) / 2), [0, 0.5, 1])),
    # removable points that need the local classes of 1 - e^g and 1 - cos g, and a
    # quotient by a square (issue 40 follow-up)
    ("one_minus_expm_over_x", "int_0^1 (1-exp(-x))/x dx = Ein(1) = gamma + E1(1)", "(1-exp(-x))/x", "0", "1",
     lambda: mp.euler + mpmath.e1(1), lambda: mpmath.quad(lambda x: -mpmath.expm1(-x) / x, [0, 1])),
    ("one_minus_cos_over_x2", "int_0^1 (1-cos(x))/x^2 dx = Si(1) + cos(1) - 1", "(1-cos(x))/x^2", "0", "1",
     lambda: mpmath.si(1) + mpmath.cos(1) - 1, lambda: mpmath.quad(lambda x: 2 * mpmath.sin(x / 2) ** 2 / x ** 2, [0, 1])),
    # removable points with two, four and three orders of cancellation, found by the
    # exact values of N, N', ... at the point (quad/expr/removable.rs); the first by parts,
    # int (e^x-1-x)/x^2 = [-(e^x-1-x)/x]_0^1 + int_0^1 (e^x-1)/x, the second by its
    # Taylor series term by term, sum_{n>=2} (-1)^n / ((2n)! (2n-3)), the third likewise
    ("expm1_minus_x_over_x2", "int_0^1 (exp(x)-1-x)/x^2 dx = 2 - e + Ei(1) - gamma", "(exp(x)-1-x)/x^2", "0", "1",
     lambda: 2 - mp.e + mpmath.ei(1) - mp.euler,
     lambda: mpmath.quad(lambda x: (mpmath.expm1(x) - x) / x ** 2 if x > mpf(10) ** -4 else mpf(1) / 2 + x / 6 + x ** 2 / 24, [0, 1])),
    ("cos_taylor4_over_x4", "int_0^1 (cos(x)-1+x^2/2)/x^4 dx = sum_{n>=2} (-1)^n / ((2n)! (2n-3))", "(cos(x)-1+x^2/2)/x^4", "0", "1",
     lambda: cos_taylor4_series(),
     lambda: mpmath.quad(lambda x: (mpmath.cos(x) - 1 + x ** 2 / 2) / x ** 4 if x > mpf(1) / 100 else mpf(1) / 24 - x ** 2 / 720 + x ** 4 / 40320, [0, 1])),
    ("sin_pi_taylor2_over_x3", "int_0^1 (sin(pi x)-pi x)/x^3 dx = sum_{n>=1} (-1)^n pi^(2n+1) / ((2n+1)! (2n-1))",
     "(sin(pi*x)-pi*x)/x^3", "0", "1", lambda: sin_pi_taylor2_series(),
     lambda: mpmath.quad(lambda x: (mpmath.sin(mp.pi * x) - mp.pi * x) / x ** 3 if x > mpf(1) / 100 else -mp.pi ** 3 / 6 + mp.pi ** 5 * x ** 2 / 120 - mp.pi ** 7 * x ** 4 / 5040, [0, 1])),
    # by parts, then u = sqrt(1+x): 3/2 - sqrt(2) - log((1 + sqrt(2))/2)
    ("sqrt_taylor2_over_x2", "int_0^1 (sqrt(1+x)-1-x/2)/x^2 dx = 3/2 - sqrt(2) - log((1+sqrt(2))/2)",
     "(sqrt(1+x)-1-x/2)/x^2", "0", "1", lambda: mpf(3) / 2 - mpmath.sqrt(2) - mpmath.log((1 + mpmath.sqrt(2)) / 2),
     lambda: mpmath.quad(lambda x: (mpmath.sqrt(1 + x) - 1 - x / 2) / x ** 2 if x > mpf(1) / 10000 else -mpf(1) / 8 + x / 16 - 5 * x ** 2 / 128, [0, 1])),
    # issue 40's table: a narrow peak on a long range (refused at 2 bits before), and a
    # shifted Lorentzian to infinity (a radius of 125 at 8 to 53 bits with a declared decay)
    ("lorentz_narrow", "int_1^10000 1/((x-5)^2+0.01) dx = 10 (atan(99950) + atan(40))", "1/((x-5)^2+0.01)", "1", "10000",
     lambda: 10 * (mpmath.atan(99950) + mpmath.atan(40)),
     lambda: mpmath.quad(lambda x: 1 / ((x - 5) ** 2 + mpf(1) / 100), [1, 4, 5, 6, 100, 10000])),
    ("lorentz_shift_tail", "int_1^inf 1/((x-5)^2+1) dx = pi/2 + atan(4)", "1/((x-5)^2+1)", "1", "inf",
     lambda: mp.pi / 2 + mpmath.atan(4),
     lambda: mpmath.quad(lambda x: 1 / ((x - 5) ** 2 + 1), [1, 5, 100, mpmath.inf])),
]


def closed(form):
    with mp.workdps(OUT_DIGITS + 20):
        v1 = form()
    with mp.workdps(OUT_DIGITS + 60):
        v2 = form()
        if abs(v1 - v2) > abs(v2) * mpf(10) ** -(OUT_DIGITS + 5):
            raise SystemExit("closed form unstable")
    with mp.workdps(OUT_DIGITS + 20):
        return mpmath.nstr(v2, OUT_DIGITS, strip_zeros=False)


def main():
    rows = []
    for ident, desc, expr, a, b, form, check in INTEGRALS:
        value = closed(form)
        with mp.workdps(CHECK_DPS):
            est = check()
            if abs(est - mpf(value)) > abs(mpf(value)) * mpf(10) ** -10:
                sys.exit(f"{ident}: closed form {value[:30]} disagrees with the estimate {est}")
        rows.append((ident, desc, expr, a, b, value))
    with open(OUT, "w", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(["id", "description", "expression", "a", "b", "value"])
        w.writerows(rows)
    print(f"wrote {len(rows)} rows to {OUT}")


if __name__ == "__main__":
    main()
