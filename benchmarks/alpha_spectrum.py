#!/usr/bin/env python3
"""Which constant alpha can converge, per variant and mesh.

Runs build/coaxfit-spectrum (eigenvalues of K1 K2^-1 on the contact surface)
for every variant on two meshes:
  paper-like: FE_Q(1), 12 uniform axial cells, 10 uniform radial cells
  shipped:    FE_Q(2), graded 1.4, one global refinement (the prm files)
and tabulates the eigenvalue range, the best constant alpha
1/(1 + sqrt(lmin lmax)), the convergent alpha range and whether the paper's
alpha* converges. Writes benchmarks/alpha_spectrum.csv and prints markdown.
"""
import os
import re
import subprocess

from coaxfit_run import ROOT, markdown_table, paper_alpha, write_csv

EXE = os.path.join(ROOT, "build", "coaxfit-spectrum")
MESHES = {
    "paper-like Q1 uniform": ["Mesh/Degree=1", "Mesh/Grading ratio=1",
                              "Mesh/Global refinements=0"],
    "shipped Q2 graded ref1": [],
}


def spectrum(case, extra):
    out = subprocess.run([EXE, os.path.join(ROOT, "prm", case + ".prm")] + extra,
                         capture_output=True, text=True, check=True).stdout
    lo, hi = map(float, re.search(r"in \[([^,]+), ([^\]]+)\]", out).groups())
    best = float(re.search(r"best constant alpha ([0-9.e+-]+)", out).group(1))
    rate = float(re.search(r"contraction per double step ([0-9.e+-]+)", out).group(1))
    m = re.search(r"converges for ([0-9.e+-]+) <= alpha <= ([0-9.e+-]+)", out)
    window = "%.3g-%.3g" % (float(m.group(1)), float(m.group(2))) if m else "none"
    paper_rate = float(re.search(r"\(Coupling/Alpha\): contraction ([0-9.e+-]+)", out).group(1))
    return lo, hi, best, rate, window, paper_rate


rows = []
for m in range(1, 19):
    case = "variant_%02d" % m
    paper = paper_alpha(case)
    for mesh, extra in MESHES.items():
        lo, hi, best, rate, window, prate = spectrum(case, extra)
        rows.append([m, mesh, "%.3g" % lo, "%.4g" % hi, paper, "%.3f" % best,
                     "%.3f" % rate, window, "%.3f" % prate,
                     "yes" if prate < 1 else "no"])
write_csv(os.path.join(ROOT, "benchmarks", "alpha_spectrum.csv"),
          ["variant", "mesh", "lambda_min", "lambda_max", "paper_alpha",
           "best_constant_alpha", "best_contraction", "convergent_alpha_range",
           "paper_alpha_contraction", "paper_alpha_converges"], rows)
print(markdown_table(["m", "mesh", "lambda min", "lambda max", "paper alpha*", "best alpha",
                      "its contraction", "convergent range", "paper alpha contraction",
                      "converges"], rows), end="")
