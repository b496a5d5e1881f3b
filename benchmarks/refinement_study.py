#!/usr/bin/env python3
"""Mesh refinement study of the mid-plane and mean contact pressure.

For every case (prm/lame.prm, prm/variant_01..18.prm, default settings:
auto controller: iqn-ils on refinement 0, ibqn above; unilateral) runs coaxfit at global refinements 0..N (default 4) and
reports the pressure at z = 0, the mean pressure over the contact and their
relative change against the finest level. Writes
benchmarks/refinement_study.csv and prints a markdown table.
Usage: python3 benchmarks/refinement_study.py [max_refinement [case...]]
(with cases given, their rows are appended to the CSV)
"""
import os
import sys

from coaxfit_run import ROOT, markdown_table, run, write_csv

finest = int(sys.argv[1]) if len(sys.argv) > 1 else 4
cases = sys.argv[2:] or ["lame"] + ["variant_%02d" % m for m in range(1, 19)]
rows = []
for case in cases:
    results = [run(case, ["Mesh/Global refinements=%d" % r])[0] for r in range(finest + 1)]
    ref = results[-1]
    for r, s in enumerate(results):
        if s is None or ref is None:
            rows.append([case, r, "", "", "", "", "", "failed"])
            continue
        p0, pm = s["pressure"]["at_mid_plane"], s["pressure"]["mean"]
        rows.append([case, r, s["mesh"]["dofs"]["shaft"] + s["mesh"]["dofs"]["hub"],
                     "%.4f" % p0, "%.4f" % pm,
                     "%.1e" % abs(p0 / ref["pressure"]["at_mid_plane"] - 1),
                     "%.1e" % abs(pm / ref["pressure"]["mean"] - 1), s["iterations"]])
        print(rows[-1], flush=True)
path = os.path.join(ROOT, "benchmarks", "refinement_study.csv")
append = len(sys.argv) > 2 and os.path.exists(path)
write_csv(path, ["case", "refinement", "dofs", "p_mid_MPa", "p_mean_MPa",
                 "rel_change_mid_vs_finest", "rel_change_mean_vs_finest", "steps"],
          rows, append)
print()
print(markdown_table(["case", "ref", "DoFs", "p(0) MPa", "mean MPa", "change of p(0) vs finest",
                      "change of mean vs finest", "steps"], rows), end="")
