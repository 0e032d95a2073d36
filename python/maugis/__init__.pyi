# Type stubs of the maugis package (editors complete the names from here).
import os
from typing import Any, Literal, Sequence, Tuple, Union, overload

import mpmath
import numpy as np
import numpy.typing as npt

ArrayLike = npt.ArrayLike
FloatArray = npt.NDArray[np.float64]
# a float64 array (a NumPy scalar for scalar arguments)
Values = Union[FloatArray, np.float64]
MpInput = Union[ArrayLike, str, mpmath.mpf]
# certified balls: (mid, rad) as mpmath.mpf or decimal strings (object arrays for array arguments)
Balls = Tuple[Any, Any]

MAX_PREC: int
PARALLEL_MIN_LEN: int
DEFAULT_DATUM: float
FIG4C_ALPHA: float
FIG4C_BETA: float
__version__: str

class TimeLimitError(ValueError): ...

@overload
def bessel_j(n: ArrayLike, x: ArrayLike, *, bounded: Literal[False] = ..., prec: None = ...) -> Values: ...
@overload
def bessel_j(n: ArrayLike, x: ArrayLike, *, bounded: Literal[True], prec: None = ...) -> Tuple[Values, Values]: ...
@overload
def bessel_j(n: MpInput, x: MpInput, *, prec: int, output: Literal["mpf", "str"] = ..., digits: int | None = ..., budget: float | None = ...) -> Balls: ...
@overload
def hyp1f2(a: ArrayLike, b1: ArrayLike, b2: ArrayLike, z: ArrayLike, *, bounded: Literal[False] = ..., prec: None = ...) -> Values: ...
@overload
def hyp1f2(a: ArrayLike, b1: ArrayLike, b2: ArrayLike, z: ArrayLike, *, bounded: Literal[True], prec: None = ...) -> Tuple[Values, Values]: ...
@overload
def hyp1f2(a: MpInput, b1: MpInput, b2: MpInput, z: MpInput, *, prec: int, output: Literal["mpf", "str"] = ..., digits: int | None = ..., budget: float | None = ...) -> Balls: ...
@overload
def hyp2f1(a: ArrayLike, b: ArrayLike, c: ArrayLike, z: ArrayLike, *, bounded: Literal[False] = ..., prec: None = ...) -> Values: ...
@overload
def hyp2f1(a: ArrayLike, b: ArrayLike, c: ArrayLike, z: ArrayLike, *, bounded: Literal[True], prec: None = ...) -> Tuple[Values, Values]: ...
@overload
def hyp2f1(a: MpInput, b: MpInput, c: MpInput, z: MpInput, *, prec: int, output: Literal["mpf", "str"] = ..., digits: int | None = ..., budget: float | None = ...) -> Balls: ...
@overload
def meijer_g_k(k: ArrayLike, y: ArrayLike, *, bounded: Literal[False] = ..., prec: None = ...) -> Values: ...
@overload
def meijer_g_k(k: ArrayLike, y: ArrayLike, *, bounded: Literal[True], prec: None = ...) -> Tuple[Values, Values]: ...
@overload
def meijer_g_k(k: MpInput, y: MpInput, *, prec: int, output: Literal["mpf", "str"] = ..., digits: int | None = ..., budget: float | None = ...) -> Balls: ...
def meijer_g_k_family(kmax: int, y: float) -> Tuple[Values, Values]: ...
def fallback_counts() -> dict[str, int]: ...
def hyp1f2_model_family(kmax: int, z: float) -> Tuple[Values, Values]: ...
@overload
def u_wave(a: ArrayLike, zeta: ArrayLike, amp: ArrayLike, x: ArrayLike, *, bounded: Literal[False] = ..., prec: None = ...) -> Values: ...
@overload
def u_wave(a: ArrayLike, zeta: ArrayLike, amp: ArrayLike, x: ArrayLike, *, bounded: Literal[True], prec: None = ...) -> Tuple[Values, Values]: ...
@overload
def u_wave(a: MpInput, zeta: MpInput, amp: MpInput, x: MpInput, *, prec: int, output: Literal["mpf", "str"] = ..., digits: int | None = ..., budget: float | None = ...) -> Balls: ...
@overload
def du_wave(a: ArrayLike, zeta: ArrayLike, amp: ArrayLike, x: ArrayLike, *, bounded: Literal[False] = ..., prec: None = ...) -> Values: ...
@overload
def du_wave(a: ArrayLike, zeta: ArrayLike, amp: ArrayLike, x: ArrayLike, *, bounded: Literal[True], prec: None = ...) -> Tuple[Values, Values]: ...
@overload
def du_wave(a: MpInput, zeta: MpInput, amp: MpInput, x: MpInput, *, prec: int, output: Literal["mpf", "str"] = ..., digits: int | None = ..., budget: float | None = ...) -> Balls: ...
def integrate(
    f: str,
    a: Union[float, int, str, mpmath.mpf],
    b: Union[float, int, str, mpmath.mpf],
    *,
    prec: int = ...,
    alpha: Union[float, int, str, mpmath.mpf, None] = ...,
    beta: Union[float, int, str, mpmath.mpf, None] = ...,
    log: int = ...,
    decay_rate: Union[float, int, str, mpmath.mpf, None] = ...,
    decay_power: Union[float, int, str, mpmath.mpf, None] = ...,
    decay_bound: Union[float, int, str, mpmath.mpf, None] = ...,
    output: Literal["mpf", "str"] = ...,
    digits: int | None = ...,
    budget: float | None = ...,
) -> Integral: ...

