"""References for tests/it/hyp2f1_exponent_range.rs: MP 2F1 at decimal inputs of
issue 37's scan whose Gammas or Pfaff prefactor pass MPFR's exponent range
(2^(2^30)) while the value is an ordinary number (Gamma(4.2e18) at z = 1;
(1 - z)^(-7.4e17)); they were refused `Overflow`.

Usage:  python3 reference/hyp2f1_exponent_range.py
Writes reference/data/hyp2f1_exponent_range.csv: a,b,c,z,value,how where `how` is
`mpmath` (mpmath.hyp2f1 from the decimal strings; mpmath's numbers have no
exponent limit), `pfaff` (Pfaff's series term by term, from
hyp2f1_decimal_corners.py) or `u` (the connection formula in u = 1/(1 - z),
DLMF 15.8.2 with 15.8.1, both series term by term, for z < -1 where
mpmath.hyp2f1 runs for minutes at a parameter of 10^17), each at 600 and 900 bits
(`u_long`: 2000 and 2400 bits, for b - a with b = 2.4e-200) and kept iff the two
agree to 45 digits; `asym` (a = 2.2e14124, b = 2.4e-97: the formula in u with its
term of size (1-z)^(-a) dropped and Gamma(a-b)/Gamma(a) by its leading power,
relative error O(b/a + (b ln(a|z|))^2), checked below 1e-60); 40 significant
digits printed.

`lead` (two large parameters, a |z| past c and b |z| by more than 2^190; issue
37's scan refused them Overflow): Gamma(c)/Gamma(c-b) (a |z|)^(-b), the leading
term of Euler's integral after t = s/(a |z|) (src/special/hyp2f1/dominant_param.rs
proves the enclosure the library uses); its relative error is about
(b + 1)(c + b^2 + 1)/(a |z|) (an estimate; the three `mpmath` rows at a = 3.3e75
to 1e90 below, where mpmath.hyp2f1 answers, check it: observed 1e-75 to 1e-64),
required below 1e-60 and at the scan's inputs below 1e-1000.
"""
import os
import sys

import mpmath
from mpmath import mp, mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hyp2f1_decimal_corners as corners  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "data", "hyp2f1_exponent_range.csv")
DIGITS = corners.DIGITS

# (a, b, c, z, how): the decimal strings as the scan's generator typed them
CASES = [
    # Gauss's sum at z = 1 with Gamma(4.2e18): issue 37's example
    ("-75.5", "25.6", "4.2e18", "1", "mpmath"),
    # the Pfaff prefactor (1 - z)^(-7.4e17) below 2^-(2^30): issue 37's example
    ("7.4e17", "2.4e-17", "23.4", "-177.9", "u"),
    # a = 4.3e18 at z = -15.375: refused TooExpensive before (the large-parameter
    # route's loss estimate took b as the large parameter); hyp2f1_decimal_corners.rs
    ("4311539713351952334", "27.5945093881107", "18.875", "-15.375", "u"),
    # one tiny positive parameter, z < 0 (the enclosure [1 - w, 1] of
    # src/special/hyp2f1/small_parameter.rs): at 128 bits w = 1.03e-39 against
    # 1 - F = 8.7e-40, the bound's lower end tested
    ("1e18", "2e-41", "2.5", "-20", "u"),
    # issue 37's scan (seed 1), refused Overflow: b - a needs 723 bits
    ("740270133684064828", "0.0000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000002437002768192932", "23.407052208362096", "-177.875", "u_long"),
    # issue 37's scan, refused Overflow: a tiny negative b, [1, 1 + w]
    ("2165949117243957876", "-0.000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000001", "23.46340274615762", "-20", "u_long"),
    # issue 37's scan (seed 1), refused Overflow: a = 2.2e14124
    ("22.377422829558384e14123", "0.00000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000024166077292173306", "2.5", "-238.25", "asym"),
    # two large parameters, a |z| >> c (dominant_param.rs): mpmath.hyp2f1 answers
    # these; the route applies at 128 bits (a |z| / c past 2^200)
    ("1e80", "2.5", "1e5", "-3", "mpmath"),
    ("3.3e75", "23.38", "2.475e12", "-222.375", "mpmath"),
    ("1e90", "27.39", "2.9e20", "-8", "mpmath"),
    # issue 37's scan (hyp2f1 alone, seed 1, and the full scan, seed 2), refused
    # Overflow: a of 10^13207 to 10^30654 with c of 10^599 to 10^16057
    ("26.62112943576951e24590", "27.391839793295098", "29.06392735855222e598", "-8", "lead"),
    ("0.9999999999999998e30654", "22.42311673806016", "22.994783413536595e10919", "-45.25", "lead"),
    ("181.5e25521", "2.3700497835751037e1", "0.0000000000000000000000000000000000000000000000000000000000000000000000000000000000000000009532593067071918e16145", "-155.5", "lead"),
    ("0.00000000000000000000005762613620960503e20842", "2.4048043416439157e1", "28.596813675772538e1284", "-14", "lead"),
    ("0.00000000000000000000000000000000000000000000000000000000000000000000000000000000000004005305780528599e13291", "23.384769896797522", "24.75e12503", "-222.375", "lead"),
    # neighbours: b below 1 (c = b + 1, the route's edge), and a symmetric case
    ("7.5e3000", "0.75", "1.75", "-0.5", "lead"),
    ("3.5", "4.5e5000", "1e20", "-2", "lead"),
    # issue 37's full scan (seed 1), refused Overflow: a tiny negative b with a tiny
    # c (the split integral of small_parameter.rs, [1, 1 + w], w about 4e-5772)
    ("0." + "0" * 90 + "41711284033363465e11056", "-202e-5878", "0." + "0" * 104 + "935750676677635", "-1", "asym"),
]


