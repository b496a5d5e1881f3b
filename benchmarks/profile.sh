#!/usr/bin/env bash
# Profile one run with perf (sampling, call graphs) and print the top
# entries by self time. Usage (from the repository root, Release build):
#   bash benchmarks/profile.sh [refinement level=3] [prm case=default]
# COAXFIT_EXE selects another executable (e.g. a build of an older commit).
set -euo pipefail
cd "$(dirname "$0")/.."
level="${1:-3}"
case="${2:-default}"
exe="${COAXFIT_EXE:-build/coaxfit}"
if ! command -v perf > /dev/null; then
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q linux-perf
fi
work="$(mktemp -d)"
perf record -q -F 999 -g -o "$work/perf.data" "$exe" \
  --set "Mesh/Global refinements=$level" --set "Output/Directory=$work/out" \
  --set "Output/Write vtu=false" "prm/$case.prm" | grep "wall time"
perf report -i "$work/perf.data" --no-children --sort dso,symbol --stdio 2> /dev/null \
  | grep -E '^ +[0-9.]+%' | head -15 | awk '{print $1, $2, $4}'
rm -rf "$work"
