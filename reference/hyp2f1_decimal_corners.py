"""References for tests/it/hyp2f1_decimal_corners.rs: MP 2F1 at the decimal inputs
that issue 23h's driver (tests/it/fuzz.rs `registry_mp_slow_scan`) found slow
(parameters like 2.9625e-28910, 2.6e18829, 4.3e18 next to moderate ones).

Usage:  python3 reference/hyp2f1_decimal_corners.py
Writes reference/data/hyp2f1_decimal_corners.csv: a,b,c,z,value,how where `how`
is `mpmath` (mpmath.hyp2f1 from the decimal strings at 600 and 900 bits, kept iff
they agree to 45 digits), `pfaff` (for z < 0: Pfaff's series in w = z/(z-1) summed
term by term at 600 and 900 bits, with the same test) or `sum` (a terminating series, a or b a non-positive
integer, summed term by term in mpmath from the decimal strings at 4000 and 8000
bits, kept iff they agree to 45 digits; mpmath.hyp2f1 gives up on it), or `inv_z`
(z < -1 with a tiny c: DLMF 15.8.2 in 1/z term by term, its Gamma ratios with an
integer difference as products, at 600 and 900 bits; mpmath.hyp2f1 runs for
minutes). 40
significant digits are printed.
"""
import os
import sys
import mpmath
from mpmath import mp, mpf

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "data", "hyp2f1_decimal_corners.csv")
DIGITS = 40

# (a, b, c, z, how): the decimal strings as the fuzz driver's generator typed them
CASES = [
    # a = -175 terminating, b = 5e-324 written out, c = 2.4e-4590, z = -192.125 (exact rationals: minutes before)
    ("-175", "0." + "0" * 323 + "5", "24.364055559326545e-4591", "-192.125", "sum"),
    # a = -220, b = 4.1e-2046, c = 4.4e-68, z = -2^63 (a majorant at 13 078 bits before)
    ("-2.2e2", "0." + "0" * 168 + "4088270749502687e-1873", "0." + "0" * 67 + "4380594785025259",
     "-9223372036854775808", "mpmath"),
    # a = -224, c = 2.6e18829: exact rationals of 10^5 bits before
    ("-224", "1.2925e2", "26.13864079447547e18828", "9.09851582217487e-117", "mpmath"),
    # a = -101, b = 1.1e-192, c = 1.0e-79, z = -17: 8.7 s (exact rationals of 1600-bit midpoints)
    ("-101", "1.1033944959127793e-192", "0." + "0" * 77 + "10158649451346211", "-17", "mpmath"),
    # issue 37's scan: the cost model planned 65 560 guard bits (an unconverged
    # Euler simulation read as |f|), the direct series then ran 5000 terms at 65 742
    # bits (2 s, then TooExpensive under a 0.1 s budget)
    ("24.1", "-34.875", "1000001", "0.5", "mpmath"),
    # issue 37's scan: c's decimal ball tightened to 54 000 bits, then ln, exp and
    # the series at that length (0.15 s at 157 bits)
    ("3", "10000", "2.304347624789777e1", "-4.25e1", "mpmath"),
    # issue 37's scan (seed 2): the logarithmic case after Pfaff (b - a = 83) with
    # z's decimal ball tightened to 58 000 bits: u = 1/(1-z), ln u and the series
    # at that length, 150 ms of CPU at 150 bits (refused under a 0.1 s budget)
    ("-245.25", "-162.25", "112.5", "-181.625e25051", "mpmath"),
    # issue 37's scan: c past the f64 range and z < -1 (Pfaff's c - b holds 97 000
    # bits, radius 2^31464 at 65 536 input bits): refused TooExpensive (Euler's
    # polynomial of degree 2^96800 for the majorant), then PrecisionExhausted
    # (the majorant's d/db bound M(B+1) is 2^31464 times the value)
    # (mpmath.hyp2f1 runs for minutes at this c: the Pfaff series, term by term)
    ("-1e-23409", "22.96", "3.4e29217", "-8", "pfaff"),
    ("1.5", "22.96", "3.4e29217", "-8", "pfaff"),
    # issue 37's scan: z far below -1 over decimal balls; Pfaff's w = 1 - 1/(1-z) next
    # to 1 made the majorant's bound useless (PrecisionExhausted at 65 536 input bits)
    ("2.6132634054252314e1", "38", "1.5", "-10.875e16463", "mpmath"),
    ("22.873558852592893", "98.25", "39", "-197.625e5243", "mpmath"),
    # issue 37's scan: polynomials (a = -9, -2) with b of 10^20000 and more held at
    # 65 536 bits; the majorant's d/db bound M(B+1) was 2^9500 times the value
    ("-9", "0.000000000000000004647996797235006e21871", "24.310973118189104e-26855", "-50.125", "sum"),
    ("-2", "27.70450403676515e20239", "22.60653980638881e-20850", "-2.1425e2", "sum"),
    # issue 37's scan: z far below -1 with a tiny c, refused PrecisionExhausted: c - b
    # (or c - a) within c of a pole, rounded onto it (mpmath.hyp2f1 runs for minutes)
    ("-206.375", "19", "0.5e-21620", "-0.5e10785", "inv_z"),
    ("0." + "0" * 156 + "10514588628797118", "164", "72.625e-27888", "-0.5e13643", "inv_z"),
    ("17", "22.94530994544671", "26.75e-30381", "-32.875e17468", "inv_z"),
    # neighbours: a moderate z, and c tiny but not as tiny
    ("-20.375", "7", "1e-300", "-1e40", "inv_z"),
    ("5", "2.5", "3e-100", "-1e20", "inv_z"),
    # issue 37's full scan (seeds 1 and 2), refused PrecisionExhausted: z far below -1
    # with b - a an integer (the logarithmic case, which the ball path lacked)
    ("-140.625", "242.375", "27.071079469956764", "-1e10556", "mpmath"),
    ("-0.5", "5e-1", "0.000001e-19395", "-14.875e5167", "mpmath"),
    # neighbours: moderate z, m = 0, 3 and 1
    ("2.25", "2.25", "1.1", "-3.7e3", "mpmath"),
    ("-1.5", "1.5", "0.3", "-1e30", "mpmath"),
    ("-0.5", "0.5", "1e-300", "-1e20", "mpmath"),
]


