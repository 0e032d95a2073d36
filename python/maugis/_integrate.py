"""Certified integrals of an expression in x (the library's ``quad::certified``)."""

from __future__ import annotations

import math
import warnings
from decimal import Decimal

import mpmath
import numpy as np

from . import _maugis as _ext
from ._special import _LOG10_2, _budget, _mp_arg, _mp_options, _to_mpf

__all__ = ["integrate", "Integral"]


class Integral(tuple):
    """``(mid, rad)`` of a certified integral, unpacked like a pair, with two more
    attributes: ``abs_tol``, the absolute tolerance a ball containing 0 met (``None``
    when the relative goal decided; an ``mpmath.mpf``, or a decimal string with
    ``output="str"``), and ``evaluations``, the integrand evaluations used."""

    def __new__(cls, mid, rad, abs_tol, evaluations):
        self = super().__new__(cls, (mid, rad))
        self.abs_tol = abs_tol
        self.evaluations = evaluations
        return self

    @property
    def mid(self):
        """The midpoint."""
        return self[0]

    @property
    def rad(self):
        """The radius (bounding each of the real and imaginary parts)."""
        return self[1]

    def __repr__(self):
        return f"Integral(mid={self[0]!r}, rad={self[1]!r}, abs_tol={self.abs_tol!r}, evaluations={self.evaluations})"


def _is_plus_inf(v):
    if isinstance(v, str):
        return v.strip().lower() in ("inf", "+inf", "infinity", "+infinity")
    if isinstance(v, mpmath.mpf):
        return v == mpmath.inf
    if isinstance(v, (float, np.floating)):
        return math.isinf(v) and v > 0
    return False


def _is_minus_inf(v):
    if isinstance(v, str):
        return v.strip().lower() in ("-inf", "-infinity")
    if isinstance(v, mpmath.mpf):
        return v == -mpmath.inf
    if isinstance(v, (float, np.floating)):
        return math.isinf(v) and v < 0
    return False


def _end(name, v):
    if _is_plus_inf(v):
        return "inf"
    if _is_minus_inf(v):
        return "-inf"
    return _mp_arg(name, v)


def _optional(name, v):
    return None if v is None else _mp_arg(name, v)


def integrate(
    f,
    a,
    b,
    *,
    prec=53,
    alpha=None,
    beta=None,
    log=0,
    decay_rate=None,
    decay_power=None,
    decay_bound=None,
    output="mpf",
    digits=None,
    budget=None,
):
    """Certified ``int_a^b w(x) f(x) dx`` for an expression ``f`` in x.

    ``f`` is a string: ``+ - * / ^``, ``sqrt exp log sin cos tan sinh cosh tanh sech
    atan``, ``besselj(n, x)``, ``pi`` and decimals (``"x^(-1/2)*cos(x)"``).
    ``a`` and ``b`` are numbers as for the ``prec=`` functions: floats, ints and
    ``mpmath.mpf`` exactly, decimal strings as balls that contain them; ``b`` may
    be ``inf`` and ``a`` ``-inf`` (``math.inf``, ``mpmath.inf`` or ``"inf"``). The
    tail bound at an infinite end is derived from the expression
    (``docs/quadrature.md``); ``decay_*`` declare one instead, for ``b = inf``:
    ``|f(x)| <= decay_bound * exp(-decay_rate x)`` or ``<= decay_bound *
    x**-decay_power`` for ``x >= a``.

    ``alpha``, ``beta``, ``log`` declare endpoint behaviour: the integrand is then
    ``(x-a)**alpha (b-x)**beta log(x-a)**log f(x)``, certified without truncation
    (``alpha, beta > -1``).

    Returns an ``Integral``, the pair ``(mid, rad)`` (``mid, rad = integrate(...)``):
    the integral lies within ``rad`` of ``mid`` (in each of the real and imaginary
    parts) and ``rad <= 2**-prec |mid|`` when the goal is met, or, for a ball that
    contains 0 (a zero integral such as ``sin(x)`` on ``[-1, 1]``), ``rad`` at most
    the default absolute tolerance, ``2**-prec`` times a bound of ``int |f|``
    (``docs/quadrature.md``), which is then its attribute ``abs_tol`` (``None``
    otherwise); ``evaluations`` counts the integrand's evaluations. ``mid`` is an
    ``mpmath.mpf``, or an ``mpmath.mpc`` when the integrand is
    complex somewhere on the range (``sqrt(x)`` for ``x < 0``) and the imaginary
    part may exceed ``rad``; with ``output="str"`` both are decimal strings (a
    complex ``mid`` written ``"re+imj"``). A result stopped by a limit before its
    goal still encloses the integral and comes with a ``RuntimeWarning``.

    ``budget=`` is the call's time budget in seconds (default 30): past it, the
    integral raises ``maugis.TimeLimitError`` (a ``ValueError``) at once, naming the
    evaluations reached; a budget never changes an answer.

    Bad input (an expression that does not parse, an endpoint singularity or pole
    that was not declared, an infinite range that is not absolutely integrable nor a
    recognised oscillatory integral) raises ``ValueError``
    naming the problem.
    """
    prec = _mp_options(prec, output)
    if not isinstance(f, str):
        raise TypeError(f"f must be the integrand as a string in x (got {type(f).__name__})")
    if isinstance(log, bool) or not isinstance(log, (int, np.integer)) or log < 0:
        raise ValueError(f"log must be a non-negative integer (got {log!r})")
    upper = _end("b", b)
    if output == "str" and digits is None:
        digits = int(prec * _LOG10_2) + 3
    r = _ext.integrate_mp(
        f,
        _end("a", a),
        upper,
        prec,
        alpha=_optional("alpha", alpha),
        beta=_optional("beta", beta),
        log=int(log),
        decay_rate=_optional("decay_rate", decay_rate),
        decay_power=_optional("decay_power", decay_power),
        decay_bound=_optional("decay_bound", decay_bound),
        digits=None if output == "mpf" else int(digits),
        budget=_budget(budget),
    )
    if r["warning"] is not None:
        warnings.warn(r["warning"], RuntimeWarning, stacklevel=2)
    (re_mid, re_rad), im = r["re"], r["im"]
    abs_tol, evaluations = r["abs_tol"], r["evaluations"]
    if output == "str":
        if im is None:
            return Integral(re_mid, re_rad, abs_tol, evaluations)
        im_mid, im_rad = im
        sign = "" if im_mid.startswith("-") else "+"
        rad = re_rad if Decimal(re_rad) >= Decimal(im_rad) else im_rad
        return Integral(f"{re_mid}{sign}{im_mid}j", rad, abs_tol, evaluations)
    abs_tol = None if abs_tol is None else mpmath.mpf(abs_tol)
    mid, rad = _to_mpf(re_mid), _to_mpf(re_rad)
    if im is None:
        return Integral(mid, rad, abs_tol, evaluations)
    im_mid, im_rad = _to_mpf(im[0]), _to_mpf(im[1])
    return Integral(mpmath.mp.make_mpc((mid._mpf_, im_mid._mpf_)), max(rad, im_rad), abs_tol, evaluations)
