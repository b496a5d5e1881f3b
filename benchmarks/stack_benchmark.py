#!/usr/bin/env python3
"""Stacks of several shrunk rings (Assembly/Bodies): coupling steps and time
against the number of bodies (2, 3, 5, 8), Gauss-Seidel against Jacobi
ordering, staggered against monolithic, and the error of the joints' mean
pressure against the plane-stress compound-cylinder solution (exact for
rings of equal length with frictionless joints, in the FE limit).

The stacks: a solid steel core D 40 mm and rings of 15 mm wall around it,
alternately steel (E 210000, nu 0.3), bronze (110000, 0.34) and aluminium
(70000, 0.33), all 40 mm long, diametral interferences 0.03 to 0.06 mm;
the mesh of prm/examples/three_rings.prm (12 x 8 cells per body, refined
once, FE_Q(2)). For each stack and method: the steps (one Neumann and one
Dirichlet visit of every joint), the body solves, the wall time of the
coupling and of the whole process (median of 3), and the largest relative
error of a joint's mean pressure. Target (issue "Several bodies"):
three_rings.prm in no more than twice the steps of its two-body
sub-problems (the joints alone).
Writes benchmarks/stack_benchmark.csv and .png (with /usr/bin/python3's
matplotlib) and prints a markdown table.
Usage: /usr/bin/python3 benchmarks/stack_benchmark.py
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

from coaxfit_run import EXE, ROOT, markdown_table, write_csv

sys.path.insert(0, os.path.join(ROOT, "benchmarks"))

MATERIALS = [(210000.0, 0.3), (110000.0, 0.34), (70000.0, 0.33)]
INTERFERENCES = [0.03, 0.05, 0.04, 0.06, 0.035, 0.055, 0.045]


def stack_prm(n):
    """A stack of n rings as a parameter file's text, and its rings."""
    names = ["Core"] + ["Ring%d" % i for i in range(1, n)]
    rings = []
    d_in = 0.0
    for i in range(n):
        d_out = 40.0 if i == 0 else d_in + 30.0
        E, nu = MATERIALS[i % 3]
        rings.append((d_in, d_out, E, nu))
        d_in = d_out
    text = "subsection Assembly\n  set Bodies = %s\nend\n" % ", ".join(names)
    text += "subsection Geometry\n"
    for name, (a, b, E, nu) in zip(names, rings):
        text += ("  subsection %s\n    set Inner diameter = %g\n    set Outer diameter = %g\n"
                 "    set Length = 40\n  end\n" % (name, a, b))
    text += "end\nsubsection Material\n"
    for name, (a, b, E, nu) in zip(names, rings):
        text += "  subsection %s\n    set E = %g\n    set nu = %g\n  end\n" % (name, E, nu)
    text += "end\nsubsection Fit\n"
    for k in range(n - 1):
        text += ("  subsection %s-%s\n    set Diametral interference = %g\n  end\n"
                 % (names[k], names[k + 1], INTERFERENCES[k]))
    text += ("end\nsubsection Mesh\n  set Axial cells = 12\n  set Radial cells = 8\n"
             "  set Global refinements = 1\nend\n"
             "subsection Output\n  set Write vtu = false\n  set Write plots = false\n"
             "  set Write report = false\n  set Print timing = false\nend\n")
    return text, rings, INTERFERENCES[: n - 1]


def exact_pressures(rings, U):
    """The compound-cylinder pressures (plane stress), by the same
    equations as design/compound_cylinders.h, solved here with numpy:
    u = A r + B / r per ring, sigma_r continuous, each interference
    closed, free core bore and outer surface (every joint closed here)."""
    import numpy as np
    n = len(rings)
    unknowns = 2 * n
    M = np.zeros((unknowns, unknowns))
    rhs = np.zeros(unknowns)
    row = 0

    def sr(i, r):  # sigma_r coefficients of (A_i, B_i)
        a, b, E, nu = rings[i]
        c = E / (1 - nu * nu)
        return c * (1 + nu), -c * (1 - nu) / (r * r)

    # core: B_0 = 0 if solid, else sigma_r(a_0) = 0
    if rings[0][0] == 0.0:
        M[row, 1] = 1.0
    else:
        ca, cb = sr(0, rings[0][0] / 2)
        M[row, 0], M[row, 1] = ca, cb
    row += 1
    for k in range(n - 1):
        R = rings[k][1] / 2
        ca, cb = sr(k, R)
        da, db = sr(k + 1, R)
        M[row, 2 * k], M[row, 2 * k + 1] = ca, cb
        M[row, 2 * k + 2], M[row, 2 * k + 3] = -da, -db
        row += 1
        # u_{k+1}(R) - u_k(R) = U_k / 2
        M[row, 2 * k + 2], M[row, 2 * k + 3] = R, 1 / R
        M[row, 2 * k], M[row, 2 * k + 1] = -R, -1 / R
        rhs[row] = U[k] / 2
        row += 1
    ca, cb = sr(n - 1, rings[-1][1] / 2)
    M[row, 2 * n - 2], M[row, 2 * n - 1] = ca, cb
    x = np.linalg.solve(M, rhs)
    p = []
    for k in range(n - 1):
        ca, cb = sr(k, rings[k][1] / 2)
        p.append(-(ca * x[2 * k] + cb * x[2 * k + 1]))
    return p


