#!/usr/bin/env python3
"""Golden values for the certified integrator (issue 22, item 7).

Usage:  python3 reference/generate_integrals.py

Writes reference/data/integrals.csv: the closed-form values of the test integrals
of F. Johansson's Arb example `examples/integrals.c` (the "I-series") that have a
closed form in the functions the integrator offers, plus a few extra analytic
integrals used by the speed comparison against Arb (reference/bench_integrals.sh).

Columns: id, description, value.  `id` is I<n> for Arb's integral number n and
X<name> for the extras; `value` is the exact integral to OUT_DIGITS significant
digits (3500 digits, about 11600 bits: enough for the 3333-bit golden test with a
wide margin).  The integrands themselves live next to their ids in
tests/it/certified_golden.rs.

Every value is computed from its closed form twice, at mp.dps = OUT_DIGITS + 20 and
OUT_DIGITS + 60, and kept only when the two agree to OUT_DIGITS + 5 digits; it is
then cross-checked against mpmath.quad at 40 digits (an independent estimate,
not a proof: the check is only that the closed form was typed correctly).  A
disagreement aborts the run.  The output depends only on mpmath 1.3.0 (pinned in
requirements.txt) and is byte-identical between runs.  A run takes a few seconds.
"""

import csv
import os
import sys

import mpmath
from mpmath import mp, mpf

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "data")
OUT_DIGITS = 3500
CHECK_DPS = 40


def spike_antiderivative(x):
    """Antiderivative of sech(10(x-1/5))^2 + sech(100(x-2/5))^4 + sech(1000(x-3/5))^6."""
    t1 = mpmath.tanh(10 * (x - mpf(1) / 5))
    t2 = mpmath.tanh(100 * (x - mpf(2) / 5))
    t3 = mpmath.tanh(1000 * (x - mpf(3) / 5))
    return t1 / 10 + (t2 - t2**3 / 3) / 100 + (t3 - 2 * t3**3 / 3 + t3**5 / 5) / 1000


