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
]


def series(a, b, c, x):
    """2F1(a, b; c; x) for |x| < 1/2, term by term until a term is below
    2^-(prec+64) of the sum with the term ratio below 3/4 (the tail is then below
    four times that term, as the ratio tends to x)."""
    t = s = mpf(1)
    n = 0
    while True:
        r = (a + n) * (b + n) / ((c + n) * (n + 1)) * x
        t *= r
        s += t
        n += 1
        if abs(r) < mpf(3) / 4 and abs(t) < abs(s) * mpf(2) ** -(mp.prec + 64):
            return s


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


def value(a, b, c, z, how):
    f = {"pfaff": corners.pfaff_sum, "u": u_sum, "u_long": u_sum, "asym": asym}.get(how, mpmath.hyp2f1)
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
        "kept iff the two agree to %d digits; %d digits printed" % (DIGITS + 5, DIGITS),
    ]
    corners.write_table(OUT, "hyp2f1_exponent_range", notes, CASES, value)


if __name__ == "__main__":
    main()
