"""The wavy Maugis model: load-area curves, single states and profiles.

Results follow the library's JSON schema, the one ``maugis curve --format
json`` and ``summary.json`` print (``maugis::contact::summary``): the same
keys, nested the same way. A JSON object becomes a :class:`Record` (a dict
whose keys are also attributes); a list of objects becomes a :class:`Table`,
whose keys are the objects' fields and whose values are NumPy arrays with one
entry per object (nested objects become nested tables). So the JSON path
``curves[0].jumps[2].from.abar`` reads ``curve(...).jumps["from"]["abar"][2]``.
:func:`run_summary` returns the JSON object itself.
"""

from __future__ import annotations

import json

import numpy as np

from . import _maugis as _ext
from ._special import _as_real, _call, _flat

__all__ = [
    "FIG4C_ALPHA",
    "FIG4C_BETA",
    "DEFAULT_DATUM",
    "Record",
    "Table",
    "run_summary",
    "sweep",
    "curve",
    "state",
    "profile",
]

#: Normalised wave amplitude of the paper's Fig. 4c, ``2 sqrt(2)/8``.
FIG4C_ALPHA = _ext.FIG4C_ALPHA
#: Normalised wavelength of the paper's Fig. 4c.
FIG4C_BETA = _ext.FIG4C_BETA
#: Default datum of displacement control (units of ``l_h``).
DEFAULT_DATUM = _ext.DEFAULT_DATUM


class Record(dict):
    """A JSON object: a dict whose keys are also attributes (where they are identifiers)."""

    __slots__ = ()

    def __getattr__(self, name):
        try:
            return self[name]
        except KeyError:
            raise AttributeError(name) from None

    def __dir__(self):
        return list(super().__dir__()) + [k for k in self if isinstance(k, str) and k.isidentifier()]


class Table(Record):
    """A list of JSON objects as columns: ``table[field][i]`` is ``list[i].field``.

    ``nrows`` is the length of the list. An empty list has no columns: any
    field asked of it is an empty array.
    """

    __slots__ = ("nrows",)

    def __init__(self, columns=(), nrows=0):
        super().__init__(columns)
        self.nrows = nrows

    def __missing__(self, key):
        if self.nrows == 0:
            return np.empty(0)
        raise KeyError(key)

    def __repr__(self):
        return f"Table(nrows={self.nrows}, columns={list(self.keys())})"


def _column(values):
    """One column of a table: numbers, booleans and strings as NumPy arrays."""
    if all(isinstance(v, dict) for v in values):
        return _table(values)
    if all(isinstance(v, bool) for v in values):
        return np.array(values, dtype=bool)
    if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values):
        return np.array(values, dtype=np.float64 if any(isinstance(v, float) for v in values) else np.int64)
    if all(isinstance(v, str) for v in values):
        return np.array(values, dtype=str)
    out = np.empty(len(values), dtype=object)
    out[:] = [_convert(v) for v in values]
    return out


def _table(rows):
    keys = list(dict.fromkeys(k for r in rows for k in r))
    return Table({k: _column([r.get(k) for r in rows]) for k in keys}, nrows=len(rows))


def _convert(obj):
    """JSON value -> Record / Table / NumPy array / scalar."""
    if isinstance(obj, dict):
        return Record({k: _convert(v) for k, v in obj.items()})
    if isinstance(obj, list):
        if not obj:
            return Table()
        if all(isinstance(r, dict) for r in obj):
            return _table(obj)
        return _column(obj)
    return obj


def _real_scalar(name, v):
    a = _as_real(name, v)
    if a.shape != ():
        raise ValueError(f"{name} must be a single number here (got an array of shape {a.shape})")
    return float(a)


def _count(name, v, least=2):
    if isinstance(v, bool) or not isinstance(v, (int, np.integer)):
        raise TypeError(f"{name} must be an integer (got {v!r})")
    if v < least:
        raise ValueError(f"{name} must be >= {least} (got {v})")
    return int(v)


