#!/usr/bin/env bash
# Cost of the output of a small explicit run (issue #7, item 9): the 1D bar
# of parameter_files/bar_impact_1d.prm (101 DoFs, 2000 steps) with
# - history every step and no VTU (Output interval = 0): 2001 rows each of
#   history.csv, energy.csv and contacts.csv; prints the run's wall time
#   (summary.json) and the output time per step (history + energy + contacts
#   row, from the "done:" line: output s in N calls);
# - the file as it is (a VTU snapshot every 20 steps, 101 snapshots).
# Medians of 7 runs. Goal: the history-every-step run at least 3 times
# faster than before the change (commit 098665e: 26.6 ms wall, 8.9 us of
# output per step on an idle 2-core machine), VTU snapshots not slower.
# Usage: bench/output_rows.sh [build directory]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
[ -x "$build/hati" ] || ./scripts/setup.sh hati
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for case in history vtu; do
  sets=()
  [ $case = history ] && sets=(--set "Output/Output interval=0")
  for i in 1 2 3 4 5 6 7; do
    "$build/hati" parameter_files/bar_impact_1d.prm "${sets[@]}" \
      --set "Output/Output directory=$work/$case" > "$work/log-$case-$i" 2>&1 ||
      { cat "$work/log-$case-$i"; exit 1; }
    /usr/bin/python3 -c "import json; print(json.load(open('$work/$case/summary.json'))['wall_time'])" >> "$work/wall-$case"
    # output time per step: "done: ... (output X s in N calls)", or (before
    # the change) the TimerOutput row "| output | N | Xs |"
    { sed -n 's/.*(output \([^ ]*\) s in \([0-9]*\) calls).*/\1 \2/p' "$work/log-$case-$i"
      sed -n 's/^| output *| *\([0-9]*\) | *\([0-9.e+-]*\)s.*/\2 \1/p' "$work/log-$case-$i"
    } | head -1 >> "$work/output-$case"
  done
  /usr/bin/python3 - "$case" "$work/wall-$case" "$work/output-$case" <<'PY'
import statistics, sys
case, wall, output = sys.argv[1:4]
w = [float(l) for l in open(wall)]
o = [l.split() for l in open(output)]
line = "%-8s wall time %8.3f ms (median of %d)" % (case, 1e3 * statistics.median(w), len(w))
if o:
    line += ", output %6.3f us per step" % statistics.median(1e6 * float(s) / int(n) for s, n in o)
print(line)
PY
done
