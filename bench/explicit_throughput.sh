#!/usr/bin/env bash
# Explicit step cost of CD-Lagrange in ns per DoF per step, for the 1D bar of
# parameter_files/bar_impact_1d.prm at 1e3, 1e4, 1e5 and 1e6 DoFs (goal:
# under 5 ns/DoF/step at 1e5 DoFs on a 2-core machine). The bar hits the wall
# halfway through each run, so the contact path is exercised; output is
# limited to the first and last rows so that the figure is the step itself
# (summary.json: stepping_wall_time = stepping loop minus output).
# Usage: bench/explicit_throughput.sh [build directory]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
[ -x "$build/hati" ] || ./scripts/setup.sh hati
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
c=$(/usr/bin/python3 -c "print((2e11/7800)**0.5)")
printf "%10s %10s %12s %14s %16s\n" "DoFs" "steps" "dt (s)" "stepping (s)" "ns/DoF/step"
for n in 1000 10000 100000 1000000; do
  elements=$((n - 1))
  steps=$(/usr/bin/python3 -c "print(max(200, int(1.5e9 / ($n * 2))))")
  # dt = 0.9 h / c, end time = steps dt, gap = v0 * end time / 2 (v0 = 1 m/s)
  read -r dt T gap < <(/usr/bin/python3 -c "h=1.0/$elements; dt=0.9*h/$c; print(dt, $steps*dt, $steps*dt/2)")
  "$build/hati" parameter_files/bar_impact_1d.prm \
    --set "Model/Bar/Number of elements=$elements" \
    --set "Time integration/Time step=$dt" --set "Time integration/End time=$T" \
    --set "Contact/Initial gap=$gap" \
    --set "Output/Output interval=0" --set "Output/History interval=$T" \
    --set "Output/Output directory=$work/n$n" > "$work/log$n" 2>&1 || { cat "$work/log$n"; exit 1; }
  /usr/bin/python3 - "$work/n$n/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print("%10d %10d %12.4g %14.4g %16.3f" % (s["n_dofs"], s["n_steps"], s["dt"],
      s["stepping_wall_time"], s["ns_per_dof_per_step"]))
PY
done
