#!/usr/bin/env bash
# HATI against fully explicit on the solid-girder crane of
# parameter_files/bridge_crane_3d.prm (doc/user_guide.md 3.6) at girder
# element sizes (default 0.4, 0.2 and 0.1 m in the plates' plane): HATI with
# the file's steps (explicit dt = 4e-5 s, DT = 5 dt) over 0.01 s of Rinaldi,
# against CD-Lagrange on the whole crane at 0.9 of its critical step (the
# 6 mm webs' quadratic hexahedra set it), timed over 2000 steps from rest:
# its cost per step is constant, so its wall time for 0.3 s of record is
# that cost times the steps, extrapolated (the table says so). Columns:
# DoFs, the explicit step (0.9 of the critical one), wall time per
# simulated second of the stepping (summary.json stepping_wall_time / end
# time) of each method, HATI's share in its implicit solves, the set-ups
# (assembly, factorisations, ramp responses; setup_wall_time), the static
# state, and the speed-up for 0.3 s of record, set-ups included, the
# static state (the same for both) left out. The machine's load average is
# printed: these are wall times. The 0.1 m mesh needs 20 GB and many minutes of set-up (the static
# state with the rope, then the factorisation; summary.json
# static_state_wall_time, setup_wall_time). HATI
# runs unreduced here (Implicit reduction = none); bench/crane3d_record.sh
# times the file's reduced run.
# Usage: bench/crane3d_speedup.sh [build directory] [sizes, default "0.4 0.2 0.1"]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
sizes=${2:-0.4 0.2 0.1}
[ -x "$build/hati" ] || ./scripts/setup.sh hati
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prm=parameter_files/bridge_crane_3d.prm
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"

run() { # tag, --set values...
  local tag=$1
  shift
  local args=()
  for s in "$@"; do args+=(--set "$s"); done
  "$build/hati" $prm "${args[@]}" --set "Output/Output interval=0" \
    --set "Model/Decomposition/Implicit reduction=none" \
    --set "Output/Output directory=$work/$tag" > "$work/$tag.log" 2>&1
}

printf "%5s %8s %10s %11s %9s %13s %10s %11s %9s %9s\n" "size" "DoFs" "dt_expl" \
  "HATI (s/s)" "implicit" "explicit(s/s)" "HATI setup" "expl. setup" "static" "speed-up"
for h in $sizes; do
  size="Model/Bridge crane/Girder element size=$h"
  run "hati_$h" "$size" "Time integration/End time=0.01" || { tail -3 "$work/hati_$h.log"; exit 1; }
  # the explicit critical step from the refusal of a too large step (before
  # the static state: instant)
  run "probe_$h" "$size" "Time integration/Method=CD-Lagrange" \
    "Time integration/Time step=1" "Time integration/End time=1" || true
  dt=$(sed -n 's/.*dt must be <= \([0-9.eE+-]*\) s.*/\1/p' "$work/probe_$h.log" | head -1)
  [ -n "$dt" ] || { tail -3 "$work/probe_$h.log"; exit 1; }
  read -r dt T < <(/usr/bin/python3 -c "dt = 0.9 * $dt; print(dt, 2000.5 * dt)")
  # its cost per step does not depend on the state: timed from rest
  # (Initial state = given), without the static state HATI paid above
  run "explicit_$h" "$size" "Time integration/Method=CD-Lagrange" "Analysis/Initial state=given" \
    "Time integration/Time step=$dt" "Time integration/End time=$T" ||
    { tail -3 "$work/explicit_$h.log"; exit 1; }
  /usr/bin/python3 - "$work/hati_$h/summary.json" "$work/explicit_$h/summary.json" "$h" "$dt" <<'PY'
import json, sys
h = json.load(open(sys.argv[1]))
e = json.load(open(sys.argv[2]))
rate = lambda s: s["stepping_wall_time"] / s["end_time"]
rh, re_ = rate(h), rate(e)
share = h.get("wall_time_implicit", 0.0) / max(h["stepping_wall_time"], 1e-30)
sh, se = h["setup_wall_time"], e["setup_wall_time"]
print("%5s %8d %10.3g %11.4g %8.0f%% %13.4g %10.3g %11.3g %9.3g %9.1f" % (
    sys.argv[3], h["n_dofs"], float(sys.argv[4]), rh, 100 * share, re_, sh, se,
    h.get("static_state_wall_time", 0.0), (se + 0.3 * re_) / (sh + 0.3 * rh)))
PY
done
echo "explicit: 2000 steps timed from rest, 0.3 s of record extrapolated at that cost per step;"
echo "static: the static state (with the rope), which both methods pay, left out of the speed-up"
