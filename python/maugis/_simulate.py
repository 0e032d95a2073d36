"""``maugis.simulate``: the numerical Dugdale-Maugis solver with every option of
``maugis simulate`` (the binding is ``python/src/simulate.rs``; the solver
logic lives in the ``maugis-solver`` crate)."""

from __future__ import annotations

import json
import os

import numpy as np

from . import _maugis as _ext
from ._model import _convert, _count, _real_scalar, _roughness


def simulate(
    lam,
    alpha=None,
    beta=None,
    *,
    waves=None,
    amax=4.0,
    cells=4096,
    steps=100,
    profile=None,
    half_width=None,
    periodic=False,
    law="dugdale",
):
    """One displacement-controlled cycle of the numerical Dugdale-Maugis solver
    (``maugis-solver``; ``maugis simulate --format json``): loading to the
    contact half-width ``amax``, unloading until the contact is gone, and
    reloading from the smallest contact the unloading held. It reaches the
    states the semi-analytical model cannot describe (cavitated contacts) and
    checks the model where it holds.

    ``cells`` is the grid (a power of two), ``steps`` the approach steps per
    leg. The options of the command line:

    * ``profile``: a profile table in place of the built-in wavy cylinder,
      either the path of a CSV file (header ``x,h``, ``x`` strictly
      increasing; ``--profile``) or a pair of arrays ``(x, h)``, in the
      normalised units of the built-in profile and covering the domain.
      ``alpha`` and ``beta`` (or ``waves``) then name the model the states are
      compared with and that sizes the domain; without them no model is
      compared (``model_load`` stays ``None``);
    * ``waves``: a list of ``(amplitude, wavelength)`` pairs in place of
      ``alpha``, ``beta``: the cylinder carrying all of them is simulated and
      compared with the model of the same profile (``--wave A,B --wave ...``;
      free domain only); the record's ``profile`` is ``"rough_cylinder"`` and
      ``waves`` lists them;
    * ``half_width``: the domain half-width ``X`` (``--half-width``);
    * ``periodic``: a periodic half-plane of period ``2X`` (``--periodic``);
      the built-in profile is then the wave ``alpha (1 - cos(2 pi x/beta))``
      on one period ``[-beta/2, beta/2]``, and no model is compared;
    * ``law``: the adhesion law (``--law``), ``"dugdale"`` (the paper's) or
      ``"exp"``, a smooth law with a hard wall and the stress
      ``lam exp(-lam g)``, matched to Dugdale's in peak stress and work of
      adhesion (so its equivalent Maugis parameter is ``lam``).

    Returns a :class:`Record` with ``law``, ``domain``, ``profile``, ``lambda``,
    ``alpha``, ``beta``, ``cells``, ``half_width``, ``datum``,
    ``stiff_cycle_work`` (``oint L dDelta`` of the simulated stiff-machine
    cycle, not the dissipation), ``dissipation`` (``load_control``,
    ``displacement_control``, ``datum``, ...: W of the closed in-contact cycle,
    as ``curve(...).dissipation``; ``None`` with fewer than two states in
    contact), ``pull_off`` (the most tensile load under load control) and
    ``states``: a :class:`Table` with ``leg`` (``loading``, ``unloading``,
    ``reloading``), ``approach``, ``abar``, ``load``, ``contact_intervals``,
    ``zone_cells``, ``model_load`` and ``model_valid`` (``None`` where the model
    has no state at that half-width), ``load_controlled`` and
    ``zone_ends_placed``.

    Bad input raises ``ValueError``; a bad profile table names its line.
    """
    without_model = profile is not None and alpha is None and beta is None and waves is None
    if without_model:
        alpha, beta = 0.0, 1.0  # the smooth cylinder sizes the domain
    else:
        alpha, beta, waves = _roughness(alpha, beta, waves)
    lam, amax = (_real_scalar(n, v) for n, v in (("lam", lam), ("amax", amax)))
    path = columns = None
    if profile is not None:
        if isinstance(profile, (str, os.PathLike)):
            path = os.fspath(profile)
        else:
            try:
                x, h = profile
            except (TypeError, ValueError):
                raise TypeError("profile must be a CSV file's path or a pair of arrays (x, h)") from None
            x, h = (np.asarray(v, dtype=np.float64).reshape(-1).tolist() for v in (x, h))
            columns = (x, h)
    if half_width is not None:
        half_width = _real_scalar("half_width", half_width)
    if not isinstance(periodic, (bool, np.bool_)):
        raise TypeError(f"periodic must be True or False (got {periodic!r})")
    if not isinstance(law, str):
        raise TypeError(f"law must be 'dugdale' or 'exp' (got {law!r})")
    text = _ext.simulate_json(
        lam, alpha, beta, amax, _count("cells", cells), _count("steps", steps),
        path, columns, half_width, bool(periodic), law, waves, without_model,
    )
    return _convert(json.loads(text))
