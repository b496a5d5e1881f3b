#!/usr/bin/env bash
# Run every study and rebuild benchmarks/README.md. Needs the Release build
# (bash .ci/build). Takes about an hour on 2 cores.
set -euo pipefail
cd "$(dirname "$0")"
if ! /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q python3-matplotlib
fi
PY=/usr/bin/python3
$PY variants_table.py
$PY refinement_study.py 4
$PY sections_benchmark.py
$PY stack_benchmark.py
$PY stack_selection_benchmark.py
$PY plastic_benchmark.py
$PY alpha_spectrum.py
$PY separation_study.py 2
$PY controller_benchmark.py
$PY alpha_sweep.py
$PY work_precision.py 5
$PY speed_benchmark.py 5
$PY stress/run_stress.py
$PY make_readme.py
