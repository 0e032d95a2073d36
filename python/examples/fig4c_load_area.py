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
# # The paper's Fig. 4c: load-area curves of a wavy cylinder
#
# A rigid cylinder carrying a sinusoidal wave (normalised amplitude
# alpha = 2 sqrt(2)/8, wavelength beta = 9/8) is pressed on an elastic
# half-plane with Maugis-Dugdale adhesion, for seven values of the Maugis
# parameter lambda. `maugis.curve` solves the semi-analytical model on 600
# contact half-widths `abar` in (0, 6], finds the turning points of the load,
# the jumps a load-controlled experiment makes, pull-off, and tests every state:
# a state is invalid where the traction inside the contact exceeds the cohesive
# stress (a valley would cavitate) or the gap in the adhesive strip is negative.

# %%
import os

import matplotlib.pyplot as plt
import numpy as np

import maugis

lambdas = [0.1, 0.25, 0.5, 1, 1.5, 3, 6]
curves = maugis.curve(lambdas)  # the Fig. 4c roughness is the default

# %% [markdown]
# Each curve is solid where its states are valid and dotted where they are not.
# Arrows are the jumps at constant load (right while loading, left while
# unloading), triangles the load maxima and minima, the circle the raw
# pull-off (the last load minimum unloading reaches; hollow when that state is
# invalid) and the diamond the valid pull-off: the most tensile valid state
# unloading reaches.

# %%
fig, ax = plt.subplots(figsize=(11, 6.5), layout="constrained")
for i, c in enumerate(curves):
    col = f"C{i}"
    p, ok = c.points, c.points.validity["valid"]
    ax.plot(p.abar, np.where(ok, p.load, np.nan), color=col, lw=2, label=f"λ = {c['lambda']:g}")
    ax.plot(p.abar, np.where(ok, np.nan, p.load), ":", color=col, alpha=0.6)
    j = c.jumps
    for a0, a1, load in zip(j["from"]["abar"], j["to"]["abar"], j["from"]["load"]):
        ax.annotate("", xy=(a1, load), xytext=(a0, load), arrowprops={"arrowstyle": "->", "color": col, "lw": 1})
    t = c.turning_points
    for kind, marker in (("max", "^"), ("min", "v")):
        sel = t.kind == kind
        ax.plot(t.abar[sel], t.load[sel], marker, color=col, mec="k", mew=0.6, ms=6, ls="none")
    po, vpo = c.pull_off, c.valid_pull_off
    ax.plot(po["abar"], po["load"], "o", ms=8, mec=col, mew=1.5, mfc=col if po["validity"]["valid"] else "white")
    ax.plot(vpo["abar"], vpo["load"], "D", color=col, ms=7, mec="k", mew=0.8)
ax.axhline(0, color="0.5", lw=0.8)
ax.set(xlabel="contact half-width ā", ylabel="load L̄", xlim=(0, 6), ylim=(-4, 31))
ax.set_title("Load-area response, α = 2√2/8, β = 9/8 (the paper's Fig. 4c)")
symbols = [
    plt.Line2D([], [], color="0.3", ls=":", label="invalid states"),
    plt.Line2D([], [], color="0.3", marker="^", ls="none", mec="k", label="load maximum"),
    plt.Line2D([], [], color="0.3", marker="v", ls="none", mec="k", label="load minimum"),
    plt.Line2D([], [], color="0.3", marker="o", ls="none", mfc="white", label="raw pull-off (hollow: invalid)"),
    plt.Line2D([], [], color="0.3", marker="D", ls="none", mec="k", label="valid pull-off"),
]
ax.legend(handles=ax.get_legend_handles_labels()[0] + symbols, loc="upper left")

# %% [markdown]
# The raw pull-off is invalid for lambda <= 1.5 (the contact cavitates on the
# way there); the valid pull-off is then less tensile. For lambda = 3 and 6 the
# two coincide.

# %%
print(f"{'lambda':>7} {'raw pull-off':>14} {'valid?':>7} {'valid pull-off':>15}")
for c in curves:
    po, vpo = c.pull_off, c.valid_pull_off
    print(f"{c['lambda']:7g} {po['load']:14.4f} {str(po['validity']['valid']):>7} {vpo['load']:15.4f}")
    if po["validity"]["valid"]:
        assert vpo["load"] == po["load"]
    else:
        assert vpo["load"] > po["load"]

# %%
out = os.environ.get("MAUGIS_EXAMPLE_OUT")
if out:
    fig.savefig(os.path.join(out, "fig4c_load_area.png"), dpi=90)
else:
    plt.show()
