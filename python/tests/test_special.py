"""The special functions against independent references (mpmath, SciPy).

Every reference is computed here, at 50 digits, from mpmath's own algorithms
(or SciPy's), never from the Rust library.
"""

import math

import mpmath
import numpy as np
import pytest
import scipy.special

import maugis

mpmath.mp.dps = 50
mp = mpmath.mpf


def rel_err(got, ref):
    """|got - ref| / max(|ref|, tiny), elementwise, ref as mpf."""
    return np.array(
        [float(abs(mp(float(g)) - r) / max(abs(r), mp("1e-300"))) for g, r in zip(np.ravel(got), np.ravel(ref))]
    )


# ---------------------------------------------------------------- J_n


def test_bessel_j_orders_0_to_49_at_30_vs_mpmath():
    # The acceptance check: bessel_j(np.arange(50), 30.0) to 1e-14.
    got = maugis.bessel_j(np.arange(50), 30.0)
    ref = [mpmath.besselj(n, 30) for n in range(50)]
    assert got.shape == (50,) and got.dtype == np.float64
    assert np.all(np.abs(got - np.array([float(r) for r in ref])) <= 1e-14)
    assert rel_err(got, ref).max() <= 1e-14


@pytest.mark.parametrize("x", [1e-3, 0.5, 2.404825557695773, 7.0, 30.0, 99.5, -12.25, 1234.5])
def test_bessel_j_grid_vs_mpmath(x):
    n = np.array([-7, -1, 0, 1, 2, 5, 20, 60])
    got = maugis.bessel_j(n, x)
    ref = [mpmath.besselj(int(k), mp(x)) for k in n]
    # absolute near zeros of J, relative elsewhere (2 ulp promised)
    err = np.array([float(abs(mp(float(g)) - r)) for g, r in zip(got, ref)])
    scale = np.maximum(np.array([float(abs(r)) for r in ref]), 1e-300)
    assert np.all((err <= 4.5e-16 * scale) | (err <= 1e-16 * 1e-2))


def test_bessel_j_vs_scipy():
    n = np.arange(0, 40)[:, None]
    x = np.linspace(0.1, 60.0, 97)[None, :]
    got = maugis.bessel_j(n, x)
    ref = scipy.special.jv(n, x)
    assert got.shape == (40, 97)
    np.testing.assert_allclose(got, ref, rtol=1e-10, atol=1e-13)


def test_bessel_j_bounded_encloses_mpmath():
    n = np.array([0, 1, 3, 10, 31])
    x = np.array([0.75, 2.5, 14.0, 33.0, 100.0])
    val, err = maugis.bessel_j(n[:, None], x[None, :], bounded=True)
    assert val.shape == err.shape == (5, 5)
    assert np.all(err >= 0)
    for i, k in enumerate(n):
        for j, t in enumerate(x):
            exact = mpmath.besselj(int(k), mp(t))
            assert abs(mp(float(val[i, j])) - exact) <= mp(float(err[i, j]))


def test_bessel_j_at_zero_is_exact():
    val, err = maugis.bessel_j([0, 1, 4], 0.0, bounded=True)
    assert list(val) == [1.0, 0.0, 0.0] and list(err) == [0.0, 0.0, 0.0]


# ---------------------------------------------------------------- 1F2, 2F1


def test_hyp1f2_vs_mpmath():
    # including the Eq. 12 parameters 1F2(1/2; k+1, k+3/2; -s) with large s (cancellation)
    cases = [(0.5, 1.0, 1.5, -300.0), (0.5, 4.0, 4.5, -25.0), (1.25, 2.5, 0.75, 3.0), (-2.0, 1.5, 2.5, 7.0),
             (0.5, 11.0, 11.5, -280.5), (0.5, 1.0, 1.5, 0.0)]
    a, b1, b2, z = (np.array(c) for c in zip(*cases))
    got = maugis.hyp1f2(a, b1, b2, z)
    ref = [mpmath.hyp1f2(*(mp(v) for v in c)) for c in cases]
    assert rel_err(got, ref).max() <= 1e-14


