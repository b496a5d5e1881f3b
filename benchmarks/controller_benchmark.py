#!/usr/bin/env python3
"""Steps and wall time to the tolerance 1e-8 for the 18 variants and the Lame
case with every alpha controller, default settings otherwise (shipped mesh,
unilateral contact). The adaptive controllers take their first alpha from
the compliances measured in the first loaded Neumann step, so the Alpha of a
variant's file is used by the fixed controller only: the adaptive columns
have no per-case setting. iqn-ils runs twice: plain (Coupling/Coarse
model = none, a uniform start) and with the coarse model (the inverse
Jacobian of the case one refinement coarser as the quasi-Newton prior, and
the start from that case's solution, whose own steps on the coarser mesh
are given in the last column). The default, auto, is ibqn here (interface
block quasi-Newton: each body's compliance modelled from all its solves,
the coarse case's compliance as prior, the contact problem solved inside
the model; same start). Active-set changes are given next to the steps.
Steps count Neumann and Dirichlet steps separately; the wall time is the
whole run's (setup, coarse case, output included).
Writes controller_benchmark.csv and prints a markdown table.
Usage: python3 benchmarks/controller_benchmark.py"""
import os

from coaxfit_run import CASES, ROOT, markdown_table, run, write_csv

COLUMNS = [
    ("fixed", ["Coupling/Alpha controller=fixed"]),
    ("winkler", ["Coupling/Alpha controller=winkler"]),
    ("pointwise", ["Coupling/Alpha controller=pointwise"]),
    ("aitken", ["Coupling/Alpha controller=aitken"]),
    ("iqn-ils, no coarse model",
     ["Coupling/Alpha controller=iqn-ils", "Coupling/Coarse model=none"]),
    ("iqn-ils, coarse model", ["Coupling/Alpha controller=iqn-ils"]),
    ("auto = ibqn (default)", []),
]
rows = []
for case in CASES + ["lame"]:
    row = [case]
    for name, settings in COLUMNS:
        s, code, err = run(case, settings)
        if s is not None and s["converged"]:
            cell = "%d / %.3f s" % (s["iterations"], s["timing"]["total"])
            if name.startswith("iqn-ils") or name.startswith("auto"):
                cell += " (%d changes)" % s["active_set"]["changes"]
            row.append(cell)
            coarse = s["coupling"].get("coarse_start_steps", 0)
        else:
            row.append("fails")
            coarse = 0
    row.append(str(coarse) if coarse else "-")
    rows.append(row)
    print(row, flush=True)
header = [name for name, _ in COLUMNS] + ["coarse start steps"]
write_csv(os.path.join(ROOT, "benchmarks", "controller_benchmark.csv"), ["case"] + header, rows)
print()
print(markdown_table(["case"] + header, rows), end="")
