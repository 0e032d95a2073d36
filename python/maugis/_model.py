"""The wavy Maugis model: load-area curves, single states and profiles.

The results are frozen dataclasses of NumPy arrays whose fields carry the names
of the ``maugis`` command's JSON (``maugis curve --format json``,
``maugis profile --format json``); ``as_json()`` returns exactly that JSON
object. The JSON key ``lambda`` is a Python keyword: it is ``lam`` here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import Optional

import numpy as np

from . import _maugis as _ext
from ._special import _as_real, _flat

__all__ = [
    "FIG4C_ALPHA",
    "FIG4C_BETA",
    "Curve",
    "CurveParams",
    "CurvePoints",
    "TurningPoints",
    "Jumps",
    "PullOff",
    "HysteresisLoops",
    "State",
    "Profile",
    "ProfileSamples",
    "curve",
    "state",
    "profile",
]

#: Normalised wave amplitude of the paper's Fig. 4c, ``2 sqrt(2)/8``.
FIG4C_ALPHA = math.sqrt(2.0) / 4.0
#: Normalised wavelength of the paper's Fig. 4c.
FIG4C_BETA = 9.0 / 8.0


def _rows(obj):
    """Column dataclass -> list of JSON row objects (one per index)."""
    cols = {f.name: getattr(obj, f.name) for f in fields(obj)}
    n = len(next(iter(cols.values()))) if cols else 0
    return [{k: _plain(v[i]) for k, v in cols.items()} for i in range(n)]


def _plain(v):
    """A NumPy scalar as the Python value ``json`` would write."""
    return v.item() if isinstance(v, np.generic) else v


def _columns(cls, d):
    return cls(**{f.name: np.asarray(d[f.name]) for f in fields(cls)})


@dataclass(frozen=True)
class CurvePoints:
    """The grid states of a curve, one entry per ``abar_i = amax i / points``."""

    abar: np.ndarray
    m: np.ndarray
    """Strip ratio ``c/a``."""
    load: np.ndarray
    """Normalised load ``Lbar`` (Eq. 14)."""
    valid: np.ndarray
    """No cavitation (``max_traction <= 1``) and no negative strip gap."""
    min_strip_gap: np.ndarray
    max_traction: np.ndarray


@dataclass(frozen=True)
class TurningPoints:
    """Refined turning points ``dLbar/dabar = 0``, by increasing ``abar``."""

    abar: np.ndarray
    load: np.ndarray
    kind: np.ndarray
    """``"max"`` or ``"min"``."""


@dataclass(frozen=True)
class Jumps:
    """Jumps at constant load under load control."""

    direction: np.ndarray
    """``"loading"`` (from a maximum to a larger contact) or ``"unloading"``."""
    from_abar: np.ndarray
    to_abar: np.ndarray
    load: np.ndarray


@dataclass(frozen=True)
class PullOff:
    """The pull-off state."""

    abar: float
    load: float


@dataclass(frozen=True)
class HysteresisLoops:
    """Loops formed by a loading jump and the unloading jump that returns past it."""

    loading_from_abar: np.ndarray
    loading_to_abar: np.ndarray
    loading_load: np.ndarray
    unloading_from_abar: np.ndarray
    unloading_to_abar: np.ndarray
    unloading_load: np.ndarray
    area: np.ndarray
    """Area enclosed in the ``(abar, Lbar)`` plane."""


@dataclass(frozen=True)
class CurveParams:
    """The JSON ``params`` object."""

    alpha: float
    beta: float
    amax: float
    points: int


@dataclass(frozen=True)
class Curve:
    """One load-area response (one entry of the JSON ``curves`` list)."""

    lam: float
    params: CurveParams
    points: CurvePoints
    turning_points: TurningPoints
    jumps: Jumps
    pull_off: Optional[PullOff]
    hysteresis_loops: HysteresisLoops

    def as_json(self):
        """The object ``maugis curve --format json`` prints for this one curve."""
        return {
            "params": {f.name: getattr(self.params, f.name) for f in fields(self.params)},
            "curves": [
                {
                    "lambda": self.lam,
                    "points": _rows(self.points),
                    "turning_points": _rows(self.turning_points),
                    "jumps": _rows(self.jumps),
                    "pull_off": None
                    if self.pull_off is None
                    else {"abar": self.pull_off.abar, "load": self.pull_off.load},
                }
            ],
        }


@dataclass(frozen=True)
class State:
    """Solved states (arrays of the broadcast shape of the arguments, or scalars)."""

    abar: np.ndarray
    m: np.ndarray
    load: np.ndarray
    valid: np.ndarray
    min_strip_gap: np.ndarray
    min_strip_gap_at: np.ndarray
    max_traction: np.ndarray
    max_traction_at: np.ndarray


@dataclass(frozen=True)
class ProfileSamples:
    """Traction, displacement, gap and surface depth against ``xbar``."""

    xbar: np.ndarray
    pbar: np.ndarray
    ubar: np.ndarray
    gbar: np.ndarray
    hbar: np.ndarray


@dataclass(frozen=True)
class Profile:
    """One state and its profile (``maugis profile --format json``)."""

    lam: float
    alpha: float
    beta: float
    abar: float
    m: float
    load: float
    valid: bool
    min_strip_gap: float
    min_strip_gap_at: float
    max_traction: float
    max_traction_at: float
    samples: ProfileSamples

    def as_json(self):
        """The object ``maugis profile --format json`` prints."""
        out = {("lambda" if f.name == "lam" else f.name): _plain(getattr(self, f.name)) for f in fields(self)}
        out["samples"] = _rows(self.samples)
        return out


def _real_scalar(name, v):
    a = _as_real(name, v)
    if a.shape != ():
        raise ValueError(f"{name} must be a single number here (got an array of shape {a.shape})")
    return float(a)


def _one_curve(lam, alpha, beta, amax, points):
    d = _ext.curve_dict(lam, alpha, beta, amax, points)
    po = d["pull_off"]
    tp = d["turning_points"]
    jumps = d["jumps"]
    return Curve(
        lam=lam,
        params=CurveParams(alpha=alpha, beta=beta, amax=amax, points=points),
        points=_columns(CurvePoints, d["points"]),
        turning_points=TurningPoints(abar=tp["abar"], load=tp["load"], kind=np.array(tp["kind"], dtype=str)),
        jumps=Jumps(
            direction=np.array(jumps["direction"], dtype=str),
            from_abar=jumps["from_abar"],
            to_abar=jumps["to_abar"],
            load=jumps["load"],
        ),
        pull_off=None if po is None else PullOff(abar=po[0], load=po[1]),
        hysteresis_loops=_columns(HysteresisLoops, d["hysteresis_loops"]),
    )


def _count(name, v):
    if isinstance(v, bool) or not isinstance(v, (int, np.integer)):
        raise TypeError(f"{name} must be an integer (got {v!r})")
    if v < 2:
        raise ValueError(f"{name} must be >= 2 (got {v})")
    return int(v)


def curve(lam, alpha=FIG4C_ALPHA, beta=FIG4C_BETA, *, amax=6.0, points=600):
    """Load-area response ``Lbar(abar)`` on ``abar_i = amax i / points``, ``i = 1..points``.

    ``lam`` (the Maugis parameter) may be one number, giving a :class:`Curve`,
    or a sequence, giving a list of them. Turning points, jumps under load
    control, pull-off and hysteresis loops are those of ``maugis curve``.
    """
    alpha = _real_scalar("alpha", alpha)
    beta = _real_scalar("beta", beta)
    amax = _real_scalar("amax", amax)
    points = _count("points", points)
    lams = _as_real("lam", lam)
    if lams.ndim == 0:
        return _one_curve(float(lams), alpha, beta, amax, points)
    return [_one_curve(float(v), alpha, beta, amax, points) for v in lams.reshape(-1)]


def state(lam, alpha, beta, abar):
    """Solved states: the strip ratio ``m``, the load and the validity diagnostics.

    The arguments broadcast like a ufunc; states are solved in parallel.
    """
    conv = [_as_real(n, v) for n, v in (("lam", lam), ("alpha", alpha), ("beta", beta), ("abar", abar))]
    flat, shape = _flat(conv)
    d = _ext.state_dict(*flat)
    cols = {}
    for f in fields(State):
        v = np.asarray(d[f.name]).reshape(shape)
        cols[f.name] = v[()] if shape == () else v
    return State(**cols)


def profile(lam, alpha, beta, abar, *, x=None, points=600):
    """Traction ``pbar``, displacement ``ubar``, gap ``gbar`` and surface depth ``hbar`` at one state.

    ``x`` (``xbar`` positions, >= 0) defaults to the grid of ``maugis profile``:
    ``points`` values over ``[0, 1.5 m abar]`` plus the contact edge and the strip end.
    """
    lam, alpha, beta, abar = (
        _real_scalar(n, v) for n, v in (("lam", lam), ("alpha", alpha), ("beta", beta), ("abar", abar))
    )
    if x is None:
        points = _count("points", points)
        m = float(state(lam, alpha, beta, abar).m)
        c = m * abar
        xs = 1.5 * c * np.arange(points, dtype=np.float64) / (points - 1)
        x = np.unique(np.concatenate([xs, [abar, c]]))
    x = np.ascontiguousarray(_as_real("x", x).reshape(-1))
    d = _ext.profile_dict(lam, alpha, beta, abar, x)
    scal = {k: _plain(np.asarray(d[k])[0]) for k in ("abar", "m", "load", "valid", "min_strip_gap",
                                                     "min_strip_gap_at", "max_traction", "max_traction_at")}
    return Profile(lam=lam, alpha=alpha, beta=beta, samples=_columns(ProfileSamples, d["samples"]), **scal)