def test_hyp2f1_vs_mpmath_and_scipy():
    # z near 1, at 1 (Gauss), negative z, the Eq. 11b family 2F1(1, k+1/2; k+2; y)
    cases = [(0.5, 0.5, 1.5, 0.999), (1.0, 10.5, 12.0, 0.75), (1.0, 0.5, 2.0, 0.9999), (0.25, 1.5, 3.0, 1.0),
             (2.0, 3.0, 4.5, -5.0), (-3.0, 2.0, 1.5, 0.3), (1.0, 100.5, 102.0, 0.5)]
    a, b, c, z = (np.array(v) for v in zip(*cases))
    got = maugis.hyp2f1(a, b, c, z)
    ref = [mpmath.hyp2f1(*(mp(v) for v in cs)) for cs in cases]
    assert rel_err(got, ref).max() <= 1e-14
    np.testing.assert_allclose(got, scipy.special.hyp2f1(a, b, c, z), rtol=1e-12)


def test_hyp2f1_bounded_encloses_mpmath():
    z = np.array([-0.5, 0.25, 0.5, 0.9, 0.999])
    val, err = maugis.hyp2f1(0.5, 1.5, 2.25, z, bounded=True)
    for v, e, t in zip(val, err, z):
        assert abs(mp(float(v)) - mpmath.hyp2f1(mp(0.5), mp(1.5), mp(2.25), mp(t))) <= mp(float(e))


# ---------------------------------------------------------------- Meijer G (Eq. 12)


def meijer_ref(k, y):
    return mpmath.re(mpmath.meijerg([[0, mp(1) / 2 - k], [1]], [[0, 0], [-k - 1]], -mp(y)))


@pytest.mark.parametrize("k", [0, 1, 3, 10])
def test_meijer_g_k_vs_mpmath(k):
    y = np.array([0.015625, 0.25, 0.5, 0.875])  # mpmath.meijerg is slow nearer y = 1
    got = maugis.meijer_g_k(k, y)
    ref = [meijer_ref(k, t) for t in y]
    err = np.array([float(abs(mp(float(g)) - r)) for g, r in zip(got, ref)])
    scale = np.maximum(np.array([float(abs(r)) for r in ref]), 1.0)
    assert np.all(err <= 1e-14 * scale)


@pytest.mark.parametrize("z", [-0.25, -400.0, -1225.0])
def test_hyp1f2_model_family_encloses_mpmath(z):
    kmax = 300
    val, err = maugis.hyp1f2_model_family(kmax, z)
    assert val.shape == err.shape == (kmax + 1,)
    assert np.all(err <= 1e-14 * np.abs(val))
    for k in (0, 1, 6, 7, 50, kmax):
        ref = mpmath.hyp1f2(mp(1) / 2, k + 1, k + mp(3) / 2, mp(z))
        assert abs(mp(float(val[k])) - ref) <= mp(float(err[k])), (k, z)


@pytest.mark.parametrize("y", [0.015625, 0.25, 0.875])
def test_meijer_g_k_family_encloses_mpmath(y):
    val, err = maugis.meijer_g_k_family(10, y)
    assert val.shape == (11,) and np.all(err <= 1e-14 * np.abs(val))
    for k in (0, 1, 3, 10):
        assert abs(mp(float(val[k])) - meijer_ref(k, y)) <= mp(float(err[k])), (k, y)


@pytest.mark.parametrize(
    "call",
    [
        lambda: maugis.meijer_g_k_family(10, 0.0),
        lambda: maugis.meijer_g_k_family(10, float("nan")),
        lambda: maugis.meijer_g_k_family(-1, 0.5),
        lambda: maugis.hyp1f2_model_family(1.5, -4.0),
        lambda: maugis.hyp1f2_model_family(10, float("inf")),
        lambda: maugis.hyp1f2_model_family(10**7, -4.0),
    ],
)
def test_families_reject_bad_input(call):
    with pytest.raises(ValueError):
        call()


# ---------------------------------------------------------------- wave displacement


def u_wave_ref(a, zeta, amp, x):
    """Bessel form of u_w (docs/displacement.md, route 2) with mpmath's J_n."""
    a, zeta, amp, x = (mp(v) for v in (a, zeta, amp, x))
    d = 2 * mpmath.pi * a / zeta
    r = x / a
    q = r - mpmath.sqrt(r * r - 1)
    total = 1 - mpmath.besselj(0, d) + d * mpmath.besselj(1, d) * mpmath.acosh(r)
    n = 1
    while True:
        term = 2 * (-1) ** (n + 1) * mpmath.besselj(2 * n, d) * q ** (2 * n)
        total += term
        if n > d and abs(term) < mp(10) ** -45:
            break
        n += 1
    return amp * total


