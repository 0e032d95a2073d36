"""maugis: certified special functions and the wavy Maugis line-contact model.

Special functions (broadcast like NumPy ufuncs; ``bounded=True`` adds a proven
error bound, ``prec=`` returns certified arbitrary-precision balls)::

    bessel_j(n, x)            J_n(x), integer n
    hyp1f2(a, b1, b2, z)      1F2(a; b1, b2; z)
    hyp2f1(a, b, c, z)        2F1(a, b; c; z), z <= 1
    meijer_g_k(k, y)          the Eq. 12 Meijer-G factor, 0 < y <= 1
    meijer_g_k_family(kmax, y), hyp1f2_model_family(kmax, z)
                              all k = 0..kmax at one argument, float64 with bounds
    u_wave(a, zeta, amp, x)   wave displacement u_w (Eq. 12)
    du_wave(a, zeta, amp, x)  its gradient (Eq. 11b)
    fallback_counts()         how often the float64 routes fell back to the MP path

Certified integrals of an expression in x (``prec=`` bits; ``b`` may be inf)::

    integrate(f, a, b, prec=53, alpha=, beta=, log=, decay_rate=, decay_power=, decay_bound=)
                              (mid, rad) of int_a^b (x-a)^alpha (b-x)^beta log^log(x-a) f(x) dx

The model (results carry the fields of the ``maugis`` command's JSON)::

    curve(lam, alpha, beta)         load-area response, jumps, loops, dissipation, pull-off
    run_summary(lam, alpha, beta)   the JSON object of `maugis curve --format json`
    state(lam, alpha, beta, abar)   solved states (broadcasting)
    strip_ratio(lam, alpha, beta, abar), load(lam, alpha, beta, abar)
                                    m and the load at one contact size (float64, or
                                    certified balls with prec=)
    profile(lam, alpha, beta, abar) traction, displacement and gap at one state
    simulate(lam, alpha, beta, ...) one cycle of the numerical solver (maugis simulate:
                                    profile=, half_width=, periodic=)

Bad input raises ``ValueError`` with the library's message. A certified call
(``prec=``) runs within ``budget=`` seconds (default 30): past it, or when its cost
estimate passes it, it raises ``TimeLimitError`` (a ``ValueError``) at once.
See docs/python.md.
"""

from ._maugis import MAX_PREC, PARALLEL_MIN_LEN, TimeLimitError, fallback_counts
from ._model import (
    DEFAULT_DATUM,
    FIG4C_ALPHA,
    FIG4C_BETA,
    Record,
    Table,
    curve,
    load,
    profile,
    run_summary,
    state,
    strip_ratio,
    sweep,
)
from ._integrate import Integral, integrate
from ._simulate import simulate
from ._special import bessel_j, du_wave, hyp1f2, hyp1f2_model_family, hyp2f1, meijer_g_k, meijer_g_k_family, u_wave

__version__ = "0.1.0"

__all__ = [
    "MAX_PREC",
    "PARALLEL_MIN_LEN",
    "TimeLimitError",
    "DEFAULT_DATUM",
    "FIG4C_ALPHA",
    "FIG4C_BETA",
    "Record",
    "Table",
    "bessel_j",
    "hyp1f2",
    "hyp2f1",
    "meijer_g_k",
    "meijer_g_k_family",
    "hyp1f2_model_family",
    "u_wave",
    "du_wave",
    "fallback_counts",
    "integrate",
    "Integral",
    "run_summary",
    "sweep",
    "simulate",
    "curve",
    "state",
    "strip_ratio",
    "load",
    "profile",
]
