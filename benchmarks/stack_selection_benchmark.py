#!/usr/bin/env python3
"""Design/Mode = select for stacks: the cost of choosing the ISO fits of all
joints together against the number of selected joints (2, 3, 4: stacks of
3, 4, 5 rings).

The stacks: a solid steel core D 40 mm and rings of 15 mm wall around it,
alternately bronze (E 110000, nu 0.34, R_e 250 MPa), aluminium (70000,
0.33, 200 MPa) and steel (210000, 0.3, 650 MPa), all 40 mm long, friction
coefficient 0.12; every joint passes the required torque with slip safety
1.5, every ring keeps yield safety 1.25 (the torque per stack below: about
what the innermost joint can carry). The mesh of
prm/examples/three_rings.prm (12 x 8 cells per body, refined once).
For each stack: the candidates, all combinations, those left out by the
exact pruning, those judged at every corner on the linear model, the
feasible ones, the FE states solved, the chosen fits with their least FE
margin, and the wall time of the selection (summary.json timing) and of
the whole run (median of 3).
Writes benchmarks/stack_selection_benchmark.csv and .png (with
/usr/bin/python3's matplotlib) and prints a markdown table.
Usage: /usr/bin/python3 benchmarks/stack_selection_benchmark.py
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

MATERIALS = [(210000.0, 0.3, 650.0), (110000.0, 0.34, 250.0), (70000.0, 0.33, 200.0)]
TORQUE = {3: 400.0, 4: 400.0, 5: 400.0}


def stack_prm(n, directory):
    """A stack of n rings selecting every joint's fit, as a file's text."""
    names = ["Core"] + ["Ring%d" % i for i in range(1, n)]
    text = "subsection Assembly\n  set Bodies = %s\nend\nsubsection Geometry\n" % ", ".join(names)
    d_in = 0.0
    for i, name in enumerate(names):
        d_out = 40.0 if i == 0 else d_in + 30.0
        text += ("  subsection %s\n    set Inner diameter = %g\n    set Outer diameter = %g\n"
                 "    set Length = 40\n  end\n" % (name, d_in, d_out))
        d_in = d_out
    text += "end\nsubsection Material\n"
    for i, name in enumerate(names):
        E, nu, Re = MATERIALS[i % 3]
        text += ("  subsection %s\n    set E = %g\n    set nu = %g\n    set Yield strength = %g\n"
                 "  end\n" % (name, E, nu, Re))
    text += ("end\nsubsection Fit\n  set Friction coefficient = 0.12\nend\n"
             "subsection Design\n  set Mode = select\n  set Required torque = %g\n"
             "  set Slip safety = 1.5\n  set Yield safety = 1.25\nend\n"
             "subsection Mesh\n  set Axial cells = 12\n  set Radial cells = 8\n"
             "  set Global refinements = 1\nend\n"
             "subsection Output\n  set Directory = %s\n  set Write vtu = false\n"
             "  set Write plots = false\n  set Write report = false\nend\n" % (TORQUE[n], directory))
    return text


def main():
    header = ["bodies", "selected joints", "candidates", "combinations", "left out",
              "judged", "lists cut to", "feasible", "FE states", "chosen", "least margin",
              "selection s", "run s"]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for n in (3, 4, 5):
            out = os.path.join(tmp, "stack%d" % n)
            prm = os.path.join(tmp, "stack%d.prm" % n)
            with open(prm, "w") as f:
                f.write(stack_prm(n, out))
            walls, selections = [], []
            for _ in range(3):
                start = time.perf_counter()
                r = subprocess.run([EXE, "--quiet", prm], capture_output=True, text=True)
                walls.append(time.perf_counter() - start)
                if r.returncode != 0:
                    sys.exit("stack of %d: exit %d: %s" % (n, r.returncode, r.stderr.strip()))
                with open(os.path.join(out, "summary.json")) as f:
                    j = json.load(f)
                selections.append(j["timing"].get("selection", float("nan")))
            s = j["selection"]
            rows.append([n, n - 1, " ".join(str(x["candidates"]) for x in s["joints"]),
                         "%.4g" % s["combinations"], s["pruned_candidates"], s["judged"],
                         next((note.split("first ")[1].split(" ")[0] for note in s["notes"]
                               if "cut to its first" in note), "-"),
                         s["feasible"], s["fe_states_solved"], " + ".join(s["fits"]),
                         "%.4f" % s["least_margin"] if s["least_margin"] is not None else "-",
                         "%.3f" % statistics.median(selections),
                         "%.3f" % statistics.median(walls)])
    write_csv(os.path.join(ROOT, "benchmarks", "stack_selection_benchmark.csv"), header, rows)
    print(markdown_table(header, rows))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 4))
        joints = [r[1] for r in rows]
        ax.semilogy(joints, [float(r[11]) for r in rows], "o-", label="selection")
        ax.semilogy(joints, [float(r[12]) for r in rows], "s-", label="whole run")
        ax.set_xlabel("selected joints")
        ax.set_ylabel("wall time (s)")
        ax.set_xticks(joints)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
        ax.set_title("Design/Mode = select for stacks of 3, 4, 5 rings")
        fig.tight_layout()
        fig.savefig(os.path.join(ROOT, "benchmarks", "stack_selection_benchmark.png"), dpi=100)
    except ImportError:
        print("(matplotlib missing: no PNG; run with /usr/bin/python3)")


if __name__ == "__main__":
    main()
