"""Special functions as NumPy ufunc-like calls.

Each function broadcasts its arguments like a ufunc and runs the Rust library
over the flat result with the GIL released (in parallel on rayon's pool from
``PARALLEL_MIN_LEN`` elements on). Three kinds of answer:

* default: a float64 array (a NumPy scalar for scalar arguments), within the
  library's documented tolerance (``docs/special-functions.md``);
* ``bounded=True``: ``(value, err)`` float64 arrays with
  ``|exact - value| <= err`` proven for the float64 arguments as given;
* ``prec=P`` (bits): certified balls ``(mid, rad)`` -- the exact value lies
  within ``rad`` of ``mid`` and ``rad <= 2**-P |mid|`` -- as ``mpmath.mpf``
  (``output="mpf"``, exact binary values) or decimal strings
  (``output="str"``; the decimal radius also covers the decimal rounding of
  ``mid``). Arguments may then be floats and ints (taken exactly),
  ``mpmath.mpf`` (exactly) or decimal strings. A decimal string is a ball
  that contains the decimal as typed (Arb's convention, as in ``maugis eval``),
  so the answer contains the function at the decimal, not at a binary
  neighbour; an edge inside the input (a pole, ``c - a - b = 0`` at ``z = 1``,
  the contact edge) raises ``ValueError`` naming it.

Bad input -- NaN, infinity, an argument out of the function's domain -- raises
``ValueError`` with the library's message and the arguments of the first
element that failed; no partial result is returned.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np

from . import _maugis as _ext

__all__ = ["bessel_j", "hyp1f2", "hyp2f1", "meijer_g_k", "u_wave", "du_wave", "hyp1f2_model_family", "meijer_g_k_family"]

_INT64_MAX = np.iinfo(np.int64).max
_LOG10_2 = math.log10(2.0)


# ---------------------------------------------------------------- argument conversion


def _as_real(name, value):
    """A float64 array of `value` (bool, int and float dtypes accepted)."""
    a = np.asarray(value)
    if a.dtype.kind not in "biuf":
        raise TypeError(f"{name} must be real numbers (got an array of dtype {a.dtype})")
    return a.astype(np.float64, copy=False)


def _as_int(name, value):
    """An int64 array of `value`: integer dtypes, or floats that are whole numbers."""
    a = np.asarray(value)
    kind = a.dtype.kind
    if kind in "bi":
        return a.astype(np.int64, copy=False)
    if kind == "u":
        if a.size and a.max() > _INT64_MAX:
            raise ValueError(f"{name} = {a.max()} is too large for an integer order")
        return a.astype(np.int64)
    if kind == "f":
        whole = np.isfinite(a) & (np.floor(a) == a) & (np.abs(a) < 2.0**63)
        if not whole.all():
            bad = float(a[~whole].flat[0])
            raise ValueError(f"{name} must be an integer (got {bad!r})")
        return a.astype(np.int64)
    raise TypeError(f"{name} must be integers (got an array of dtype {a.dtype})")


def _flat(args):
    """Broadcasts converted arrays; returns the flat contiguous copies and the shape."""
    shape = np.broadcast_shapes(*(a.shape for a in args))
    flat = [np.ascontiguousarray(np.broadcast_to(a, shape)).reshape(-1) for a in args]
    return flat, shape


def _shaped(out, shape):
    """Reshapes a flat result (or a (value, err) pair); 0-d becomes a NumPy scalar."""
    if isinstance(out, tuple):
        return tuple(_shaped(o, shape) for o in out)
    out = out.reshape(shape)
    return out[()] if shape == () else out


def _mp_arg(name, v):
    """One MP argument: ``(mantissa text, exponent)`` for exact values, else a decimal string."""
    if isinstance(v, np.ndarray) and v.shape == ():
        v = v[()]
    if isinstance(v, str):
        return v.strip()
    if isinstance(v, mpmath.mpf):
        if not mpmath.isfinite(v):
            raise ValueError(f"{name} must be a finite number (got NaN or infinity)")
        man, exp = v.man_exp
        return (str(man), int(exp))
    if isinstance(v, (bool, int, np.integer)):
        return (str(int(v)), 0)
    if isinstance(v, (float, np.floating)):
        f = float(v)
        if not math.isfinite(f):
            raise ValueError(f"{name} must be a finite number (got NaN or infinity)")
        num, den = f.as_integer_ratio()
        return (str(num), -(den.bit_length() - 1))
    raise TypeError(f"{name} must be a real number, mpmath.mpf or decimal string (got {type(v).__name__})")


def _to_mpf(pair):
    """An exact ``mpmath.mpf`` from ``(mantissa text, exponent)`` (no rounding)."""
    man, exp = pair
    return mpmath.mp.make_mpf(mpmath.libmp.from_man_exp(int(man), exp))


def _mp_options(prec, output):
    """Checks ``prec=`` and ``output=`` of a certified call; returns ``prec`` as an int."""
    if output not in ("mpf", "str"):
        raise ValueError(f'output must be "mpf" or "str" (got {output!r})')
    if isinstance(prec, bool) or not isinstance(prec, (int, np.integer)):
        raise TypeError(f"prec must be an integer number of bits (got {prec!r})")
    prec = int(prec)
    if not 2 <= prec <= _ext.MAX_PREC:
        raise ValueError(f"precision {prec} bits is out of range: use 2 ..= {_ext.MAX_PREC} bits")
    return prec


def _budget(budget):
    """Checks ``budget=`` (seconds, ``None`` for the library default of 30 s)."""
    if budget is None:
        return None
    if isinstance(budget, bool) or not isinstance(budget, (int, float, np.integer, np.floating)):
        raise TypeError(f"budget must be a number of seconds (got {budget!r})")
    return float(budget)


def _eval_mp(function, names, values, prec, output, digits, budget=None):
    prec = _mp_options(prec, output)
    arrays = [np.asarray(v, dtype=object) for v in values]
    b = np.broadcast(*arrays)
    shape = b.shape
    rows = list(b)
    columns = [[_mp_arg(n, r[j]) for r in rows] for j, n in enumerate(names)]
    if output == "str":
        if digits is None:
            digits = int(prec * _LOG10_2) + 2
        balls = _ext.eval_mp(function, columns, prec, int(digits), _budget(budget))
        mids = [m for m, _ in balls]
        rads = [r for _, r in balls]
    else:
        balls = _ext.eval_mp(function, columns, prec, None, _budget(budget))
        mids = [_to_mpf(m) for m, _ in balls]
        rads = [_to_mpf(r) for _, r in balls]
    if shape == ():
        return mids[0], rads[0]
    mid = np.empty(len(mids), dtype=object)
    rad = np.empty(len(rads), dtype=object)
    mid[:] = mids
    rad[:] = rads
    return mid.reshape(shape), rad.reshape(shape)


def _call(function, values, bounded, prec, output, digits, budget):
    """Runs the library's registry function `function` (its parameter names and
    kinds come from the registry, ``_ext.signature``) over broadcast arguments."""
    signature = _ext.signature(function)
    repeated = _ext.repeated(function)
    if repeated is not None:
        # a group taken any number of times after the fixed parameters (the waves of
        # strip_ratio_waves: alpha_1, beta_1, alpha_2, ...), all reals
        _, group, _ = repeated
        extra = max(len(values) - len(signature), 0)
        signature = list(signature) + [(f"{group[k % len(group)]}_{k // len(group) + 1}", "real") for k in range(extra)]
    names = [n for n, _ in signature]
    if prec is not None:
        if bounded:
            raise ValueError("choose one of bounded=True (float64 with an error bound) and prec= (certified balls)")
        return _eval_mp(function, names, values, prec, output, digits, budget)
    if budget is not None:
        raise ValueError("budget= is the time budget of a certified call: give it with prec=")
    conv = [(_as_int if k == "int" else _as_real)(n, v) for (n, k), v in zip(signature, values)]
    flat, shape = _flat(conv)
    return _shaped(_ext.eval_f64(function, flat, bool(bounded)), shape)


# ---------------------------------------------------------------- the functions


def bessel_j(n, x, *, bounded=False, prec=None, output="mpf", digits=None, budget=None):
    """Bessel function of the first kind ``J_n(x)``, integer order ``n``, real ``x``.

    float64: within 2 ulp. Domain: ``|n| <= 1e6``; see ``docs/special-functions.md``.
    """
    return _call("bessel_j", (n, x), bounded, prec, output, digits, budget)


def hyp1f2(a, b1, b2, z, *, bounded=False, prec=None, output="mpf", digits=None, budget=None):
    """Hypergeometric function ``1F2(a; b1, b2; z)``, real parameters and argument (entire in z)."""
    return _call("hyp1f2", (a, b1, b2, z), bounded, prec, output, digits, budget)


def hyp2f1(a, b, c, z, *, bounded=False, prec=None, output="mpf", digits=None, budget=None):
    """Gauss hypergeometric function ``2F1(a, b; c; z)``, real, ``z <= 1`` (principal branch)."""
    return _call("hyp2f1", (a, b, c, z), bounded, prec, output, digits, budget)


def meijer_g_k(k, y, *, bounded=False, prec=None, output="mpf", digits=None, budget=None):
    """The Eq. 12 Meijer-G factor ``Re G^{2,2}_{3,3}(-y | 0, 1/2-k, 1; 0, 0, -k-1)``, ``0 < y <= 1``."""
    return _call("meijer_g_k", (k, y), bounded, prec, output, digits, budget)


def hyp1f2_model_family(kmax, z):
    """The model family ``1F2(1/2; k+1, k+3/2; z)`` for ``k = 0..kmax`` at one float64 ``z``
    (``z = -s**2`` in Eq. 12), in float64 with proven bounds.

    Returns ``(value, err)`` float64 arrays of length ``kmax + 1`` with
    ``|exact - value| <= err <= 1e-14 |value|`` for ``z`` as given; a downward
    recurrence in k, each value it cannot certify recomputed on its own.
    """
    return _ext.family_f64("hyp1f2", _family_order(kmax), float(z))


def meijer_g_k_family(kmax, y):
    """The Eq. 12 Meijer-G factor ``G(k, y)`` for ``k = 0..kmax`` at one float64 ``0 < y <= 1``,
    in float64 with proven bounds: ``(value, err)`` arrays as :func:`hyp1f2_model_family`."""
    return _ext.family_f64("meijer_g_k", _family_order(kmax), float(y))


def _family_order(kmax):
    if isinstance(kmax, bool) or not isinstance(kmax, (int, np.integer)):
        raise ValueError(f"kmax must be a non-negative integer (got {kmax!r})")
    return int(kmax)


def u_wave(a, zeta, amp, x, *, bounded=False, prec=None, output="mpf", digits=None, budget=None):
    """Wave displacement ``u_w(x)`` of the seed paper's Eq. 12 (Bessel form), ``x >= a``.

    ``a``: contact half-width, ``zeta``: wavelength, ``amp``: wave amplitude, ``x``: position.
    """
    return _call("u_wave", (a, zeta, amp, x), bounded, prec, output, digits, budget)


def du_wave(a, zeta, amp, x, *, bounded=False, prec=None, output="mpf", digits=None, budget=None):
    """Gradient ``du_w/dx`` of the wave displacement (the seed paper's Eq. 11b), ``x >= a``."""
    return _call("du_wave", (a, zeta, amp, x), bounded, prec, output, digits, budget)
