#!/usr/bin/env python3
"""Golden values for integrals to infinity without a declared decay (issue 36).

Usage:  python3 reference/generate_infinite_integrals.py

Writes reference/data/integrals_infinite.csv: id, description, expression (as the
tests pass it to the integrator), a, b, value.  Each value is its closed form
computed at mp.dps = OUT_DIGITS + 20 and OUT_DIGITS + 60 and kept only when the two
agree to OUT_DIGITS + 5 digits; it is then cross-checked against mpmath's quad or
quadosc at CHECK_DPS digits (an estimate: the check is only that the closed form
was typed correctly).  A disagreement aborts the run.  Depends only on mpmath
(pinned in requirements.txt); the output is byte-identical between runs.
"""

import csv
import os
import sys

import mpmath
from mpmath import mp, mpf

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "data", "integrals_infinite.csv")
OUT_DIGITS = 400
CHECK_DPS = 25
inf = mpmath.inf


def osc(f, period):
    return lambda: mpmath.quadosc(f, [0, inf], period=period)


# (id, description, expression, a, b, closed form, independent estimate)
INTEGRALS = [
    ("exp_over_1px", "int_0^inf exp(-x)/(1+x) dx = e E1(1)", "exp(-x)/(1+x)", "0", "inf",
     lambda: mpmath.e * mpmath.e1(1),
     lambda: mpmath.quad(lambda x: mpmath.exp(-x) / (1 + x), [0, inf])),
    ("x2_gauss", "int_-inf^inf x^2 exp(-x^2) dx = sqrt(pi)/2", "x^2*exp(-x^2)", "-inf", "inf",
     lambda: mpmath.sqrt(mp.pi) / 2,
     lambda: mpmath.quad(lambda x: x * x * mpmath.exp(-x * x), [-inf, inf])),
    ("lorentz_half", "int_0^inf 1/(1+x^2) dx = pi/2", "1/(1+x^2)", "0", "inf",
     lambda: mp.pi / 2,
     lambda: mpmath.quad(lambda x: 1 / (1 + x * x), [0, inf])),
    ("x_exp_sin", "int_0^inf x exp(-x) sin(x) dx = 1/2", "x*exp(-x)*sin(x)", "0", "inf",
     lambda: mpf(1) / 2,
     lambda: mpmath.quad(lambda x: x * mpmath.exp(-x) * mpmath.sin(x), [0, inf])),
    ("gauss_left", "int_-inf^1 exp(-x^2) dx = sqrt(pi)(1 + erf(1))/2", "exp(-x^2)", "-inf", "1",
     lambda: mpmath.sqrt(mp.pi) * (1 + mpmath.erf(1)) / 2,
     lambda: mpmath.quad(lambda x: mpmath.exp(-x * x), [-inf, 0, 1])),
    ("sech2", "int_0^inf sech(x)^2 dx = 1", "sech(x)^2", "0", "inf",
     lambda: mpf(1),
     lambda: mpmath.quad(lambda x: mpmath.sech(x) ** 2, [0, inf])),
    ("rsqrt_cube", "int_1^inf x^(-3/2) dx = 2", "x^(-3/2)", "1", "inf",
     lambda: mpf(2),
     lambda: mpmath.quad(lambda x: x ** mpf(-1.5), [1, inf])),
    ("exp_sqrt", "int_0^inf exp(-sqrt(x)) dx = 2", "exp(-sqrt(x))", "0", "inf",
     lambda: mpf(2),
     lambda: mpmath.quad(lambda x: mpmath.exp(-mpmath.sqrt(x)), [0, inf])),
    ("exp_sinc", "int_0^inf exp(-x) sin(x)/x dx = atan(1) = pi/4", "exp(-x)*sin(x)/x", "0", "inf",
     lambda: mp.pi / 4,
     lambda: mpmath.quad(lambda x: mpmath.exp(-x) * mpmath.sinc(x), [0, inf])),
    ("exp_log", "int_0^inf exp(-x) log(x) dx = -gamma", "exp(-x)*log(x)", "0", "inf",
     lambda: -mp.euler,
     lambda: mpmath.quad(lambda x: mpmath.exp(-x) * mpmath.log(x), [0, 1, inf])),
    ("exp_one_minus_cos", "int_0^inf exp(-x) (1-cos(x))/x^2 dx = pi/4 - log(2)/2", "exp(-x)*(1-cos(x))/x^2", "0", "inf",
     lambda: mp.pi / 4 - mpmath.log(2) / 2,
     lambda: mpmath.quad(lambda x: mpmath.exp(-x) * 2 * mpmath.sin(x / 2) ** 2 / x ** 2, [0, inf])),
    ("sinc", "int_0^inf sin(x)/x dx = pi/2", "sin(x)/x", "0", "inf",
     lambda: mp.pi / 2,
     osc(lambda x: mpmath.sin(x) / x, 2 * mp.pi)),
    ("j0", "int_0^inf J_0(x) dx = 1", "besselj(0, x)", "0", "inf",
     lambda: mpf(1),
     osc(lambda x: mpmath.besselj(0, x), 2 * mp.pi)),
    ("cos_lorentz", "int_0^inf cos(x)/(1+x^2) dx = pi/(2e)", "cos(x)/(1+x^2)", "0", "inf",
     lambda: mp.pi / (2 * mpmath.e),
     osc(lambda x: mpmath.cos(x) / (1 + x * x), 2 * mp.pi)),
]
# sums with oscillatory terms (`quad/expr/oscillatory_sum.rs`)
INTEGRALS += [
    ("one_minus_cos_sq", "int_0^inf (1-cos(x))/x^2 dx = pi/2", "(1-cos(x))/x^2", "0", "inf",
     lambda: mp.pi / 2,
     # quadosc extrapolates poorly past the non-oscillating 1/x^2: [0, 1] by quad,
     # int_1^inf x^-2 = 1, and the cos(x)/x^2 tail by quadosc
     lambda: (mpmath.quad(lambda x: 2 * mpmath.sin(x / 2) ** 2 / x ** 2, [0, 1]) + 1
              - mpmath.quadosc(lambda x: mpmath.cos(x) / x ** 2, [1, inf], period=2 * mp.pi))),
    ("x_minus_sin_cube", "int_0^inf (x-sin(x))/x^3 dx = pi/4", "(x-sin(x))/x^3", "0", "inf",
     lambda: mp.pi / 4,
     lambda: (mpmath.quad(lambda x: (x - mpmath.sin(x)) / x ** 3, [0, 1]) + 1
              - mpmath.quadosc(lambda x: mpmath.sin(x) / x ** 3, [1, inf], period=2 * mp.pi))),
    ("sinc_plus_lorentz", "int_0^inf (sin(x)/x + 1/(1+x^2)) dx = pi", "sin(x)/x + 1/(1+x^2)", "0", "inf",
     lambda: mp.pi,
     lambda: (mpmath.quadosc(mpmath.sinc, [0, inf], period=2 * mp.pi)
              + mpmath.quad(lambda x: 1 / (1 + x * x), [0, inf]))),
    ("one_minus_cos_full", "int_-inf^inf (1-cos(x))/x^2 dx = pi", "(1-cos(x))/x^2", "-inf", "inf",
     lambda: mp.pi,
     lambda: 2 * (mpmath.quad(lambda x: 2 * mpmath.sin(x / 2) ** 2 / x ** 2, [0, 1]) + 1
                  - mpmath.quadosc(lambda x: mpmath.cos(x) / x ** 2, [1, inf], period=2 * mp.pi))),
    ("sin2_sq", "int_0^inf sin(x)^2/x^2 dx = pi/2", "sin(x)^2/x^2", "0", "inf",
     lambda: mp.pi / 2,
     lambda: (mpmath.quad(lambda x: mpmath.sinc(x) ** 2, [0, 1]) + mpf(1) / 2
              - mpmath.quadosc(lambda x: mpmath.cos(2 * x) / (2 * x ** 2), [1, inf], period=mp.pi))),
    ("sin2_lorentz", "int_0^inf sin(x)^2/(1+x^2) dx = pi (1 - e^-2)/4", "sin(x)^2/(1+x^2)", "0", "inf",
     lambda: mp.pi * (1 - mpmath.exp(-2)) / 4,
     lambda: (mpmath.quad(lambda x: 1 / (1 + x * x), [0, inf])
              - mpmath.quadosc(lambda x: mpmath.cos(2 * x) / (1 + x * x), [0, inf], period=mp.pi)) / 2),
    ("cos_lorentz_full", "int_-inf^inf cos(x)/(1+x^2) dx = pi/e", "cos(x)/(1+x^2)", "-inf", "inf",
     lambda: mp.pi / mpmath.e,
     lambda: 2 * mpmath.quadosc(lambda x: mpmath.cos(x) / (1 + x * x), [0, inf], period=2 * mp.pi)),
]
for k in ["0.5", "1", "5"]:
    INTEGRALS.append((
        f"hankel_k{k}", f"int_0^inf x J_0({k} x)/(x^2+1)^(3/2) dx = e^-{k}",
        f"x*besselj(0, {k}*x)/(x^2+1)^(3/2)", "0", "inf",
        (lambda k=k: mpmath.exp(-mpf(k))),
        (lambda k=k: mpmath.quadosc(lambda x: x * mpmath.besselj(0, mpf(k) * x) / (x * x + 1) ** mpf(1.5),
                                    [0, inf], period=2 * mp.pi / mpf(k)))))
