#!/usr/bin/env python3
"""Time against error for the section examples (gear_on_shaft, flush_pulley,
taper_fit; rounded_gear, a gmsh file, against its outline; rounded_bore_edge,
a .geo whose contact spreads onto a fillet: its error column is the contact
force per 22 mm of bore).

Each example runs at Mesh/Global refinements 0..2 at its shipped cell size
(refinement 1) and at cell sizes 0.5 and 0.125 mm (refinement 1), and with meshes of their own (Mesh/Joint nodes = own, the hub
coarser or finer: the mortar projection couples them); the whole
process is timed (median of 3 runs) and the mean pressure and the pressure
at interior points of the joint (linear between the points of
contact_pressure.csv) are compared with independent CalculiX solutions (CAX8,
u_r tied with the interference at coinciding nodes, four meshes down to
0.0125 mm at the joint ends, converged to 5e-5; not in the repository).
Targets (issue "Real parts"): each example under 1 s at its shipped mesh and
within 0.5 % of the reference; a non-matching run at most 1.5x a matching
one of about the same size. Writes benchmarks/sections_benchmark.csv and
.png (with /usr/bin/python3's matplotlib) and prints a markdown table.
Usage: /usr/bin/python3 benchmarks/sections_benchmark.py
"""
import csv
import os
import statistics
import subprocess
import tempfile
import time

from coaxfit_run import EXE, ROOT, markdown_table, write_csv

REFERENCE = {
    "gear_on_shaft": (75.455, {0: 86.431, 5: 83.513, 10: 76.384, 15: 69.023, 20: 64.934}),
    "flush_pulley": (31.5515, {0: 31.834, 5: 31.665, 10: 31.495, 20: 31.088,
                               30: 30.747, 35: 31.260}),
    # The hub pushed 0.5 mm onto a taper 1:10 (tie along the cone's normal,
    # five meshes down to 0.0625 mm, converged to 3e-5).
    "taper_fit": (87.850, {10: 86.742, 15: 83.402, 20: 82.536, 25: 81.749,
                           30: 80.832, 35: 80.512, 40: 84.136}),
    # The hub's end face on the shaft's shoulder (contact on the cylinder
    # and on the face, which carries no force; meshes to 0.0125 mm at the
    # bore's ends; the mean from the hub's hoop stresses; +-0.06 MPa).
    "hub_against_shoulder": (82.83, {-15: 79.45, -10: 76.26, 0: 76.73,
                                     10: 76.89, 20: 77.55}),
}
SETTINGS = [("shipped", []),
            ("refinements 0", ["Mesh/Global refinements=0"]),
            ("refinements 2", ["Mesh/Global refinements=2"]),
            ("cell 0.5 mm", ["Mesh/Cell size=0.5"]),
            ("cell 0.125 mm", ["Mesh/Cell size=0.125"]),
            ("own nodes, hub 0.4 mm", ["Mesh/Joint nodes=own", "Mesh/Hub cell size=0.4"]),
            ("own nodes, hub 0.15 mm", ["Mesh/Joint nodes=own", "Mesh/Hub cell size=0.15"])]
# hub_against_shoulder's hub at 0.4 mm has about as many joint nodes as its
# shaft (97 against 89), finer in one place and coarser in another: refused
# (the coupling would be singular); 0.25 mm is finer everywhere.
CASE_SETTINGS = {"hub_against_shoulder": SETTINGS[:5] + [
    ("own nodes, hub 0.25 mm", ["Mesh/Joint nodes=own", "Mesh/Hub cell size=0.25"]),
    ("own nodes, hub 0.15 mm", ["Mesh/Joint nodes=own", "Mesh/Hub cell size=0.15"])]}


# A section from a gmsh file against the same section written as an
# outline (half model, shared joint nodes) at the same refinement: the
# gmsh route's own error, beside the outline route's error against
# CalculiX above (no independent solution of the filleted gear).
FILE_CASES = {
    "rounded_gear": "-25, 50; 25, 50; 25, 80; 6, 80, 4; 6, 150, 4; 15, 150; "
                    "15, 180; -15, 180; -15, 150; -6, 150, 4; -6, 80, 4; "
                    "-25, 80; -25, 50",
}
FILE_SETTINGS = SETTINGS[:3]
# A rounded bore edge (a .geo): contact spreads onto the fillet. CalculiX
# (CAX8, frictionless surface-to-surface penalty contact 1e8-1e9 MPa/mm,
# meshes to 0.005 mm at the fillet): p at interior points, and the contact
# force per 22 mm of straight bore (MPa), 88.66 +- 0.07.
ROUNDED = {"rounded_bore_edge": (88.66, {0: 76.936, 10: 77.322, 15: 79.793})}
FILE_POINTS = [0, 5, 10, 15, 20]


