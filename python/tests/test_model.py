"""The model calls against the `maugis` command line's JSON."""

import json
import subprocess

import numpy as np
import pytest

import maugis

ALPHA = 2**0.5 / 4
BETA = 9 / 8


def run_cli(cli, *args):
    out = subprocess.run([cli, *args], capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    return out.stdout


@pytest.fixture(scope="module")
def curve6():
    return maugis.curve(6, ALPHA, BETA)


def test_curve_equals_cli_json(maugis_cli, curve6):
    # the acceptance check: same jumps (and everything else) as the CLI
    cli = json.loads(run_cli(maugis_cli, "curve", "--lambda", "6", "--alpha", repr(ALPHA), "--beta", repr(BETA),
                             "--format", "json"))
    ours = curve6.as_json()
    assert ours["params"] == cli["params"]
    (c_cli,), (c_ours,) = cli["curves"], ours["curves"]
    assert c_ours["jumps"] == c_cli["jumps"]
    assert c_ours["pull_off"] == c_cli["pull_off"]
    assert c_ours["turning_points"] == c_cli["turning_points"]
    assert c_ours == c_cli
    assert len(c_cli["jumps"]) >= 4


def test_hysteresis_loops_equal_cli_summary(maugis_cli, curve6, tmp_path):
    run_cli(maugis_cli, "curve", "--lambda", "6", "--out", str(tmp_path))
    summary = json.loads((tmp_path / "summary.json").read_text())
    (s,) = summary["curves"]
    loops = curve6.hysteresis_loops
    assert len(s["hysteresis_loops"]) == len(loops.area) > 0
    for i, lp in enumerate(s["hysteresis_loops"]):
        for key, value in lp.items():
            assert getattr(loops, key)[i] == value, key
    assert s["invalid_points"] == int((~curve6.points.valid).sum())


def test_curve_fields_and_types(curve6):
    p = curve6.points
    assert p.abar.shape == p.m.shape == p.load.shape == (600,)
    assert p.valid.dtype == bool and p.abar.dtype == np.float64
    np.testing.assert_allclose(p.abar, 6.0 * np.arange(1, 601) / 600, rtol=0, atol=0)
    assert set(curve6.turning_points.kind) <= {"max", "min"}
    assert set(curve6.jumps.direction) == {"loading", "unloading"}
    assert curve6.pull_off is not None and curve6.pull_off.load < 0
    # the paper's Fig. 4c instabilities at lambda = 6: abar = 2.71 loading, 3.16 unloading
    j = curve6.jumps
    loading = j.from_abar[j.direction == "loading"]
    unloading = j.from_abar[j.direction == "unloading"]
    assert np.min(np.abs(loading - 2.71)) < 0.05
    assert np.min(np.abs(unloading - 3.16)) < 0.05


def test_curve_accepts_several_lambdas():
    curves = maugis.curve([0.5, 6.0], amax=2.0, points=40)
    assert [c.lam for c in curves] == [0.5, 6.0]
    assert all(c.points.abar.shape == (40,) for c in curves)
    assert curves[0].params == maugis.CurveParams(alpha=maugis.FIG4C_ALPHA, beta=maugis.FIG4C_BETA, amax=2.0, points=40)


def test_state_matches_curve_points(curve6):
    idx = np.array([0, 99, 333, 599])
    s = maugis.state(6, ALPHA, BETA, curve6.points.abar[idx])
    for field in ("abar", "m", "load", "valid", "min_strip_gap", "max_traction"):
        np.testing.assert_array_equal(getattr(s, field), getattr(curve6.points, field)[idx])
    # broadcasting over lambda and abar
    s2 = maugis.state(np.array([1.0, 6.0])[:, None], ALPHA, BETA, np.array([0.5, 1.0, 2.0]))
    assert s2.m.shape == (2, 3)
    one = maugis.state(6.0, ALPHA, BETA, 1.0)
    assert isinstance(one.m, np.float64) and one.m > 1


def test_profile_equals_cli_json(maugis_cli):
    cli = json.loads(run_cli(maugis_cli, "profile", "--abar", "2", "--lambda", "1.5", "--format", "json"))
    ours = maugis.profile(1.5, maugis.FIG4C_ALPHA, maugis.FIG4C_BETA, 2.0)
    assert ours.as_json() == cli
    assert ours.samples.xbar.shape == (602,)


def test_profile_at_given_points():
    x = np.array([0.0, 1.0, 1.99, 2.0, 2.05, 3.0])
    p = maugis.profile(6, ALPHA, BETA, 2.0, x=x)
    np.testing.assert_array_equal(p.samples.xbar, x)
    assert p.samples.gbar[3] == pytest.approx(0.0, abs=1e-9)  # the gap closes at the contact edge
    assert np.all(p.samples.gbar[:4] == pytest.approx(0.0, abs=1e-9))


def test_model_errors_are_value_errors():
    with pytest.raises(ValueError, match="lambda must lie in"):
        maugis.curve(-1.0)
    with pytest.raises(ValueError, match="finite"):
        maugis.curve(np.nan)
    with pytest.raises(ValueError, match="points must be >= 2"):
        maugis.curve(1.0, points=1)
    with pytest.raises(ValueError, match="amax"):
        maugis.curve(1.0, amax=0.0)
    with pytest.raises(ValueError, match=r"state\(lam=6.0, alpha=.*abar=NaN\)"):
        maugis.state(6.0, ALPHA, BETA, [1.0, np.nan])
    with pytest.raises(ValueError, match="abar must lie in"):
        maugis.profile(6.0, ALPHA, BETA, -1.0)
    with pytest.raises(ValueError, match="single number"):
        maugis.profile(6.0, ALPHA, BETA, [1.0, 2.0])
    empty = maugis.state(6.0, ALPHA, BETA, np.array([]))
    assert empty.m.shape == (0,)