def _roughness(alpha, beta, waves, default=True):
    """``(alpha, beta, waves)`` for the extension: the one wave ``(alpha, beta)``
    (the Fig. 4c wave where ``None`` and ``default``), or the list of
    ``(amplitude, wavelength)`` pairs ``waves`` (then ``alpha`` and ``beta`` must be
    ``None``; they become the first wave's, for the records' ``alpha``/``beta``)."""
    if waves is None:
        if alpha is None and default:
            alpha = FIG4C_ALPHA
        if beta is None and default:
            beta = FIG4C_BETA
        if alpha is None or beta is None:
            raise TypeError("give alpha and beta (one wave) or waves=[(amplitude, wavelength), ...]")
        return _real_scalar("alpha", alpha), _real_scalar("beta", beta), None
    if alpha is not None or beta is not None:
        raise ValueError("give waves=[(amplitude, wavelength), ...] or alpha and beta, not both")
    if isinstance(waves, (str, bytes)):
        raise TypeError("waves must be a sequence of (amplitude, wavelength) pairs")
    pairs = []
    for j, w in enumerate(waves):
        try:
            a, b = w
        except (TypeError, ValueError):
            raise TypeError(f"waves[{j}] must be a pair (amplitude, wavelength) (got {w!r})") from None
        pairs.append((_real_scalar(f"waves[{j}] amplitude", a), _real_scalar(f"waves[{j}] wavelength", b)))
    first = pairs[0] if pairs else (0.0, 1.0)
    return first[0], first[1], pairs


def _summary(lams, alpha, beta, amax, points, datum, waves=None):
    alpha, beta, waves = _roughness(alpha, beta, waves)
    amax, datum = (_real_scalar(n, v) for n, v in (("amax", amax), ("datum", datum)))
    text = _ext.curve_summary_json([float(v) for v in lams], alpha, beta, amax, _count("points", points), datum, waves)
    return json.loads(text)


def run_summary(lam, alpha=None, beta=None, *, waves=None, amax=6.0, points=600, datum=DEFAULT_DATUM):
    """The JSON object ``maugis curve --format json`` prints, as plain Python values.

    ``lam`` is one Maugis parameter or several (sorted and deduplicated, as the
    command does; the smallest is ``mdmt_limit_lambda``). The profile is the one
    wave ``alpha``, ``beta`` (default: the paper's Fig. 4c wave) or, with ``waves``,
    the cylinder carrying every ``(amplitude, wavelength)`` pair of the list
    (normalised; ``maugis curve --wave A,B --wave ...``); the summary's ``params``
    then list them under ``waves``.
    """
    lams = sorted(set(_as_real("lam", lam).reshape(-1).tolist()))
    return _summary(lams, alpha, beta, amax, points, datum, waves)


def curve(lam, alpha=None, beta=None, *, waves=None, amax=6.0, points=600, datum=DEFAULT_DATUM):
    """Load-area response on ``abar_i = amax i / points``, ``i = 1..points``, of the
    one wave ``alpha``, ``beta`` (default: Fig. 4c) or of the profile ``waves`` (a list
    of ``(amplitude, wavelength)`` pairs, as :func:`run_summary`).

    Returns one entry of the JSON ``curves`` list as a :class:`Record`: the grid
    ``points``, ``turning_points``, the ``jumps`` and ``loops`` met under load
    control, ``pull_off``, ``dissipation``, the ``load_control`` and
    ``displacement_control`` paths, the invalid stretches. ``lam`` may be a
    sequence: then a list of records, in the given order.
    """
    lams = _as_real("lam", lam)
    out = [_convert(c) for c in _summary(lams.reshape(-1).tolist(), alpha, beta, amax, points, datum, waves)["curves"]]
    return out[0] if lams.ndim == 0 else out


