#!/usr/bin/env python3
"""Mesh refinement study of the mid-plane and mean contact pressure.

For every case (prm/lame.prm and prm/variant_01..18.prm) runs coaxfit at
global refinements 0..N (default 4) and reports the pressure at z = 0, the
mean pressure over the contact, and their relative change against the
finest level. Writes benchmarks/refinement_study.csv and prints a markdown
table. Usage: python3 benchmarks/refinement_study.py [max_refinement]
"""
import csv
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.environ.get("COAXFIT_EXE", os.path.join(ROOT, "build", "coaxfit"))
CASES = ["lame"] + ["variant_%02d" % m for m in range(1, 19)]


def run(case, refinement, extra=()):
    out = os.path.join(ROOT, "output", "refinement_study", "%s_r%d" % (case, refinement))
    cmd = [EXE, "--set", "Mesh/Global refinements=%d" % refinement,
           "--set", "Output/Directory=" + out, "--set", "Output/Write vtu=false"]
    for e in extra:
        cmd += ["--set", e]
    cmd.append(os.path.join(ROOT, "prm", case + ".prm"))
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        return None
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def main():
    finest = int(sys.argv[1]) if len(sys.argv) > 1 else 4
    rows = []
    for case in CASES:
        results = [run(case, r) for r in range(finest + 1)]
        ref = results[-1]
        for r, s in enumerate(results):
            if s is None:
                rows.append([case, r, "", "", "", "", "", "failed"])
                continue
            p0, pm = s["pressure"]["at_mid_plane"], s["pressure"]["mean"]
            d0 = abs(p0 / ref["pressure"]["at_mid_plane"] - 1) if ref else float("nan")
            dm = abs(pm / ref["pressure"]["mean"] - 1) if ref else float("nan")
            rows.append([case, r, s["mesh"]["dofs"]["shaft"] + s["mesh"]["dofs"]["hub"],
                         "%.4f" % p0, "%.4f" % pm, "%.2e" % d0, "%.2e" % dm,
                         s["iterations"]])
            print(case, r, rows[-1][2:], flush=True)
    path = os.path.join(ROOT, "benchmarks", "refinement_study.csv")
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "refinement", "dofs", "p_mid_MPa", "p_mean_MPa",
                    "rel_change_mid_vs_finest", "rel_change_mean_vs_finest", "steps"])
        w.writerows(rows)
    print("\n| case | ref | DoFs | p(0) MPa | mean MPa | d p(0) | d mean | steps |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print("| " + " | ".join(str(x) for x in r) + " |")


if __name__ == "__main__":
    main()
