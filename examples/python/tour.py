"""A tour of kinsyn from Python: one result of each of the five seed papers
(README.md names them), each printed beside the paper's value.

Each section is a cell of the notebook ``examples/python/tour.ipynb`` (``# %%`` starts a code
cell, ``# %% [markdown]`` a text cell; ``examples/python/make_notebook.py`` writes the notebook
from this file). The lines ``paper NNN: WHAT: kinsyn X, paper Y`` are the results; the notebook
test checks them against the papers' values.

Run from anywhere after ``pip install ./crates/kinsyn-py``:

    python examples/python/tour.py
"""

# %%
from pathlib import Path

import numpy as np

import kinsyn

try:
    ROOT = Path(__file__).resolve().parents[2]
except NameError:  # in the notebook, run from examples/python
    ROOT = Path.cwd().resolve().parents[1]
MECHANISMS = ROOT / "mechanisms"

# %% [markdown]
# ## Paper 000: multioperation capacity (Ibarreche et al.)
#
# The catalogue of 3T3R legs (§2): the legs whose joints, when three are locked, give the
# translations T3. Then the 3-UPS of §5: 6 dof with every input free (§5.1), the 3-RPS's 1T2R
# motion when the three α are locked (§5.2), and its Jacobians J_D, J_I (eqs. 12–19).

# %%
cat = kinsyn.catalogue()
print(f"catalogue: {len(cat)} entries, {int(cat.verified.sum())} verified 3T3R")
print(cat.groupby("table").size().rename("entries").to_string(), "\n")

t3 = kinsyn.query("T3", max_locks=3)
print(f"{t3.id.nunique()} legs give T3 with three joints locked; the first five:")
print(t3.head().to_string(index=False), "\n")

# The same question in pandas, over every entry's minimal lock sets.
p = kinsyn.catalogue_patterns()
print("patterns reached with exactly three locks, by how many legs:")
print(p[p.locks == 3].groupby("pattern").id.nunique().sort_values(ascending=False).head(8).to_string(), "\n")

# %%
ups = kinsyn.Manipulator.from_file(MECHANISMS / "3-ups.json")
a = ups.analyze()
print(f"paper 000: 3-UPS platform dof, every input free: kinsyn {a.dof}, paper 6 (§5.1)")
print("J_D (rows: wrenches; columns v_P, ω):")
print(a.J_D.round(4) + 0.0)  # + 0.0: no "-0." for round-off
print("diagonal of J_I:", a.J_I.diagonal().round(4), "\n")

modes = ups.modes()
print(f"{len(modes)} lock subsets; the patterns reached, by dof:")
print(modes.groupby(["dof", "pattern"]).size().rename("subsets").to_string(), "\n")
rps = modes[modes.pattern == "1T2R"]
print("1T2R (the 3-RPS, paper 000 §5.2) when locking:", ", ".join(rps.locked))
locked = ups.analyze(lock=["R1.1", "R2.1", "R3.1"])
print(f"with the α locked: platform dof {locked.dof}; rows {locked.rows}")

# %% [markdown]
# ## See it move
#
# The 3-UPS's operation modes as a table, the number of lock subsets reaching each pattern as a
# figure, and the manipulator in 3D (`ups.show()`, the page of `kinsyn view`): drag to orbit,
# choose a mode to animate it, move an input with its slider.

# %%
reached = modes.groupby(["dof", "pattern"]).size().rename("subsets").reset_index()
reached

# %%
axes = reached.plot.barh(x="pattern", y="subsets", legend=False, figsize=(6, 3.2))
axes.set_xlabel("lock subsets of the 3-UPS's six inputs")
axes.set_ylabel("motion pattern")
axes.figure.tight_layout()

# %%
ups.show(steps=8, assemblies=False)

# %% [markdown]
# ## Paper 001: the HEXA with reconfigurable platforms (Wu, Dong)
#
# Both end-effectors make the Schönflies motion X(z) (4 dof). End-effector 2 is the middle of
# a four-bar hung from the sub-platforms (docs/hexa.md): `modes(body="ee2")` classifies its
# motion with every input free (`kinsyn modes … --body ee2 --lock -`).