def poly_sum(a, b, c, z):
    """The terminating 2F1 (a or b a non-positive integer) summed term by term."""
    a, b, c, z = (mpf(x) for x in (a, b, c, z))
    deg = int(-a) if a == int(a) and a <= 0 else int(-b)
    t = s = mpf(1)
    for n in range(deg):
        t = t * (a + n) * (b + n) * z / ((c + n) * (n + 1))
        s += t
    return s


def pfaff_sum(a, b, c, z):
    """(1-z)^-a 2F1(a, c-b; c; w), w = z/(z-1) in (0, 1), summed term by term
    until a term is below 2^-(prec+64) of the sum with the term ratio below
    (1 + w)/2 (then the tail is below twice that term)."""
    a, b, c, z = (mpf(x) for x in (a, b, c, z))
    w = z / (z - 1)
    t = s = mpf(1)
    n = 0
    while True:
        r = (a + n) * (c - b + n) / ((c + n) * (n + 1)) * w
        t *= r
        s += t
        n += 1
        if abs(r) < (1 + w) / 2 and abs(t) < abs(s) * mpf(2) ** -(mp.prec + 64):
            break
    return (1 - z) ** (-a) * s


def series(a, b, c, x, past_poles=False):
    """2F1(a, b; c; x) for |x| < 1/2, term by term (with `past_poles`, past every
    sign change of c + n first), then until a term is below 2^-(prec+64) of the sum with the term ratio below
    3/4 (the tail is then below four times that term, as the ratio tends to x)."""
    t = s = mpf(1)
    n = 0
    while True:
        r = (a + n) * (b + n) / ((c + n) * (n + 1)) * x
        t *= r
        s += t
        n += 1
        if (not past_poles or n > -c) and abs(r) < mpf(3) / 4 and abs(t) < abs(s) * mpf(2) ** -(mp.prec + 64):
            return s


