#!/usr/bin/env python3
"""The paper's alpha table reproduced: for every variant, the constant-alpha
process (Coupling/Alpha controller = fixed, bilateral contact) over a grid of
alpha in (0, 1), on the paper-like mesh (FE_Q(1), 12 uniform axial cells,
10 radial) and on the shipped mesh (FE_Q(2), graded, refinement 1). Records
the steps to max|du|/d < 1e-2 (the paper's criterion) and to 1e-8.
Writes alpha_sweep.csv, alpha_sweep.png (steps vs alpha per variant, the
paper's alpha* marked) and prints the best alpha of each mesh next to the
paper's. Usage: python3 benchmarks/alpha_sweep.py"""
import csv
import os

from coaxfit_run import CASES, ROOT, paper_alpha, run, write_csv

ALPHAS = [0.002, 0.004, 0.006, 0.008, 0.01, 0.013, 0.016, 0.02, 0.025, 0.03,
          0.04, 0.05, 0.06, 0.08, 0.1, 0.12, 0.15, 0.2, 0.25, 0.3, 0.35,
          0.4, 0.45, 0.5, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8, 0.85, 0.9, 0.95]
MESHES = {"paper-like Q1": ["Mesh/Degree=1", "Mesh/Grading ratio=1",
                            "Mesh/Global refinements=0"],
          "shipped Q2 ref1": []}


def history(directory):
    with open(os.path.join(directory, "convergence.csv")) as f:
        return [(int(r["step"]), r["kind"], float(r["displacement_mismatch_relative"]))
                for r in csv.DictReader(f)]


rows = []
for case in CASES:
    for mesh, settings in MESHES.items():
        for alpha in ALPHAS:
            d = os.path.join(ROOT, "output", "alpha_sweep", "run")
            s, code, _ = run(case, settings + ["Coupling/Alpha controller=fixed",
                                               "Contact/Unilateral=false",
                                               "Coupling/Alpha=%g" % alpha,
                                               "Coupling/Max steps=400"], keep=d)
            to_2 = to_8 = ""
            if s is not None:
                h = history(d)
                to_2 = next((st for st, k, v in h if k == "neumann" and v < 1e-2), "")
                to_8 = s["iterations"] if s["converged"] else ""
            rows.append([case, mesh, alpha, to_2, to_8])
        print(case, mesh, "done", flush=True)

write_csv(os.path.join(ROOT, "benchmarks", "alpha_sweep.csv"),
          ["case", "mesh", "alpha", "steps_to_1e-2", "steps_to_1e-8"], rows)


def best(case, mesh, column):
    cand = [(r[column], r[2]) for r in rows if r[0] == case and r[1] == mesh and r[column] != ""]
    if not cand:
        return "none", ""
    steps = min(c[0] for c in cand)
    alphas = [a for st, a in cand if st == steps]
    return "%g-%g" % (min(alphas), max(alphas)) if len(alphas) > 1 else "%g" % alphas[0], steps


summary = ["| m | paper alpha* | mesh | best alpha to 1e-2 (steps) | best alpha to 1e-8 (steps) | convergent alphas on the grid |",
           "|---|---|---|---|---|---|"]
for case in CASES:
    for mesh in MESHES:
        a2, s2 = best(case, mesh, 3)
        a8, s8 = best(case, mesh, 4)
        conv = [r[2] for r in rows if r[0] == case and r[1] == mesh and r[4] != ""]
        rng = "%g-%g" % (min(conv), max(conv)) if conv else "none"
        summary.append("| %d | %g | %s | %s (%s) | %s (%s) | %s |" % (int(case[-2:]), paper_alpha(case), mesh, a2, s2, a8, s8, rng))
print("\n".join(summary))
with open(os.path.join(ROOT, "benchmarks", "alpha_sweep_summary.md"), "w") as f:
    f.write("\n".join(summary) + "\n")

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(6, 3, figsize=(12, 16), sharey=True)
    for ax, case in zip(axes.flat, CASES):
        for mesh, style in zip(MESHES, ["o-", "s-"]):
            pts = [(r[2], r[4]) for r in rows if r[0] == case and r[1] == mesh and r[4] != ""]
            if pts:
                ax.plot([p[0] for p in pts], [p[1] for p in pts], style, ms=2, label=mesh)
        ax.axvline(paper_alpha(case), color="k", ls="--", lw=1, label="paper alpha*")
        ax.set_xscale("log")
        ax.set_title(case, fontsize=9)
        ax.set_ylim(0, 400)
    axes.flat[0].legend(fontsize=7)
    fig.supxlabel("constant alpha")
    fig.supylabel("steps to max|du|/d < 1e-8 (missing: diverged)")
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "benchmarks", "alpha_sweep.png"), dpi=100)
except ImportError:
    print("matplotlib not available: no PNG (apt-get install python3-matplotlib)")