def test_u_wave_vs_mpmath_bessel_form():
    # the paper's setting (beta = 9/8) at abar = 1, 3 and 6, from the edge outwards
    for a in (1.0, 3.0, 6.0):
        x = a * np.array([1.0, 1.001, 1.25, 2.0, 7.5])
        got = maugis.u_wave(a, 1.125, 0.5, x)
        for g, t in zip(got, x):
            ref = u_wave_ref(a, 1.125, 0.5, t)
            assert abs(mp(float(g)) - ref) <= 1e-14 * max(abs(ref), mp(0.5))


def test_du_wave_vs_mpmath_derivative():
    a, zeta, amp = 3.0, 1.125, 0.5
    x = np.array([3.003, 3.5, 4.25, 9.0])
    got = maugis.du_wave(a, zeta, amp, x)
    for g, t in zip(got, x):
        ref = mpmath.diff(lambda s: u_wave_ref(a, zeta, amp, s), mp(t))
        assert abs(mp(float(g)) - ref) <= 1e-13 * max(abs(ref), mp(1))


def test_u_wave_edge_value():
    # u_w(a) = A (1 - cos D)
    a, zeta, amp = 2.0, 1.125, 0.75
    d = 2 * math.pi * a / zeta
    assert maugis.u_wave(a, zeta, amp, a) == pytest.approx(amp * (1 - math.cos(d)), rel=1e-14)


def test_wave_bounded_encloses_mpmath():
    x = np.array([6.006, 7.0, 12.0])
    val, err = maugis.u_wave(6.0, 1.125, 1.0, x, bounded=True)
    for v, e, t in zip(val, err, x):
        assert abs(mp(float(v)) - u_wave_ref(6.0, 1.125, 1.0, t)) <= mp(float(e))
    dval, derr = maugis.du_wave(6.0, 1.125, 1.0, x, bounded=True)
    assert np.all(derr > 0) and np.all(np.isfinite(dval))


# ---------------------------------------------------------------- arbitrary precision


def test_prec_returns_certified_mpf_balls():
    mid, rad = maugis.bessel_j(5, 2.5, prec=200)
    assert isinstance(mid, mpmath.mpf) and isinstance(rad, mpmath.mpf)
    with mpmath.workdps(80):
        exact = mpmath.besselj(5, mpmath.mpf(2.5))
        assert abs(mid - exact) <= rad
        assert rad <= abs(mid) * mpmath.mpf(2) ** -200


def test_prec_mid_is_exact_binary_not_rounded_to_context():
    # the mpf midpoint keeps all its bits even though mpmath.mp.prec is smaller
    with mpmath.workprec(53):
        mid, rad = maugis.hyp2f1(0.5, 0.5, 1.5, 0.25, prec=300)
        assert mid.man.bit_length() > 200
    with mpmath.workdps(120):
        exact = mpmath.hyp2f1(0.5, 0.5, 1.5, mpmath.mpf(0.25))
        assert abs(mid - exact) <= rad


def test_prec_decimal_strings_enclose():
    mid, rad = maugis.meijer_g_k(1000, 1.0, prec=128, output="str", digits=30)
    assert isinstance(mid, str) and isinstance(rad, str)
    with mpmath.workdps(60):
        m, r = mpmath.mpf(mid), mpmath.mpf(rad)
        exact, _ = maugis.meijer_g_k(1000, 1.0, prec=190)
        assert abs(exact - m) <= r


def test_prec_inputs_mpf_and_strings():
    with mpmath.workprec(120):
        x = mpmath.mpf(1) / 3  # 120 bits, taken exactly
        mid, rad = maugis.bessel_j(2, x, prec=110)
        assert abs(mid - mpmath.besselj(2, x)) <= rad + mpmath.mpf(2) ** -118
    # a decimal string is a ball that contains the decimal, as in `maugis eval`
    mids, rads = maugis.bessel_j(2, "0.1", prec=110)
    with mpmath.workprec(400):
        assert abs(mids - mpmath.besselj(2, mpmath.mpf("0.1"))) <= rads + mpmath.mpf(2) ** -170