def gamma_ratio(x, y, d):
    """Gamma(x) / Gamma(y) with d = x - y: for an integer d (as typed) the product
    (x-1)...(x-d) (d > 0) or 1/((y-1)...(y-|d|)) (d < 0), where both Gammas may sit
    next to their poles; else mpmath.gamma of each."""
    if d == int(d) and 0 < abs(d) <= 5000:
        n = int(d)
        if n > 0:
            return mpmath.fprod(x - j for j in range(1, n + 1))
        return 1 / mpmath.fprod(y - j for j in range(1, -n + 1))
    return mpmath.gamma(x) / mpmath.gamma(y)


def inv_z(a, b, c, z):
    """2F1(a, b; c; z) for z < -1, b - a not an integer, by DLMF 15.8.2:
    G1 (-z)^(-a) F(a, a-c+1; a-b+1; 1/z) + G2 (-z)^(-b) F(b, b-c+1; b-a+1; 1/z),
    G1 = [Gamma(c)/Gamma(c-a)] [Gamma(b-a)/Gamma(b)], G2 likewise with a and b
    exchanged (each ratio by gamma_ratio), each series term by term past every
    sign change of its lower parameter (`series`; |1/z| is at most 1e-20 here)."""
    x = 1 / z
    g1 = gamma_ratio(c, c - a, a) * gamma_ratio(b - a, b, -a)
    g2 = gamma_ratio(c, c - b, b) * gamma_ratio(a - b, a, -b)
    return g1 * (-z) ** (-a) * series(a, a - c + 1, a - b + 1, x, True) + g2 * (-z) ** (-b) * series(b, b - c + 1, b - a + 1, x, True)


def value(a, b, c, z, how):
    f = {"sum": poly_sum, "pfaff": pfaff_sum, "inv_z": inv_z}.get(how, mpmath.hyp2f1)
    bits = (4000, 8000) if how == "sum" else (600, 900)
    vals = []
    for p in bits:
        mp.prec = p
        vals.append(f(mpf(a), mpf(b), mpf(c), mpf(z)))
    mp.prec = bits[1]
    if not abs(vals[0] - vals[1]) <= abs(vals[1]) * mpf(10) ** -(DIGITS + 5):
        raise SystemExit("%s at %d and %d bits disagree at %r" % (how, bits[0], bits[1], (a, b, c, z)))
    return vals[1]


def write_table(out, name, notes, cases, value):
    """Writes a reference table: the generator's header, `notes` as comment
    lines, then a,b,c,z,value,how for each case at DIGITS digits."""
    with open(out, "w") as fh:
        fh.write("# maugis reference table %s, generated by reference/%s.py\n" % (name, name))
        fh.write("# mpmath %s (backend %s), Python %s\n" % (mpmath.__version__, mpmath.libmp.BACKEND, sys.version.split()[0]))
        for line in notes:
            fh.write("# %s\n" % line)
        fh.write("a,b,c,z,value,how\n")
        for a, b, c, z, how in cases:
            v = value(a, b, c, z, how)
            fh.write("%s,%s,%s,%s,%s,%s\n" % (a, b, c, z, mpmath.nstr(v, DIGITS, min_fixed=1, max_fixed=0), how))
    print("wrote %s (%d rows)" % (out, len(cases)))


def main():
    notes = [
        "2F1(a, b; c; z) at the DECIMALS as typed (issues 23h and 37's slow inputs); how: mpmath.hyp2f1 at 600",
        "and 900 bits, pfaff: Pfaff's series term by term at 600 and 900 bits, or sum: the terminating",
        "series term by term at 4000 and 8000 bits; kept iff the two",
        "agree to %d digits; %d digits printed" % (DIGITS + 5, DIGITS),
    ]
    write_table(OUT, "hyp2f1_decimal_corners", notes, CASES, value)


if __name__ == "__main__":
    main()