INTEGRALS.append((
    "j1_rsqrt", "int_0^inf J_1(x)/sqrt(x) dx = Gamma(3/4)/(sqrt(2) Gamma(5/4)) (DLMF 10.22.43)",
    "besselj(1, x)/sqrt(x)", "0", "inf",
    lambda: mpmath.gamma(mpf(3) / 4) / (mpmath.sqrt(2) * mpmath.gamma(mpf(5) / 4)),
    osc(lambda x: mpmath.besselj(1, x) / mpmath.sqrt(x), 2 * mp.pi)))


def closed(form):
    with mp.workdps(OUT_DIGITS + 20):
        v1 = form()
    with mp.workdps(OUT_DIGITS + 60):
        v2 = form()
    with mp.workdps(OUT_DIGITS + 60):
        if abs(v1 - v2) > abs(v2) * mpf(10) ** -(OUT_DIGITS + 5):
            raise SystemExit("closed form unstable")
    with mp.workdps(OUT_DIGITS + 20):
        return mpmath.nstr(v2, OUT_DIGITS, strip_zeros=False, min_fixed=1, max_fixed=0)


def main():
    rows = []
    for ident, desc, expr, a, b, form, check in INTEGRALS:
        value = closed(form)
        with mp.workdps(CHECK_DPS):
            est = check()
            if abs(est - mpf(value)) > abs(mpf(value)) * mpf(10) ** -6:
                sys.exit(f"{ident}: closed form {value[:30]} disagrees with the estimate {est}")
        rows.append((ident, desc, expr, a, b, value))
    with open(OUT, "w", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(["id", "description", "expression", "a", "b", "value"])
        w.writerows(rows)
    print(f"wrote {len(rows)} rows to {OUT}")


if __name__ == "__main__":
    main()