class Integral(Tuple[Any, Any]):
    """``(mid, rad)`` of a certified integral, with ``abs_tol`` and ``evaluations``."""
    abs_tol: Any
    evaluations: int
    @property
    def mid(self) -> Any: ...
    @property
    def rad(self) -> Any: ...

class Record(dict[str, Any]):
    """A JSON object; keys are also attributes."""
    def __getattr__(self, name: str) -> Any: ...

class Table(Record):
    """A list of JSON objects as columns of NumPy arrays."""
    nrows: int
    def __init__(self, columns: Any = ..., nrows: int = ...) -> None: ...

def run_summary(lam: Union[float, Sequence[float]], alpha: float | None = ..., beta: float | None = ..., *, waves: Sequence[tuple[float, float]] | None = ..., amax: float = ..., points: int = ..., datum: float = ...) -> dict[str, Any]: ...
@overload
def curve(lam: float, alpha: float | None = ..., beta: float | None = ..., *, waves: Sequence[tuple[float, float]] | None = ..., amax: float = ..., points: int = ..., datum: float = ...) -> Record: ...
@overload
def curve(lam: Sequence[float], alpha: float | None = ..., beta: float | None = ..., *, waves: Sequence[tuple[float, float]] | None = ..., amax: float = ..., points: int = ..., datum: float = ...) -> list[Record]: ...
def state(lam: ArrayLike, alpha: ArrayLike | None, beta: ArrayLike | None, abar: ArrayLike, *, waves: Sequence[tuple[float, float]] | None = ...) -> Record: ...
@overload
def strip_ratio(lam: ArrayLike, alpha: ArrayLike | None, beta: ArrayLike | None, abar: ArrayLike, *, waves: Sequence[tuple[Any, Any]] | None = ..., prec: None = ...) -> Values: ...
@overload
def strip_ratio(lam: MpInput, alpha: MpInput | None, beta: MpInput | None, abar: MpInput, *, waves: Sequence[tuple[Any, Any]] | None = ..., prec: int, output: Literal["mpf", "str"] = ..., digits: int | None = ...) -> Balls: ...
@overload
def load(lam: ArrayLike, alpha: ArrayLike | None, beta: ArrayLike | None, abar: ArrayLike, *, waves: Sequence[tuple[Any, Any]] | None = ..., prec: None = ...) -> Values: ...
@overload
def load(lam: MpInput, alpha: MpInput | None, beta: MpInput | None, abar: MpInput, *, waves: Sequence[tuple[Any, Any]] | None = ..., prec: int, output: Literal["mpf", "str"] = ..., digits: int | None = ...) -> Balls: ...
def profile(lam: float, alpha: float | None, beta: float | None, abar: float, *, waves: Sequence[tuple[float, float]] | None = ..., x: ArrayLike | None = ..., points: int = ...) -> Record: ...
def sweep(lambda_min: float, lambda_max: float, lambda_n: int, axis: Literal["alpha", "beta", "johnson", "amplitude"], min: float, max: float, n: int, fixed: float | None = ..., *, waves: Sequence[tuple[float, float]] | None = ..., amax: float = ..., points: int = ...) -> Record: ...
def simulate(
    lam: float,
    alpha: float | None = ...,
    beta: float | None = ...,
    *,
    waves: Sequence[tuple[float, float]] | None = ...,
    amax: float = ...,
    cells: int = ...,
    steps: int = ...,
    profile: str | os.PathLike[str] | tuple[ArrayLike, ArrayLike] | None = ...,
    half_width: float | None = ...,
    periodic: bool = ...,
    law: Literal["dugdale", "exp"] = ...,
) -> Record: ...
