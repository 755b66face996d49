#!/usr/bin/env bash
# HATI against fully explicit CD-Lagrange over a window around the first
# trolley uplift of the solid-girder crane under Rinaldi X + Z (issue #26:
# "0.05 s around the first trolley uplift"; the suite's short version is
# test_cases/crane_3d_hati_explicit.py, 3 ms).
#
# The crane of parameter_files/bridge_crane_3d.prm with true heights, tied
# wheels, rigid hoist, undamped. The window is reached by restarts
# (Analysis/Initial state = file): HATI with the girders reduced
# (Craig-Bampton, 150 Hz) from the static state to START - 32 ms, HATI
# unreduced from there to START (the unreduced girders take up the reduced
# state there, and its jolt rings in the undamped plates: 5 ms later HATI
# and CD-Lagrange still differed by 2-6 % at the trolley wheels), then from the state at START both HATI unreduced (dt 4e-5 s,
# DT 2e-4 s) and CD-Lagrange (3.2e-7 s) to START + WINDOW. Printed: the
# monitors' displacement differences from the window's start in % of the
# explicit peak, each contact's first loss of contact in both runs, the
# wall times of the two window runs (set-up and stepping) and the speed-up.
# The fully explicit run costs about 4 ms a step at 1.1 m (18,918 DoFs):
# 0.05 s is 156,250 steps, 11 min.
# Usage: bench/crane3d_uplift_window.sh [build directory] [plate size, m,
#        default 1.1] [START, s, default 1.7325] [WINDOW, s, default 0.05]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
size=${2:-1.1}
start=${3:-1.7325}
window=${4:-0.05}
[ -x "$build/hati" ] || ./scripts/setup.sh hati
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
prefix_end=$(/usr/bin/python3 -c "print(round($start - 0.032, 10))")
end=$(/usr/bin/python3 -c "print(round($start + $window, 10))")

run() { # tag, --set values...
  local tag=$1
  shift
  local args=()
  for s in "$@"; do args+=(--set "$s"); done
  "$build/hati" parameter_files/bridge_crane_3d.prm "${args[@]}" \
    --set "Model/Bridge crane/Girder element size=$size" \
    --set "Model/Bridge crane/Eccentricities=true" \
    --set "Model/Bridge crane/Travel=tied" --set "Model/Bridge crane/Hoist=rigid" \
    --set "Model/Bridge crane/Damping ratio=0" --set "Output/Output interval=0" \
    --set "Output/Section force interval=1e20" --set "Output/Progress interval=60" \
    --set "Output/Output directory=$work/$tag" > "$work/$tag.log" 2>&1 ||
    { tail -3 "$work/$tag.log"; exit 1; }
}
unreduced=("Model/Decomposition/Implicit reduction=none" "Output/History interval=4e-5")

run prefix "Time integration/End time=$prefix_end" "Output/History interval=0.01" \
  "Output/State interval=100"
run settle "${unreduced[@]}" "Analysis/Initial state=file" \
  "Analysis/Initial state file=$work/prefix/state.bin" "Time integration/End time=$start" \
  "Output/State interval=100"
from_state=("${unreduced[@]}" "Analysis/Initial state=file"
  "Analysis/Initial state file=$work/settle/state.bin" "Time integration/End time=$end")
run hati "${from_state[@]}"
run explicit "${from_state[@]}" "Time integration/Method=CD-Lagrange" \
  "Time integration/Time step=3.2e-7"
/usr/bin/python3 bench/compare_hati_explicit.py "$work/hati" "$work/explicit"
