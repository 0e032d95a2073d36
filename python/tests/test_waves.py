"""Profiles of many waves (issue 35): ``waves=`` against the command line's ``--wave``."""

import json
import subprocess

import mpmath
import numpy as np
import pytest

import maugis

WAVES = [(2**0.5 / 4, 9 / 8), (2**0.5 / 8, 3 / 8)]
FLAGS = [arg for a, b in WAVES for arg in ("--wave", f"{a!r},{b!r}")]


def run_cli(cli, *args):
    out = subprocess.run([cli, *args], capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout)


def test_run_summary_of_many_waves_equals_cli_json(maugis_cli):
    cli = run_cli(maugis_cli, "curve", "--lambda", "3", "--amax", "2", "--points", "40", "--format", "json", *FLAGS)
    py = maugis.run_summary(3, waves=WAVES, amax=2, points=40)
    assert py == cli
    assert [(w["alpha"], w["beta"]) for w in py["params"]["waves"]] == WAVES


def test_one_wave_in_waves_is_alpha_beta():
    a = maugis.run_summary(3, 0.3, 0.9, amax=2, points=30)
    b = maugis.run_summary(3, waves=[(0.3, 0.9)], amax=2, points=30)
    assert a == b
    assert "waves" not in b["params"]


def test_profile_of_many_waves_equals_cli_json(maugis_cli):
    cli = run_cli(maugis_cli, "profile", "--lambda", "3", "--abar", "1.5", "--format", "json", *FLAGS)
    py = maugis.profile(3, None, None, 1.5, waves=WAVES)
    assert py["m"] == cli["m"] and py["load"] == cli["load"] and py["valid"] == cli["valid"]
    assert [tuple(w) for w in py["waves"]] == WAVES
    assert list(py.samples["pbar"]) == [s["pbar"] for s in cli["samples"]]


def test_simulate_many_waves_compares_the_same_profile():
    sim = maugis.simulate(3, waves=WAVES, amax=1.5, cells=1024, steps=10)
    assert sim.profile == "rough_cylinder"
    assert list(sim.waves["beta"]) == [b for _, b in WAVES]
    assert any(v is not None for v in sim.states["model_load"])


def test_bad_waves_raise():
    with pytest.raises(ValueError, match="wave 2"):
        maugis.curve(3, waves=[(0.3, 1.0), (-0.1, 0.5)])
    with pytest.raises(ValueError, match="not both"):
        maugis.curve(3, 0.3, 1.0, waves=WAVES)
    with pytest.raises(TypeError, match="pair"):
        maugis.curve(3, waves=[(0.3, 1.0, 2.0)])
    with pytest.raises(ValueError, match="65 waves"):
        maugis.curve(3, waves=[(0.01, 1.0)] * 65)
    with pytest.raises(TypeError):
        maugis.profile(3, None, None, 1.5)


def test_state_of_many_waves_is_the_curves_grid_state():
    # maugis.state with waves= solves the same states as the curve's grid, bit for bit
    c = maugis.curve(3, waves=WAVES, amax=2, points=20)
    grid = c.points["abar"]
    st = maugis.state(3, None, None, grid, waves=WAVES)
    for key in ("m", "m_minus_1", "load", "approach"):
        assert list(st[key]) == list(c.points[key]), key
    assert list(st.validity["valid"]) == list(c.points.validity["valid"])
    # lam and abar broadcast; one profile for every element
    st2 = maugis.state([[1.0], [3.0]], None, None, grid[:4], waves=WAVES)
    assert st2.load.shape == (2, 4)
    assert list(st2.load[1]) == list(c.points["load"][:4])


def test_state_one_wave_in_waves_is_alpha_beta():
    abar = [0.5, 1.5, 2.5]
    a = maugis.state(3, 0.3, 0.9, abar)
    b = maugis.state(3, None, None, abar, waves=[(0.3, 0.9)])
    for key in ("m", "load", "approach"):
        assert list(a[key]) == list(b[key]), key


