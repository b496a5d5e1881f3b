#!/usr/bin/env python3
"""The stiffness and geometry family of the stress suite: variant 5's scene
(prm/default.prm, default coupling settings) with E_shaft/E_hub from 1e-4 to
1e4, solid, hollow (beta1 = 0.5, 0.9) and thin (0.99) shafts and hub ratios
beta2 = D_hub/D_F from 1.05 to 4. Every case must converge with the defaults
and its contact pressure match the monolithic solver's to 1e-8 (max pointwise
difference over the largest pressure; both are solutions of the same
discrete problem). Writes contrast_family.csv next to this script, prints a
table and a summary. run_stress.py runs it as part of the suite.
Usage: python3 benchmarks/stress/contrast_family.py [--quick]"""
import csv
import os
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from coaxfit_run import EXE, prm, write_csv  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
RATIOS = [1e-4, 1e-3, 1e-2, 1e-1, 1.0, 1e1, 1e2, 1e3, 1e4]
SHAFTS = [0.0, 0.5, 0.9, 0.99]
HUBS = [1.05, 1.2, 2.0, 4.0]


def pressures(directory):
    with open(os.path.join(directory, "contact_pressure.csv")) as f:
        return [float(r["pressure_MPa"]) for r in csv.DictReader(f)]


def run_one(settings, method):
    out = tempfile.mkdtemp(prefix="coaxfit_family_")
    cmd = [EXE, "--quiet", "--set", "Output/Directory=" + out, "--set", "Output/Write vtu=false",
           "--set", "Output/Write plots=false", "--set", "Output/Write report=false",
           "--set", "Solver/Method=" + method]
    for s in settings:
        cmd += ["--set", s]
    proc = subprocess.run(cmd + [prm("default")], capture_output=True, text=True)
    result = None
    if proc.returncode == 0:
        import json
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        result = (summary, pressures(out))
    subprocess.run(["rm", "-rf", out])
    return result, proc.returncode, proc.stderr.strip()


def case(ratio, beta1, beta2):
    """One member: (label, steps or None, difference to monolithic, note)."""
    settings = ["Material/Shaft/E=%g" % (2e5 * ratio ** 0.5),
                "Material/Hub/E=%g" % (2e5 / ratio ** 0.5),
                "Geometry/Shaft bore diameter=%g" % (200 * beta1),
                "Geometry/Hub outer diameter=%g" % (200 * beta2)]
    label = "E1/E2 = %g, beta1 = %g, beta2 = %g" % (ratio, beta1, beta2)
    staggered, code, err = run_one(settings, "staggered")
    mono, mcode, merr = run_one(settings, "monolithic")
    if mono is None:
        return label, None, None, "monolithic exit %d: %s" % (mcode, merr[:80])
    if staggered is None:
        return label, None, None, "exit %d: %s" % (code, err[:100])
    s, p = staggered
    _, q = mono
    scale = max(abs(x) for x in q)
    diff = max(abs(a - b) for a, b in zip(p, q)) / scale if scale > 0 else 0.0
    return label, s["iterations"], diff, "%d separated" % s["contact"]["separated_points"]


def write_summary(rows):
    """contrast_family_summary.md: steps per E ratio (rows) and shaft
    (columns), the smallest and largest over the hub ratios."""
    lines = ["| E_shaft/E_hub | " + " | ".join("beta1 = %g" % b for b in SHAFTS) + " |",
             "|---|" + "---|" * len(SHAFTS)]
    for ratio in RATIOS:
        cells = []
        for beta1 in SHAFTS:
            steps = [r[3] for r in rows if r[0] == ratio and r[1] == beta1]
            if any(s == "fails" for s in steps):
                cells.append("%d of %d fail" % (steps.count("fails"), len(steps)))
            else:
                cells.append("%d-%d" % (min(steps), max(steps)))
        lines.append("| %g | %s |" % (ratio, " | ".join(cells)))
    worst = max((r for r in rows if r[4] != "-"), key=lambda r: float(r[4]), default=None)
    with open(os.path.join(HERE, "contrast_family_summary.md"), "w") as f:
        f.write("Steps to 1e-8 with the default settings (smallest-largest over "
                "beta2 = %s); every case's pressure equals the monolithic solver's "
                "to %s of the largest pressure (worst case).\n\n"
                % (", ".join("%g" % b for b in HUBS), worst[4] if worst else "-"))
        f.write("\n".join(lines) + "\n")


def run_family(add=None, quick=False):
    """Run the family; with add(case, check, figure, passed) report rows to
    the stress suite. Returns the number of failures."""
    members = [(r, b1, b2) for r in RATIOS for b1 in SHAFTS for b2 in HUBS]
    if quick:
        members = [(r, b1, b2) for r, b1, b2 in members
                   if r in (1e-4, 1.0, 1e4) and b2 in (1.05, 4.0)]
    with ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        results = list(pool.map(lambda m: case(*m), members))
    rows, failures = [], 0
    for (label, steps, diff, note), m in zip(results, members):
        passed = steps is not None and diff is not None and diff < 1e-8
        failures += not passed
        rows.append([m[0], m[1], m[2], steps if steps is not None else "fails",
                     "%.1e" % diff if diff is not None else "-", note])
        if add is not None:
            add(label, "converges with the defaults, p = monolithic to 1e-8",
                ("%d steps, difference %.1e" % (steps, diff)) if passed or steps else note, passed)
        else:
            print("%-42s %6s %9s  %s" % (label, rows[-1][3], rows[-1][4], note), flush=True)
    if not quick:
        write_csv(os.path.join(HERE, "contrast_family.csv"),
                  ["E1_over_E2", "beta1", "beta2", "steps", "difference_to_monolithic", "note"],
                  rows)
    if not quick:
        write_summary(rows)
    steps = [r[3] for r in rows if r[3] != "fails"]
    print("\ncontrast family: %d cases, %d converge and match the monolithic solver, "
          "%d fail; steps median %s, max %s"
          % (len(rows), len(rows) - failures, failures,
             sorted(steps)[len(steps) // 2] if steps else "-", max(steps) if steps else "-"))
    return failures


if __name__ == "__main__":
    sys.exit(1 if run_family(quick="--quick" in sys.argv) else 0)
