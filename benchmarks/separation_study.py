#!/usr/bin/env python3
"""Onset and extent of separation of a thin tube in a hub (issue: unilateral
contact). Sweeps the tube ratio beta1 = R0/R1 with beta2 = 2, l1 = 3, l2 = 2,
delta = 0.005 (the paper's variants 11-18) on several meshes:
  paper-like : FE_Q(1), 12 uniform axial cells, 10 radial, no refinement
  Q2 ref k   : the shipped settings (FE_Q(2), graded 1.4) at refinement k
For each run: the minimum bilateral pressure away from the corner (its zero
crossing is the onset of separation), and with the unilateral pass the
separated length and zones. Writes separation_study.csv, a markdown table
and separation_profiles.png (unilateral pressure near the hub end on the
finest mesh).
Usage: python3 benchmarks/separation_study.py [finest_refinement=3]"""
import csv
import os
import sys

from coaxfit_run import ROOT, markdown_table, run, write_csv

BETAS = [0.90, 0.92, 0.93, 0.94, 0.95, 0.96, 0.97, 0.975, 0.98, 0.9825,
         0.985, 0.9875, 0.99, 0.9925, 0.995]
finest = int(sys.argv[1]) if len(sys.argv) > 1 else 3
MESHES = {"paper-like Q1": ["Mesh/Degree=1", "Mesh/Grading ratio=1",
                            "Mesh/Global refinements=0"]}
for k in range(finest + 1):
    MESHES["Q2 ref %d" % k] = ["Mesh/Global refinements=%d" % k]


def geometry(beta1):
    return ["Geometry/Shaft bore diameter=%.6g" % (200 * beta1),
            "Geometry/Hub outer diameter=400", "Geometry/Shaft length=600",
            "Geometry/Hub length=400", "Fit/Diametral interference=1",
            "Coupling/Max steps=2000"]


def min_away_from_corner(profile_dir):
    rows = list(csv.DictReader(open(os.path.join(profile_dir, "contact_pressure.csv"))))
    inner = [r for r in rows if float(r["z_mm"]) < 199.0]
    r = min(inner, key=lambda r: float(r["pressure_MPa"]))
    return float(r["pressure_MPa"]), float(r["z_mm"]), rows


rows, profiles = [], {}
for mesh, settings in MESHES.items():
    for beta1 in BETAS:
        base = geometry(beta1) + settings
        d_bi = os.path.join(ROOT, "output", "separation_study", "bi")
        s_bi, _, err_bi = run("variant_15", base + ["Contact/Unilateral=false"], keep=d_bi)
        d_un = os.path.join(ROOT, "output", "separation_study", "un_%s_%g" % (mesh.replace(" ", "_"), beta1))
        s_un, _, err_un = run("variant_15", base + ["Contact/Unilateral=true"], keep=d_un)
        if s_bi is None or s_un is None:
            rows.append([mesh, beta1, "failed", "", "", "", "", ""])
            print(rows[-1], err_bi, err_un, flush=True)
            continue
        pmin, zmin, _ = min_away_from_corner(d_bi)
        zones = s_un["contact"]["separated_zones"]
        rows.append([mesh, beta1, "%.2f" % pmin, "%.1f" % zmin,
                     "%.2f" % s_un["contact"]["separated_length"],
                     " ".join("[%.1f, %.1f]" % tuple(z) for z in zones) or "-",
                     s_un["iterations"], s_un["active_set"]["changes"]])
        if mesh == "Q2 ref %d" % finest:
            profiles[beta1] = list(csv.DictReader(open(os.path.join(d_un, "contact_pressure.csv"))))
        print(rows[-1], flush=True)

# Onset: linear interpolation of the zero crossing of the bilateral minimum.
onsets = {}
for mesh in MESHES:
    pts = [(float(r[1]), float(r[2])) for r in rows if r[0] == mesh and r[2] != "failed"]
    for (b0, p0), (b1, p1) in zip(pts, pts[1:]):
        if p0 > 0 >= p1:
            onsets[mesh] = b0 + (b1 - b0) * p0 / (p0 - p1)
            break

write_csv(os.path.join(ROOT, "benchmarks", "separation_study.csv"),
          ["mesh", "beta1", "bilateral_min_pressure_MPa", "z_of_min_mm",
           "separated_length_mm", "separated_zones_mm", "steps", "active_set_changes"], rows)
print()
print(markdown_table(["mesh", "beta1", "bilateral min p (MPa)", "at z (mm)",
                      "separated length (mm)", "separated zones (mm)", "steps",
                      "active set changes"], rows), end="")
lines = ["Onset of separation (the bilateral minimum pressure away from the "
         "corner crosses zero; linear interpolation between the sampled beta1):", ""]
for mesh in MESHES:
    lines.append("- %s: beta1 = %s" % (mesh, "%.4f" % onsets[mesh] if mesh in onsets else "not in range"))
print("\n".join(lines))
with open(os.path.join(ROOT, "benchmarks", "separation_summary.md"), "w") as f:
    f.write("\n".join(lines) + "\n")

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 5))
    for beta1, prof in sorted(profiles.items()):
        z = [float(r["z_mm"]) for r in prof]
        p = [float(r["pressure_MPa"]) for r in prof]
        ax.plot(z, p, label="beta1 = %g" % beta1)
    ax.set_xlim(150, 200)
    ax.set_ylim(-5, 80)
    ax.set_xlabel("z (mm), hub end at 200")
    ax.set_ylabel("contact pressure (MPa)")
    ax.set_title("Unilateral contact pressure near the hub end, Q2 ref %d" % finest)
    ax.legend(fontsize=7, ncol=2)
    ax.grid(True)
    fig.savefig(os.path.join(ROOT, "benchmarks", "separation_profiles.png"), dpi=120)
except ImportError:
    print("matplotlib not available: no PNG (apt-get install python3-matplotlib)")
