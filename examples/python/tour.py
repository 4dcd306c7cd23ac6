"""A tour of kinsyn from Python: two results of paper 000 (Gogu's structural synthesis of
3T3R parallel manipulators with multioperation capacity).

1. The catalogue: legs whose joints, when some are locked, give the translations T3.
2. The 3-UPS of paper 000 §5: 6 dof with every input free (§5.1), the 3-RPS's 1T2R motion
   when the three α are locked (§5.2), and its Jacobians J_D, J_I (eqs. 12–19).

Run from the repository root after `pip install ./crates/kinsyn-py`:

    python examples/python/tour.py
"""

from pathlib import Path

import kinsyn

ROOT = Path(__file__).resolve().parents[2]

# 1. Catalogue queries as DataFrames.
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

# 2. The 3-UPS of paper 000 §5.
ups = kinsyn.Manipulator.from_file(ROOT / "mechanisms" / "3-ups.json")
a = ups.analyze()
print(f"{ups.name}: mobility {a.mobility}, platform dof {a.dof} (paper 000 §5.1: 6 dof)")
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
