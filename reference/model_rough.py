#!/usr/bin/env python3
"""Golden values of the model on a rough profile: the strip ratio m (first root
of Eq. 15b, corrected) and the load (Eq. 14) at decimal inputs with beta =
"0.001", where D = 2 pi abar/beta is about 6283 (issue 23).

generate.py's model_decimal route sums mpmath.besselj order by order, thousands
of calls at D ~ 6283 for every evaluation of F. Here J_0(D) .. J_N(D) come from
Miller's backward recurrence J_{n-1} = (2n/D) J_n - J_{n+1} [DLMF 10.6.1],
normalised by J_0 + 2 sum_k J_2k = 1 [DLMF 10.12.4], started far above the
turning point; the sequence's J_0, J_1 are checked against mpmath.besselj.
Each row is computed at two precisions with two different start orders and kept
iff both runs agree to OUT_DIGITS + 20 digits. Independent of the Rust code
(which uses a forward recurrence below the turning point and a ratio walk above).

Usage:  python3 reference/model_rough.py      -> reference/data/model_rough.csv
"""
import os
import sys
import time

import mpmath
from mpmath import mp, mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import generate  # noqa: E402  (the model's root search, shared with model_decimal)

BITS = (450, 600)
OUT_DIGITS = 100
INPUTS = [("2.5", "2.5", "0.001", "1"), ("1", "0.3535533905932737622004221810524245196424", "0.001", "1.5")]


def log(msg):
    print(msg, file=sys.stderr, flush=True)


def miller(nmax, d, margin_factor):
    """J_0(d) .. J_nmax(d) at the current precision (d > 0)."""
    bits = mp.prec
    extra = int(margin_factor * (4 * float(d) ** (1.0 / 3.0) * bits ** (2.0 / 3.0) + 60))
    top = max(nmax, int(d)) + extra
    top += top % 2  # even start, so the normalisation sum is simple
    vals = [mpf(0)] * (nmax + 1)
    j_next, j = mpf(0), mpf(2) ** (-bits)
    norm = 2 * j  # top is even
    two_over_d = 2 / d
    for n in range(top, 0, -1):
        j_prev = n * two_over_d * j - j_next
        j_next, j = j, j_prev
        k = n - 1
        if k <= nmax:
            vals[k] = j
        if k % 2 == 0:
            norm += j if k == 0 else 2 * j
    return [v / norm for v in vals]


class Model:
    """F(m) and the load at one precision, with one Miller margin."""

    def __init__(self, args, margin_factor):
        self.lam, self.alpha, self.beta, self.abar = (mpf(v) for v in args)
        self.d = 2 * mpmath.pi * self.abar / self.beta
        # past the turning point J_n(D) falls below 2^-(prec + 40) well before this order
        nmax = int(self.d) + int(3 * float(self.d) ** (1.0 / 3.0) * mp.prec ** (2.0 / 3.0)) + 40
        self.j = miller(nmax, self.d, margin_factor)
        if not abs(self.j[-1]) < mpf(2) ** (-mp.prec - 40):
            raise ValueError("sequence too short: J_%d = %s" % (nmax, mpmath.nstr(self.j[-1], 5)))

    def wave(self, x):
        """u_w(x) by the Bessel form of docs/displacement.md, Route 2."""
        r = x / self.abar
        q = 1 / (r + mpmath.sqrt((r - 1) * (r + 1)))
        su = mpf(0)
        q2 = q * q
        qp = mpf(1)
        for n in range(1, (len(self.j) - 1) // 2 + 1):
            qp *= q2
            su += (1 if n % 2 == 1 else -1) * self.j[2 * n] * qp
        j0, j1 = self.j[0], self.j[1]
        return self.alpha * (1 - j0 + self.d * j1 * mpmath.acosh(r) + 2 * su)

    def residual(self, e):
        m = 1 + e
        s = mpmath.sqrt(e * (e + 2))
        acosh_m = mpmath.acosh(m)
        hertz = self.abar ** 2 / 2 * (m * s - acosh_m)
        adhesive = 4 / mpmath.pi * self.lam * self.abar * (s * acosh_m - m * mpmath.log(m))
        wave = 2 * self.alpha * mpmath.sin(mpmath.pi * m * self.abar / self.beta) ** 2 - self.wave(m * self.abar)
        return self.lam * (hertz + adhesive + wave) - 1

    def load(self, m):
        return (mpmath.pi * self.abar ** 2 / 4 - 2 * self.lam * self.abar * mpmath.sqrt(m * m - 1)
                + mpmath.pi ** 2 * self.alpha * self.abar / self.beta * self.j[1])


def first_root(args, bits, margin_factor):
    """generate.py's root search (a scan and bisection at 80 bits, the secant
    method and a sign change at `bits`) on F with this file's J_n, and the load."""
    models = {}

    def residual(lam, alpha, beta, abar, e):
        if mp.prec not in models:  # one sequence per precision (it depends on D only)
            models[mp.prec] = Model(args, margin_factor)
        return models[mp.prec].residual(e)

    mp.prec = bits
    root = generate.model_first_root(args, residual)
    model = models[bits]
    for k in (0, 1):
        if not abs(model.j[k] - mpmath.besselj(k, model.d)) < mpf(2) ** (-bits + 16):
            raise ValueError("Miller J_%d disagrees with mpmath.besselj" % k)
    return root, model.load(1 + root)


def main():
    rows = []
    for args in INPUTS:
        t0 = time.time()
        vals = [first_root(args, bits, margin) for bits, margin in zip(BITS, (1.0, 1.3))]
        mp.prec = BITS[1]
        (e0, l0), (e1, l1) = vals
        tol = mpf(10) ** -(OUT_DIGITS + 20)
        if not (abs(e0 - e1) < tol * abs(e1) and abs(l0 - l1) < tol * max(abs(l1), 1)):
            log("model_rough: reject %s" % (args,))
            continue
        fmt = lambda v: mpmath.nstr(v, OUT_DIGITS, min_fixed=1, max_fixed=0)
        rows.append(args + (fmt(1 + e1), fmt(e1), fmt(l1)))
        log("model_rough: %s m - 1 = %s, load = %s [%.0f s]" % (args, mpmath.nstr(e1, 12), mpmath.nstr(l1, 12), time.time() - t0))
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "model_rough.csv")
    with open(path, "w") as f:
        f.write("# maugis reference table model_rough, generated by reference/model_rough.py\n")
        f.write("# mpmath %s (backend %s), Python %s\n" % (mpmath.__version__, mpmath.libmp.BACKEND, sys.version.split()[0]))
        f.write("# the strip ratio m (first root of Eq. 15b, corrected) and the load (Eq. 14) at the DECIMALS as typed, beta = 0.001 (D ~ 6283);\n")
        f.write("# J_n(D) by Miller's recurrence normalised by J_0 + 2 sum J_2k = 1; at %d and %d bits with different start orders,\n" % BITS)
        f.write("# kept iff they agree to %d digits; %d digits printed\n" % (OUT_DIGITS + 20, OUT_DIGITS))
        f.write("lambda,alpha,beta,abar,m,m_minus_1,load\n")
        for r in rows:
            f.write(",".join(r) + "\n")
    log("wrote %s (%d rows)" % (path, len(rows)))


if __name__ == "__main__":
    main()
