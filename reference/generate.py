#!/usr/bin/env python3
"""Reference-table generator for the `maugis` crate.

Usage:  python3 reference/generate.py [--jobs N] [--only bessel_j,hyp1f2,...]

Regenerates reference/data/{bessel_j,hyp1f2,hyp2f1,meijer_g_k}.csv
deterministically (fixed seeds; the output depends only on the inputs and on
mpmath 1.3.0).  See reference/README.md for the full description.

Every reference value is computed twice, at two working precisions
(tier 1: mp.dps = 70 and 95).  A point is kept only if the two results agree to
>= 52 significant digits (relative; an absolute test against a natural scale
is used only for the Meijer-G table, where the value crosses zero).  If tier 1
disagrees, the point is retried once at tier 2 (mp.dps = 110 and 140); if
that also disagrees the point is rejected and counted.  Values are written
with 50 significant digits from the higher-precision result.

In addition, wherever an *independent* algorithm is cheap, the kept value is
cross-checked against it (direct power series with rigorous adaptive
precision, Euler integrals via mpmath.quad, closed forms).  A disagreement of
a cross-check rejects the point (and is reported); for the Meijer-G table the
overlap checks are assertions that abort the run.
"""

import argparse
import decimal
import math
import multiprocessing as mproc
import os
import random
import signal
import sys
import time
from fractions import Fraction

import mpmath
from mpmath import mp, mpf

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "data")

SEED = 20240611
TIERS = [(70, 95), (110, 140)]
AGREE_DIGITS = 52
OUT_DIGITS = 50
TASK_TIMEOUT = 240  # seconds, safety net only (never triggered in the reference run)
BIG = dict(maxterms=10**6, maxprec=10**6)

# --------------------------------------------------------------------------
# small helpers
# --------------------------------------------------------------------------


def log(msg):
    sys.stderr.write(msg + "\n")
    sys.stderr.flush()


def mpf_to_fraction(v):
    sign, man, exp, _bc = mpf(v)._mpf_
    if man == 0:
        return Fraction(0)
    f = Fraction(int(man)) * (Fraction(2) ** exp)
    return -f if sign else f


def nearest_float(v):
    """Round an mpf (or Fraction) to the nearest IEEE double (ties-to-even)."""
    if not isinstance(v, Fraction):
        v = mpf_to_fraction(v)
    return float(v)  # float(Fraction) is correctly rounded


def one_minus_ten_pow(j):
    """1 - 10^-j correctly rounded to a double."""
    return float(Fraction(1) - Fraction(1, 10**j))


def fmt_in(x):
    if isinstance(x, int):
        return str(x)
    r = repr(float(x))
    assert float(r) == x
    return r


def fmt_val(v):
    s = mpmath.nstr(v, OUT_DIGITS, min_fixed=1, max_fixed=0)
    if "e" not in s:
        s = s + "e0"
    s = s.replace("e+", "e")
    return s


def agree(v1, v2, scale=None, digits=AGREE_DIGITS):
    if v1 == v2:
        return True
    if not (mpmath.isfinite(v1) and mpmath.isfinite(v2)):
        return False
    ref = abs(v2)
    if scale is not None:
        ref = max(ref, abs(scale))
    return abs(v1 - v2) <= ref * mpf(10) ** (-digits)


def as_real(v):
    if isinstance(v, mpmath.mpc):
        if v.imag != 0:
            raise ValueError("unexpected non-real result %s" % v)
        return v.real
    return v


def dyadic(rng, lo, hi, bits):
    """Random dyadic rational k/2^bits in [lo, hi]."""
    q = 2**bits
    k = rng.randint(math.ceil(lo * q), math.floor(hi * q))
    return k / q


def loguni(rng, lo, hi):
    return 10.0 ** rng.uniform(math.log10(lo), math.log10(hi))


class Timeout(Exception):
    pass


def _alarm(signum, frame):
    raise Timeout()


# --------------------------------------------------------------------------
# independent algorithm 1: direct power series with rigorous adaptive precision
# --------------------------------------------------------------------------


def direct_series(a_list, b_list, z, target_bits=200, max_terms=400000):
    """sum_n prod (a_i)_n / prod (b_j)_n * z^n / n!  by plain summation.

    a_list, b_list, z must be exact mpf/int values, all b_j > 0, and either
    p <= q, or p = q + 1 with |z| < 1, or some a_i a non-positive integer.
    The working precision is raised until the rounding-error bound
        (sum_n |t_n|) * 2^-wp * (N+1) * (p+q+4)  +  tail bound
    is below 2^-target_bits * |sum|.  The tail bound uses
        sup_{n>=N} |t_{n+1}/t_n| <= R_N = |z| prod_pairs max(1, (|a_i|+N)/(b_j+N)) prod_unpaired 1/(b_j+N)
    (a's paired with the b's and with the 1 of n!, largest with largest),
    valid because each (|a|+n)/(b+n) is monotone in n and tends to 1.
    """
    p, q = len(a_list), len(b_list)
    assert all(mpf(b) > 0 for b in b_list)
    terminating = any(mpf(a) <= 0 and mpf(a) == int(mpf(a)) for a in a_list)
    if not terminating and (p > q + 1 or (p == q + 1 and abs(mpf(z)) >= 1)):
        raise ValueError("divergent series")
    abs_a = sorted((abs(mpf(a)) for a in a_list), reverse=True)
    bb = sorted([mpf(b) for b in b_list] + [mpf(1)], reverse=True)
    pairs = list(zip(abs_a, bb[: len(abs_a)]))
    unpaired = bb[len(abs_a):]

    def ratio_bound(N):
        R = abs(mpf(z))
        for a, b in pairs:
            R *= max(1, (a + N) / (b + N))
        for b in unpaired:
            R /= b + N
        return R

    wp = target_bits + 64
    for _attempt in range(12):
        with mp.workprec(wp):
            a_ = [mpf(v) for v in a_list]
            b_ = [mpf(v) for v in b_list]
            zz = mpf(z)
            s = mpf(1)
            t = mpf(1)
            asum = mpf(1)
            n = 0
            tail = mpf(0)
            eps = mpf(2) ** (-wp - 4)
            while True:
                num = mpf(1)
                for a in a_:
                    num *= a + n
                if num == 0:
                    tail = mpf(0)
                    break
                den = mpf(n + 1)
                for b in b_:
                    den *= b + n
                t = t * (num * zz / den)
                n += 1
                s += t
                at = abs(t)
                asum += at
                if at <= asum * eps:
                    R = ratio_bound(n)
                    if R < 0.99:
                        tail = at * R / (1 - R)
                        break
                if n > max_terms:
                    raise ValueError("direct_series: too many terms")
            err = asum * mpf(2) ** (-wp) * (n + 1) * (p + q + 4) + tail
            if s != 0 and err <= abs(s) * mpf(2) ** (-target_bits):
                with mp.workprec(target_bits + 32):
                    return +s
            if s != 0 and abs(s) > 4 * err:
                need = int(mpmath.log(err / abs(s), 2)) + target_bits + 64
            else:
                need = max(wp, int(mpmath.log(asum, 2)) + 64)
            wp += max(need, 64)
    raise ValueError("direct_series: precision escalation failed")


# --------------------------------------------------------------------------
# table A: Bessel J_n(x)
# --------------------------------------------------------------------------


def bessel_ref(n, x, dps):
    with mp.workdps(dps):
        v = mpmath.besselj(n, mpf(x), **BIG)
        return +as_real(v)


def bessel_series(n, x):
    """Independent: J_n(x) = s (x/2)^m / m! 0F1(; m+1; -x^2/4), m=|n|."""
    m = abs(n)
    sign = -1 if (n < 0 and m % 2 == 1) else 1
    with mp.workprec(400):
        z = -mpf(x) ** 2 / 4  # exact (106-bit mantissa)
    s = direct_series([], [m + 1], z, target_bits=230)
    with mp.workprec(400):
        if x == 0:
            pre = mpf(1) if m == 0 else mpf(0)
        else:
            pre = (mpf(x) / 2) ** m / mpf(math.factorial(m))
        return sign * pre * s


def bessel_task(inp):
    n, x = inp
    ref, tier = two_prec(lambda d: bessel_ref(n, x, d))
    if ref is None:
        return "reject", None, tier
    checks = []
    # cost of the direct series grows like |x|^2; check all |x|<=3000, a
    # deterministic quarter of the rest
    if abs(x) <= 3000 or (abs(n) + int(abs(x))) % 4 == 0:
        c = bessel_series(n, x)
        checks.append(("series", c))
    return finish(ref, tier, checks, None)


# --------------------------------------------------------------------------
# table B: 1F2
# --------------------------------------------------------------------------


def hyp1f2_ref(a, b1, b2, z, dps):
    with mp.workdps(dps):
        return +as_real(mpmath.hyp1f2(mpf(a), mpf(b1), mpf(b2), mpf(z), **BIG))


def hyp1f2_task(inp):
    a, b1, b2, z = inp
    ref, tier = two_prec(lambda d: hyp1f2_ref(a, b1, b2, z, d))
    if ref is None:
        return "reject", None, tier
    if min(b1, b2) <= 0 or z < -1e4:
        # direct_series needs b > 0; at z < -1e4 it needs thousands of bits:
        # the two-precision agreement of mpmath is the check there
        return finish(ref, tier, [], None)
    c = direct_series([a], [b1, b2], z, target_bits=230)
    return finish(ref, tier, [("series", c)], None)


# --------------------------------------------------------------------------
# table C: 2F1
# --------------------------------------------------------------------------


def hyp2f1_ref(a, b, c, z, dps):
    with mp.workdps(dps):
        return +as_real(mpmath.hyp2f1(mpf(a), mpf(b), mpf(c), mpf(z), **BIG))


def is_nonpos_int(v):
    return v <= 0 and v == int(v)