def run(path, settings):
    """Run; returns (summary, wall time of the process)."""
    out = tempfile.mkdtemp(prefix="coaxfit_stack_")
    cmd = [EXE, "--set", "Output/Directory=" + out]
    for s in settings:
        cmd += ["--set", s]
    cmd.append(path)
    start = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.perf_counter() - start
    if proc.returncode != 0:
        raise RuntimeError(" ".join(cmd) + ": " + proc.stderr)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    subprocess.run(["rm", "-rf", out])
    return summary, wall


METHODS = [("gauss-seidel", ["Solver/Method=staggered", "Coupling/Ordering=gauss-seidel"]),
           ("jacobi", ["Solver/Method=staggered", "Coupling/Ordering=jacobi"]),
           ("monolithic", ["Solver/Method=monolithic"])]


def main():
    header = ["bodies", "method", "steps", "steps_alone_max", "body_solves",
              "coupling_s", "process_s", "max_error_mean"]
    rows = []
    workdir = tempfile.mkdtemp(prefix="coaxfit_stacks_")
    for n in (2, 3, 5, 8):
        text, rings, U = stack_prm(n)
        path = os.path.join(workdir, "stack_%d.prm" % n)
        with open(path, "w") as f:
            f.write(text)
        exact = exact_pressures(rings, U)
        for name, settings in METHODS:
            walls, coupling = [], []
            for _ in range(3):
                summary, wall = run(path, settings)
                walls.append(wall)
                coupling.append(summary["timing"]["coupling"])
            error = max(abs(j["pressure"]["mean"] / e - 1)
                        for j, e in zip(summary["joints"], exact))
            c = summary["coupling"]
            rows.append([n, name, c.get("steps", ""),
                         max(j["alone"]["staggered_steps"] for j in summary["joints"]),
                         c.get("body_solves", ""),
                         "%.4f" % statistics.median(coupling),
                         "%.3f" % statistics.median(walls), "%.1e" % error])
    subprocess.run(["rm", "-rf", workdir])
    # The example of the issue.
    summary, wall = run(os.path.join(ROOT, "prm", "examples", "three_rings.prm"),
                        ["Output/Write vtu=false", "Output/Write plots=false",
                         "Output/Write report=false", "Output/Print timing=false"])
    alone = max(j["alone"]["staggered_steps"] for j in summary["joints"])
    steps = summary["coupling"]["steps"]
    write_csv(os.path.join(ROOT, "benchmarks", "stack_benchmark.csv"), header, rows)
    print(markdown_table(header, rows))
    print("three_rings.prm: %d steps, the joints alone at most %d: %s (target: at most twice)"
          % (steps, alone, "met" if steps <= 2 * alone else "NOT met"))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
        for name, _ in METHODS:
            r = [x for x in rows if x[1] == name]
            ns = [x[0] for x in r]
            if name != "monolithic":
                a.plot(ns, [x[2] for x in r], "o-", label=name)
            b.plot(ns, [float(x[5]) for x in r], "o-", label=name)
        a.plot(ns, [x[3] for x in r], "k--", label="a joint alone (max)")
        a.set_xlabel("bodies")
        a.set_ylabel("coupling steps")
        a.legend()
        b.set_xlabel("bodies")
        b.set_ylabel("coupling wall time (s)")
        b.set_yscale("log")
        b.legend()
        fig.tight_layout()
        fig.savefig(os.path.join(ROOT, "benchmarks", "stack_benchmark.png"), dpi=100)
    except ImportError:
        print("(matplotlib missing: no PNG; run with /usr/bin/python3)")


if __name__ == "__main__":
    main()
