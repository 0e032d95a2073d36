"""Profiles of many waves (issue 35): ``waves=`` against the command line's ``--wave``."""

import json
import subprocess

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