def state(lam, alpha, beta, abar, *, waves=None):
    """Solved states (the fields of a curve's grid ``points``), broadcasting like a ufunc.

    The profile is the one wave ``alpha``, ``beta`` (both broadcast), or with
    ``alpha = beta = None`` the cylinder carrying ``waves``, a list of
    ``(amplitude, wavelength)`` pairs (one profile for every element; ``lam`` and
    ``abar`` broadcast), as :func:`curve` takes them.

    Returns a :class:`Record` of arrays of the broadcast shape (NumPy scalars
    for scalar arguments): ``abar``, ``m``, ``m_minus_1``, ``load``,
    ``approach`` and the ``validity`` record. States are solved in parallel.
    """
    if waves is None:
        conv = [_as_real(n, v) for n, v in (("lam", lam), ("alpha", alpha), ("beta", beta), ("abar", abar))]
        flat, shape = _flat(conv)
        rows = json.loads(_ext.states_json(*flat))
    else:
        _, _, pairs = _roughness(alpha, beta, waves, default=False)
        flat, shape = _flat([_as_real("lam", lam), _as_real("abar", abar)])
        rows = json.loads(_ext.states_waves_json(*flat, pairs))
    return _reshape(_table(rows), shape) if rows else Table()


def _wave_pairs(waves):
    """The ``(amplitude, wavelength)`` pairs of ``waves``, each value as given (numbers,
    ``mpmath.mpf`` or decimal strings; the library checks them and names a bad wave)."""
    if isinstance(waves, (str, bytes)):
        raise TypeError("waves must be a sequence of (amplitude, wavelength) pairs")
    pairs = []
    for j, w in enumerate(waves):
        if isinstance(w, (str, bytes)):
            raise TypeError(f"waves[{j}] must be a pair (amplitude, wavelength) (got {w!r})")
        try:
            a, b = w
        except (TypeError, ValueError):
            raise TypeError(f"waves[{j}] must be a pair (amplitude, wavelength) (got {w!r})") from None
        pairs.append((a, b))
    return pairs


def _model_at(function, lam, alpha, beta, abar, waves, prec, output, digits, budget):
    """``strip_ratio`` or ``load`` of the registry: the one wave ``(alpha, beta)``, or the
    profile ``waves`` through ``strip_ratio_waves``/``load_waves``
    (``lambda, abar, alpha_1, beta_1, ...``)."""
    if waves is None:
        if alpha is None or beta is None:
            raise TypeError("give alpha and beta (one wave) or waves=[(amplitude, wavelength), ...]")
        return _call(function, (lam, alpha, beta, abar), False, prec, output, digits, budget)
    if alpha is not None or beta is not None:
        raise ValueError("give waves=[(amplitude, wavelength), ...] or alpha and beta, not both")
    flat = [v for pair in _wave_pairs(waves) for v in pair]
    return _call(function + "_waves", (lam, abar, *flat), False, prec, output, digits, budget)


def strip_ratio(lam, alpha, beta, abar, *, waves=None, prec=None, output="mpf", digits=None, budget=None):
    """The strip ratio ``m = c/a`` at contact size ``abar``: the first root of the
    corrected Eq. 15b, broadcasting like a ufunc (``maugis eval``'s ``strip_ratio``).

    The profile is the one wave ``alpha``, ``beta``, or with ``alpha = beta = None``
    the cylinder carrying ``waves``, a list of ``(amplitude, wavelength)`` pairs
    (``strip_ratio_waves``; one wave gives exactly what ``alpha``, ``beta`` give).
    float64 by default; ``prec=P`` returns certified balls ``(mid, rad)`` as the
    special functions do, each decimal string (of ``waves`` too) a ball that contains
    the decimal as typed. A bad wave raises ``ValueError`` naming the wave and the field.
    ``budget`` (seconds) bounds a certified call as for the special functions
    (``TimeLimitError`` past it).
    """
    return _model_at("strip_ratio", lam, alpha, beta, abar, waves, prec, output, digits, budget)