def test_state_bad_waves_raise():
    with pytest.raises(ValueError, match="wave 2"):
        maugis.state(3, None, None, 1.5, waves=[(0.3, 1.0), (0.1, 0.0)])
    with pytest.raises(ValueError, match="not both"):
        maugis.state(3, 0.3, None, 1.5, waves=WAVES)
    with pytest.raises(ValueError, match="65 waves"):
        maugis.state(3, None, None, 1.5, waves=[(0.01, 1.0)] * 65)


def test_strip_ratio_and_load_of_many_waves():
    # float64: one wave in waves= is alpha, beta bit for bit; two waves agree with state()
    for f, key in ((maugis.strip_ratio, "m"), (maugis.load, "load")):
        assert f(3, 0.35, 1.125, 2.2) == f(3, None, None, 2.2, waves=[(0.35, 1.125)])
        abar = np.array([0.7, 2.2])
        assert list(f(3, None, None, abar, waves=WAVES)) == list(maugis.state(3, None, None, abar, waves=WAVES)[key])
    # certified: decimal strings are balls that contain the decimals as typed; the ball
    # contains the f64 value up to its error and carries the digits asked for
    texts = [("0.3535533905932737622", "1.125"), ("0.1767766952966368811", "0.375")]
    mid, rad = maugis.strip_ratio("3", None, None, "2.2", waves=texts, prec=80)
    m64 = maugis.strip_ratio(3, None, None, 2.2, waves=WAVES)
    assert rad <= abs(mid) * mpmath.mpf(2) ** -80
    assert abs(mid - m64) <= rad + 1e-12
    one = maugis.load("3", "0.35", "1.125", "2.2", prec=64, output="str")
    assert one == maugis.load("3", None, None, "2.2", waves=[("0.35", "1.125")], prec=64, output="str")
    with pytest.raises(ValueError, match="wave 2: amplitude"):
        maugis.load("3", None, None, "2.2", waves=[("0.35", "1.125"), ("-0.1", "0.375")], prec=64)
    with pytest.raises(ValueError, match="65 waves"):
        maugis.strip_ratio(3, None, None, 2.2, waves=[(0.01, 1.0)] * 65)
    with pytest.raises(TypeError, match="pair"):
        maugis.strip_ratio(3, None, None, 2.2, waves=[(0.3, 1.0, 2.0)])


def test_sweep_scales_the_amplitudes_of_a_profile():
    # one wave of amplitude 1 on the amplitude axis is the alpha axis, point for point
    one = maugis.sweep(1.0, 6.0, 2, "amplitude", 0.1, 0.35, 2, waves=[(1.0, 1.125)], amax=2.0, points=30)
    ref = maugis.sweep(1.0, 6.0, 2, "alpha", 0.1, 0.35, 2, 1.125, amax=2.0, points=30)
    assert list(one["points"]["dissipation"]) == list(ref["points"]["dissipation"])
    assert list(one["points"]["alpha"]) == list(ref["points"]["alpha"])
    # two waves: the grid records the profile; the points carry the first wave, scaled
    two = maugis.sweep(1.0, 6.0, 2, "amplitude", 0.0, 1.0, 2, waves=WAVES, amax=2.0, points=30)
    profile = two["grid"]["profile"]
    assert list(zip(profile["alpha"], profile["beta"])) == [tuple(map(float, w)) for w in WAVES]
    assert list(two["points"]["alpha"]) == [0.0, WAVES[0][0], 0.0, WAVES[0][0]]
    with pytest.raises(TypeError, match="waves"):
        maugis.sweep(1.0, 6.0, 2, "amplitude", 0.0, 1.0, 2)
    with pytest.raises(ValueError, match="amplitude"):
        maugis.sweep(1.0, 6.0, 2, "alpha", 0.0, 1.0, 2, 1.125, waves=WAVES)
    with pytest.raises(ValueError, match="wave 2"):
        maugis.sweep(1.0, 6.0, 2, "amplitude", 0.0, 1.0, 2, waves=[(0.3, 1.0), (0.1, 0.0)])