def hyp2f1_model_connection(k, y):
    """Independent closed form for the model 2F1(1, k+1/2; k+2; y), 0<y<=1:
    2F1 = y^(-k-1) [ 2(k+1) P_k(1-y) - C sqrt(1-y) ],
    P_k(u) = 2F1(-1/2, -k; 1/2; u) (polynomial), C = 2 sqrt(pi) Gamma(k+2)/Gamma(k+1/2).
    """
    with mp.workprec(500):
        u = 1 - mpf(y)  # exact
    extra = int((k + 1) * math.log2(1.0 / y) * 1.05) + 128
    P = direct_series([mpf(-0.5), -k], [mpf(0.5)], u, target_bits=260 + extra)
    with mp.workprec(260 + extra):
        C = 2 * mpmath.sqrt(mp.pi) * mpmath.gamma(k + 2) / mpmath.gamma(mpf(k) + mpf(0.5))
        br = 2 * (k + 1) * P - C * mpmath.sqrt(u)
        return br / mpf(y) ** (k + 1)


def hyp2f1_euler_quad(a, b, c, z, dps):
    """Independent: Euler integral, requires c > b > 0 (b, c-b >= 1/4), z < 1.
    2F1 = Gamma(c)/(Gamma(b)Gamma(c-b)) [ Int_0^1/2 t^(b-1)(1-t)^(c-b-1)(1-zt)^(-a) dt
                                         + Int_0^1/2 (1-w)^(b-1) w^(c-b-1)(1-z+zw)^(-a) dw ]
    Both endpoint singularities sit at 0 of their own variable and are removed
    by t = u^n1, w = v^n2 (n1 = ceil(2/b), n2 = ceil(2/(c-b))); the t-part is
    split at 4^j/|z| (z < -1), the w-part at 4^j (1-z)/z (z > 1/2).
    Returns (value, quad error estimate relative)."""
    with mp.workdps(dps):
        a, b, c, z = mpf(a), mpf(b), mpf(c), mpf(z)
        half = mpf(0.5)
        n1 = int(math.ceil(2 / float(b)))
        n2 = int(math.ceil(2 / float(c - b)))

        def f1(u):
            t = u**n1
            return n1 * u ** (n1 * b - 1) * (1 - t) ** (c - b - 1) * (1 - z * t) ** (-a)

        def f2(v):
            w = v**n2
            return n2 * v ** (n2 * (c - b) - 1) * (1 - w) ** (b - 1) * (1 - z + z * w) ** (-a)

        p1 = {mpf(0), half}
        if z < -1:
            p = 1 / abs(z)
            while p < half:
                p1.add(p)
                p *= 4
        p2 = {mpf(0), half}
        if z > half:
            p = (1 - z) / z
            while p < half:
                p2.add(p)
                p *= 4
        I1, e1 = mpmath.quad(f1, sorted(mpmath.root(p, n1) for p in p1), error=True)
        I2, e2 = mpmath.quad(f2, sorted(mpmath.root(p, n2) for p in p2), error=True)
        I = I1 + I2
        pref = mpmath.gamma(c) / (mpmath.gamma(b) * mpmath.gamma(c - b))
        return pref * I, (e1 + e2) / abs(I)


def hyp2f1_euler_check(a, b, c, z):
    """Euler integral at dps 70 and 90; returns the dps-90 value if the two
    agree to 58 digits, else None (inconclusive)."""
    v1, _ = hyp2f1_euler_quad(a, b, c, z, 70)
    v2, _ = hyp2f1_euler_quad(a, b, c, z, 90)
    if agree(v1, v2, digits=58):
        return v2
    return None


def hyp2f1_task(inp):
    a, b, c, z, region = inp
    ref, tier = two_prec(lambda d: hyp2f1_ref(a, b, c, z, d))
    if ref is None:
        return "reject", None, tier
    checks = []
    soft = []

    def attempt(name, fn):
        try:
            v = fn()
        except Exception as e:  # noqa: BLE001 - a failing cross-check is only inconclusive
            soft.append("%s_error %s" % (name, repr(e)[:80]))
            return
        if v is None:
            soft.append("%s_inconclusive" % name)
        else:
            checks.append((name, v))

    if is_nonpos_int(a) or is_nonpos_int(b) or abs(z) <= 0.75:
        attempt("series", lambda: direct_series([a, b], [c], z, target_bits=230))
    if region == "model" and z > 0.75:
        k = int(b - 0.5)
        attempt("model_closed_form", lambda: hyp2f1_model_connection(k, z))
    if z == 1 and c - a - b > 0:
        def gauss():
            with mp.workdps(95):
                A, B, C = mpf(a), mpf(b), mpf(c)
                return mpmath.gamma(C) * mpmath.gamma(C - A - B) * mpmath.rgamma(C - A) * mpmath.rgamma(C - B)
        attempt("gauss_sum", gauss)
    # Euler integral (c > b > 0 after possibly swapping a and b) on a
    # deterministic half of the eligible rows (it costs ~1 s per row)
    if region in ("near_one", "degenerate", "negative_z") and z != 1:
        if int((a + b + c) * 64) % 2 == 0:
            for (aa, bb) in ((a, b), (b, a)):
                if bb >= 0.25 and c - bb >= 0.25:
                    attempt("euler_quad", lambda: hyp2f1_euler_check(aa, bb, c, z))
                    break
    return finish(ref, tier, checks, None, soft)


# --------------------------------------------------------------------------
# table D: Re G^{2,2}_{3,3}(-y | 0, 1/2-k, 1; 0, 0, -k-1)
# --------------------------------------------------------------------------


def mg_S_hyp3f2(k, y):
    """S(y) = sum_{n>=1} (b)_n y^n / ((c)_n n) = (b y / c) 3F2(1,1,b+1; 2,c+1; y)."""
    b = mpf(k) + mpf(0.5)
    c = mpf(k) + 2
    y = mpf(y)
    return b * y / c * mpmath.hyp3f2(1, 1, b + 1, 2, c + 1, y)


def mg_S_quad(k, y):
    """S(y) = -(1/B(b, 3/2)) Int_0^1 s^(b-1) (1-s)^(1/2) ln(1 - y s) ds, split at s = 1/2:
      part 1: s = u^n (n = ceil(2/b)), u in [0, 2^(-1/n)]:  n u^(nb-1) (1-u^n)^(1/2) ln(1 - y u^n)
      part 2: s = 1 - v^2, v in [0, 2^(-1/2)]:  2 v^2 (1-v^2)^(b-1) ln(d + y v^2),  d = 1 - y,
              split at sqrt(d)*4^j and at v = {1,4,10}/sqrt(b).
    The substitutions remove both endpoint singularities (tanh-sinh nodes near an
    endpoint only carry absolute precision)."""
    b = mpf(k) + mpf(0.5)
    y = mpf(y)
    d = 1 - y
    half = mpf(0.5)
    n = int(math.ceil(2 / float(b)))
    f1 = lambda u: n * u ** (n * b - 1) * mpmath.sqrt(1 - u**n) * mpmath.log(1 - y * u**n)
    f2 = lambda v: 2 * v * v * (1 - v * v) ** (b - 1) * mpmath.log(d + y * v * v)
    vmax = mpmath.sqrt(half)
    pts = {mpf(0), vmax}
    if d > 0:
        p = mpmath.sqrt(d)
        while p < vmax:
            pts.add(p)
            p *= 4
    for s in (1, 4, 10):
        q = s / mpmath.sqrt(b)
        if q < vmax:
            pts.add(q)
    I1 = mpmath.quad(f1, [0, mpmath.root(half, n)])
    I2 = mpmath.quad(f2, sorted(pts))
    return -(I1 + I2) / mpmath.beta(b, mpf(1.5))


def mg_S_at_one(k):
    """S(1) = psi(k+2) - psi(3/2) exactly."""
    return mpmath.digamma(mpf(k) + 2) - mpmath.digamma(mpf(1.5))


def mg_from_S(k, y, S):
    """Re G = (2 Gamma(b)/Gamma(c)) [ -ln(y)/2 - S/2 + (psi(c) - psi(b))/2 ],
    returns (value, natural_scale)."""
    b = mpf(k) + mpf(0.5)
    c = mpf(k) + 2
    pref = 2 * mpmath.gamma(b) / mpmath.gamma(c)
    L = -mpmath.log(mpf(y)) / 2
    P = (mpmath.digamma(c) - mpmath.digamma(b)) / 2
    val = pref * (L - S / 2 + P)
    scale = pref * (abs(L) + abs(S) / 2 + abs(P))
    return val, scale


def mg_closed(k, y, method, dps):
    with mp.workdps(dps):
        if method == "closed_form_hyp3f2":
            S = mg_S_hyp3f2(k, y)
        elif method == "closed_form_quad":
            S = mg_S_quad(k, y)
        elif method == "closed_form_psi":
            assert y == 1
            S = mg_S_at_one(k)
        else:
            raise ValueError(method)
        return mg_from_S(k, y, S)


def mg_meijerg(k, y, dps):
    with mp.workdps(dps):
        kk = mpf(k)
        v = mpmath.meijerg([[0, mpf(0.5) - kk], [1]], [[0, 0], [-kk - 1]], -mpf(y))
        return mpmath.re(v)


def mg_method_for(y):
    if y == 1:
        return "closed_form_psi"
    if y <= 0.9:
        return "closed_form_hyp3f2"
    return "closed_form_quad"


def meijer_task(inp):
    k, y, method = inp
    if method == "meijerg":
        scale_holder = {}

        def f(d):
            v, sc = mg_closed(k, y, mg_method_for(y), d)
            scale_holder[d] = (v, sc)
            return mg_meijerg(k, y, d)

        ref, tier = two_prec(f, scale=lambda d: scale_holder[d][1])
        if ref is None:
            return "reject", None, tier
        cf, sc = scale_holder[tier[1]]
        # overlap assertion: meijerg vs closed form (same point, same dps)
        if not agree(ref, cf, sc):
            return "overlap_fail", fmt_val(ref), "meijerg %s vs closed %s" % (fmt_val(ref), fmt_val(cf))
        return "ok", fmt_val(ref), (tier, ["closed_form"], [])
    scale_holder = {}

    def g(d):
        v, sc = mg_closed(k, y, method, d)
        scale_holder[d] = sc
        return v

    ref, tier = two_prec(g, scale=lambda d: scale_holder[d])
    if ref is None:
        return "reject", None, tier
    sc = scale_holder[tier[1]]
    checks = []
    if method == "closed_form_hyp3f2":
        # independent direct series for S(y)
        b = mpf(k) + mpf(0.5)
        with mp.workprec(300):
            yy = mpf(y)
        F = direct_series([1, 1, b + 1], [2, mpf(k) + 3], yy, target_bits=230)
        with mp.workdps(95):
            S = b * mpf(y) / (mpf(k) + 2) * F
            v, _ = mg_from_S(k, y, S)
        checks.append(("series", v))
    if method == "closed_form_psi":
        # (mpmath.hyp3f2 at y = 1 takes 2-12 s per point at dps 95, so the
        # per-row check uses the Euler integral; hyp3f2 at y = 1 is compared in
        # the overlap tasks for a few k)
        with mp.workdps(95):
            S = mg_S_quad(k, 1)
            v, _ = mg_from_S(k, 1, S)
        checks.append(("quad_at_1", v))
    return finish(ref, tier, checks, sc)


