"""Shared helper of the benchmark scripts: run build/coaxfit on a prm file
with --set overrides and return its summary.json (None if it failed); write
result tables as CSV and as markdown."""
import csv
import json
import os
import re
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.environ.get("COAXFIT_EXE", os.path.join(ROOT, "build", "coaxfit"))
CASES = ["variant_%02d" % m for m in range(1, 19)]


def prm(case):
    return os.path.join(ROOT, "prm", case + ".prm")


def run(case, settings=(), keep=None):
    """Run one case; settings are 'Section/Name=value' strings. Returns
    (summary dict or None, exit code, stderr)."""
    out = keep or tempfile.mkdtemp(prefix="coaxfit_")
    if keep:
        subprocess.run(["rm", "-rf", keep])  # no stale results of a failed run
    cmd = [EXE, "--set", "Output/Directory=" + out, "--set", "Output/Write vtu=false"]
    for s in settings:
        cmd += ["--set", s]
    cmd.append(prm(case))
    proc = subprocess.run(cmd, capture_output=True, text=True)
    path = os.path.join(out, "summary.json")
    summary = None
    if proc.returncode in (0, 2) and os.path.exists(path):
        with open(path) as f:
            summary = json.load(f)
    if keep is None:
        subprocess.run(["rm", "-rf", out])
    return summary, proc.returncode, proc.stderr.strip()


def steps_to(convergence_history, criterion):
    """First Neumann step whose displacement mismatch is below criterion."""
    for step, kind, value in convergence_history:
        if kind == "neumann" and value < criterion:
            return step
    return None


def paper_alpha(case):
    with open(prm(case)) as f:
        return float(re.search(r"set Alpha\s+= ([0-9.]+)", f.read()).group(1))


def write_csv(path, header, rows, append=False):
    """Write (or append, without the header) rows as CSV."""
    with open(path, "a" if append else "w", newline="") as f:
        w = csv.writer(f)
        if not append:
            w.writerow(header)
        w.writerows(rows)


def markdown_table(header, rows):
    """Rows as a markdown table (with a trailing newline)."""
    lines = ["| " + " | ".join(str(x) for x in header) + " |", "|---" * len(header) + "|"]
    lines += ["| " + " | ".join(str(x) for x in r) + " |" for r in rows]
    return "\n".join(lines) + "\n"
