#!/usr/bin/env python3
"""All 18 variants and the Lame case: the paper's process (constant alpha*
of the table, bilateral, every-step) and the default (auto = ibqn, unilateral)
on the shipped mesh. Records iterations to max|du|/d < 1e-2 and to the
tolerance 1e-8, mid-plane, mean, peak and minimum pressure and separated
zones. Writes benchmarks/variants_table.csv and prints markdown.
Usage: python3 benchmarks/variants_table.py"""
import os
import re

from coaxfit_run import ROOT, markdown_table, run, write_csv

MODES = {
    "paper process (fixed alpha*, bilateral)": ["Coupling/Alpha controller=fixed",
                                                "Contact/Unilateral=false"],
    "default (auto = ibqn, unilateral)": [],
}

rows = []
for case in ["lame"] + ["variant_%02d" % m for m in range(1, 19)]:
    for mode, settings in MODES.items():
        s, code, err = run(case, settings)
        if s is None:
            m = re.search(r"failed at step (\d+) .*?: (the [^;]*)", err)
            why = "%s at step %s" % (m.group(2), m.group(1)) if m else err[:80]
            rows.append([case, mode, "no: " + why, "", "", "", "", "", "", "", ""])
            print(rows[-1], flush=True)
            continue
        zones = s["contact"]["separated_zones"]
        rows.append([case, mode, "yes" if s["converged"] else "no",
                     s["iterations_to_paper_criterion"], s["iterations"],
                     "%.2f" % s["pressure"]["at_mid_plane"], "%.2f" % s["pressure"]["mean"],
                     "%.1f @ %.2f" % (s["pressure"]["max"], s["pressure"]["z_of_max"]),
                     "%.1f @ %.2f" % (s["pressure"]["min"], s["pressure"]["z_of_min"]),
                     " ".join("[%.1f, %.1f]" % tuple(z) for z in zones) or "-",
                     "%.2f" % s["pressure"]["lame"]])
        print(rows[-1], flush=True)

write_csv(os.path.join(ROOT, "benchmarks", "variants_table.csv"),
          ["case", "mode", "converged", "steps_to_1e-2", "steps_to_tol", "p_mid_MPa",
           "p_mean_MPa", "p_max_MPa_at_z", "p_min_MPa_at_z", "separated_zones_mm",
           "p_lame_MPa"], rows)
print()
print(markdown_table(["case", "mode", "converged", "steps to 1e-2", "steps to 1e-8", "p(0) MPa",
                      "mean MPa", "max MPa @ z mm", "min MPa @ z mm", "separated zones mm",
                      "Lame MPa"], rows), end="")
