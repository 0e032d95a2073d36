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
def cli6(maugis_cli):
    args = ["curve", "--lambda", "6", "--alpha", repr(ALPHA), "--beta", repr(BETA), "--format", "json"]
    return json.loads(run_cli(maugis_cli, *args))


@pytest.fixture(scope="module")
def curve6():
    # the acceptance call
    return maugis.curve(6, 2**0.5 / 4, 9 / 8)


def test_run_summary_equals_cli_json(cli6):
    assert maugis.run_summary(6, ALPHA, BETA) == cli6


def test_curve_jumps_and_dissipation_equal_cli_json(cli6, curve6):
    (c,) = cli6["curves"]
    jumps = curve6.jumps
    assert jumps.nrows == len(c["jumps"]) >= 4
    for i, j in enumerate(c["jumps"]):
        assert jumps["direction"][i] == j["direction"]
        for end in ("from", "to"):
            for key, value in j[end].items():
                assert jumps[end][key][i] == value, (end, key)
    assert dict(curve6.dissipation) == c["dissipation"]
    assert curve6.pull_off["abar"] == c["pull_off"]["abar"]
    assert curve6.pull_off["load"] == c["pull_off"]["load"]
    assert dict(curve6.pull_off["validity"]) == c["pull_off"]["validity"]
    for i, lp in enumerate(c["loops"]):
        for key, value in lp.items():
            assert curve6.loops[key][i] == value, key


def test_curve_points_are_columns(cli6, curve6):
    (c,) = cli6["curves"]
    p = curve6.points
    assert p.nrows == 600
    for key in ("abar", "m", "m_minus_1", "load", "approach"):
        assert p[key].dtype == np.float64 and p[key].shape == (600,)
        np.testing.assert_array_equal(p[key], [q[key] for q in c["points"]])
    assert p.validity["valid"].dtype == bool
    np.testing.assert_array_equal(p.validity["max_traction"], [q["validity"]["max_traction"] for q in c["points"]])
    np.testing.assert_array_equal(p.abar, 6.0 * np.arange(1, 601) / 600)
    assert set(curve6.turning_points.kind) <= {"max", "min"}
    # the paper's Fig. 4c instabilities at lambda = 6: abar = 2.71 loading, 3.16 unloading
    j = curve6.jumps
    loading = j["from"]["abar"][j.direction == "loading"]
    unloading = j["from"]["abar"][j.direction == "unloading"]
    assert np.min(np.abs(loading - 2.71)) < 0.05
    assert np.min(np.abs(unloading - 3.16)) < 0.05


def test_summary_file_equals_run_summary(maugis_cli, tmp_path):
    run_cli(maugis_cli, "curve", "--lambda", "1/2", "--lambda", "3", "--amax", "3", "--points", "120", "--out",
            str(tmp_path))
    summary = json.loads((tmp_path / "summary.json").read_text())
    ours = maugis.run_summary([3.0, 0.5], amax=3.0, points=120)
    for c in summary["curves"]:
        c["csv"] = None  # the file name is the one field a files run adds
    assert ours == summary


def test_curve_accepts_several_lambdas():
    curves = maugis.curve([6.0, 0.5], amax=2.0, points=40)
    assert [c["lambda"] for c in curves] == [6.0, 0.5]
    assert all(c.points.nrows == 40 for c in curves)


def test_state_matches_curve_points(curve6):
    idx = np.array([0, 99, 333, 599])
    s = maugis.state(6, ALPHA, BETA, curve6.points.abar[idx])
    for key in ("abar", "m", "m_minus_1", "load", "approach"):
        np.testing.assert_array_equal(s[key], curve6.points[key][idx])
    for key in ("valid", "min_strip_gap", "max_traction", "cavitation"):
        np.testing.assert_array_equal(s.validity[key], curve6.points.validity[key][idx])
    # broadcasting over lambda and abar
    s2 = maugis.state(np.array([1.0, 6.0])[:, None], ALPHA, BETA, np.array([0.5, 1.0, 2.0]))
    assert s2.m.shape == (2, 3) and s2.validity["valid"].shape == (2, 3)
    one = maugis.state(6.0, ALPHA, BETA, 1.0)
    assert isinstance(one.m, np.float64) and one.m > 1


