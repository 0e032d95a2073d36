"""maugis.integrate: certified integrals of expressions, checked against mpmath."""

import math
import warnings

import mpmath
import pytest

import maugis


@pytest.fixture(autouse=True)
def _high_precision():
    """Exact values (14/3, pi, mpmath.quad) at 1000 bits, well past every prec tested."""
    with mpmath.workprec(1000):
        yield


def _contains(mid, rad, exact):
    """Whether the ball mid +/- rad (rad bounding each part) contains `exact`."""
    with mpmath.workprec(4000):
        d = mpmath.mpc(mid) - mpmath.mpc(exact)
        return abs(d.real) <= rad and abs(d.imag) <= rad


def _quad(f, a, b, dps=100):
    with mpmath.workdps(dps):
        return mpmath.quad(f, [a, b])


def test_sqrt_over_one_to_four_contains_fourteen_thirds():
    for text in ("sqrt(x)", "x^0.5", "x^(1/2)", "exp(log(x)/2)"):
        mid, rad = maugis.integrate(text, 1, 4, prec=128)
        assert isinstance(mid, mpmath.mpf)
        assert _contains(mid, rad, mpmath.mpf(14) / 3), text
        assert rad <= mpmath.mpf(2) ** -127 * abs(mid)


@pytest.mark.parametrize(
    "text, f, a, b",
    [
        ("1/(1 + x^2)", lambda x: 1 / (1 + x**2), 0, 1),
        ("sin(x + exp(x))", lambda x: mpmath.sin(x + mpmath.exp(x)), 0, 3),
        ("atan(x)^2 - tanh(x)*cosh(x/2)", lambda x: mpmath.atan(x) ** 2 - mpmath.tanh(x) * mpmath.cosh(x / 2), -1, 2),
        ("x^-2 * sinh(x)", lambda x: x**-2 * mpmath.sinh(x), 1, 2),
        ("tan(x)*pi", lambda x: mpmath.tan(x) * mpmath.pi, 0, 1),
    ],
)
def test_analytic_integrands_against_mpmath(text, f, a, b):
    want = _quad(f, a, b)
    for prec in (64, 200):
        mid, rad = maugis.integrate(text, a, b, prec=prec)
        assert _contains(mid, rad, want), (text, prec, mid, rad)
        assert rad <= mpmath.mpf(2) ** -(prec - 1) * abs(mid)


def test_bessel_integrand_against_mpmath():
    # one precision only: CBall.bessel_j on the integrator's widest ellipse boxes
    # currently costs seconds (series at |z| ~ 6e4)
    want = _quad(lambda x: mpmath.besselj(2, x) * mpmath.exp(-x / 3), 0, 1)
    mid, rad = maugis.integrate("besselj(2, x)*exp(-x/3)", 0, 1, prec=64)
    assert _contains(mid, rad, want)


def test_decimal_inputs_are_balls_that_contain_them():
    # int_0^0.1 x dx = 0.005 exactly, with 0.1 typed as a decimal string
    mid, rad = maugis.integrate("x", 0, "0.1", prec=128)
    assert _contains(mid, rad, mpmath.mpf(1) / 200)
    # the decimal 0.3 inside the expression, not the double nearest to it
    mid, rad = maugis.integrate("0.3", 0, 1, prec=200)
    assert _contains(mid, rad, mpmath.mpf(3) / 10)
    assert rad > 0


def test_endpoint_weights_against_mpmath():
    # x^(-1/2) cos(x) over [0, 1] as cos(x) with alpha = -0.5
    want = _quad(lambda x: mpmath.cos(x) / mpmath.sqrt(x), 0, 1)
    mid, rad = maugis.integrate("cos(x)", 0, 1, prec=128, alpha=-0.5)
    assert _contains(mid, rad, want)
    # x log x and log^2 x over [0, 1]
    mid, rad = maugis.integrate("x", 0, 1, prec=128, log=1)
    assert _contains(mid, rad, mpmath.mpf(-1) / 4)
    mid, rad = maugis.integrate("1", 0, 1, prec=128, log=2)
    assert _contains(mid, rad, 2)
    # both ends: (x (1-x))^(-1/2) = pi over [0, 1]
    mid, rad = maugis.integrate("1", 0, 1, prec=100, alpha="-0.5", beta="-0.5")
    assert _contains(mid, rad, mpmath.pi)


