#!/usr/bin/env bash
# HATI against fully explicit on the beam / box-girder model of
# parameter_files/beam_solid_cantilever.prm (doc/user_guide.md 3.5) at three
# girder element sizes (0.2, 0.1 and 0.05 m in the plates' plane): the
# explicit tip beam at dt = 1e-5 s and the girder implicit at DT = 10 dt
# (HATI), against CD-Lagrange on the whole model at 0.9 of its critical step
# (the 12 mm webs' quadratic hexahedra set it). Each run covers a short end
# time; the table gives the wall time per simulated second of the stepping
# (summary.json stepping_wall_time / End time), the set-up (summary.json
# setup_wall_time: assembly, factorisation, ramp responses) and the
# speed-up of HATI, `explicit / HATI` per simulated second, and for a 10 s
# record including the set-ups. The machine's load average is printed: the
# timings are wall times.
# Usage: bench/beam_solid_speedup.sh [build directory] [sizes, default "0.2 0.1 0.05"]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
sizes=${2:-0.2 0.1 0.05}
[ -x "$build/hati" ] || ./scripts/setup.sh hati
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prm=parameter_files/beam_solid_cantilever.prm
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"

run() { # tag, --set values...
  local tag=$1
  shift
  local args=()
  for s in "$@"; do args+=(--set "$s"); done
  "$build/hati" $prm "${args[@]}" --set "Output/Output interval=0" \
    --set "Output/Output directory=$work/$tag" > "$work/$tag.log" 2>&1
}

printf "%6s %8s %11s %11s %11s %11s %11s %9s %9s\n" "size" "DoFs" "dt_exp (s)" \
  "HATI (s/s)" "expl. (s/s)" "HATI set-up" "expl. set-up" "speed-up" "10 s rec."
for h in $sizes; do
  solid="Model/Frame/Solids=girder: box girder, 2, 0, 0, 6, 0, 0, 0.4, 0.6, 0.012, 0.016, $h, steel, 2"
  run "hati_$h" "$solid" "Time integration/End time=0.005" || { cat "$work/hati_$h.log"; exit 1; }
  # the explicit critical step from the refusal of a too large step
  run "probe_$h" "$solid" "Time integration/Method=CD-Lagrange" \
    "Time integration/Time step=1" "Time integration/End time=1" || true
  dt=$(sed -n 's/.*dt_crit = [^=]*= \([0-9.eE+-]*\) s.*/\1/p' "$work/probe_$h.log" | head -1)
  [ -n "$dt" ] || { cat "$work/probe_$h.log"; exit 1; }
  read -r dt T < <(/usr/bin/python3 -c "dt = 0.9 * $dt; print(dt, 2000.5 * dt)")
  run "explicit_$h" "$solid" "Time integration/Method=CD-Lagrange" \
    "Time integration/Time step=$dt" "Time integration/End time=$T" ||
    { cat "$work/explicit_$h.log"; exit 1; }
  /usr/bin/python3 - "$work/hati_$h/summary.json" "$work/explicit_$h/summary.json" "$h" "$dt" <<'PY'
import json, sys
h = json.load(open(sys.argv[1]))
e = json.load(open(sys.argv[2]))
rate = lambda s: s["stepping_wall_time"] / s["end_time"]
setup = lambda s: s["setup_wall_time"]
rh, re_ = rate(h), rate(e)
print("%6s %8d %11.3g %11.4g %11.4g %11.3g %11.3g %9.1f %9.1f" % (
    sys.argv[3], h["n_dofs"], float(sys.argv[4]), rh, re_, setup(h), setup(e), re_ / rh,
    (setup(e) + 10 * re_) / (setup(h) + 10 * rh)))
PY
done