# %%
hexa = kinsyn.Manipulator.from_file(MECHANISMS / "6-ruu-hexa.json")
for body in ("ee1", "ee2"):
    m = hexa.modes(body=body, lock=[])
    print(f"paper 001: {body} dof: kinsyn {m.dof[0]}, paper 4 (pattern {m.pattern[0]}: Schönflies)")

# %% [markdown]
# ## Paper 002: the 3-RPS-3-SPR series-parallel manipulator (Nayak, Caro, Wenger)
#
# Six dof at a general configuration (§4–5). Table 1, row 1, places both platforms by their
# Study parameters (`analyze --study`); for this file, the text's mechanism (the 3-SPR's
# spherical joints on the coupler), kinsyn finds twist-system order 3 where the paper prints 5:
# both modules' constraint forces are the same three lines. Table 1's data describe a
# 3-RPS-3-RPS (multibody/3-rps-3-rps-table-1.json), which gives the printed 5
# (docs/deviations.md, "Paper 002").

# %%
spm = kinsyn.Manipulator.from_file(MECHANISMS / "multibody" / "3-rps-3-spr.json")
general = spm.analyze()
print(f"paper 002: end-effector dof at a general configuration: kinsyn {general.dof}, paper 6")
row1 = spm.analyze(study=["1:0:0:0:0:0:0:0.75", "1:0:0:0:0:0:0:0.8"])
order = row1.report["series_parallel"]["twist_system_order"]["rank"]
print(f"Table 1 row 1, text's mechanism: twist-system order {order}, printed 5 (the table's 3-RPS-3-RPS gives it)")
print("J_S-PM (eqs. 7–8) there:")
print(np.asarray(row1.report["series_parallel"]["jacobian"]).round(4) + 0.0)

# %% [markdown]
# ## Paper 003: a configurable 4-RRR (Gallardo-Alvarado et al.)
#
# The forward position at §5's inputs, by method 2 and homotopy continuation: two real
# assemblies (Fig. 10), Table 1's pose C4 = (25.112, −147.043) mm, θ = 80°, φ = 105° one of
# them. Then the corner velocities by screw theory (§4) there.

# %%
f = kinsyn.configurable.forward([141.956, 203.366, 337.773, 305.499])
print(f"paper 003: real assemblies: kinsyn {f.real_solutions}, paper 2 "
      f"(of {f.complex_solutions} complex solutions)")
print(f.assemblies.round(3).to_string(index=False))
v = kinsyn.configurable.velocity([141.956, 203.366, 337.773, 305.499], [-1.5, -1.25, -2, 1.5])
print(f"ω(m1) = ω(m3) = {v['omega_m1']:.6f} rad/s (eq. 27); corner velocities (mm/s):")
print(v["corner_velocities"].round(4))

# %% [markdown]
# ## Paper 004: reconfiguration of a 4-RUU (Nurahmi et al.)
#
# With every input free the platform makes a 4-dof Schönflies motion (one of the two X(z)
# modes). At generic inputs the constraint equations in the Study parameters have 32 isolated
# solutions (16 poses, ± each), what Singular's `vdim` gives (docs/operation-modes.md).

# %%
ruu = kinsyn.Manipulator.from_file(MECHANISMS / "4-ruu.json")
mode = ruu.modes(lock="-")
print(f"paper 004: platform dof with the inputs free: kinsyn {mode.dof[0]}, paper 4 "
      f"(pattern {mode.pattern[0]}: Schönflies)")
c = kinsyn.components(MECHANISMS / "4-ruu.json", inputs="R1.1=17,R2.1=-11,R3.1=14,R4.1=6")
print(f"at generic inputs: {len(c)} components, dimensions {sorted(set(c.dimension))}, "
      f"{int((c.real_points > 0).sum())} real; Singular's vdim 32")