def meijer_overlap_task(inp):
    """Check-only task: two S(y) methods at the same point.  Returns status."""
    k, y, m1, m2, dps = inp
    with mp.workdps(dps):
        f = {"hyp3f2": mg_S_hyp3f2, "quad": mg_S_quad}
        s1 = f[m1](k, y) if m1 != "psi" else mg_S_at_one(k)
        s2 = f[m2](k, y)
        v1, sc = mg_from_S(k, y, s1)
        v2, _ = mg_from_S(k, y, s2)
        ok = agree(v1, v2, sc, digits=min(AGREE_DIGITS, dps - 8))
        msg = "%s=%s %s=%s" % (m1, fmt_val(v1), m2, fmt_val(v2))
        return ("ok" if ok else "overlap_fail"), fmt_val(v1), (None, [msg], [])


# --------------------------------------------------------------------------
# common evaluation driver
# --------------------------------------------------------------------------


def two_prec(f, scale=None):
    """Evaluate f at the two precisions of each tier; return (value, tier)."""
    last = None
    for tier in TIERS:
        try:
            v1 = f(tier[0])
            v2 = f(tier[1])
        except Timeout:
            raise
        except Exception as e:  # noqa: BLE001 - mpmath convergence failures etc.
            last = "error: %s" % (repr(e)[:200],)
            continue
        sc = scale(tier[1]) if scale is not None else None
        if agree(v1, v2, sc):
            return v2, tier
        last = "disagree at %s: %s vs %s" % (tier, mpmath.nstr(v1, 20), mpmath.nstr(v2, 20))
    return None, last


def finish(ref, tier, checks, scale, soft=()):
    for name, c in checks:
        if not agree(c, ref, scale):
            return "xcheck_fail", fmt_val(ref), "%s: ref %s vs %s" % (name, fmt_val(ref), mpmath.nstr(c, 55))
    info = tier
    return "ok", fmt_val(ref), (info, [n for n, _ in checks], list(soft))


TASK_FUNCS = {
    "bessel_j": bessel_task,
    "hyp1f2": hyp1f2_task,
    "hyp2f1": hyp2f1_task,
    "meijer_g_k": meijer_task,
    "meijer_overlap": meijer_overlap_task,
}


def run_task(task):
    idx, table, inp = task
    signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(TASK_TIMEOUT)
    t0 = time.time()
    try:
        st, val, info = TASK_FUNCS[table](inp)
    except Timeout:
        st, val, info = "reject", None, "timeout"
    except Exception as e:  # noqa: BLE001
        st, val, info = "reject", None, "exception: %s" % (repr(e)[:200],)
    finally:
        signal.alarm(0)
    return idx, st, val, info, time.time() - t0


# --------------------------------------------------------------------------
# point sets
# --------------------------------------------------------------------------


def besseljzero_float(nm):
    n, m = nm
    with mp.workdps(40):
        return nearest_float(mpmath.besseljzero(n, m))


def bessel_points(pool):
    rng = random.Random(SEED + 1)
    pts = []  # (n, x, region)
    # ---- small: 0 <= n <= 20, 0 <= x <= 10
    for n in range(4):
        pts.append((n, 0.0, "small"))
    for n in (0, 1, 2, 3):
        pts.append((n, 1e-300, "small"))
        pts.append((n, 5e-324, "small"))
    for n in range(21):
        for x in (0.5, 1.0, 2.5, 5.0, 7.75, 10.0):
            pts.append((n, x, "small"))
    for _ in range(330):
        n = rng.randint(0, 20)
        u = rng.random()
        if u < 0.5:
            x = rng.uniform(0.0, 10.0)
        elif u < 0.8:
            x = min(loguni(rng, 1e-12, 10.0), 10.0)
        else:
            x = dyadic(rng, 1 / 64, 10.0, 6)
        pts.append((n, x, "small"))
    # ---- large_x: x in [10, 1e4], modest n (x >= 1.5 n)
    for n in (0, 1, 2, 5, 10, 20, 50, 100):
        for x in (1e4, 5000.5, 1234.5678, 100.25):
            pts.append((n, x, "large_x"))
    for _ in range(450):
        u = rng.random()
        n = rng.randint(0, 50) if u < 0.6 else (rng.randint(0, 500) if u < 0.9 else rng.randint(0, 2000))
        x = loguni(rng, max(10.0, 1.5 * n), 1e4)
        pts.append((n, x, "large_x"))
    # ---- transition: x = n (1 + t), |t| < 0.1, n in [20, 1e4]
    for n in (20, 100, 1000, 5000, 10000):
        pts.append((n, float(n), "transition"))
    for x in (9000.0, 9500.25, 9900.0, 9999.0, 9999.5):
        pts.append((10000, x, "transition"))
    for n in (9100, 9500, 9990):
        pts.append((n, 10000.0, "transition"))
    for _ in range(450):
        n = int(round(loguni(rng, 20, 10000)))
        if rng.random() < 0.5:
            t = rng.uniform(-0.0999, 0.0999)
        else:
            t = rng.uniform(-6, 6) * n ** (-2.0 / 3.0)  # Airy layer x = n + s n^(1/3)
            t = max(-0.0999, min(0.0999, t))
        pts.append((n, min(n * (1 + t), 1e4), "transition"))
    # ---- deep_tail: x << n
    for (n, x) in ((10000, 1.0), (10000, 1000.0), (10000, 5000.0), (2, 1e-300), (50, 1e-10), (1000, 0.5)):
        pts.append((n, x, "deep_tail"))
    for _ in range(380):
        n = int(round(loguni(rng, 2, 10000)))
        x = n * loguni(rng, 1e-8, 0.5)
        pts.append((n, x, "deep_tail"))
    # ---- near_zeros: rounded zeros j_{n,m} (n<=50, m<=40) and 1e-10..1e-16 perturbations
    pairs = [(n, m) for n in (0, 1, 2, 5, 10, 20, 50) for m in range(1, 41)]
    others = [(n, m) for n in range(51) for m in range(1, 41) if (n, m) not in set(pairs)]
    rng.shuffle(others)
    pairs += sorted(others[:120])
    zeros = pool.map(besseljzero_float, pairs, chunksize=8)
    for (n, m), z in zip(pairs, zeros):
        pts.append((n, z, "near_zeros"))
        delta = (1 if rng.random() < 0.5 else -1) * 10.0 ** (-rng.uniform(10, 16))
        pts.append((n, z * (1 + delta), "near_zeros"))
    # ---- negative: n < 0 and/or x < 0
    def neg_sign():
        u = rng.random()
        return (-1, 1) if u < 1 / 3 else ((1, -1) if u < 2 / 3 else (-1, -1))
    for (n, x) in ((-1, -1.0), (-10000, 10000.0), (10000, -10000.0), (-10000, -10000.0), (-3, 0.0), (-7, -1e-300)):
        pts.append((n, x, "negative"))
    for _ in range(150):
        sn, sx = neg_sign()
        pts.append((sn * rng.randint(0, 20), sx * rng.uniform(0, 10), "negative"))
    for _ in range(100):
        sn, sx = neg_sign()
        pts.append((sn * rng.randint(0, 200), sx * loguni(rng, 300, 1e4), "negative"))
    for _ in range(80):
        sn, sx = neg_sign()
        N = int(round(loguni(rng, 20, 10000)))
        pts.append((sn * N, sx * min(N * (1 + rng.uniform(-0.0999, 0.0999)), 1e4), "negative"))
    for _ in range(70):
        sn, sx = neg_sign()
        N = int(round(loguni(rng, 2, 10000)))
        pts.append((sn * N, sx * N * loguni(rng, 1e-8, 0.5), "negative"))
    # sanitize: exact floats, no negative zero, dedupe
    out, seen = [], set()
    for n, x, r in pts:
        x = float(x)
        if x == 0:
            x = 0.0
        assert abs(n) <= 10000 and abs(x) <= 10000
        key = (n, x)
        if key in seen:
            continue
        seen.add(key)
        out.append(((n, x), r))
    return out