# (id, description, closed form (a function of nothing, evaluated at mp.dps),
#  independent check by mpmath.quad at CHECK_DPS digits)
INTEGRALS = [
    ("I0", "int_0^100 sin(x) dx = 1 - cos(100)",
     lambda: 1 - mpmath.cos(100),
     lambda: mpmath.quad(mpmath.sin, mpmath.linspace(0, 100, 40))),
    ("I1", "4 int_0^1 1/(1+x^2) dx = pi",
     lambda: +mp.pi,
     lambda: 4 * mpmath.quad(lambda x: 1 / (1 + x * x), [0, 1])),
    ("I2", "2 int_0^inf 1/(1+x^2) dx = pi (declared decay |f| <= x^-2 on [1, inf))",
     lambda: +mp.pi,
     lambda: 2 * mpmath.quad(lambda x: 1 / (1 + x * x), [0, 1, mpmath.inf])),
    ("I3", "4 int_0^1 sqrt(1-x^2) dx = pi (weight (1-x)^(1/2), g = sqrt(1+x))",
     lambda: +mp.pi,
     lambda: 4 * mpmath.quad(lambda x: mpmath.sqrt(1 - x * x), [0, 1])),
    ("I10", "int_0^10000 x^1000 exp(-x) dx = lower incomplete gamma(1001, 10000)",
     lambda: mpmath.gammainc(1001, 0, 10000),
     lambda: mpmath.quad(lambda x: x**1000 * mpmath.exp(-x), [0, 500, 900, 1000, 1100, 1500, 3000, 10000])),
    ("I12", "int_{-10}^{10} sin(x) + exp(-200-x^2) dx = e^-200 sqrt(pi) erf(10)",
     lambda: mpmath.exp(-200) * mpmath.sqrt(mp.pi) * mpmath.erf(10),
     # mpmath.quad's error test is absolute: integrate exp(-x^2), then scale
     lambda: mpmath.exp(-200) * mpmath.quad(lambda x: mpmath.exp(-x * x), [-10, 0, 10])),
    ("I13", "int_{-1020}^{-1010} exp(x) dx = e^-1010 - e^-1020",
     lambda: mpmath.exp(-1010) - mpmath.exp(-1020),
     lambda: mpmath.exp(-1010) * mpmath.quad(mpmath.exp, [-10, 0])),
    ("I14", "int_0^inf exp(-x^2) dx = sqrt(pi)/2 (declared decay |f| <= 3 e^(-2x))",
     lambda: mpmath.sqrt(mp.pi) / 2,
     lambda: mpmath.quad(lambda x: mpmath.exp(-x * x), [0, mpmath.inf])),
    ("I15", "int_0^1 sech(10(x-0.2))^2 + sech(100(x-0.4))^4 + sech(1000(x-0.6))^6 dx",
     lambda: spike_antiderivative(mpf(1)) - spike_antiderivative(mpf(0)),
     lambda: mpmath.quad(lambda x: mpmath.sech(10 * (x - mpf(1) / 5))**2 + mpmath.sech(100 * (x - mpf(2) / 5))**4
                         + mpmath.sech(1000 * (x - mpf(3) / 5))**6,
                         sorted(set(mpmath.linspace(0, 1, 101) + mpmath.linspace(0.35, 0.45, 101)
                                    + mpmath.linspace(0.58, 0.62, 401))))),
    ("I17", "int_0^inf sech(x) dx = pi/2 (declared decay |f| <= 2 e^-x)",
     lambda: mp.pi / 2,
     lambda: mpmath.quad(mpmath.sech, [0, mpmath.inf])),
    ("I18", "int_0^inf sech(x)^3 dx = pi/4 (declared decay |f| <= 8 e^(-3x))",
     lambda: mp.pi / 4,
     lambda: mpmath.quad(lambda x: mpmath.sech(x)**3, [0, mpmath.inf])),
    ("I19", "int_0^1 -log(x)/(1+x) dx = pi^2/12 (weight log(x), g = -1/(1+x))",
     lambda: mp.pi**2 / 12,
     lambda: mpmath.quad(lambda x: -mpmath.log(x) / (1 + x), [0, 1])),
    ("I20", "int_0^inf x exp(-x)/(1+exp(-x)) dx = pi^2/12 (declared decay |f| <= e^(-x/2))",
     lambda: mp.pi**2 / 12,
     lambda: mpmath.quad(lambda x: x * mpmath.exp(-x) / (1 + mpmath.exp(-x)), [0, mpmath.inf])),
    ("I24", "int_0^pi max(sin(x), cos(x)) dx = 1 + sqrt(2) (split at pi/4: cos, then sin)",
     lambda: 1 + mpmath.sqrt(2),
     lambda: mpmath.quad(lambda x: max(mpmath.sin(x), mpmath.cos(x)), [0, mp.pi / 4, mp.pi])),
    ("I31", "int_0^pi x sin(x) / (1 + cos(x)^2) dx = pi^2/4",
     lambda: mp.pi**2 / 4,
     lambda: mpmath.quad(lambda x: x * mpmath.sin(x) / (1 + mpmath.cos(x)**2), [0, mp.pi / 2, mp.pi])),
    ("Xexp", "int_0^1 exp(x) dx = e - 1",
     lambda: mpmath.e - 1,
     lambda: mpmath.quad(mpmath.exp, [0, 1])),
    ("Xsqrt", "int_1^4 sqrt(x) dx = 14/3",
     lambda: mpf(14) / 3,
     lambda: mpmath.quad(mpmath.sqrt, [1, 4])),
    ("XxJ0", "int_0^1 x J_0(x) dx = J_1(1)",
     lambda: mpmath.besselj(1, 1),
     lambda: mpmath.quad(lambda x: x * mpmath.besselj(0, x), [0, 1])),
    ("Xatan", "int_0^1 atan(x) dx = pi/4 - log(2)/2",
     lambda: mp.pi / 4 - mpmath.log(2) / 2,
     lambda: mpmath.quad(mpmath.atan, [0, 1])),
    ("Xcos_rsqrt", "int_0^1 x^(-1/2) cos(x) dx = sqrt(2 pi) C(sqrt(2/pi)) (weight x^(-1/2), g = cos; C Fresnel's integral)",
     lambda: mpmath.sqrt(2 * mp.pi) * mpmath.fresnelc(mpmath.sqrt(2 / mp.pi)),
     # x = u^2: int_0^1 2 cos(u^2) du, no endpoint singularity for the check
     lambda: 2 * mpmath.quad(lambda u: mpmath.cos(u * u), [0, 1])),
]


def main():
    os.makedirs(DATA, exist_ok=True)
    rows = []
    for ident, descr, closed, check in INTEGRALS:
        with mp.workdps(OUT_DIGITS + 20):
            v1 = closed()
        with mp.workdps(OUT_DIGITS + 60):
            v2 = closed()
            if abs(v1 - v2) > abs(v2) * mpf(10) ** -(OUT_DIGITS + 5):
                sys.exit(f"{ident}: the closed form does not agree with itself at two precisions")
            text = mpmath.nstr(v2, OUT_DIGITS, min_fixed=1, max_fixed=0)
        with mp.workdps(CHECK_DPS):
            q = check()
            exact = mpf(text)
            rel = abs(q - exact) / abs(exact)
            if rel > mpf(10) ** -(CHECK_DPS - 12):
                sys.exit(f"{ident}: mpmath.quad gives {q}, the closed form {exact} (relative {rel})")
        sys.stderr.write(f"{ident}: ok (quad check relative {mpmath.nstr(rel, 3)})\n")
        rows.append((ident, descr, text))
    path = os.path.join(DATA, "integrals.csv")
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(["id", "description", "value"])
        w.writerows(rows)
    sys.stderr.write(f"wrote {len(rows)} rows to {path}\n")


if __name__ == "__main__":
    main()