@pytest.mark.parametrize(
    "function, args, reference",
    [
        # J_1 at its first zero typed to 20 digits: the value at the decimal, not at its binary neighbour
        ("bessel_j", (1, "3.83170597020751231561"), lambda: mpmath.besselj(1, mpmath.mpf("3.83170597020751231561"))),
        # 2F1 next to z = 1: exactly 1e20 at the decimal
        ("hyp2f1", ("1", "2", "2", "0.99999999999999999999"), lambda: mpmath.mpf(10) ** 20),
        ("hyp1f2", ("0.5", "-2.00000000000000000001", "1.5", "-3.3"),
         lambda: mpmath.hyp1f2(mpmath.mpf("0.5"), mpmath.mpf("-2.00000000000000000001"), mpmath.mpf("1.5"), mpmath.mpf("-3.3"))),
        ("meijer_g_k", (7, "0.9"), lambda: mpmath.re(mpmath.meijerg([[0, mpmath.mpf(0.5) - 7], [1]], [[0, 0], [-8]], -mpmath.mpf("0.9")))),
        # u_w at the contact edge a = 50 with zeta = 0.1: 1 - cos(1000 pi) = 0
        ("u_wave", ("50", "0.1", "1", "50"), lambda: mpmath.mpf(0)),
    ],
)
def test_prec_strings_are_balls_that_contain_the_decimal(function, args, reference):
    mid, rad = getattr(maugis, function)(*args, prec=128)
    with mpmath.workprec(600):
        assert abs(mid - reference()) <= rad + mpmath.mpf(2) ** -500


@pytest.mark.parametrize(
    "function, args, message",
    [
        ("hyp2f1", ("0.3", "0.7", "1", "1"), "needs c - a - b > 0 over the whole ball"),
        ("hyp1f2", ("0.5", "-2", "1.5", "-3"), "pole"),
        ("meijer_g_k", (3, "1.5"), "y"),
    ],
)
def test_prec_edges_inside_the_input_raise(function, args, message):
    with pytest.raises(ValueError, match=message):
        getattr(maugis, function)(*args, prec=64)


def test_prec_broadcasts_to_object_arrays():
    mid, rad = maugis.bessel_j(np.arange(4)[:, None], [1.5, 3.0], prec=64)
    assert mid.shape == rad.shape == (4, 2) and mid.dtype == object
    for n in range(4):
        for j, x in enumerate([1.5, 3.0]):
            assert abs(mid[n, j] - mpmath.besselj(n, x)) <= rad[n, j] + mpmath.mpf(2) ** -100


def test_prec_wave_matches_bessel_form():
    mid, rad = maugis.u_wave(6, 1.125, 1, 6.006, prec=128)
    with mpmath.workdps(50):
        assert abs(mid - u_wave_ref(6, 1.125, 1, 6.006)) <= rad + mpmath.mpf(10) ** -44


def test_fallback_counts_snapshot_every_route_and_count_2f1():
    keys = {"bessel_j", "hyp1f2", "hyp2f1", "meijer_g_k", "wave_bounded", "wave_bounded_mp_contacts"}
    before = maugis.fallback_counts()
    assert set(before) == keys and all(isinstance(v, int) and v >= 0 for v in before.values())
    # points next to z = 1 and with large parameters where the native float64 path does not
    # certify (at least one of them falls back: the Rust test f64_mp_fallbacks_are_counted)
    a, b, c, z = zip((40.5, -35.25, 2.5, 0.999), (100.5, 90.25, 1.5, -0.99), (-60.5, 70.25, 0.75, 0.9999), (1.0e3, 1.5, 2.25, -0.999))
    value, err = maugis.hyp2f1(np.array(a), np.array(b), np.array(c), np.array(z), bounded=True)
    assert np.all(np.isfinite(value)) and np.all(err >= 0)
    after = maugis.fallback_counts()
    assert after["hyp2f1"] >= before["hyp2f1"] + 1
    assert all(after[k] >= before[k] for k in keys)


def test_budget_refuses_at_once_and_never_changes_an_answer():
    # 1F2(1e12; 1.5, 2.5; 100): about 4.6e4 series terms, estimated past 1 ms
    args = ("1e12", 1.5, 2.5, 100)
    with pytest.raises(maugis.TimeLimitError, match="would take about"):
        maugis.hyp1f2(*args, prec=64, budget=0.001)
    assert issubclass(maugis.TimeLimitError, ValueError)
    default = maugis.hyp1f2(*args, prec=64)
    generous = maugis.hyp1f2(*args, prec=64, budget=600)
    assert default == generous
    with pytest.raises(ValueError, match="budget"):
        maugis.hyp1f2(*args, prec=64, budget=0)
    with pytest.raises(ValueError, match="prec="):
        maugis.hyp1f2(0.5, 1, 1.5, -2, budget=1)
    with pytest.raises(TypeError):
        maugis.hyp1f2(*args, prec=64, budget="1")
