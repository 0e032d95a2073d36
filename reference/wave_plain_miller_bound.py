#!/usr/bin/env python3
"""The best bound a proof could give for u_w and du_w/dx computed from a PLAIN
(uncompensated) f64 Miller recurrence (issue 23, item 5; docs/performance.md,
"u_w and du_w/dx in f64").

Usage:  python3 reference/wave_plain_miller_bound.py        (mpmath 1.3.0, ~1 min)

The one-pass bounded route (src/contact/displacement/bounded/value.rs) carries
each p_k of Miller's recurrence p_{k-1} = c_k p_k - p_{k+1}, c_k = 2k/D, as a
compensated pair h + l.  Dropping the compensation would halve the loop; this
script measures what that would cost in the bound.

The plain recurrence commits at step k (forming p_{k-1}) a local error
|delta_k| <= u (|p_{k-1}| + 2.01 c_k |p_k|) (one fused multiply-add, the
multiplier fl(2k fl(1/D)) within 2.01 u).  A local error propagates to the
lower orders as the solution w of the recurrence with w_k = 0, w_{k-1} = 1
(the Green's function, (pi D/2)|J_j Y_k - Y_j J_k| [DLMF 10.5.2]), and the
outputs are the ratios R = B(p)/Lambda(p) of linear functionals (Lambda the
normalisation p_0 + 2 sum p_{2m}, B the numerators of u_w and of the gradient's
sum S; module docs of value.rs).  A perturbation changes R by
(B(w) - R Lambda(w))/Lambda (first order), so the smallest bound the triangle
inequality over the steps allows is

    sum_k |delta_k| |B(w^(k)) - R Lambda(w^(k))| / |Lambda|,

with every w^(k) exact (here in 60-digit arithmetic): no analysis of the
recurrence can prove less without knowing the signs of the roundings.  It is
printed as a fraction of the scales max(|u_w|, A) and max(|du_w/dx|, 2 pi A/zeta)
(A = 1, zeta = 9/8), in total and per region of the step index k:
top (k > 1.5 D), mid (D < k <= 1.5 D), osc (D/2 < k <= D), low (k <= D/2).
M = 2 (N + 1) with N the truncation of value.rs (both Bessel tails below 2^-64).
"""
import mpmath as mp

mp.mp.dps = 60
U = mp.mpf(2) ** -53
ZETA = mp.mpf(9) / 8


def truncation(d):
    """N: both tails sum_{n>N} (D/2)^{2n}/(2n)! and sum_{n>N} n^2 (D/2)^{2n}/(2n)! below 2^-64."""
    h = d / 2
    for n_cut in range(1, 400):
        t0 = mp.nsum(lambda n: h ** (2 * n) / mp.factorial(2 * n), [n_cut + 1, mp.inf])
        t2 = mp.nsum(lambda n: n * n * h ** (2 * n) / mp.factorial(2 * n), [n_cut + 1, mp.inf])
        if t0 < mp.mpf(2) ** -64 and t2 < mp.mpf(2) ** -64:
            return n_cut
    raise ValueError("D too large")


def region(k, d):
    if k > 1.5 * d:
        return "top"
    if k > d:
        return "mid"
    return "osc" if k > d / 2 else "low"


def bounds(a, ratios):
    d = 2 * mp.pi * a / ZETA
    top = truncation(d) + 1
    m = 2 * top
    c = [2 * k / d for k in range(m + 2)]
    p = [mp.mpf(0)] * (m + 2)
    p[m] = mp.mpf(1)
    for k in range(m, 0, -1):
        p[k - 1] = c[k] * p[k] - p[k + 1]
    f_lam = [mp.mpf(0)] * (m + 2)
    f_lam[0] = 1
    for i in range(1, top + 1):
        f_lam[2 * i] = 2
    lam = sum(f * v for f, v in zip(f_lam, p))
    # the Green's functions, one per step
    green = {}
    for k in range(m, 0, -1):
        w = [mp.mpf(0)] * (m + 2)
        w[k - 1] = mp.mpf(1)
        for j in range(k - 1, 0, -1):
            w[j - 1] = c[j] * w[j] - w[j + 1]
        green[k] = w
    rows = []
    for r in ratios:
        r = mp.mpf(r)
        t = mp.sqrt((r - 1) / (r + 1))
        q = (1 - t) / (1 + t)
        big_x = q * q
        y = -big_x
        # u_w = 1 + B_u/Lambda, B_u = -p_0 + D p_1 acosh(r) + 2 X sum_{m>=1} p_{2m} Y^{m-1}
        f_u = [mp.mpf(0)] * (m + 2)
        f_u[0] = -1
        f_u[1] = d * mp.acosh(r)
        for i in range(1, top + 1):
            f_u[2 * i] += 2 * big_x * y ** (i - 1)
        # du_w/dx = (8/a) q S/Lambda, S = sum_i V_i Y^i, V_{i} = sum_{n>i} (-1)^{n-1-i} n p_{2n}
        f_s = [mp.mpf(0)] * (m + 2)
        for n in range(1, top + 1):
            f_s[2 * n] = n * sum((-1) ** (n - 1 - i) * y ** i for i in range(n))
        r_u = sum(f * v for f, v in zip(f_u, p)) / lam
        r_s = sum(f * v for f, v in zip(f_s, p)) / lam
        scale_u = max(abs(1 + r_u), 1)
        du = 8 / a * q * r_s
        scale_s = max(abs(du), 2 * mp.pi / ZETA)
        per = {}
        for k, w in green.items():
            delta = U * (abs(p[k - 1]) + mp.mpf("2.01") * c[k] * abs(p[k]))
            eu = delta * abs(sum((f_u[j] - r_u * f_lam[j]) * w[j] for j in range(k))) / abs(lam) / scale_u
            es = delta * 8 / a * q * abs(sum((f_s[j] - r_s * f_lam[j]) * w[j] for j in range(k))) / abs(lam) / scale_s
            acc = per.setdefault(region(k, d), [mp.mpf(0), mp.mpf(0)])
            acc[0] += eu
            acc[1] += es
        tot_u = sum(v[0] for v in per.values())
        tot_s = sum(v[1] for v in per.values())
        rows.append((float(r), float(tot_u), float(tot_s), {kk: (float(v[0]), float(v[1])) for kk, v in per.items()}))
    return float(d), m, rows


def main():
    print("| a | D | M | x/a | bound u_w | bound du_w/dx | top | mid | osc | low (u / du each) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for a in [0.5, 1.5, 3, 4.5, 6]:
        d, m, rows = bounds(mp.mpf(a), [1, 1.01, 1.5, 3])
        for r, bu, bs, per in rows:
            cells = " | ".join(f"{per[k][0]:.1e} / {per[k][1]:.1e}" if k in per else "-" for k in ["top", "mid", "osc", "low"])
            print(f"| {a} | {d:.2f} | {m} | {r} | {bu:.2e} | {bs:.2e} | {cells} |", flush=True)


if __name__ == "__main__":
    main()
