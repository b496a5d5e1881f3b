#!/usr/bin/env python3
"""Whole-process speed of coaxfit (issue "A whole run, and a whole study, as
fast as the solve"): start-up, the default case, the output share, all 18
variants in one command against 18 processes, and a sweep of 20
interference values against one run.

Usage: /usr/bin/python3 benchmarks/speed_benchmark.py [RUNS]
(RUNS: repetitions per figure, default 5; the median is reported). Needs the
Release build (bash .ci/build). COAXFIT_EXE=... times another build (an
older one that lacks several files per command or --sweep gets n/a there).
Writes benchmarks/speed.csv and benchmarks/speed_summary.md, prints the
table. Wall time and peak memory are those of the whole process tree
(os.wait4 of the child; peak resident memory of the largest process)."""
import csv
import glob
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

from coaxfit_run import EXE, ROOT, markdown_table

RUNS = int(sys.argv[1]) if len(sys.argv) > 1 else 5
HERE = os.path.dirname(os.path.abspath(__file__))
WORK = tempfile.mkdtemp(prefix="coaxfit_speed_")


def timed(cmd, cwd=WORK):
    """Run cmd once; (wall s, peak MiB of the largest process, exit code)."""
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    proc.returncode = os.waitstatus_to_exitcode(status)
    proc.stderr.close()
    # ru_maxrss of RUSAGE_CHILDREN covers reaped grandchildren too.
    return wall, usage.ru_maxrss / 1024., proc.returncode


def median_of(cmd, runs=RUNS, before=None):
    """Median wall, median peak memory and the exit codes of runs runs
    after one warm-up; before() is called before each run."""
    walls, peaks, codes = [], [], set()
    for i in range(runs + 1):
        if before:
            before()
        wall, peak, code = timed(cmd)
        codes.add(code)
        if i > 0:
            walls.append(wall)
            peaks.append(peak)
    return statistics.median(walls), statistics.median(peaks), codes


def internal(directory):
    with open(os.path.join(directory, "summary.json")) as f:
        return json.load(f)["timing"]


rows = []


def add(figure, wall, peak, note=""):
    rows.append([figure, "%.3f" % wall if wall is not None else "n/a",
                 "%.0f" % peak if peak is not None else "n/a", note])
    print("%-58s %8s s %6s MiB  %s" % tuple(rows[-1]), flush=True)


variants = [os.path.join(ROOT, "prm", "variant_%02d.prm" % m)
            for m in range(1, 19)]
default = os.path.join(ROOT, "prm", "default.prm")

# The floor of any process that links deal.II: an empty main() linked to
# Debian's libdeal.ii.so (its ~200 libraries are loaded and relocated
# before main()).
empty = os.path.join(WORK, "empty")
with open(empty + ".cc", "w") as f:
    f.write("int main() { return 0; }\n")
built = subprocess.run(["g++", "-O2", empty + ".cc", "-o", empty,
                        "-Wl,--no-as-needed", "-ldeal.ii"],
                       capture_output=True).returncode == 0
if built:
    w, p, _ = median_of([empty])
    add("an empty program linked to libdeal.ii.so (start-up floor)", w, p)

# Start-up: --help, and --print-parameters (loads the libraries, builds
# every parameter).
w, p, _ = median_of([EXE, "--help"])
add("coaxfit --help", w, p)
w, p, _ = median_of([EXE, "--print-parameters"])
add("coaxfit --print-parameters", w, p)

# The default case with complete output, and its output share.
out = os.path.join(WORK, "default")
w, p, codes = median_of([EXE, "--quiet", "--set", "Output/Directory=" + out,
                         default])
t = internal(out)
add("default case (variant 5), complete output", w, p,
    "output %.3f s = %.0f %% of the process; solve phases %.3f s"
    % (t["output"], 100 * t["output"] / w, t["total"] - t["output"]))
one_run = w

# Refinement 3 (186k DoFs), complete output.
out3 = os.path.join(WORK, "ref3")
w, p, _ = median_of([EXE, "--quiet", "--set", "Output/Directory=" + out3,
                     "--set", "Mesh/Global refinements=3", default],
                    runs=max(1, RUNS // 2))
t = internal(out3)
add("default case at refinement 3, complete output", w, p,
    "output %.3f s = %.0f %% of the process" % (t["output"],
                                               100 * t["output"] / w))

# 18 variants: 18 processes one after another, and one command.
def eighteen_processes():
    for v in variants:
        subprocess.run([EXE, "--quiet", "--set",
                        "Output/Directory=" + os.path.join(WORK, "seq",
                                                           os.path.basename(v)),
                        v], cwd=WORK, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL, check=False)


walls = []
for i in range(max(1, RUNS // 2) + 1):
    start = time.perf_counter()
    eighteen_processes()
    if i > 0:
        walls.append(time.perf_counter() - start)
add("18 variants as 18 processes, complete output", statistics.median(walls),
    None)
w, p, codes = median_of([EXE, "--quiet"] + variants, runs=max(1, RUNS // 2))
if codes == {0}:
    add("18 variants in one command (coaxfit --quiet prm/variant_*.prm)",
        w, p, "complete output, cases in parallel on %d cores"
        % os.cpu_count())
else:
    add("18 variants in one command", None, None,
        "not supported by this build (exit %s)" % sorted(codes))

# A sweep of 20 interference values of variant 5 against one run.
sweep = [EXE, "--quiet", "--sweep", "Fit/Diametral interference=0.1:0.6:20",
         os.path.join(ROOT, "prm", "variant_05.prm")]
w, p, codes = median_of(sweep)
if codes == {0}:
    add("sweep of 20 interference values of variant 5", w, p,
        "%.2f x one run (default Output/Sweep files = figures)"
        % (w / one_run))
    w, p, codes = median_of(sweep[:2] + ["--set", "Output/Sweep files=complete"]
                            + sweep[2:])
    add("the same sweep, every value with complete output", w, p,
        "%.2f x one run" % (w / one_run))
else:
    add("sweep of 20 interference values", None, None,
        "not supported by this build (exit %s)" % sorted(codes))

shutil.rmtree(WORK, ignore_errors=True)
header = ["figure", "wall_s", "peak_MiB", "note"]
name = os.environ.get("SPEED_TABLE", "speed")
with open(os.path.join(HERE, name + ".csv"), "w", newline="") as f:
    csv.writer(f).writerows([header] + rows)
with open(os.path.join(HERE, name + "_summary.md"), "w") as f:
    f.write("Whole-process figures, median of %d runs after a warm-up, "
            "%s, %d cores:\n\n" % (RUNS, os.path.basename(EXE), os.cpu_count()))
    f.write(markdown_table(["figure", "wall (s)", "peak memory (MiB)",
                            "note"], rows))