def test_profile_equals_cli_json(maugis_cli):
    cli = json.loads(run_cli(maugis_cli, "profile", "--abar", "2", "--lambda", "1.5", "--format", "json"))
    ours = maugis.profile(1.5, maugis.FIG4C_ALPHA, maugis.FIG4C_BETA, 2.0)
    samples = cli.pop("samples")
    assert {k: v for k, v in ours.items() if k != "samples"} == cli
    assert ours.samples.nrows == len(samples)
    for key in ("xbar", "pbar", "ubar", "gbar", "hbar"):
        np.testing.assert_array_equal(ours.samples[key], [s[key] for s in samples])


def test_profile_at_given_points():
    x = np.array([0.0, 1.0, 1.99, 2.0, 2.05, 3.0])
    p = maugis.profile(6, ALPHA, BETA, 2.0, x=x)
    np.testing.assert_array_equal(p.samples.xbar, x)
    assert p.samples.gbar[3] == pytest.approx(0.0, abs=1e-9)  # the gap closes at the contact edge
    assert p.samples.gbar[4] > 0


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


def test_empty_tables_give_empty_columns():
    t = maugis.Table()
    assert t.nrows == 0 and t["abar"].shape == (0,)


def test_sweep_small_grid():
    s = maugis.sweep(1.0, 6.0, 2, "alpha", 0.1, 0.35, 2, 9 / 8, amax=2.0, points=30)
    pts = [v for v in s.values() if isinstance(v, maugis.Table)]
    assert pts and pts[0].nrows == 4
    with pytest.raises(ValueError):
        maugis.sweep(1.0, 6.0, 2, "gamma", 0.1, 0.35, 2, 9 / 8)
    with pytest.raises(ValueError):
        maugis.sweep(-1.0, 6.0, 2, "alpha", 0.1, 0.35, 2, 9 / 8)


def test_simulate_equals_cli_json(maugis_cli):
    # a small smooth cycle: the numerical solver through Python and through the CLI
    args = dict(lam=1.0, alpha=0.0, beta=1.0, amax=1.5, cells=512, steps=8)
    cli = json.loads(run_cli(
        maugis_cli, "simulate", "--lambda", "1", "--alpha", "0", "--beta", "1", "--amax", "1.5",
        "--grid", "512", "--steps", "8", "--format", "json",
    ))
    sim = maugis.simulate(**args)
    assert sim.cells == cli["cells"] == 512
    assert sim.stiff_cycle_work == cli["stiff_cycle_work"]
    assert sim.dissipation["load_control"] == cli["dissipation"]["load_control"]
    assert sim.half_width == cli["half_width"] and sim.datum == cli["datum"]
    s = sim.states
    assert s.nrows == len(cli["states"]) > 8
    for key in ("approach", "abar", "load", "contact_intervals", "zone_cells", "zone_ends_placed"):
        np.testing.assert_array_equal(s[key], [r[key] for r in cli["states"]])
    assert list(s.leg) == [r["leg"] for r in cli["states"]]
    assert {"loading", "unloading"} <= set(s.leg) <= {"loading", "unloading", "reloading"}


def test_simulate_bad_input_raises():
    with pytest.raises(ValueError, match="power of two"):
        maugis.simulate(1.0, 0.0, 1.0, cells=1000, steps=4)
    with pytest.raises(ValueError):
        maugis.simulate(-1.0, 0.0, 1.0, cells=512, steps=4)
    with pytest.raises(ValueError, match="steps"):
        maugis.simulate(1.0, 0.0, 1.0, cells=512, steps=2**20)
