#!/usr/bin/env bash
# scripts/regression_digests.sh [hati executable] : run every
# parameter_files/*.prm for a short end time (at most 0.5 s of simulated
# time; the crane 1 s with HATI and fully explicit) plus a few variants
# that no parameter file selects (event-driven, damping), and print one
# SHA-256 digest per result file (every CSV, the VTU snapshots and the
# parsed parameters.prm), one line each:
#
#   <digest>  <case>/<file>
#
# A refactoring that must leave the results bitwise unchanged is checked by
# running this script before and after and comparing the two lists
# (`diff before.txt after.txt`). summary.json is left out: it holds wall
# times. Runs are done in a temporary folder, removed at the end.
set -euo pipefail
cd "$(dirname "$0")/.."
hati="$(realpath "${1:-build/hati}")"
[ -x "$hati" ] || { echo "regression_digests.sh: no executable $hati (build first)" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# run_case NAME FILE END_CAP [--set ...]: the file with End time = min(its own, END_CAP)
run_case() {
  local name="$1" prm="$2" cap="$3"
  shift 3
  local own
  own=$(sed -n 's/^[[:space:]]*set End time[[:space:]]*=[[:space:]]*\([^[:space:]#]*\).*/\1/p' "$prm" | head -1)
  local end="$cap"
  if [ -n "$own" ]; then
    end=$(python3 -c "print(min(float('$own'), float('$cap')))")
  fi
  local out="$work/$name"
  if ! "$hati" "$prm" --set "Time integration/End time=$end" \
       --set "Output/Output directory=$out" "$@" >"$work/$name.log" 2>&1; then
    echo "FAILED  $name (see below)"
    tail -5 "$work/$name.log"
    return 0
  fi
  (cd "$out" && find . -type f \( -name '*.csv' -o -name '*.vtu' -o -name 'parameters.prm' \) \
     | sort | while read -r f; do
         printf '%s  %s/%s\n' "$(sha256sum "$f" | cut -c1-16)" "$name" "${f#./}"
       done)
}

for prm in parameter_files/*.prm; do
  name=$(basename "$prm" .prm)
  case "$name" in
    bridge_crane_hati|bridge_crane_full_explicit) run_case "$name" "$prm" 1 ;;
    *) run_case "$name" "$prm" 0.5 ;;
  esac
done

# Paths that no parameter file takes
run_case bouncing_ball_event_driven parameter_files/bouncing_ball.prm 0.5 \
  --set "Time integration/Method=event-driven"
run_case portal_frame_split_damped parameter_files/portal_frame_split.prm 0.2 \
  --set "Time integration/Damping/Damping ratio=0.02" \
  --set "Time integration/Damping/First frequency=2" \
  --set "Time integration/Damping/Second frequency=20"
run_case bar_impact_1d_damped parameter_files/bar_impact_1d.prm 0.5 \
  --set "Time integration/Damping/Mass coefficient=5" \
  --set "Time integration/Damping/Stiffness coefficient=1e-7"
run_case crane_hati_undamped parameter_files/bridge_crane_hati.prm 0.3 \
  --set "Model/Bridge crane/Damping ratio=0"
