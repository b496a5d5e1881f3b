#!/usr/bin/env python3
"""Run time against error, staggered (default controller) and monolithic in
the same run. For refinement levels 0.. (until a run passes 60 s or level 5)
on prm/lame.prm (error against the exact Lame pressure) and on variants 5
and 17 (error against the finest monolithic level): DoFs, wall time per
phase, peak memory (max RSS of the process) and the errors of the mid-plane
and mean pressure, plus the peak pressure (singular: it grows).
Writes work_precision.csv, work_precision.png and prints markdown.
Usage: python3 benchmarks/work_precision.py [max_level=5]"""
import csv
import json
import os
import subprocess
import sys
import tempfile

from coaxfit_run import EXE, ROOT, prm

CASES = ["lame", "variant_05", "variant_17"]
METHODS = {"staggered": [], "monolithic": ["Solver/Method=monolithic"]}
max_level = int(sys.argv[1]) if len(sys.argv) > 1 else 5


def run(case, level, settings):
    out = tempfile.mkdtemp(prefix="coaxfit_wp_")
    cmd = [EXE, "--set", "Output/Directory=" + out, "--set", "Output/Write vtu=false",
           "--set", "Mesh/Global refinements=%d" % level] + \
        sum([["--set", s] for s in settings], []) + [prm(case)]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    summary = None
    if os.WEXITSTATUS(status) == 0:
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        summary["peak_memory_MB"] = usage.ru_maxrss / 1024.0
    subprocess.run(["rm", "-rf", out])
    return summary


rows = []
for case in CASES:
    results = {}
    for level in range(max_level + 1):
        for method, settings in METHODS.items():
            s = run(case, level, settings)
            results[(method, level)] = s
            print(case, level, method, s and s["timing"]["total"], flush=True)
        if any(results[(m, level)] is None or results[(m, level)]["timing"]["total"] > 60
               for m in METHODS):
            break
    levels = sorted({l for (_, l) in results})
    finest = results[("monolithic", levels[-1])]
    for (method, level), s in sorted(results.items(), key=lambda x: (x[0][1], x[0][0])):
        if s is None:
            rows.append([case, method, level] + [""] * 10)
            continue
        if case == "lame":
            ref0 = ref_mean = s["pressure"]["lame"]
        else:
            ref0, ref_mean = finest["pressure"]["at_mid_plane"], finest["pressure"]["mean"]
        e0 = abs(s["pressure"]["at_mid_plane"] / ref0 - 1)
        em = abs(s["pressure"]["mean"] / ref_mean - 1)
        t = s["timing"]
        rows.append([case, method, level, s["mesh"]["dofs"]["shaft"] + s["mesh"]["dofs"]["hub"],
                     s["iterations"], "%.3f" % t["setup"], "%.3f" % t["factorization"],
                     "%.3f" % t["coupling"], "%.3f" % t["total"], "%.0f" % s["peak_memory_MB"],
                     "%.2e" % e0, "%.2e" % em, "%.1f" % s["pressure"]["max"]])

with open(os.path.join(ROOT, "benchmarks", "work_precision.csv"), "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["case", "method", "level", "dofs", "steps", "setup_s", "factorization_s",
                "coupling_s", "total_s", "peak_memory_MB", "error_mid_plane",
                "error_mean", "peak_pressure_MPa"])
    w.writerows(rows)
print("\n| case | method | level | DoFs | steps | setup s | factorization s | solve s | total s | peak MB | error p(0) | error mean | peak p MPa |")
print("|---" * 13 + "|")
for r in rows:
    print("| " + " | ".join(str(x) for x in r) + " |")
lines = ["Staggered (iqn-ils, full solves) / monolithic total wall time:", ""]
for case in CASES:
    for r in rows:
        if r[0] == case and r[1] == "staggered" and r[8] != "":
            mono = [x for x in rows if x[0] == case and x[1] == "monolithic" and x[2] == r[2]]
            if mono and mono[0][8] != "":
                lines.append("- %s level %d (%s DoFs): %.2f" % (case, r[2], r[3], float(r[8]) / float(mono[0][8])))
print("\n".join(lines))
with open(os.path.join(ROOT, "benchmarks", "work_precision_summary.md"), "w") as f:
    f.write("\n".join(lines) + "\n")

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.5))
    for ax, case in zip(axes, CASES):
        for method, style in zip(METHODS, ["o-", "s--"]):
            pts = [(float(r[8]), float(r[11])) for r in rows
                   if r[0] == case and r[1] == method and r[8] != "" and float(r[11]) > 0]
            if pts:
                ax.loglog([p[0] for p in pts], [p[1] for p in pts], style, label=method)
        ax.set_title(case + (" (exact Lame)" if case == "lame" else " (vs finest monolithic)"))
        ax.set_xlabel("total wall time (s)")
        ax.set_ylabel("relative error of the mean pressure")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "benchmarks", "work_precision.png"), dpi=110)
except ImportError:
    print("matplotlib not available: no PNG (apt-get install python3-matplotlib)")
