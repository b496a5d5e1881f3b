#!/usr/bin/env python3
"""Elastic-plastic fits (Material/Hub/Plasticity = von Mises): the cost of
prm/examples/yielding_hub.prm against the elastic run of the same mesh and
interference (Plasticity = none: the elastic code), its increments and
Newton iterations, staggered against monolithic, and a refinement study of
the example (mesh and load increments) with the radial plane-stress model
beside it.

The example: a solid elastic steel shaft D 50 mm in a steel hub D 50-100 mm
yielding at 300 MPa (perfectly plastic), both 40 mm long, U = 0.16 mm. Wall
times are medians of 3 whole processes. Target (issue "Elastic-plastic
fits"): the example in at most 5 times the elastic run's time.
Writes benchmarks/plastic_benchmark.csv and .png (with /usr/bin/python3's
matplotlib) and prints markdown tables.
Usage: /usr/bin/python3 benchmarks/plastic_benchmark.py
"""
import csv
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

from coaxfit_run import EXE, ROOT, markdown_table, write_csv

EXAMPLE = os.path.join(ROOT, "prm", "examples", "yielding_hub.prm")


def run(settings):
    """Run the example; (summary, load_path rows, wall time)."""
    out = tempfile.mkdtemp(prefix="coaxfit_plastic_")
    cmd = [EXE, "--set", "Output/Directory=" + out, "--set", "Output/Write vtu=false"]
    for s in settings:
        cmd += ["--set", s]
    cmd.append(EXAMPLE)
    start = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.perf_counter() - start
    if proc.returncode != 0:
        raise RuntimeError(" ".join(cmd) + ": " + proc.stderr)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    rows = []
    path = os.path.join(out, "load_path.csv")
    if os.path.exists(path):
        with open(path) as f:
            rows = list(csv.DictReader(f))
    subprocess.run(["rm", "-rf", out])
    return summary, rows, wall


def median_run(settings):
    walls = []
    for _ in range(3):
        summary, rows, wall = run(settings)
        walls.append(wall)
    return summary, rows, statistics.median(walls)


def main():
    # Cost against the elastic run of the same mesh.
    header = ["run", "process_s", "ratio_to_elastic", "increments",
              "coupling_steps", "newton_iterations_hub", "factorizations_hub",
              "mean_pressure_MPa"]
    rows = []
    elastic, _, t_elastic = median_run(["Material/Hub/Plasticity=none"])
    rows.append(["elastic (Plasticity = none)", "%.3f" % t_elastic, "1.00", "",
                 elastic["iterations"], "", "", "%.2f" % elastic["pressure"]["mean"]])
    for name, settings in [("staggered", ["Solver/Method=staggered"]),
                           ("monolithic", ["Solver/Method=monolithic"])]:
        s, path, t = median_run(settings)
        c = s["coupling"]
        rows.append([name, "%.3f" % t, "%.2f" % (t / t_elastic), len(path), c["steps"],
                     c["newton_iterations"]["hub"], c["factorizations"]["hub"],
                     "%.2f" % s["pressure"]["mean"]])
        if name == "staggered":
            per_increment = [(int(r["coupling_steps"]), int(r["max_newton_iterations"]))
                             for r in path]
    print(markdown_table(header, rows))
    ratio = float(rows[1][2])
    print("the example in %.2f x the elastic run's time: %s (target: at most 5 x)"
          % (ratio, "met" if ratio <= 5 else "NOT met"))
    print("staggered, per increment (coupling steps, largest Newton iterations "
          "of a body solve): %s" % per_increment)

    # Refinement study: mesh (global refinements) and increments.
    study_header = ["global_refinements", "increments", "cells_hub", "p_mid_MPa",
                    "p_mean_MPa", "p_min_MPa", "plastic_diameter_mm", "process_s"]
    study = []
    for g in (0, 1, 2):
        for n in (8, 32):
            s, _, t = run(["Mesh/Global refinements=%d" % g, "Load path/Increments=%d" % n,
                           "Solver/Method=monolithic"])
            p = s["pressure"]
            study.append([g, n, s["mesh"]["cells"]["hub"], "%.3f" % p["at_mid_plane"],
                          "%.3f" % p["mean"], "%.3f" % p["min"],
                          "%.3f" % s["plasticity"]["bodies"][1]["plastic_zone"]["diameter_at_mid_plane"],
                          "%.2f" % t])
    radial = s["plasticity"]["radial_model"]
    print()
    print(markdown_table(study_header, study))
    print("radial plane-stress model: p %.3f MPa, hub plastic to D %.3f mm"
          % (radial["pressure"], radial["plastic_diameter_hub"]))
    write_csv(os.path.join(ROOT, "benchmarks", "plastic_benchmark.csv"),
              study_header, study)
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
        for n, style in ((8, "o-"), (32, "s--")):
            r = [x for x in study if x[1] == n]
            a.plot([x[2] for x in r], [float(x[4]) for x in r], style,
                   label="mean, %d increments" % n)
            a.plot([x[2] for x in r], [float(x[3]) for x in r], style,
                   label="mid-plane, %d increments" % n)
        a.axhline(radial["pressure"], color="k", ls=":", label="radial model (plane stress)")
        a.set_xscale("log")
        a.set_xlabel("cells of the hub")
        a.set_ylabel("joint pressure (MPa)")
        a.legend(fontsize=8)
        b.bar([x[0] for x in rows], [float(x[1]) for x in rows])
        b.set_ylabel("process wall time (s)")
        fig.tight_layout()
        fig.savefig(os.path.join(ROOT, "benchmarks", "plastic_benchmark.png"), dpi=100)
    except ImportError:
        print("(matplotlib missing: no PNG; run with /usr/bin/python3)")


if __name__ == "__main__":
    main()
