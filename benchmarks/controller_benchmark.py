#!/usr/bin/env python3
"""Steps and wall time to the tolerance 1e-8 for the 18 variants and the Lame
case with every alpha controller, default settings otherwise (shipped mesh,
unilateral contact). The adaptive controllers take their first alpha from
the compliances measured in the first Dirichlet step, so the Alpha of a
variant's file is used by the fixed controller only: the adaptive columns
have no per-case setting. The last column gives the active-set changes of
the default controller (iqn-ils) next to its steps. Writes
controller_benchmark.csv and prints a markdown table.
Usage: python3 benchmarks/controller_benchmark.py"""
import os

from coaxfit_run import CASES, ROOT, markdown_table, run, write_csv

CONTROLLERS = ["fixed", "winkler", "pointwise", "aitken", "iqn-ils"]
rows = []
for case in CASES + ["lame"]:
    row = [case]
    changes = "-"
    for c in CONTROLLERS:
        s, code, err = run(case, ["Coupling/Alpha controller=" + c])
        if s is not None and s["converged"]:
            row.append("%d / %.3f s" % (s["iterations"], s["timing"]["total"]))
            if c == "iqn-ils":
                changes = str(s["active_set"]["changes"])
        else:
            row.append("fails")
    row.append(changes)
    rows.append(row)
    print(row, flush=True)
header = CONTROLLERS + ["active-set changes (iqn-ils)"]
write_csv(os.path.join(ROOT, "benchmarks", "controller_benchmark.csv"), ["case"] + header, rows)
print()
print(markdown_table(["case"] + header, rows), end="")