def hyp1f2_points():
    rng = random.Random(SEED + 2)
    pts = []
    K = [0, 1, 2, 10, 100, 500, 1000]
    half = 0.5

    def model(k, z):
        pts.append(((half, float(k + 1), k + 1.5, z), "model"))

    def rk():
        return rng.choice(K) if rng.random() < 0.5 else rng.randint(0, 1000)

    for k in sorted(set(range(0, 1001, 5)) | set(K)):
        model(k, -300.0)
    for k in K:
        model(k, -1e4)
    for k in (0, 1000):
        model(k, 0.0)
    for beta in (0.5, 1.125, 2.0, 5.0):
        for i in range(140):
            if i < 5:
                abar = (6.0, 3.0, 1.0, 0.5, 0.125)[i]
            else:
                abar = rng.uniform(0.0, 6.0)
                if abar == 0.0:
                    abar = 6.0
            with mp.workdps(60):
                z = nearest_float(-(mp.pi * mpf(abar) / mpf(beta)) ** 2)
            k = rk()
            model(k, z)
            if i % 4 == 0:
                model(k, z * (1 + rng.uniform(-1e-3, 1e-3)))
    for _ in range(350):
        model(rk(), -loguni(rng, 1e-8, 1e4))
    # general
    for i in range(820):
        if i < 20:
            a = float(-(i % 5) - 1)
        else:
            a = dyadic(rng, -5, 5, 8)
        b1 = dyadic(rng, 0.25, 20, 6)
        b2 = dyadic(rng, 0.25, 20, 6)
        if i < 30:
            z = (-1e4, 100.0)[i % 2]
        elif rng.random() < 0.7:
            z = -loguni(rng, 1e-6, 1e4)
        else:
            z = rng.uniform(0.0, 100.0)
        pts.append(((a, b1, b2, z), "general"))
    # positive
    for i in range(500):
        if i < 7:
            z = 1e3
        else:
            z = loguni(rng, 1e-8, 1e3)
        if i % 2 == 0:
            k = K[i // 2] if i // 2 < len(K) else rk()
            pts.append(((half, float(k + 1), k + 1.5, z), "positive"))
        else:
            pts.append(((dyadic(rng, -5, 5, 8), dyadic(rng, 0.25, 20, 6), dyadic(rng, 0.25, 20, 6), z), "positive"))
    # issue 23 (own generator, so the draws above are unchanged): the model family
    # at large |z| (its Bessel route), and parameters of either sign up to 500
    for k in (0, 1, 5, 50):
        for z in (-3e4, -1e5, -1e6):
            pts.append(((half, float(k + 1), k + 1.5, z), "large_z"))
    rng23 = random.Random(SEED + 23)
    pts.append(((-337.8177490234375, 427.4927978515625, 294.2845458984375, -63.8824462890625), "large_params"))
    while sum(1 for _, r in pts if r == "large_params") < 40:
        a, b1, b2, z = (dyadic(rng23, -500, 500, 13) for _ in range(4))
        if any(b <= 0 and abs(b - round(b)) < 1 / 16 for b in (b1, b2)):
            continue  # near a pole
        pts.append(((a, b1, b2, z), "large_params"))
    out, seen = [], set()
    for inp, r in pts:
        inp = tuple(float(v) for v in inp)
        if r == "large_params":
            assert max(abs(v) for v in inp) <= 500
        else:
            assert inp[1] > 0 and inp[2] > 0 and -1e6 <= inp[3] <= 1e3
        if inp in seen:
            continue
        seen.add(inp)
        out.append((inp, r))
    return out


def hyp2f1_points():
    rng = random.Random(SEED + 3)
    pts = []
    K = [0, 1, 2, 3, 5, 10, 50, 100, 500, 1000]
    special_y = [1.0] + [1.0 - 2.0**-j for j in range(1, 53)] + [one_minus_ten_pow(j) for j in range(1, 16)]

    def model(k, y):
        pts.append(((1.0, k + 0.5, float(k + 2), y), "model"))

    for k in K:
        for y in special_y:
            model(k, y)
    extra_k = [k for k in range(1001) if k not in K]
    rng.shuffle(extra_k)
    for k in sorted(extra_k[:100]):
        model(k, 1.0)
    for _ in range(300):
        k = rng.randint(0, 1000)
        u = rng.random()
        if u < 0.4:
            y = rng.uniform(0.0, 1.0)
        elif u < 0.7:
            y = 1.0 - 10.0 ** (-rng.uniform(0.0, 15.5))
        else:
            y = 10.0 ** (-rng.uniform(0.0, 300.0))
        if 0 < y <= 1:
            model(k, y)

    def par():
        return dyadic(rng, -10, 10, 6), dyadic(rng, -10, 10, 6), dyadic(rng, 0.25, 15, 6)

    def near1():
        return 1.0 - 10.0 ** (-rng.uniform(0.31, 15.0))

    # general_inside
    for i in range(450):
        a, b, c = par()
        if i < 40:
            z = (-1.0, 0.5, -1e-20, 1e-20)[i % 4]
        else:
            z = rng.uniform(-1.0, 0.5)
        pts.append(((a, b, c, z), "general_inside"))
    # near_one: c-a-b non-integer
    n = 0
    while n < 350:
        a, b, c = par()
        if (c - a - b) == round(c - a - b):
            continue
        pts.append(((a, b, c, near1()), "near_one"))
        n += 1
    # at_one: Gauss sum, c-a-b > 0
    n = 0
    while n < 250:
        a, b, c = par()
        if c - a - b <= 0:
            continue
        pts.append(((a, b, c, 1.0), "at_one"))
        n += 1
    # degenerate: c - a - b integer
    n = 0
    while n < 350:
        m = (0, 1, 2, 3, -1, -2)[n % 6]
        a, b = dyadic(rng, -10, 10, 6), dyadic(rng, -10, 10, 6)
        c = a + b + m
        if not (0.25 <= c <= 15):
            continue
        pts.append(((a, b, c, near1()), "degenerate"))
        n += 1
    # negative_z
    for i in range(400):
        a, b, c = par()
        if i < 60:
            b = a + rng.randint(-5, 5)  # a - b integer (degenerate 1/z transformation)
        if i < 10:
            z = -1e6
        else:
            z = -(10.0 ** rng.uniform(1e-9, 6.0))
        if z >= -1:
            continue
        pts.append(((a, b, c, z), "negative_z"))
    # terminating: a = -N
    for i in range(300):
        N = rng.randint(0, 40)
        _, b, c = par()
        u = rng.random()
        if u < 0.4:
            z = rng.uniform(-1.0, 1.0)
        elif u < 0.7:
            z = -(10.0 ** rng.uniform(0, 6.0))
        elif u < 0.9:
            z = 1.0
        else:
            z = near1()
        pts.append(((float(-N), b, c, z), "terminating"))
    out, seen = [], set()
    for inp, r in pts:
        inp = tuple(float(v) for v in inp)
        a, b, c, z = inp
        assert z <= 1 and c > 0
        if inp in seen:
            continue
        seen.add(inp)
        out.append((inp, r))
    return out


def meijer_points():
    rng = random.Random(SEED + 4)
    pts = []
    K = [0, 1, 2, 3, 5, 10, 50, 100, 500, 1000]

    def rk():
        return rng.choice(K) if rng.random() < 0.3 else rng.randint(0, 1000)

    def region(y):
        if y == 1:
            return "at_one"
        if y <= 1e-3:
            return "small_y"
        if y <= 0.9:
            return "mid_y"
        return "near_one"

    def add(k, y):
        pts.append(((k, y, mg_method_for(y)), region(y)))

    # small_y
    for k in (0, 1000):
        add(k, 5e-324)
    for k in K:
        add(k, 1e-300)
        add(k, 1e-3)
    for _ in range(600):
        add(rk(), 10.0 ** rng.uniform(-300, -3))
    # mid_y
    for _ in range(900):
        y = rng.uniform(1e-3, 0.9)
        if y > 1e-3:
            add(rk(), y)
    # specials
    sy = [one_minus_ten_pow(j) for j in range(1, 13)] + [1.0 - 2.0**-j for j in range(1, 41)]
    for k in K:
        for y in sy:
            add(k, y)
    # near_one random
    for _ in range(300):
        y = 1.0 - 10.0 ** (-rng.uniform(1.0, 15.5))
        if y < 1:
            add(rk(), y)
    # at_one: all K + 140 random distinct k
    extra = [k for k in range(1001) if k not in K]
    rng.shuffle(extra)
    for k in sorted(K + extra[:140]):
        add(k, 1.0)
    # meijerg cross-check subset
    for k in range(6):
        ys = [0.05, 0.95] if k in (0, 5) else []
        while len(ys) < 10:
            ys.append(rng.uniform(0.05, 0.95))
        for y in ys:
            pts.append(((k, y, "meijerg"), "meijerg_check"))
    out, seen = [], set()
    for (k, y, m), r in pts:
        y = float(y)
        assert 0 < y <= 1 and 0 <= k <= 1000
        key = (k, y, m)
        if key in seen:
            continue
        seen.add(key)
        out.append(((k, y, m), r))
    return out


def meijer_overlap_inputs():
    out = []
    # hyp3f2 vs quad where both are cheap
    for k in (0, 1, 3, 10, 100, 1000):
        for y in (0.5, 0.9, 0.95):
            out.append((k, y, "hyp3f2", "quad", 75))
    # psi (exact y = 1 identity) vs hyp3f2 at y = 1 (hyp3f2 slow here: 2-12 s)
    for k in (0, 3, 500):
        out.append((k, 1.0, "psi", "hyp3f2", 75))
    # hyp3f2 vs quad close to 1 (hyp3f2 is slow here: ~10 s per point)
    for k in (0, 10):
        for y in (0.99, one_minus_ten_pow(3)):
            out.append((k, y, "hyp3f2", "quad", 70))
    return out


# --------------------------------------------------------------------------
# output
# --------------------------------------------------------------------------

TABLE_COLUMNS = {
    "bessel_j": ["n", "x"],
    "hyp1f2": ["a", "b1", "b2", "z"],
    "hyp2f1": ["a", "b", "c", "z"],
    "meijer_g_k": ["k", "y"],
}

TABLE_METHOD = {
    "bessel_j": [
        "value = mpmath.besselj(n, x, maxterms=10**6, maxprec=10**6)",
        "cross-check (rows with |x| <= 3000 and (|n|+floor|x|) % 4 == 0 otherwise): direct series "
        "J_n(x) = s (x/2)^m/m! sum_j (-x^2/4)^j/(j!(m+1)_j), m=|n|, with rigorous adaptive precision",
    ],
    "hyp1f2": [
        "value = mpmath.hyp1f2(a, b1, b2, z, maxterms=10**6, maxprec=10**6)",
        "cross-check (all rows): direct power series with rigorous adaptive precision",
    ],
    "hyp2f1": [
        "value = mpmath.hyp2f1(a, b, c, z, maxterms=10**6, maxprec=10**6)",
        "cross-checks: direct series (|z| <= 0.75 or a/b non-positive integer); model rows with z > 0.75: "
        "y^(-k-1)[2(k+1) 2F1(-1/2,-k;1/2;1-y) - 2 sqrt(pi) Gamma(k+2)/Gamma(k+1/2) sqrt(1-y)]; "
        "z = 1: Gauss sum via gamma; near_one/degenerate/negative_z rows with c > b > 0 (or c > a > 0) and "
        "floor(64(a+b+c)) even: Euler integral with mpmath.quad at dps 70 and 90 (used only if those agree to 58 digits)",
    ],
    "meijer_g_k": [
        "function: Re G^{2,2}_{3,3}(-y | 0, 1/2-k, 1; 0, 0, -k-1)",
        "closed form: (2 Gamma(b)/Gamma(c)) [ -ln(y)/2 - S(y)/2 + (psi(c) - psi(b))/2 ], b = k+1/2, c = k+2, "
        "S(y) = sum_{n>=1} (b)_n y^n/((c)_n n) = (b y/c) 3F2(1,1,b+1; 2,c+1; y)",
        "method closed_form_hyp3f2 (0 < y <= 0.9): S via mpmath.hyp3f2; cross-checked against the direct series",
        "method closed_form_quad (0.9 < y < 1): S = -(1/B(b,3/2)) Int_0^1 s^(b-1)(1-s)^(1/2) ln(1-ys) ds "
        "via mpmath.quad, split at s = 1/2; s = u^ceil(2/b) on [0,1/2]; s = 1-v^2 on [1/2,1] split at "
        "v = sqrt(1-y)*4^j and {1,4,10}/sqrt(b)",
        "method closed_form_psi (y = 1): S(1) = psi(k+2) - psi(3/2); cross-checked per row against the quad integral at y = 1 "
        "and, for k = 0, 3, 500, against mpmath.hyp3f2 at y = 1",
        "method meijerg (region meijerg_check, k = 0..5): re(mpmath.meijerg([[0, 1/2-k],[1]], [[0, 0],[-k-1]], -y)); "
        "asserted to agree with the closed form at the same point",
        "agreement test uses |v1 - v2| <= 1e-52 * max(|v2|, scale), scale = (2 Gamma(b)/Gamma(c)) (|ln y|/2 + |S|/2 + |psi(c)-psi(b)|/2)",
    ],
}


def write_table(name, rows, stats):
    path = os.path.join(DATA, name + ".csv")
    cols = TABLE_COLUMNS[name] + (["value", "method", "region"] if name == "meijer_g_k" else ["value", "region"])
    lines = []
    lines.append("# maugis reference table %s, generated by reference/generate.py (seed %d)" % (name, SEED))
    lines.append("# mpmath %s (backend %s), Python %s" % (mpmath.__version__, mpmath.libmp.BACKEND, sys.version.split()[0]))
    lines.append(
        "# each value computed at mp.dps = %d and %d (retry at %d and %d); kept iff the two agree to >= %d significant "
        "digits; value printed with %d significant digits from the higher precision"
        % (TIERS[0] + TIERS[1] + (AGREE_DIGITS, OUT_DIGITS))
    )
    for m in TABLE_METHOD[name]:
        lines.append("# " + m)
    lines.append("# inputs are exact IEEE binary64 values written as Python repr(float); integer args as integers")
    lines.append("# kept %d, rejected %d (of which cross-check failures %d)" % (stats["kept"], stats["rejected"], stats["xfail"]))
    lines.append(",".join(cols))
    for inp, val, region in rows:
        if name == "meijer_g_k":
            k, y, method = inp
            lines.append("%d,%s,%s,%s,%s" % (k, fmt_in(y), val, method, region))
        elif name == "bessel_j":
            n, x = inp
            lines.append("%d,%s,%s,%s" % (n, fmt_in(x), val, region))
        else:
            lines.append(",".join(fmt_in(v) for v in inp) + ",%s,%s" % (val, region))
    with open(path, "w") as fh:
        fh.write("\n".join(lines) + "\n")
    return path


# --------------------------------------------------------------------------
# J_n at decimal inputs (the decimal-as-ball contract of `maugis eval`)
# --------------------------------------------------------------------------

BESSEL_DECIMAL_ORDERS = [0, 1, 2, 5, 13, 40, 100]
BESSEL_DECIMAL_ZERO_INDEX = [1, 2, 7, 30]
BESSEL_DECIMAL_DIGITS = [17, 20, 25, 33, 40, 50, 60]
# Reference precisions: >= 3 * 256 + 200 bits (the tests go up to 256 bits), checked
# against a second, higher precision; values printed with 100 significant digits.
BESSEL_DECIMAL_BITS = (1100, 1400)
BESSEL_DECIMAL_OUT_DIGITS = 100


def truncate_decimal(v, digits):
    """v (an mpf > 0) truncated toward zero to `digits` significant digits, as text."""
    s = mpmath.nstr(v, digits + 10, strip_zeros=False, min_fixed=-mpmath.inf, max_fixed=mpmath.inf)
    mant, _, exp = s.partition("e")
    exp = int(exp or 0)
    ds = mant.replace(".", "").lstrip("0")
    return "%s.%se%d" % (ds[0], ds[1:digits], exp)


def bessel_j_decimal_rows():
    """J_n at Bessel zeros j_{n,k} typed to 17..60 significant digits (truncated),
    and at the same decimal with its last digit raised by one.  Each value is
    computed from the decimal string itself (not a binary rounding of it)."""
    rows = []
    for n in BESSEL_DECIMAL_ORDERS:
        for k in BESSEL_DECIMAL_ZERO_INDEX:
            mp.prec = 600
            zero = mpmath.besseljzero(n, k)
            for d in BESSEL_DECIMAL_DIGITS:
                typed = truncate_decimal(zero, d)
                mant, _, exp = typed.partition("e")
                bumped_int = int(mant.replace(".", "")) + 1
                bs = str(bumped_int)
                bumped = "%s.%se%d" % (bs[0], bs[1:], int(exp) + (len(bs) - d))
                for text in (typed, bumped):
                    value, rel = besselj_at_decimal(n, text, BESSEL_DECIMAL_BITS, BESSEL_DECIMAL_OUT_DIGITS)
                    if value is None:
                        log("bessel_j_decimal: reject n=%d x=%s (rel diff %s)" % (n, text, mpmath.nstr(rel, 3)))
                        continue
                    rows.append((n, text, value))
    return rows


def besselj_at_decimal(n, text, bits, out_digits):
    """J_n at the decimal string `text`, computed at the two precisions `bits`:
    (the value printed to `out_digits` digits, or None where the two disagree
    beyond `out_digits + 20` digits; their relative difference)."""
    vals = []
    for b in bits:
        mp.prec = b
        vals.append(mpmath.besselj(n, mpf(text)))
    mp.prec = bits[1]
    rel = abs(vals[0] - vals[1]) / abs(vals[1])
    if not rel < mpf(10) ** -(out_digits + 20):
        return None, rel
    return mpmath.nstr(vals[1], out_digits, min_fixed=1, max_fixed=0), rel


def write_decimal_table(name, description, bits, out_digits, header, rows):
    """Writes reference/data/<name>.csv: the provenance lines, `description`
    (comment lines), the precisions used, the header and the rows (tuples)."""
    path = os.path.join(DATA, name + ".csv")
    with open(path, "w") as fh:
        fh.write("# maugis reference table %s, generated by reference/generate.py\n" % name)
        fh.write("# mpmath %s (backend %s), Python %s\n" % (mpmath.__version__, mpmath.libmp.BACKEND, sys.version.split()[0]))
        for line in description:
            fh.write("# %s\n" % line)
        fh.write("# computed from the decimal strings at %d and %d bits, kept iff they agree to %d digits; %d digits printed\n"
                 % (bits + (out_digits + 20, out_digits)))
        fh.write(header + "\n")
        for row in rows:
            fh.write(",".join(str(c) for c in row) + "\n")
    log("%s: %d rows -> %s" % (name, len(rows), path))
    return path


def write_bessel_j_decimal():
    return write_decimal_table(
        "bessel_j_decimal",
        ["J_n(x) at the DECIMAL x as typed (zeros j_{n,k} truncated to 17..60 digits, and last digit + 1);"],
        BESSEL_DECIMAL_BITS, BESSEL_DECIMAL_OUT_DIGITS, "n,x,value", bessel_j_decimal_rows())


# J_n at the decimal "0.001" itself (bessel_j_grid holds the binary64 nearest it),
# for the issue-23 request J_10000("0.001") and tests/it/ball_input_relative.rs: at
# 512 bits the tests need more digits than bessel_j_decimal prints.
BESSEL_TINY_X = "0.001"
BESSEL_TINY_ORDERS = (0, 1, 7, 60, 500, 2000, 10000)
BESSEL_TINY_BITS = (1000, 1300)
BESSEL_TINY_OUT_DIGITS = 180


def bessel_j_tiny_decimal_rows():
    """J_n(x) at the decimal x = 0.001 (mpmath.besselj from the decimal string)."""
    rows = []
    for n in BESSEL_TINY_ORDERS:
        value, rel = besselj_at_decimal(n, BESSEL_TINY_X, BESSEL_TINY_BITS, BESSEL_TINY_OUT_DIGITS)
        if value is None:
            sys.exit("bessel_j_tiny_decimal: n=%d disagrees between precisions (%s)" % (n, mpmath.nstr(rel, 3)))
        rows.append((n, BESSEL_TINY_X, value))
    return rows


def write_bessel_j_tiny_decimal():
    return write_decimal_table(
        "bessel_j_tiny_decimal",
        ["J_n(x) at the DECIMAL x = 0.001 as typed (not its binary64 neighbour), for large n;"],
        BESSEL_TINY_BITS, BESSEL_TINY_OUT_DIGITS, "n,x,value", bessel_j_tiny_decimal_rows())

# --------------------------------------------------------------------------
# J_n on the large (n, x) plane (issue 13 grid), 170 digits
# --------------------------------------------------------------------------

BESSEL_GRID_ORDERS = (0, 1, 7, 60, 500, 2000, 10000)
BESSEL_GRID_ARGS = ("0.001", "1.5", "30.25", "150.5", "999.5", "5000.25", "20000.5", "99999.5", "1000000.5")
# off-grid points named by the issue, and the edges of the recurrence's regions:
# m = the largest integer below x, orders m - 1 .. m + 3 (J_m by the forward
# recurrence, J_{m+1} by one ball step, J_{m+2}.. by the ratio product)
BESSEL_GRID_EXTRA = (
    ("30000", (500,)),
    ("50000.25", (-1200,)),
    ("2.5", (0,)),
    ("30.25", (5, 29, 30, 31, 32, 33)),
    ("150.5", (40, 149, 150, 151, 152)),
    ("999.5", (998, 999, 1000, 1001, 1002)),
    ("5000.25", (4999, 5000, 5001, 5002, 5003, 7500)),
    ("5000", (4998, 4999, 5000, 5001, 5002)),
    ("20000.5", (19999, 20000, 20001, 20002, 30000)),
    ("100000.5", (50000, 99999, 100000, 100001, 100002)),
)
BESSEL_GRID_BITS = (1900, 2300)  # >= 3 * 512 + 200
BESSEL_GRID_OUT_DIGITS = 170


def bessel_miller(x_text, orders, bits, extra):
    """J_n(x) for all n in `orders` (n >= 0) by Miller's backward recurrence
    J_{k-1} = (2k/x) J_k - J_{k+1} [DLMF 10.6.1] at `bits` bits, started at an
    order N past max(orders, x) where prod_{j} (x/(2j - x))^2 < 2^-(bits + 64 +
    extra) (the neglected dominant solution), normalised by
    J_0 + 2 sum_k J_{2k} = 1 [DLMF 10.12.4].  Independent of the crate's methods
    (no Hankel, no error bounds): checked by running two precisions and two
    starting orders and requiring agreement."""
    mp.prec = bits
    x = mpf(float(x_text))  # the binary64 number nearest the text, exactly
    xf = float(x)
    nmax = max(orders)
    j = max(nmax, int(math.ceil(xf))) + 1
    acc = 0.0
    while acc < bits + 64 + extra:
        acc += -2.0 * math.log2(xf / (2.0 * j - xf))
        j += 1
    top = j + (j % 2)
    want = set(orders)
    out = {}
    two_over_x = 2 / x
    y_next = mpf(0)
    y = mpf(2) ** -bits
    norm = mpf(0)
    for k in range(top, 0, -1):
        if k in want:
            out[k] = y
        if k % 2 == 0:
            norm += 2 * y
        y_prev = (k * two_over_x) * y - y_next
        y_next, y = y, y_prev
    norm += y  # k = 0
    if 0 in want:
        out[0] = y
    return {n: v / norm for n, v in out.items()}


def bessel_grid_task(item):
    x_text, orders = item
    absn = sorted(set(abs(n) for n in orders))
    a = bessel_miller(x_text, absn, BESSEL_GRID_BITS[0], 0)
    b = bessel_miller(x_text, absn, BESSEL_GRID_BITS[1], 100)
    mp.prec = BESSEL_GRID_BITS[1]
    rows, notes = [], []
    for n in orders:
        m = abs(n)
        sign = -1 if (n < 0 and m % 2 == 1) else 1
        va, vb = a[m], b[m]
        rel = abs(va - vb) / abs(vb)
        if not rel < mpf(10) ** -(BESSEL_GRID_OUT_DIGITS + 20):
            notes.append("reject n=%d x=%s (rel diff %s)" % (n, x_text, mpmath.nstr(rel, 3)))
            continue
        if float(x_text) <= 1000 and m <= 2000:
            # cross-check: mpmath's own besselj (hypergeometric series) at the same precision
            c = mpmath.besselj(m, mpf(float(x_text)), maxterms=10**6, maxprec=10**6)
            if not abs(c - vb) <= abs(vb) * mpf(10) ** -(BESSEL_GRID_OUT_DIGITS + 10):
                notes.append("cross-check fail n=%d x=%s" % (n, x_text))
                continue
        rows.append((n, x_text, mpmath.nstr(sign * vb, BESSEL_GRID_OUT_DIGITS, min_fixed=1, max_fixed=0)))
    return rows, notes


def write_bessel_j_grid(jobs):
    items = [(x, BESSEL_GRID_ORDERS) for x in BESSEL_GRID_ARGS] + list(BESSEL_GRID_EXTRA)
    items.sort(key=lambda it: -float(it[0]))  # the long recurrences first
    ctx = mproc.get_context("fork")
    with ctx.Pool(jobs) as pool:
        results = pool.map(bessel_grid_task, items, chunksize=1)
    rows = []
    for r, notes in results:
        rows += r
        for note in notes:
            log("bessel_j_grid: " + note)
    rows.sort(key=lambda r: (float(r[1]), r[0]))
    path = os.path.join(DATA, "bessel_j_grid.csv")
    with open(path, "w") as fh:
        fh.write("# maugis reference table bessel_j_grid, generated by reference/generate.py\n")
        fh.write("# mpmath %s (backend %s), Python %s\n" % (mpmath.__version__, mpmath.libmp.BACKEND, sys.version.split()[0]))
        fh.write("# J_n(x) on the issue-13 grid and the recurrence's region edges, at x = the binary64 number nearest the text (exact except 0.001)\n")
        fh.write("# Miller's backward recurrence normalised by J_0 + 2 sum J_2k = 1, at %d and %d bits with different start orders;\n" % BESSEL_GRID_BITS)
        fh.write("# kept iff they agree to %d digits; cross-checked with mpmath.besselj where x <= 1000, |n| <= 2000; %d digits printed\n"
                 % (BESSEL_GRID_OUT_DIGITS + 20, BESSEL_GRID_OUT_DIGITS))
        fh.write("n,x,value\n")
        for n, x_text, val in rows:
            fh.write("%d,%s,%s\n" % (n, x_text, val))
    log("bessel_j_grid: %d rows -> %s" % (len(rows), path))
    return path


# --------------------------------------------------------------------------
# 2F1 at decimal inputs (the decimal-as-ball contract of `maugis eval`)
# --------------------------------------------------------------------------

# Reference precisions: >= 3 * 256 + 200 bits (the tests go up to 256 bits), checked
# against a second, higher precision; values printed with 100 significant digits.
HYP2F1_DECIMAL_BITS = (1000, 1300)
HYP2F1_DECIMAL_OUT_DIGITS = 100


def hyp2f1_decimal_inputs():
    """(a, b, c, z) as decimal strings: next to z = 1 (z = 0.9...9 with 3..40
    nines, and 1 - 10^-k + 10^-(k+5)), next to c - a - b = 0 (c = a + b +- 10^-k),
    and at z = 1 with c - a - b > 0 small; parameters typed as decimals that are
    not binary fractions (0.3, 0.7, 1.1, ...)."""
    params = [
        ("1", "2", "2"),          # 1/(1-z): c - a - b = -1
        ("1", "0.5", "2"),        # 2 (1 - sqrt(1-z)) / z: c - a - b = 1/2
        ("0.3", "0.7", "1"),      # c - a - b = 0 (logarithmic), typed decimals
        ("0.3", "0.45", "1.1"),   # c - a - b = 0.35
        ("1.7", "-0.3", "2.9"),
        ("2.2", "1.3", "3.1"),    # c - a - b = -0.4
        ("-1.3", "0.4", "0.6"),
    ]
    out = []
    for a, b, c in params:
        for k in (3, 6, 10, 15, 20, 30, 40):
            out.append((a, b, c, "0." + "9" * k))
        for k in (4, 12, 25):
            out.append((a, b, c, "0." + "9" * (k - 1) + "8" + "0" * 4 + "1"))
        for z in ("0.1", "-0.7", "-3.3", "-0.49999999999999999999"):
            out.append((a, b, c, z))
    # next to c - a - b = 0: c = a + b +- 10^-k, z near 1 and at 1
    for k in (5, 10, 20, 30):
        c_plus = "1." + "0" * (k - 1) + "1"
        c_minus = "0." + "9" * k
        for z in ("0.9999999999", "0.99999999999999999999", "0.5"):
            out.append(("0.3", "0.7", c_plus, z))
            out.append(("0.3", "0.7", c_minus, z))
        out.append(("0.3", "0.7", c_plus, "1"))       # Gauss: Gamma(c) Gamma(eps) / ...
        out.append(("0.25", "0.5", "0.75" + "0" * (k - 1) + "1", "1"))
    return out


def hyp2f1_decimal_rows():
    rows = []
    for a, b, c, z in hyp2f1_decimal_inputs():
        vals = []
        for bits in HYP2F1_DECIMAL_BITS:
            mp.prec = bits
            vals.append(mpmath.hyp2f1(mpf(a), mpf(b), mpf(c), mpf(z)))
        mp.prec = HYP2F1_DECIMAL_BITS[1]
        rel = abs(vals[0] - vals[1]) / abs(vals[1])
        if not rel < mpf(10) ** -(HYP2F1_DECIMAL_OUT_DIGITS + 20):
            log("hyp2f1_decimal: reject %s %s %s %s (rel diff %s)" % (a, b, c, z, mpmath.nstr(rel, 3)))
            continue
        rows.append((a, b, c, z, mpmath.nstr(vals[1], HYP2F1_DECIMAL_OUT_DIGITS, min_fixed=1, max_fixed=0)))
    return rows


def write_hyp2f1_decimal():
    return write_decimal_table(
        "hyp2f1_decimal",
        ["2F1(a, b; c; z) at the DECIMALS as typed, next to z = 1 and to c - a - b = 0;"],
        HYP2F1_DECIMAL_BITS, HYP2F1_DECIMAL_OUT_DIGITS, "a,b,c,z,value", hyp2f1_decimal_rows())


# --------------------------------------------------------------------------
# 1F2, G(k, y), u_w and du_w/dx at decimal inputs (the ball contract)
# --------------------------------------------------------------------------

BALL_DECIMAL_BITS = (1000, 1300)
BALL_DECIMAL_OUT_DIGITS = 100


def wave_bessel_ref(a, zeta, amp, x):
    """(u_w, du_w/dx) by the Bessel form of docs/displacement.md, Route 2 (mpmath at the
    current precision), from decimal strings.  At x = a: q = 1, acosh = 0 and
    g_n = 2n (the limit from x > a)."""
    a, zeta, amp, x = mpf(a), mpf(zeta), mpf(amp), mpf(x)
    D = 2 * mpmath.pi * a / zeta
    r = x / a
    sq = mpmath.sqrt((r - 1) * (r + 1))
    q = 1 / (r + sq)
    pre = 1 - mpmath.sqrt((r - 1) / (r + 1))
    eps = mpf(2) ** (-mp.prec - 20)
    su = mpf(0)
    sdu = mpf(0)
    geo = mpf(0)
    n = 1
    while True:
        geo += q ** (2 * n - 2) + q ** (2 * n - 1)
        j = mpmath.besselj(2 * n, D)
        sign = 1 if n % 2 == 1 else -1
        su += sign * j * q ** (2 * n)
        sdu += sign * n * j * geo
        if 2 * n > D + 20 and abs(j) * n * n < eps:
            break
        n += 1
    u = amp * (1 - mpmath.besselj(0, D) + D * mpmath.besselj(1, D) * mpmath.acosh(r) + 2 * su)
    du = 4 * amp / a * pre * sdu
    return u, du


def ball_decimal_inputs():
    """(fn, args) with every argument a decimal string."""
    out = []
    for a, b1, b2 in [("0.5", "1", "1.5"), ("0.3", "1.1", "2.7"), ("1.5", "-0.5", "0.25"),
                      ("0.5", "-1.9999999999", "1.5"), ("0.5", "-2.00000000000000000001", "1.5"),
                      ("0.5", "8", "8.5"), ("0.5", "1001", "1001.5")]:
        for z in ("-300.1", "-0.3", "-12.345678901234567890123", "2.7", "-1000.01", "0.1"):
            out.append(("hyp1f2", (a, b1, b2, z)))
    for k in (0, 1, 7, 100, 1000):
        # y <= 0.99: mpmath's 3F2 at |y| -> 1 needs ~prec/(1-y) terms at 1300 bits
        for y in ("0.3", "0.1", "0.5", "0.75", "0.9", "0.95", "0.99", "0.6",
                  "1e-10", "0.123456789012345678901234567890"):
            out.append(("meijer_g_k", (str(k), y)))
    wave = [("1.3", "0.1", "1", "1.3"), ("50", "0.1", "1", "50"), ("2.7", "1.1", "0.3", "2.7"),
            ("6", "1.125", "0.1", "6"), ("0.7", "0.3", "1", "0.7")]
    for a, zeta in (("1.3", "1.125"), ("2.7", "1.1"), ("6", "1.125"), ("0.7", "0.3")):
        for x in ("1.0000000001", "1.001", "1.35", "2.9"):
            # x = a * ratio, an exact decimal product of the two strings
            with decimal.localcontext() as ctx:
                ctx.prec = 100
                xd = str(decimal.Decimal(a) * decimal.Decimal(x))
            wave.append((a, zeta, "0.7", xd))
    for a, zeta, amp, x in wave:
        out.append(("u_wave", (a, zeta, amp, x)))
        if not (a == "50"):
            out.append(("du_wave", (a, zeta, amp, x)))
    return out


def ball_decimal_value(fn, args):
    if fn == "hyp1f2":
        a, b1, b2, z = args
        return mpmath.hyp1f2(mpf(a), mpf(b1), mpf(b2), mpf(z))
    if fn == "meijer_g_k":
        # the closed form through 3F2 (mg_S_hyp3f2; the golden table checks it
        # against mpmath.meijerg, which is ~100x slower at 1300 bits)
        k, y = args
        return mg_from_S(int(k), y, mg_S_hyp3f2(int(k), y))[0]
    a, zeta, amp, x = args
    if fn == "u_wave" and a == x:
        # the edge value A (1 - cos(2 pi a/zeta)) (docs/displacement.md, Route 2)
        return mpf(amp) * (1 - mpmath.cos(2 * mpmath.pi * mpf(a) / mpf(zeta)))
    u, du = wave_bessel_ref(a, zeta, amp, x)
    return u if fn == "u_wave" else du


def ball_decimal_rows():
    rows = []
    for fn, args in ball_decimal_inputs():
        vals = []
        for bits in BALL_DECIMAL_BITS:
            mp.prec = bits
            vals.append(ball_decimal_value(fn, args))
        mp.prec = BALL_DECIMAL_BITS[1]
        scale = max(abs(vals[1]), mpf(10) ** -200)
        if fn in ("u_wave", "du_wave"):
            scale = max(scale, abs(mpf(args[2])))
        if not abs(vals[0] - vals[1]) / scale < mpf(10) ** -(BALL_DECIMAL_OUT_DIGITS + 20):
            log("ball_decimal: reject %s %s" % (fn, args))
            continue
        rows.append((fn, " ".join(args), mpmath.nstr(vals[1], BALL_DECIMAL_OUT_DIGITS, min_fixed=1, max_fixed=0)))
    return rows


def write_ball_decimal():
    return write_decimal_table(
        "ball_inputs_decimal",
        ["1F2, G(k, y), u_w, du_w/dx at the DECIMALS as typed (args: space-separated decimal strings);"],
        BALL_DECIMAL_BITS, BALL_DECIMAL_OUT_DIGITS, "fn,args,value", ball_decimal_rows())


# --------------------------------------------------------------------------
# The model's strip ratio m and load at decimal parameters (the ball contract)
# --------------------------------------------------------------------------

MODEL_DECIMAL_BITS = (700, 900)
MODEL_DECIMAL_OUT_DIGITS = 100
# sqrt(2)/4 (Fig. 4c's alpha) typed to 40 digits: not a binary fraction.
FIG4C_ALPHA = "0.3535533905932737622004221810524245196424"


def model_cylinder_gap(lam, abar, e):
    """The Hertz and adhesive terms of the strip gap at m = 1 + e (Eq. 15b)."""
    m = 1 + e
    s = mpmath.sqrt(e * (e + 2))
    acosh_m = mpmath.acosh(m)
    hertz = abar ** 2 / 2 * (m * s - acosh_m)
    adhesive = 4 / mpmath.pi * lam * abar * (s * acosh_m - m * mpmath.log(m))
    return hertz + adhesive


def model_wave_gap(alpha, beta, abar, e):
    """One wave's term of the strip gap at m = 1 + e; u_w by the Bessel form."""
    if alpha == 0:
        return 0
    m = 1 + e
    u = wave_bessel_ref(abar, beta, alpha, m * abar)[0]
    return 2 * alpha * mpmath.sin(mpmath.pi * m * abar / beta) ** 2 - u


def model_residual(lam, alpha, beta, abar, e):
    """F(m) = lambda gbar(m abar) - 1 of Eq. 15b (corrected, docs/model.md),
    m = 1 + e, at mpmath's current precision; u_w by the Bessel form."""
    return lam * (model_cylinder_gap(lam, abar, e) + model_wave_gap(alpha, beta, abar, e)) - 1


def model_first_root(args, residual=None):
    """The first root e = m - 1 > 0 of F (F(1) = -1 < 0): a scan on a
    geometric grid of e and bisection at 80 bits, then the secant method at
    the current precision, and a proven-by-evaluation sign change of F across
    the result at that precision. `residual(lam, alpha, beta, abar, e)` is
    `model_residual` unless given (reference/model_rough.py passes its own)."""
    residual = residual or model_residual
    work = mp.prec
    mp.prec = 80
    lam, alpha, beta, abar = (mpf(v) for v in args)
    f = lambda e: residual(lam, alpha, beta, abar, e)
    lo = hi = None
    prev = mpf(0)
    for i in range(2400):
        e = mpf(10) ** -14 * mpf("1.02") ** i
        if f(e) > 0:
            lo, hi = prev, e
            break
        prev = e
    if hi is None:
        raise ValueError("no sign change of F below e = %s" % e)
    while hi - lo > hi * mpf(2) ** -70:
        mid = (lo + hi) / 2
        if f(mid) > 0:
            hi = mid
        else:
            lo = mid
    mp.prec = work
    lam, alpha, beta, abar = (mpf(v) for v in args)
    f = lambda e: residual(lam, alpha, beta, abar, e)
    root = mpmath.findroot(f, (mpf(lo), mpf(hi)), solver="secant", tol=mpf(2) ** (-2 * work))
    delta = abs(root) * mpf(2) ** (-work + 20)
    if not (f(root - delta) < 0 < f(root + delta)):
        raise ValueError("no sign change of F across the refined root at %d bits" % work)
    return root


def model_load(args, m):
    lam, alpha, beta, abar = (mpf(v) for v in args)
    d = 2 * mpmath.pi * abar / beta
    return (mpmath.pi * abar ** 2 / 4 - 2 * lam * abar * mpmath.sqrt(m * m - 1)
            + mpmath.pi ** 2 * alpha * abar / beta * mpmath.besselj(1, d))


def model_decimal_inputs():
    """(lambda, alpha, beta, abar) decimal strings: Fig. 4c roughness, the
    smooth cylinder, a large lambda (m -> 1) and decimals that are not binary."""
    out = []
    for lam in ("0.25", "1", "3", "6", "0.3"):
        for abar in ("0.7", "2.2", "3.16"):
            out.append((lam, FIG4C_ALPHA, "1.125", abar))
    for lam, abar in (("0.1", "1.3"), ("1", "0.7"), ("10", "2.5"), ("1000", "1.7")):
        out.append((lam, "0", "1.125", abar))
    out.append(("2.7182818284590452353602874713526624977572", "0.1", "0.3", "1.4142135623730950488"))
    out.append(("6", "0.35", "1.1", "1.05"))
    return out


def model_decimal_rows():
    rows = []
    for args in model_decimal_inputs():
        vals = []
        for bits in MODEL_DECIMAL_BITS:
            mp.prec = bits
            m = 1 + model_first_root(args)
            vals.append((m, model_load(args, m)))
        mp.prec = MODEL_DECIMAL_BITS[1]
        (m0, l0), (m1, l1) = vals
        tol = mpf(10) ** -(MODEL_DECIMAL_OUT_DIGITS + 20)
        if not (abs(m0 - m1) < tol * abs(m1) and abs(l0 - l1) < tol * max(abs(l1), 1)):
            log("model_decimal: reject %s" % (args,))
            continue
        fmt = lambda v: mpmath.nstr(v, MODEL_DECIMAL_OUT_DIGITS, min_fixed=1, max_fixed=0)
        rows.append(args + (fmt(m1), fmt(l1)))
        log("model_decimal: %s m = %s" % (args, mpmath.nstr(m1, 12)))
    return rows


def write_model_decimal():
    return write_decimal_table(
        "model_decimal",
        ["the strip ratio m (first root of Eq. 15b, corrected) and the load (Eq. 14) at the DECIMALS as typed;",
         "F by the Bessel form of u_w, root by a scan at 80 bits and bisection at each precision;"],
        MODEL_DECIMAL_BITS, MODEL_DECIMAL_OUT_DIGITS, "lambda,alpha,beta,abar,m,load", model_decimal_rows())


# Many waves (issue 35): the strip ratio and the load of a profile of several waves at
# decimals as typed; the waves' terms of F and of the load summed (docs/model.md,
# "Many waves"). Columns: lambda, abar, waves (alpha_1 beta_1 alpha_2 beta_2 ...,
# space-separated), m, load.
def model_waves_decimal_inputs():
    two = ((FIG4C_ALPHA, "1.125"), ("0.1767766952966368811002110905262122598212", "0.375"))
    out = [("3", abar, two) for abar in ("0.7", "2.2", "3.16")]
    out.append(("0.5", "1.5", two))
    out.append(("6", "2.5", two))
    out.append(("1", "1.3", (("0.3", "1.2"), ("0.21", "0.6"), ("0.15", "0.3"))))
    out.append(("2.7182818284590452353602874713526624977572", "1.4142135623730950488", (("0.1", "0.3"), ("0", "0.7"), ("0.05", "0.11"))))
    return out


def model_waves_residual(waves):
    """F(m) of Eq. 15b for the profile `waves` (decimal strings), m = 1 + e."""
    def residual(lam, _alpha, _beta, abar, e):
        wave = sum(model_wave_gap(mpf(a), mpf(b), abar, e) for a, b in waves)
        return lam * (model_cylinder_gap(lam, abar, e) + wave) - 1
    return residual


def model_waves_load(lam, abar, waves, m):
    lam, abar = mpf(lam), mpf(abar)
    load = mpmath.pi * abar ** 2 / 4 - 2 * lam * abar * mpmath.sqrt(m * m - 1)
    for a, b in waves:
        alpha, beta = mpf(a), mpf(b)
        load += mpmath.pi ** 2 * alpha * abar / beta * mpmath.besselj(1, 2 * mpmath.pi * abar / beta)
    return load


def model_waves_decimal_rows():
    rows = []
    for lam, abar, waves in model_waves_decimal_inputs():
        vals = []
        for bits in MODEL_DECIMAL_BITS:
            mp.prec = bits
            # model_first_root reads (lambda, alpha, beta, abar); the residual ignores alpha, beta
            m = 1 + model_first_root((lam, "0", "1", abar), model_waves_residual(waves))
            vals.append((m, model_waves_load(lam, abar, waves, m)))
        mp.prec = MODEL_DECIMAL_BITS[1]
        (m0, l0), (m1, l1) = vals
        tol = mpf(10) ** -(MODEL_DECIMAL_OUT_DIGITS + 20)
        if not (abs(m0 - m1) < tol * abs(m1) and abs(l0 - l1) < tol * max(abs(l1), 1)):
            log("model_waves_decimal: reject %s" % ((lam, abar, waves),))
            continue
        fmt = lambda v: mpmath.nstr(v, MODEL_DECIMAL_OUT_DIGITS, min_fixed=1, max_fixed=0)
        flat = " ".join(v for w in waves for v in w)
        rows.append((lam, abar, flat, fmt(m1), fmt(l1)))
        log("model_waves_decimal: %s %s %s m = %s" % (lam, abar, flat, mpmath.nstr(m1, 12)))
    return rows


def write_model_waves_decimal():
    return write_decimal_table(
        "model_waves_decimal",
        ["the strip ratio m (first root of Eq. 15b, corrected) and the load (Eq. 14) of a profile of MANY waves",
         "at the DECIMALS as typed (waves: alpha_1 beta_1 alpha_2 beta_2 ..., the waves' terms summed);",
         "F by the Bessel form of each u_w, root by a scan at 80 bits and bisection at each precision;"],
        MODEL_DECIMAL_BITS, MODEL_DECIMAL_OUT_DIGITS, "lambda,abar,waves,m,load", model_waves_decimal_rows())


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--only", default="bessel_j,hyp1f2,hyp2f1,meijer_g_k,bessel_j_decimal,bessel_j_tiny_decimal,hyp2f1_decimal,bessel_j_grid,ball_inputs_decimal,model_decimal,model_waves_decimal")
    ap.add_argument("--limit", type=int, default=0, help="debug: only the first N points per table")
    args = ap.parse_args()
    tables = args.only.split(",")
    os.makedirs(DATA, exist_ok=True)
    if "bessel_j_grid" in tables:
        write_bessel_j_grid(args.jobs)
        tables = [t for t in tables if t != "bessel_j_grid"]
        if not tables:
            return
    if "bessel_j_tiny_decimal" in tables:
        write_bessel_j_tiny_decimal()
        tables = [t for t in tables if t != "bessel_j_tiny_decimal"]
        if not tables:
            return
    if "bessel_j_decimal" in tables:
        write_bessel_j_decimal()
        tables = [t for t in tables if t != "bessel_j_decimal"]
        if not tables:
            return
    if "model_waves_decimal" in tables:
        write_model_waves_decimal()
        tables = [t for t in tables if t != "model_waves_decimal"]
        if not tables:
            return
    if "model_decimal" in tables:
        write_model_decimal()
        tables = [t for t in tables if t != "model_decimal"]
        if not tables:
            return
    if "ball_inputs_decimal" in tables:
        write_ball_decimal()
        tables = [t for t in tables if t != "ball_inputs_decimal"]
        if not tables:
            return
    if "hyp2f1_decimal" in tables:
        write_hyp2f1_decimal()
        tables = [t for t in tables if t != "hyp2f1_decimal"]
        if not tables:
            return
    t_start = time.time()
    log("maugis reference generator: mpmath %s, backend %s, %d workers" % (mpmath.__version__, mpmath.libmp.BACKEND, args.jobs))
    ctx = mproc.get_context("fork")
    with ctx.Pool(args.jobs) as pool:
        points = {}
        if "bessel_j" in tables:
            log("computing Bessel zeros for near_zeros ...")
            points["bessel_j"] = bessel_points(pool)
        if "hyp1f2" in tables:
            points["hyp1f2"] = hyp1f2_points()
        if "hyp2f1" in tables:
            points["hyp2f1"] = [((a, b, c, z), r) for (a, b, c, z), r in hyp2f1_points()]
        if "meijer_g_k" in tables:
            points["meijer_g_k"] = meijer_points()
            points["meijer_overlap"] = [(inp, "overlap") for inp in meijer_overlap_inputs()]
        if args.limit:
            for t in points:
                points[t] = points[t][: args.limit]
        tasks = []
        for t, plist in points.items():
            for i, (inp, region) in enumerate(plist):
                if t == "hyp2f1":
                    inp = inp + (region,)
                tasks.append(((t, i), t, inp))
        # expensive tasks first (rough cost model) for better load balance
        def cost(task):
            (t, _), _, inp = task
            if t == "meijer_overlap":
                return 1e9 if "hyp3f2" in inp[2:4] and inp[1] > 0.95 else 10
            if t == "bessel_j":
                n, x = inp
                return abs(x) ** 2 / 1e4 + (abs(n) if abs(x) > 0.5 * abs(n) else 0)
            if t == "meijer_g_k":
                return 50 if inp[2] == "closed_form_quad" else 1
            return 1
        tasks.sort(key=lambda tk: -cost(tk))
        for t, plist in points.items():
            log("  %-15s %5d points" % (t, len(plist)))
        results = {}
        stats = {t: dict(kept=0, rejected=0, xfail=0, tier2=0, done=0, time=0.0) for t in points}
        notes = []
        last = time.time()
        for n_done, (idx, st, val, info, dt) in enumerate(pool.imap_unordered(run_task, tasks, chunksize=1), 1):
            t = idx[0]
            results[idx] = (st, val, info)
            s = stats[t]
            s["done"] += 1
            s["time"] += dt
            if st == "ok":
                s["kept"] += 1
                if info[0] == TIERS[1]:
                    s["tier2"] += 1
                if info[2]:
                    notes.append((idx, points[t][idx[1]][0], "note: %s" % (info[2],)))
            else:
                s["rejected"] += 1
                if st in ("xcheck_fail", "overlap_fail"):
                    s["xfail"] += 1
                notes.append((idx, points[t][idx[1]][0], "%s: %s" % (st, info)))
                log("  [%s] %s %s: %s" % (t, points[t][idx[1]][0], st, info))
            if time.time() - last > 20 or n_done == len(tasks):
                last = time.time()
                log("[%7.1fs] %d/%d tasks  " % (time.time() - t_start, n_done, len(tasks))
                    + "  ".join("%s %d/%d (rej %d)" % (tt, ss["done"], len(points[tt]), ss["rejected"]) for tt, ss in stats.items()))

    # ----- overlap assertions (Meijer G)
    failed = False
    if "meijer_overlap" in points:
        for i, (inp, _) in enumerate(points["meijer_overlap"]):
            st, val, info = results[("meijer_overlap", i)]
            log("overlap check k=%d y=%r %s vs %s: %s" % (inp[0], inp[1], inp[2], inp[3], st))
            if st != "ok":
                log("   " + str(info))
                failed = True
    if "meijer_g_k" in points:
        for i, (inp, region) in enumerate(points["meijer_g_k"]):
            st, val, info = results[("meijer_g_k", i)]
            if inp[2] == "meijerg" and st != "ok":
                log("meijerg overlap failed at k=%d y=%r: %s %s" % (inp[0], inp[1], st, info))
                failed = True
    if failed:
        log("ABORT: overlap assertion failed; no tables written")
        sys.exit(1)

    # ----- write tables
    summary = []
    for t in ("bessel_j", "hyp1f2", "hyp2f1", "meijer_g_k"):
        if t not in points:
            continue
        rows = []
        for i, (inp, region) in enumerate(points[t]):
            st, val, info = results[(t, i)]
            if st == "ok":
                rows.append((inp, val, region))
        path = write_table(t, rows, stats[t])
        summary.append((t, stats[t], path))
    log("")
    log("%-12s %7s %9s %8s %8s %10s %9s" % ("function", "kept", "rejected", "xfail", "tier2", "cpu[s]", "size[kB]"))
    for t, s, path in summary:
        log("%-12s %7d %9d %8d %8d %10.1f %9.1f" % (t, s["kept"], s["rejected"], s["xfail"], s["tier2"], s["time"], os.path.getsize(path) / 1024))
    log("total wall time %.1f s" % (time.time() - t_start))
    if notes:
        log("notes / rejections:")
        for idx, inp, msg in notes[:200]:
            log("  %s %s %s" % (idx[0], inp, msg))
    for t, s, _ in summary:
        if s["kept"] < 2000:
            log("ERROR: table %s has only %d kept rows" % (t, s["kept"]))
            sys.exit(2)


if __name__ == "__main__":
    main()
