#!/usr/bin/env python3
"""Run time against error: the staggered method with the default settings
(iqn-ils, Interface operator = auto, i.e. condensed on these meshes), the
staggered method with full solves every step, and the monolithic reference,
in the same run. For refinement levels 0..5 on prm/lame.prm (error against
the exact Lame pressure) and on variants 5 and 17 (error against the finest
monolithic level): DoFs, wall time per phase, peak memory (max RSS of the
process), the errors of the mid-plane and mean pressure, and the peak
pressure (singular at the corner: it grows). A method is dropped for the
remaining levels of a case once one of its runs passes 60 s.
Writes work_precision.csv, work_precision_summary.md, work_precision.png
and prints a markdown table.
Usage: python3 benchmarks/work_precision.py [max_level=5]"""
import json
import math
import os
import subprocess
import sys
import tempfile

from coaxfit_run import EXE, ROOT, markdown_table, prm, write_csv

CASES = ["lame", "variant_05", "variant_17"]
METHODS = {"staggered": [],
           "staggered-full": ["Coupling/Interface operator=full"],
           "monolithic": ["Solver/Method=monolithic"]}
TIME_LIMIT = 60.0
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
summary_lines = []
for case in CASES:
    results = {}
    active = list(METHODS)
    for level in range(max_level + 1):
        for method in list(active):
            s = run(case, level, METHODS[method])
            results[(method, level)] = s
            print(case, level, method, s and "%.3f s" % s["timing"]["total"], flush=True)
            if s is None or s["timing"]["total"] > TIME_LIMIT:
                active.remove(method)
        if not active:
            break
    mono_levels = [l for (m, l), s in results.items() if m == "monolithic" and s]
    finest = results[("monolithic", max(mono_levels))]
    for (method, level), s in sorted(results.items(), key=lambda x: (x[0][1], x[0][0])):
        if s is None:
            rows.append([case, method, level] + ["failed"] + [""] * 11)
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
                     "%.3f" % t["condensation"], "%.3f" % t["coupling"], "%.3f" % t["total"],
                     "%.0f" % s["peak_memory_MB"], "%.2e" % e0, "%.2e" % em,
                     "%.1f" % s["pressure"]["max"]])

    # Ratios and growth of the solve time (total minus setup) per case.
    summary_lines.append("**%s**" % case)
    for level in range(max_level + 1):
        st, mo = results.get(("staggered", level)), results.get(("monolithic", level))
        if st and mo:
            dofs = st["mesh"]["dofs"]["shaft"] + st["mesh"]["dofs"]["hub"]
            summary_lines.append(
                "- level %d (%d DoFs): staggered / monolithic total time %.2f "
                "(%.3f s / %.3f s)" % (level, dofs, st["timing"]["total"] / mo["timing"]["total"],
                                      st["timing"]["total"], mo["timing"]["total"]))
    for method in METHODS:
        pts = [(s["mesh"]["dofs"]["shaft"] + s["mesh"]["dofs"]["hub"], s["timing"]["total"])
               for (m, l), s in sorted(results.items(), key=lambda x: x[0][1])
               if m == method and s and s["timing"]["total"] > 0.5]
        if len(pts) >= 2:
            slopes = ["%.2f" % (math.log(b[1] / a[1]) / math.log(b[0] / a[0]))
                      for a, b in zip(pts, pts[1:])]
            summary_lines.append("- %s: total time grows as N^p between successive levels "
                                 "(runs over 0.5 s), p = %s" % (method, ", ".join(slopes)))
    summary_lines.append("")

header = ["case", "method", "level", "dofs", "steps", "setup_s", "factorization_s",
          "condensation_s", "coupling_s", "total_s", "peak_memory_MB", "error_mid_plane",
          "error_mean", "peak_pressure_MPa"]
write_csv(os.path.join(ROOT, "benchmarks", "work_precision.csv"), header, rows)
print()
print(markdown_table(header, rows), end="")
print("\n".join(summary_lines))
with open(os.path.join(ROOT, "benchmarks", "work_precision_summary.md"), "w") as f:
    f.write("\n".join(summary_lines) + "\n")

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
    for ax, case in zip(axes, CASES):
        for method, style in zip(METHODS, ["o-", "^:", "s--"]):
            pts = [(float(r[9]), float(r[12])) for r in rows
                   if r[0] == case and r[1] == method and r[3] != "failed" and float(r[12]) > 0]
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
