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
# # The numerical solver at lambda = 1/4, over the semi-analytical model
#
# At lambda = 1/4 (Fig. 4c roughness) most states of the semi-analytical model
# are invalid: the traction inside the contact exceeds the cohesive stress, so
# the valleys would open (cavitate). `maugis.simulate` runs the crate's
# boundary-element Dugdale-Maugis solver through one loading-unloading cycle
# under displacement control; it allows several contact intervals, so it
# follows the cavitated contact where the model cannot. Here: 2048 cells, 40
# approach steps per leg (about a second).

# %%
import os

import matplotlib.pyplot as plt
import numpy as np

import maugis

lam, amax = 0.25, 5.0
model = maugis.curve(lam, amax=amax)
sim = maugis.simulate(lam, amax=amax, cells=2048, steps=40)
st = sim.states
print(f"{st.nrows} simulated states, contact intervals per state: {sorted(set(st.contact_intervals.tolist()))}")

# %% [markdown]
# Filled markers are simulated states with one contact interval, open markers
# cavitated ones (several intervals); squares on loading, circles on
# unloading, which revisits many loading states. The model is solid where
# valid, dotted where not.

# %%
fig, ax = plt.subplots(figsize=(10, 6), layout="constrained")
p, ok = model.points, model.points.validity["valid"]
ax.plot(p.abar, np.where(ok, p.load, np.nan), color="C0", lw=2, label="model, valid")
ax.plot(p.abar, np.where(ok, np.nan, p.load), ":", color="C0", alpha=0.7, label="model, invalid (cavitation)")
for leg, col, marker, size in (("loading", "C3", "s", 9), ("unloading", "C2", "o", 5)):
    sel = (st.leg == leg) & (st.abar > 0)
    one = sel & (st.contact_intervals == 1)
    many = sel & (st.contact_intervals > 1)
    ax.plot(st.abar[one], st.load[one], marker, color=col, ms=size, ls="none", label=f"solver, {leg}, one contact")
    ax.plot(st.abar[many], st.load[many], marker, color=col, mfc="none", ms=size, ls="none", label=f"solver, {leg}, cavitated")
vpo = model.valid_pull_off
ax.plot(vpo["abar"], vpo["load"], "D", color="C0", mec="k", ms=8, ls="none", label="model: valid pull-off")
ax.axhline(sim.pull_off, color="0.4", ls="--", lw=1, label="solver: pull-off (load control)")
ax.set(xlabel="contact half-width ā", ylabel="load L̄", xlim=(0, amax))
ax.set_title("λ = 1/4, α = 2√2/8, β = 9/8: solver (2048 cells) over the model")
ax.legend(loc="upper left", fontsize=9)

# %% [markdown]
# Where the model is valid and the solver's contact is one interval, the two
# agree to the solver's grid error; the most tensile load the solver reaches
# under load control is the model's valid pull-off, not its raw (invalid) one.

# %%
model_load = np.array([np.nan if v is None else v for v in st.model_load], dtype=float)
both = np.array([v is True for v in st.model_valid]) & (st.contact_intervals == 1)
err = np.max(np.abs(st.load[both] - model_load[both]))
print(f"{both.sum()} states where both describe the contact: largest load difference {err:.4f}")
print(f"pull-off: solver {sim.pull_off:.4f}, model valid {model.valid_pull_off['load']:.4f}, model raw {model.pull_off['load']:.4f} (invalid)")
assert err < 0.03
assert abs(sim.pull_off - model.valid_pull_off["load"]) < 0.01
assert sim.pull_off > model.pull_off["load"] + 0.2

# %%
out = os.environ.get("MAUGIS_EXAMPLE_OUT")
if out:
    fig.savefig(os.path.join(out, "solver_lambda_quarter.png"), dpi=90)
else:
    plt.show()
