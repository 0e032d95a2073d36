"""Array behaviour: broadcasting, dtypes, scalars, empty arrays, bad input, threads."""

import threading

import mpmath
import numpy as np
import pytest

import maugis

FUNCTIONS = {
    "bessel_j": (maugis.bessel_j, (3, 2.5)),
    "hyp1f2": (maugis.hyp1f2, (0.5, 1.0, 1.5, -3.0)),
    "hyp2f1": (maugis.hyp2f1, (0.5, 0.5, 1.5, 0.5)),
    "meijer_g_k": (maugis.meijer_g_k, (2, 0.5)),
    "u_wave": (maugis.u_wave, (2.0, 1.125, 0.5, 4.0)),
    "du_wave": (maugis.du_wave, (2.0, 1.125, 0.5, 4.0)),
}


@pytest.mark.parametrize("name", FUNCTIONS)
def test_scalar_in_scalar_out(name):
    f, args = FUNCTIONS[name]
    v = f(*args)
    assert isinstance(v, np.float64)
    val, err = f(*args, bounded=True)
    assert isinstance(val, np.float64) and isinstance(err, np.float64)
    assert abs(val - v) <= err + 4e-15 * abs(v)


@pytest.mark.parametrize("name", FUNCTIONS)
def test_broadcasting_matches_elementwise(name):
    f, args = FUNCTIONS[name]
    # vary the last argument along axis 1 and the first real one along axis 0
    last = np.array([args[-1], args[-1] * 1.25, args[-1] * 1.5])[None, :]
    first = np.array([args[0], args[0] + 1])[:, None]
    got = f(first, *args[1:-1], last)
    assert got.shape == (2, 3)
    for i in range(2):
        for j in range(3):
            assert got[i, j] == f(first[i, 0], *args[1:-1], last[0, j])
    val, err = f(first, *args[1:-1], last, bounded=True)
    assert val.shape == err.shape == (2, 3)


@pytest.mark.parametrize("name", FUNCTIONS)
def test_empty_arrays(name):
    f, args = FUNCTIONS[name]
    out = f(*args[:-1], np.array([]))
    assert out.shape == (0,) and out.dtype == np.float64
    out = f(*args[:-1], np.zeros((3, 0)))
    assert out.shape == (3, 0)
    val, err = f(*args[:-1], [], bounded=True)
    assert val.shape == err.shape == (0,)
    mid, rad = f(*args[:-1], [], prec=64)
    assert mid.shape == rad.shape == (0,)


@pytest.mark.parametrize("name", FUNCTIONS)
def test_nan_and_inf_raise_value_error_with_the_librarys_message(name):
    f, args = FUNCTIONS[name]
    for bad in (np.nan, np.inf, -np.inf):
        with pytest.raises(ValueError, match="finite"):
            f(*args[:-1], np.array([args[-1], bad]))
        with pytest.raises(ValueError, match="finite"):
            f(*args[:-1], bad, bounded=True)
        with pytest.raises(ValueError, match="finite"):
            f(*args[:-1], bad, prec=64)
        with pytest.raises(ValueError, match="finite"):
            f(*args[:-1], mpmath.mpf(bad), prec=64)


def test_error_names_the_failing_element():
    with pytest.raises(ValueError, match=r"bessel_j\(n=4, x=NaN\)"):
        maugis.bessel_j([2, 3, 4], [1.0, 2.0, np.nan])


def test_out_of_domain_raises():
    with pytest.raises(ValueError, match=r"z must lie in \(-inf, 1\] \(got 2\.0\)"):
        maugis.hyp2f1(0.5, 0.5, 1.5, 2.0)
    with pytest.raises(ValueError, match=r"y \(= \(a/x\)\^2 with x >= a\) must lie in \(0, 1\]"):
        maugis.meijer_g_k(1, [0.5, 0.0])
    with pytest.raises(ValueError, match="k must be an integer in 0 "):
        maugis.meijer_g_k(-1, 0.5)
    with pytest.raises(ValueError, match="x >= a"):
        maugis.u_wave(2.0, 1.125, 0.5, 1.0)
    with pytest.raises(ValueError, match=r"n must be an integer in -1000000 \.\.= 1000000"):
        maugis.bessel_j(10**7, 1.0)
    with pytest.raises(ValueError, match=r"z must lie in \(-inf, 1\]"):
        maugis.hyp2f1(0.5, 0.5, 1.5, 2.0, prec=64)