def load(lam, alpha, beta, abar, *, waves=None, prec=None, output="mpf", digits=None, budget=None):
    """The load (Eq. 14) at the strip ratio of :func:`strip_ratio`, with the same
    arguments (``maugis eval``'s ``load`` and ``load_waves``). Certified balls are
    accurate relative to ``max(|load|, pi abar**2/4)``: the load crosses zero."""
    return _model_at("load", lam, alpha, beta, abar, waves, prec, output, digits, budget)


def _reshape(table, shape):
    out = Record()
    for k, v in table.items():
        if isinstance(v, Table):
            out[k] = _reshape(v, shape)
        else:
            v = v.reshape(shape)
            out[k] = v[()] if shape == () else v
    return out


def profile(lam, alpha, beta, abar, *, waves=None, x=None, points=600):
    """Traction ``pbar``, displacement ``ubar``, gap ``gbar`` and surface depth ``hbar`` at one state.

    The profile is the one wave ``alpha``, ``beta``, or with ``alpha = beta = None``
    the cylinder carrying ``waves``, a list of ``(amplitude, wavelength)`` pairs
    (``maugis profile --wave A,B --wave ...``; the record then has ``waves``).

    Returns the fields of ``maugis profile --format json`` as a :class:`Record`,
    with ``samples`` as a :class:`Table` of columns. ``x`` (``xbar`` positions)
    defaults to the command's grid: ``points`` values over ``[0, 1.5 m abar]``
    plus the contact edge and the strip end.
    """
    alpha, beta, waves = _roughness(alpha, beta, waves, default=False)
    lam, abar = (_real_scalar(n, v) for n, v in (("lam", lam), ("abar", abar)))
    if x is None:
        points = _count("points", points)
    else:
        x = np.ascontiguousarray(_as_real("x", x).reshape(-1))
        points = 0
    d = _ext.profile_dict(lam, alpha, beta, abar, x, points, waves)
    samples = d.pop("samples")
    out = Record(d)
    out["samples"] = Table(samples, nrows=len(samples["xbar"]))
    return out


def sweep(lambda_min, lambda_max, lambda_n, axis, min, max, n, fixed=None, *, waves=None, amax=6.0, points=600):
    """A ``maugis sweep``: ``lambda_n`` log-spaced ``lambda`` times ``n`` linearly spaced
    values of ``axis`` (``"alpha"``, ``"beta"`` or ``"johnson"``), the other roughness
    parameter held at ``fixed``; each grid point's regime, dissipation and pull-off.

    With ``axis="amplitude"`` the second axis is the scale ``s`` of every amplitude of
    the profile ``waves`` (a list of ``(amplitude, wavelength)`` pairs; ``fixed`` is not
    used): grid point ``(lambda, s)`` is the profile with waves ``(s alpha_j, beta_j)``.

    Returns the library's ``Sweep`` as a :class:`Record` (its point list as a :class:`Table`).
    """
    axis = str(axis)
    if axis == "amplitude":
        if waves is None:
            raise TypeError('axis="amplitude" scales a profile: give waves=[(amplitude, wavelength), ...]')
        _, _, pairs = _roughness(None, None, waves)
        fixed = 0.0 if fixed is None else fixed
    else:
        if waves is not None:
            raise ValueError(f'waves are swept on axis="amplitude", not "{axis}"')
        if fixed is None:
            raise TypeError(f'axis="{axis}" needs fixed (the other parameter of the one wave)')
    grid = {
        "lambda_min": _real_scalar("lambda_min", lambda_min),
        "lambda_max": _real_scalar("lambda_max", lambda_max),
        "lambda_n": _count("lambda_n", lambda_n, least=1),
        "axis": str(axis),
        "min": _real_scalar("min", min),
        "max": _real_scalar("max", max),
        "n": _count("n", n, least=1),
        "fixed": _real_scalar("fixed", fixed),
        "amax": _real_scalar("amax", amax),
        "points": _count("points", points),
    }
    if axis == "amplitude":
        grid["profile"] = [{"alpha": a, "beta": b} for a, b in pairs]
    return _convert(json.loads(_ext.sweep_json(json.dumps(grid))))
