#!/usr/bin/env bash
# Implicit Newmark cost on the 3D portal frame of
# parameter_files/portal_frame_dynamic.prm refined to about 1e3, 1e4 and 1e5
# DoFs: assembly + factorisation time (once) and the cost of one implicit
# step (predictor, one solve, corrector), from summary.json.
# Usage: bench/implicit_step.sh [build directory] [linear solver: auto|KLU|MUMPS|direct|iterative]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
# KLU by default: the numbers measured in the user guide (auto: MUMPS at 1e5 DoFs)
solver=${2:-KLU}
[ -x "$build/hati" ] || ./scripts/setup.sh hati
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf "%10s %8s %18s %16s %16s\n" "DoFs" "steps" "factorisation (s)" "step (ms)" "us/DoF/step"
for scale in 2 22 220; do
  c=$((8 * scale)); b=$((10 * scale)); x=$((8 * scale))
  members="colA: A0, A1, column, steel, $c; colB: B0, B1, column, steel, $c; colC: C0, C1, column, steel, $c; colD: D0, D1, column, steel, $c; beamAB: A1, B1, beam, steel, $b; beamCD: C1, D1, beam, steel, $b; crossAC: A1, C1, beam, steel, $x; crossBD: B1, D1, beam, steel, $x"
  steps=50
  "$build/hati" parameter_files/portal_frame_dynamic.prm \
    --set "Model/Frame/Members=$members" \
    --set "Time integration/Time step=1e-3" --set "Time integration/End time=$(/usr/bin/python3 -c "print($steps*1e-3)")" \
    --set "Time integration/Newmark/Linear solver=$solver" \
    --set "Output/Output interval=0" --set "Output/History interval=1" \
    --set "Output/Output directory=$work/s$scale" > "$work/log$scale" 2>&1 || { cat "$work/log$scale"; exit 1; }
  /usr/bin/python3 - "$work/s$scale/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
step = s["stepping_wall_time"] / s["n_steps"]
print("%10d %8d %18.4g %16.4g %16.4g" % (s["n_dofs"], s["n_steps"], s["factorization_time"],
      1e3 * step, 1e6 * step / s["n_dofs"]))
PY
done