def test_order_must_be_an_integer():
    assert maugis.bessel_j(3.0, 2.5) == maugis.bessel_j(3, 2.5)
    with pytest.raises(ValueError, match="n must be an integer"):
        maugis.bessel_j(2.5, 1.0)
    with pytest.raises(ValueError, match="n must be an integer"):
        maugis.bessel_j(np.nan, 1.0)
    with pytest.raises(ValueError, match="k must be an integer"):
        maugis.meijer_g_k([1.0, 1.5], 0.5)
    with pytest.raises(ValueError, match="n = .* is not an integer"):
        maugis.bessel_j(2.5, 1.0, prec=64)
    with pytest.raises(TypeError):
        maugis.bessel_j("3", 1.0)
    with pytest.raises(ValueError, match="too large"):
        maugis.bessel_j(np.array([2**64 - 1], dtype=np.uint64), 1.0)


def test_dtypes():
    ref = maugis.bessel_j(np.arange(6), 2.5)
    for ndt in (np.int8, np.int16, np.int32, np.int64, np.uint8, np.uint32, np.uint64, np.float32, np.float64):
        np.testing.assert_array_equal(maugis.bessel_j(np.arange(6, dtype=ndt), 2.5), ref)
    # float32 x is converted exactly to float64
    x32 = np.float32(0.1)
    assert maugis.bessel_j(1, x32) == maugis.bessel_j(1, float(x32))
    # integer and bool x
    assert maugis.bessel_j(1, np.int32(3)) == maugis.bessel_j(1, 3.0)
    assert maugis.bessel_j(0, True) == maugis.bessel_j(0, 1.0)
    # python lists and nested lists
    assert maugis.bessel_j([[0, 1], [2, 3]], 1.0).shape == (2, 2)
    with pytest.raises(TypeError):
        maugis.bessel_j(1, np.array([1 + 2j]))
    with pytest.raises(TypeError):
        maugis.hyp2f1(0.5, 0.5, 1.5, "0.5")


def test_non_contiguous_and_fortran_inputs():
    x = np.linspace(0.5, 40.0, 200).reshape(10, 20)
    ref = maugis.bessel_j(7, x)
    np.testing.assert_array_equal(maugis.bessel_j(7, np.asfortranarray(x)), ref)
    np.testing.assert_array_equal(maugis.bessel_j(7, x[:, ::3]), ref[:, ::3])
    np.testing.assert_array_equal(maugis.bessel_j(7, x.T), ref.T)


def test_incompatible_shapes_raise():
    with pytest.raises(ValueError):
        maugis.bessel_j(np.arange(3), np.ones(4))


def test_prec_arguments_are_checked():
    with pytest.raises(ValueError, match="precision"):
        maugis.bessel_j(1, 1.0, prec=1)
    with pytest.raises(ValueError, match="precision"):
        maugis.bessel_j(1, 1.0, prec=maugis.MAX_PREC + 1)
    with pytest.raises(TypeError):
        maugis.bessel_j(1, 1.0, prec=64.5)
    with pytest.raises(ValueError, match="choose one"):
        maugis.bessel_j(1, 1.0, prec=64, bounded=True)
    with pytest.raises(ValueError, match="output"):
        maugis.bessel_j(1, 1.0, prec=64, output="float")
    with pytest.raises(ValueError, match="not a number"):
        maugis.bessel_j(1, "one", prec=64)


def test_large_arrays_run_in_parallel_with_the_same_result():
    # above PARALLEL_MIN_LEN the loop runs on rayon's pool: same numbers as
    # evaluating the same elements in small (serial) pieces
    n = maugis.PARALLEL_MIN_LEN + 17
    x = np.linspace(0.01, 80.0, n)
    whole = maugis.bessel_j(3, x)
    step = maugis.PARALLEL_MIN_LEN // 4
    pieces = np.concatenate([maugis.bessel_j(3, x[i : i + step]) for i in range(0, n, step)])
    np.testing.assert_array_equal(whole, pieces)
    val, err = maugis.bessel_j(3, x, bounded=True)
    np.testing.assert_array_equal(val, whole)
    # the error of a bad element far into the array is still reported
    bad = x.copy()
    bad[-5] = np.nan
    with pytest.raises(ValueError, match="finite"):
        maugis.bessel_j(3, bad)


def test_threads_share_the_module():
    # the GIL is released inside the loops: concurrent calls give the same results
    x = np.linspace(0.5, 50.0, 400)
    ref = maugis.bessel_j(5, x)
    out = [None] * 4

    def work(i):
        out[i] = maugis.bessel_j(5, x)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for o in out:
        np.testing.assert_array_equal(o, ref)


def test_stubs_cover_the_public_names():
    import ast
    import pathlib

    stub = pathlib.Path(maugis.__file__).with_name("__init__.pyi")
    assert stub.exists(), "the wheel ships the .pyi stubs"
    tree = ast.parse(stub.read_text())
    names = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    names |= {t.id for n in tree.body if isinstance(n, ast.AnnAssign) for t in [n.target]}
    assert set(maugis.__all__) <= names
