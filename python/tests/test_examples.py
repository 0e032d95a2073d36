"""The worked examples in python/examples/ run headless (matplotlib's Agg
backend) as they are, each in a few seconds, pass their own checks, and draw
their figures: each saved PNG shows the colours of its curves."""

import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest
from matplotlib.colors import to_rgb
from matplotlib.image import imread

EXAMPLES = pathlib.Path(__file__).resolve().parents[1] / "examples"

# example -> (figure, colours its curves or cells are drawn in)
CASES = {
    "fig4c_load_area": ("fig4c_load_area.png", [f"C{i}" for i in range(7)]),
    "solver_lambda_quarter": ("solver_lambda_quarter.png", ["C0", "C2", "C3"]),
    "regime_map": ("regime_map.png", ["#1f5bb4", "#d66018"]),
    "special_functions_vs_scipy": ("special_functions_vs_scipy.png", ["C0", "C1", "C2"]),
}


def test_every_example_is_covered():
    assert sorted(p.stem for p in EXAMPLES.glob("*.py")) == sorted(CASES)


def pixels_of(img, colour):
    """How many pixels of `img` (RGB(A) floats) are `colour`, within 4/255."""
    rgb = np.array(to_rgb(colour))
    return int((np.abs(img[..., :3] - rgb) <= 4 / 255).all(axis=-1).sum())


@pytest.mark.parametrize("name", sorted(CASES))
def test_example_runs_headless(name, tmp_path):
    script = EXAMPLES / f"{name}.py"
    text = script.read_text(encoding="utf-8")
    # jupytext's percent format: the header, markdown and code cells
    assert text.startswith("# ---\n# jupyter:\n") and "format_name: percent" in text
    assert text.count("# %% [markdown]") >= 2 and text.count("# %%\n") >= 2
    env = dict(os.environ, MPLBACKEND="Agg", MAUGIS_EXAMPLE_OUT=str(tmp_path))
    run = subprocess.run([sys.executable, str(script)], cwd=tmp_path, env=env, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, f"{name} failed:\n{run.stdout}\n{run.stderr}"
    figure, colours = CASES[name]
    img = imread(tmp_path / figure)
    assert img.shape[0] > 300 and img.shape[1] > 500
    missing = [c for c in colours if pixels_of(img, c) < 30]
    assert not missing, f"{figure} shows no pixels of {missing}"