def run(case, settings):
    out = tempfile.mkdtemp(prefix="coaxfit_sections_")
    cmd = [EXE, "--quiet", "--set", "Output/Directory=" + out]
    for s in settings:
        cmd += ["--set", s]
    cmd.append(os.path.join(ROOT, "prm", "examples", case + ".prm"))
    times = []
    for _ in range(3):
        start = time.perf_counter()
        proc = subprocess.run(cmd, capture_output=True, text=True)
        times.append(time.perf_counter() - start)
        if proc.returncode != 0:
            raise SystemExit("%s %s failed: %s" % (case, settings, proc.stderr))
    import json
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(out, "contact_pressure.csv")) as f:
        rows = list(csv.DictReader(f))
    subprocess.run(["rm", "-rf", out])
    z = [float(r["z_mm"]) for r in rows]
    p = [float(r["pressure_MPa"]) for r in rows]
    return statistics.median(times), summary, z, p


def at(z, p, x):
    for i in range(1, len(z)):
        if z[i] >= x:
            return p[i - 1] + (p[i] - p[i - 1]) * (x - z[i - 1]) / (z[i] - z[i - 1])
    return float("nan")


rows = []
for case, (mean_ref, points) in REFERENCE.items():
    for label, settings in CASE_SETTINGS.get(case, SETTINGS):
        seconds, s, z, p = run(case, settings)
        dofs = sum(s["mesh"]["dofs"].values())
        mean_error = abs(s["pressure"]["mean"] / mean_ref - 1)
        point_error = max(abs(at(z, p, x) / v - 1) for x, v in points.items())
        rows.append([case, label, dofs, "%.3f" % seconds, "%.4f" % s["pressure"]["mean"],
                     "%.1e" % mean_error, "%.1e" % point_error])
        print(rows[-1], flush=True)

for case, outline in FILE_CASES.items():
    for label, settings in FILE_SETTINGS:
        seconds, s, z, p = run(case, settings)
        _, o, zo, po = run(case, settings + ["Geometry/Hub section=" + outline])
        dofs = sum(s["mesh"]["dofs"].values())
        mean_error = abs(s["pressure"]["mean"] / o["pressure"]["mean"] - 1)
        point_error = max(abs(at(z, p, x) / at(zo, po, x) - 1) for x in FILE_POINTS)
        rows.append([case + " (vs outline)", label, dofs, "%.3f" % seconds,
                     "%.4f" % s["pressure"]["mean"], "%.1e" % mean_error,
                     "%.1e" % point_error])
        print(rows[-1], flush=True)

for case, (force_ref, points) in ROUNDED.items():
    for label, settings in FILE_SETTINGS:
        seconds, s, z, p = run(case, settings)
        dofs = sum(s["mesh"]["dofs"].values())
        last = max(zz for zz, pp in zip(z, p) if pp > 0)
        nxt = min(zz for zz in z if zz > last)
        force = s["pressure"]["mean"] * 0.5 * (last + nxt) / 22.
        point_error = max(abs(at(z, p, x) / v - 1) for x, v in points.items())
        rows.append([case, label, dofs, "%.3f" % seconds, "%.4f" % s["pressure"]["mean"],
                     "%.1e" % abs(force / force_ref - 1), "%.1e" % point_error])
        print(rows[-1], flush=True)

header = ["case", "mesh", "DoFs", "wall_s", "mean_MPa", "mean_error", "max_point_error"]
write_csv(os.path.join(ROOT, "benchmarks", "sections_benchmark.csv"), header, rows)
print()
print(markdown_table(header, rows), end="")
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for case in list(REFERENCE) + [c + " (vs outline)" for c in FILE_CASES] + list(ROUNDED):
        r = [row for row in rows if row[0] == case]
        ax.loglog([float(x[3]) for x in r], [max(float(x[6]), 1e-7) for x in r], "o",
                  label=case)
        for x in r:
            ax.annotate(x[1], (float(x[3]), max(float(x[6]), 1e-7)), fontsize=7)
    ax.axhline(5e-3, ls="--", c="gray", label="0.5 % (issue's limit)")
    ax.axvline(1.0, ls=":", c="gray", label="1 s")
    ax.set_xlabel("whole process wall time (s), median of 3")
    ax.set_ylabel("largest relative error at interior points")
    ax.set_title("Section examples against CalculiX")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "benchmarks", "sections_benchmark.png"), dpi=120)
except ImportError:
    print("matplotlib not available: no PNG")
