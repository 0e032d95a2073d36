"""maugis.simulate with every option of `maugis simulate`: the same JSON as the
command line for the built-in profile, a profile table (file or columns), the
periodic domain and a given half-width; bad tables raise naming the line."""

import json
import math
import subprocess

import numpy as np
import pytest

import maugis

ALPHA = 2**0.5 / 4
BETA = 9 / 8
SMALL = dict(amax=2.5, cells=1024, steps=20)


def fig4c(x):
    return 0.5 * x * x + ALPHA * (1 - np.cos(2 * np.pi * x / BETA))


def cli_json(cli, *args):
    out = subprocess.run([cli, "simulate", *args, "--format", "json"], capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout)


@pytest.fixture(scope="module")
def built_in():
    return maugis.simulate(1.0, ALPHA, BETA, **SMALL)


def test_every_leg_and_the_options_reported(built_in):
    assert built_in.domain == "free" and built_in.profile == "wavy_cylinder"
    assert {"loading", "unloading"} <= set(built_in.states.leg) <= {"loading", "unloading", "reloading"}


def test_a_table_file_equals_the_cli_and_the_built_in_loads(built_in, maugis_cli, tmp_path):
    x = np.arange(-built_in.half_width - 0.5, built_in.half_width + 0.51, 0.01)
    csv = tmp_path / "fig4c.csv"
    csv.write_text("x,h\n" + "".join(f"{float(a)!r},{float(b)!r}\n" for a, b in zip(x, fig4c(x))))
    sim = maugis.simulate(1.0, ALPHA, BETA, profile=csv, **SMALL)
    assert sim.profile == "table"
    np.testing.assert_allclose(sim.states.load, built_in.states.load, rtol=0, atol=1e-3)
    cli = cli_json(
        maugis_cli, "--lambda", "1", "--alpha", repr(ALPHA), "--beta", repr(BETA), "--amax", "2.5",
        "--grid", "1024", "--steps", "20", "--profile", str(csv),
    )
    np.testing.assert_array_equal(sim.states.load, [s["load"] for s in cli["states"]])
    # the same table as columns
    cols = maugis.simulate(1.0, ALPHA, BETA, profile=(x, fig4c(x)), **SMALL)
    np.testing.assert_array_equal(cols.states.load, sim.states.load)


def test_periodic_and_half_width_equal_the_cli(maugis_cli):
    args = dict(amax=1.2, cells=512, steps=30, periodic=True, half_width=2.0)
    sim = maugis.simulate(10.0, 3.0, 4.0, **args)
    cli = cli_json(
        maugis_cli, "--lambda", "10", "--alpha", "3", "--beta", "4", "--amax", "1.2", "--grid", "512",
        "--steps", "30", "--periodic", "--half-width", "2",
    )
    assert sim.domain == cli["domain"] == "periodic" and sim.profile == "sinusoid"
    assert sim.half_width == cli["half_width"] == 2.0
    np.testing.assert_array_equal(sim.states.load, [s["load"] for s in cli["states"]])
    # one period of Johnson's (1995) sinusoid: near the JKR mean pressure
    s = sim.states
    ok = (s.abar > 0.3) & (s.abar < 1.2) & (s.contact_intervals == 1)
    a = s.abar[ok]
    jkr = np.pi * 3 / 4 * np.sin(np.pi * a / 4) ** 2 - np.sqrt(0.5 * np.tan(np.pi * a / 4))
    assert np.max(np.abs(s.load[ok] / 4 - jkr)) < 0.05


def test_bad_tables_raise_naming_the_line(tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("x,h\n-30,450\n0,0\n1,oops\n30,450\n")
    with pytest.raises(ValueError, match="line 4"):
        maugis.simulate(1.0, ALPHA, BETA, profile=bad, **SMALL)
    with pytest.raises(ValueError, match="row 2"):
        maugis.simulate(1.0, ALPHA, BETA, profile=([-30, 1, -1, 30], [450, 0.5, 0.5, 450]), **SMALL)
    with pytest.raises(ValueError, match="covers"):
        maugis.simulate(1.0, ALPHA, BETA, profile=([-1, 0, 1, 2], [0.5, 0, 0.5, 2]), **SMALL)
    with pytest.raises(TypeError):
        maugis.simulate(1.0, ALPHA, BETA, profile=42, **SMALL)
    with pytest.raises(TypeError):
        maugis.simulate(1.0, ALPHA, BETA, periodic="yes", **SMALL)
    with pytest.raises(ValueError):
        maugis.simulate(1.0, ALPHA, BETA, half_width=math.nan, **SMALL)


def test_the_smooth_law_equals_the_cli_and_differs_from_dugdale(built_in, maugis_cli):
    sim = maugis.simulate(1.0, ALPHA, BETA, law="exp", **SMALL)
    assert sim.law == "exp" and built_in.law == "dugdale"
    cli = cli_json(
        maugis_cli, "--lambda", "1", "--alpha", repr(ALPHA), "--beta", repr(BETA), "--amax", "2.5",
        "--grid", "1024", "--steps", "20", "--law", "exp",
    )
    assert cli["law"] == "exp"
    np.testing.assert_array_equal(sim.states.load, [s["load"] for s in cli["states"]])
    np.testing.assert_array_equal(sim.states.approach, [s["approach"] for s in cli["states"]])
    # another law, another cycle: the loads at the first contacts differ
    n = min(len(sim.states.load), len(built_in.states.load))
    assert np.max(np.abs(sim.states.load[:n] - built_in.states.load[:n])) > 1e-3


def test_an_unknown_law_raises_naming_the_known_ones():
    with pytest.raises(ValueError, match="dugdale"):
        maugis.simulate(1.0, ALPHA, BETA, law="lennard-jones", **SMALL)
    with pytest.raises(TypeError):
        maugis.simulate(1.0, ALPHA, BETA, law=3, **SMALL)
