#!/usr/bin/env python3
"""Steps and wall time to the tolerance 1e-8 for every variant and every
alpha controller, default settings otherwise (shipped mesh, unilateral
contact). Writes controller_benchmark.csv and prints a markdown table.
Usage: python3 benchmarks/controller_benchmark.py"""
import os

from coaxfit_run import CASES, ROOT, markdown_table, run, write_csv

CONTROLLERS = ["fixed", "winkler", "pointwise", "aitken", "iqn-ils"]
rows = []
for case in CASES:
    row = [case]
    for c in CONTROLLERS:
        s, code, err = run(case, ["Coupling/Alpha controller=" + c])
        if s is not None and s["converged"]:
            row.append("%d / %.3f s" % (s["iterations"], s["timing"]["total"]))
        else:
            row.append("fails")
    rows.append(row)
    print(row, flush=True)
write_csv(os.path.join(ROOT, "benchmarks", "controller_benchmark.csv"), ["case"] + CONTROLLERS, rows)
print()
print(markdown_table(["variant"] + CONTROLLERS, rows), end="")
