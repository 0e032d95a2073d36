# ---
# jupyter:
#   jupytext:
#     formats: py:percent
#     text_representation:
#       extension: .py
#       format_name: percent
#   kernelspec:
#     display_name: Python 3
#     language: python
#     name: python3
# ---

# %% [markdown]
# # A small regime map: where does the waviness dissipate energy?
#
# `maugis.sweep` solves a load-area curve at every point of a grid, here
# lambda from 0.1 to 10 (9 values, log-spaced) against the wave amplitude
# alpha from 0 to 0.7 (8 values) at beta = 9/8, and labels each point:
#
# * **dissipative**: the waviness adds hysteresis loops under load control,
#   through valid states;
# * **cavitating**: there are loops, but through invalid states (the contact
#   would cavitate, so the model's dissipation is not physical there);
# * **smooth-like**: no roughness-induced loop.
#
# 72 curves of 200 states each take about a second.

# %%
import os

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.colors import ListedColormap
from matplotlib.patches import Patch

import maugis

sw = maugis.sweep(0.1, 10, 9, "alpha", 0.0, 0.7, 8, maugis.FIG4C_BETA, points=200)
pts, g = sw.points, sw.grid
assert (pts.index == np.arange(pts.nrows)).all()  # lambda-major: index = i_lambda * n + i_alpha


def grid_of(column):
    """A sweep column as an (alpha, lambda) array."""
    return np.asarray(column).reshape(g["lambda_n"], g["n"]).T


regimes = ["dissipative", "cavitating", "smooth_like"]
code = grid_of([regimes.index(r) for r in pts.regime])
work = grid_of(np.abs(pts.dissipation))
# cell edges: half a step beyond each grid value (log-spaced in lambda)
ll = np.log10(np.geomspace(g["lambda_min"], g["lambda_max"], g["lambda_n"]))
dl = ll[1] - ll[0]
lam_edges = 10 ** np.linspace(ll[0] - dl / 2, ll[-1] + dl / 2, g["lambda_n"] + 1)
da = (g["max"] - g["min"]) / (g["n"] - 1)
alpha_edges = np.linspace(g["min"] - da / 2, g["max"] + da / 2, g["n"] + 1)

# %% [markdown]
# Left: the regime of each grid point. Right: the energy dissipated per
# load-control cycle, |W|, whatever the regime.

# %%
colours = ["#1f5bb4", "#d66018", "#e1e1e1"]
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 5), layout="constrained", sharey=True)
ax1.pcolormesh(lam_edges, alpha_edges, code, cmap=ListedColormap(colours), vmin=-0.5, vmax=2.5)
ax1.legend(handles=[Patch(color=c, label=r.replace("_", "-")) for c, r in zip(colours, regimes)], loc="lower left")
ax1.set(xscale="log", xlabel="Maugis parameter λ", ylabel="wave amplitude α", title="regime (β = 9/8)")
mesh = ax2.pcolormesh(lam_edges, alpha_edges, work, cmap="viridis")
fig.colorbar(mesh, ax=ax2, label="dissipation |W| per cycle (load control)")
ax2.set(xscale="log", xlabel="Maugis parameter λ", title="dissipation")
for ax in (ax1, ax2):
    ax.set_xticks([0.1, 0.3, 1, 3, 10], ["0.1", "0.3", "1", "3", "10"])
    ax.minorticks_off()

# %% [markdown]
# A flat surface (alpha = 0) has no roughness-induced loop, and at large
# lambda and amplitude the loops are valid.

# %%
print("regime counts:", {r: int((pts.regime == r).sum()) for r in regimes})
assert (code[0] == regimes.index("smooth_like")).all()
assert code[-1, -1] == regimes.index("dissipative")

# %%
out = os.environ.get("MAUGIS_EXAMPLE_OUT")
if out:
    fig.savefig(os.path.join(out, "regime_map.png"), dpi=90)
else:
    plt.show()