series = corners.series


def u_sum(a, b, c, z):
    """2F1(a, b; c; z), z < -1, by the formula in u = 1/(1 - z):
    Gamma(c) Gamma(b-a) / (Gamma(b) Gamma(c-a)) (1-z)^(-a) F(a, c-b; a-b+1; u)
    + Gamma(c) Gamma(a-b) / (Gamma(a) Gamma(c-b)) (1-z)^(-b) F(b, c-a; b-a+1; u)."""
    a, b, c, z = (mpf(x) for x in (a, b, c, z))
    u = 1 / (1 - z)
    t1 = mpmath.gammaprod([c, b - a], [b, c - a]) * (1 - z) ** (-a) * series(a, c - b, a - b + 1, u)
    t2 = mpmath.gammaprod([c, a - b], [a, c - b]) * (1 - z) ** (-b) * series(b, c - a, b - a + 1, u)
    return t1 + t2


def asym(a, b, c, z):
    """2F1(a, b; c; z) for a huge, b tiny, z < 0: the formula in u = 1/(1 - z)
    with its first term (of size (1-z)^(-a)) dropped, Gamma(a-b)/Gamma(a) =
    a^(-b) (1 + O(b/a)) and its series F(b, c-a; b-a+1; u) = (1-u)^(-b) (1 + O(b^2)
    + O(b/a)): Gamma(c)/Gamma(c-b) (a |z|)^(-b), relative error O(b/a + (b ln(a|z|))^2),
    checked below 1e-60 before use."""
    a, b, c, z = (mpf(x) for x in (a, b, c, z))
    err = abs(b) / a + (b * mpmath.log(a * abs(z))) ** 2
    if not (a > 0 and z < 0 and err < mpf(10) ** -60):
        raise SystemExit("asym does not apply at %r" % ((a, b, c, z),))
    return mpmath.gammaprod([c], [c - b]) * mpmath.exp(-b * mpmath.log(a * -z))


def lead(a, b, c, z):
    """2F1(a, b; c; z) for a |z| >> c, b |z| (z < 0, a > 0, c >= b + 1): the
    leading term Gamma(c)/Gamma(c-b) (a |z|)^(-b) (module docs; a and b swapped
    when b is the larger)."""
    a, b, c, z = (mpf(x) for x in (a, b, c, z))
    if b > a:
        a, b = b, a
    x = -z
    err = (b + 1) * (c + b * b + 1) / (a * x)
    if not (a > 0 and b > 0 and c >= b + 1 and x > 0 and err < mpf(10) ** -60):
        raise SystemExit("lead does not apply at %r" % ((a, b, c, z),))
    # ln Gamma(c) - ln Gamma(c - b) cancels log2(c ln c) bits: carried at that much more
    with mpmath.workprec(mp.prec + int(mpmath.log(c * mpmath.log(c + 2), 2)) + 64):
        ratio = mpmath.loggamma(c) - mpmath.loggamma(c - b)
    return mpmath.exp(ratio - b * mpmath.log(a * x))


def value(a, b, c, z, how):
    f = {"pfaff": corners.pfaff_sum, "u": u_sum, "u_long": u_sum, "asym": asym, "lead": lead}.get(how, mpmath.hyp2f1)
    vals = []
    # u_long: b - a needs log2(a/b) bits before any digit of the value
    for p in (2000, 2400) if how == "u_long" else (600, 900):
        mp.prec = p
        vals.append(f(mpf(a), mpf(b), mpf(c), mpf(z)))
    if not abs(vals[0] - vals[1]) <= abs(vals[1]) * mpf(10) ** -(DIGITS + 5):
        raise SystemExit("%s at 600 and 900 bits disagree at %r" % (how, (a, b, c, z)))
    return vals[1]


def main():
    notes = [
        "2F1(a, b; c; z) at the DECIMALS as typed (issue 37's Overflow refusals); how: mpmath.hyp2f1,",
        "pfaff: Pfaff's series term by term, u: the formula in 1/(1-z) term by term; at 600 and 900 bits,",
        "(u_long: 2000 and 2400), asym: Gamma(c)/Gamma(c-b) (a|z|)^-b (a huge, b tiny; error below 1e-60),",
        "lead: the same leading term for a|z| >> c, b|z| (two large parameters; error estimate below 1e-60),",
        "kept iff the two agree to %d digits; %d digits printed" % (DIGITS + 5, DIGITS),
    ]
    corners.write_table(OUT, "hyp2f1_exponent_range", notes, CASES, value)


if __name__ == "__main__":
    main()