def test_semi_infinite_range_with_declared_decay():
    for b in (math.inf, "inf", mpmath.inf):
        mid, rad = maugis.integrate("exp(-x^2)", 0, b, prec=128, decay_rate=1, decay_bound="1.2841")
        assert _contains(mid, rad, mpmath.sqrt(mpmath.pi) / 2)
    want = _quad(lambda x: 1 / (1 + x**2) ** 2, 1, mpmath.inf)
    mid, rad = maugis.integrate("1/(1 + x^2)^2", 1, "inf", prec=64, decay_power=4, decay_bound=1)
    assert _contains(mid, rad, want)


def test_string_output():
    mid, rad = maugis.integrate("sqrt(x)", 1, 4, prec=64, output="str")
    assert isinstance(mid, str) and isinstance(rad, str)
    assert _contains(mpmath.mpf(mid), mpmath.mpf(rad) * 2, mpmath.mpf(14) / 3)


def test_complex_values_and_flagged_results():
    # sqrt(x) over [-1, 0] = 2i/3: an endpoint branch point, so a limit stops it
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        mid, rad = maugis.integrate("sqrt(x)", -1, 0, prec=64)
    assert isinstance(mid, mpmath.mpc)
    assert _contains(mid, rad, mpmath.mpc(0, mpmath.mpf(2) / 3))
    assert any(issubclass(w.category, RuntimeWarning) and "goal was not met" in str(w.message) for w in caught)


@pytest.mark.parametrize(
    "args, kwargs, needle",
    [
        (("foo(x)", 0, 1), {}, "unknown function 'foo'"),
        (("x^", 0, 1), {}, "syntax error"),
        (("besselj(1.5, x)", 0, 1), {}, "order of besselj"),
        (("y + 1", 0, 1), {}, "unknown name 'y'"),
        (("x", 0, math.inf), {}, "decay"),
        (("1/x", -1, 1), {}, "not bounded"),
        (("1", 0, 1), {"alpha": -1}, "alpha"),
        (("x", 0, math.nan), {}, "finite"),
        (("x", 0, "1x"), {}, "not a number"),
        (("x", 0, 1), {"prec": 1}, "precision"),
        (("x", 0, math.inf), {"decay_rate": 1}, "decay_bound"),
    ],
)
def test_bad_input_raises_value_error(args, kwargs, needle):
    with pytest.raises(ValueError, match=needle):
        maugis.integrate(*args, **kwargs)


def test_type_errors():
    with pytest.raises(TypeError):
        maugis.integrate(lambda x: x, 0, 1)
    with pytest.raises(TypeError):
        maugis.integrate("x", 0, 1, prec=1.5)


def test_zero_integral_carries_its_absolute_tolerance():
    """sin(x) on [-1, 1] is 0: the ball meets the default absolute tolerance, 2^-prec
    times a certified bound of int |sin| = 2 (1 - cos 1) = 0.92 (at most four times the
    rough estimate of it), and says so in abs_tol; a nonzero integral has none."""
    for prec in (64, 200):
        r = maugis.integrate("sin(x)", -1, 1, prec=prec)
        mid, rad = r
        assert (mid, rad) == (r.mid, r.rad)
        assert _contains(mid, rad, 0)
        assert r.abs_tol is not None and rad <= r.abs_tol
        scale = r.abs_tol * mpmath.mpf(2) ** prec
        assert 2 * (1 - mpmath.cos(1)) <= scale <= 8, scale
        assert r.evaluations > 0
    r = maugis.integrate("exp(x)", 0, 1, prec=64)
    assert r.abs_tol is None and r.evaluations > 0
    s = maugis.integrate("sin(x)", -1, 1, prec=64, output="str")
    assert isinstance(s.abs_tol, str) and mpmath.mpf(s.abs_tol) > 0


def test_budget_refuses_at_once_and_never_changes_an_answer():
    """int_0^300 sin(x^2) at 1000 bits takes seconds (docs/quadrature.md, "Time
    budget"): under 20 ms it raises TimeLimitError, a ValueError, naming the
    evaluations reached; a budget never changes an answer."""
    with pytest.raises(maugis.TimeLimitError, match="evaluations"):
        maugis.integrate("sin(x^2)", 0, 300, prec=1000, budget=0.02)
    assert issubclass(maugis.TimeLimitError, ValueError)
    default = maugis.integrate("exp(-x^2)", 0, 2, prec=200)
    generous = maugis.integrate("exp(-x^2)", 0, 2, prec=200, budget=600)
    assert tuple(default) == tuple(generous)
    with pytest.raises(ValueError, match="budget"):
        maugis.integrate("x", 0, 1, budget=0)
    with pytest.raises(TypeError):
        maugis.integrate("x", 0, 1, budget="1")
