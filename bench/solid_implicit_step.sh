#!/usr/bin/env bash
# Cost of a 3D solid in a frame model (doc/user_guide.md 3.5): a steel
# 'box' solid of quadratic hexahedra (cubes of 0.1 m, nx x ny x nz cells,
# about 1e4, 5e4 and 1.5e5 DoFs) clamped by 'Solid supports' at x = 0 and
# loaded at the tip of a 1 m beam tied to its face x = L.
#
# 1. Newmark (implicit, consistent mass, the tie eliminated): the
#    factorisation time of the effective matrix (summary.json
#    factorization_time), the whole Newmark set-up of the terminal's timer
#    (that factorisation and the one of the consistent mass for the initial
#    acceleration under the step load, M A_0 = F_0 - K U_0) and the cost of
#    one step (stepping_wall_time / n_steps: predictor, one substitution,
#    corrector) with KLU and with MUMPS. A run longer than the limit (second
#    argument, default 600 s) is cut and shown as such. KLU (no nested
#    dissection: its fill grows fast on a 3D mesh) is skipped at 1.5e5 DoFs
#    unless the third argument is 'all': measured 67 s of factorisation at
#    5e4 DoFs and more than 300 s of set-up at 1.5e5 (2 cores, load about 4).
# 2. CD-Lagrange (explicit, lumped mass, the tie as bilateral rows): the
#    step cost in ns per DoF per step (summary.json ns_per_dof_per_step),
#    at 0.9 dt_crit (dt_crit read from the refusal of a too large step),
#    against the beam-only portal frame of parameter_files/
#    portal_frame_dynamic.prm refined to a similar number of DoFs, and the
#    5e4 DoF solid without its tie (the cost of the tie's rows).
# The machine's load average is printed first: the timings are wall times.
# Usage: bench/solid_implicit_step.sh [build directory] [time limit per run, s] [all]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
limit=${2:-600}
all=${3:-}
[ -x "$build/hati" ] || ./scripts/setup.sh hati
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"

# the solid model for nx ny nz cells: echo its --set arguments, one a line
solid_model() {
  local nx=$1 ny=$2 nz=$3
  /usr/bin/python3 - "$nx" "$ny" "$nz" <<'PY'
import sys
nx, ny, nz = map(int, sys.argv[1:4])
L, b, h = 0.1 * nx, 0.1 * ny, 0.1 * nz
for s in ("Model/Frame/Nodes=T0: %g, 0, 0; T1: %g, 0, 0" % (L, L + 1),
          "Model/Frame/Members=tip: T0, T1, rod, steel, 4",
          "Model/Frame/Supports=",
          "Model/Frame/Solids=block: box, 0, %g, %g, %g, %g, %g, %d, %d, %d, steel"
          % (-b / 2, -h / 2, L, b / 2, h / 2, nx, ny, nz),
          "Model/Frame/Solid element degree=2",
          "Model/Frame/Solid supports=block: x=0",
          "Model/Frame/Ties=t: T0, block, x=%g" % L,
          "Model/Frame/Point masses=",
          "Model/Frame/Nodal loads=T1: 0, 0, -1e4, 0, 0, 0",
          "Model/Frame/Monitor nodes=T1",
          "Output/Output interval=0", "Output/History interval=1"):
    print(s)
PY
}

# run hati on parameter file $1 with the --set lines of file $2 and further
# --set values; into $work/$3; returns hati's exit code (124: cut at $limit s)
run() {
  local prm=$1 sets=$2 tag=$3
  shift 3
  local args=()
  while IFS= read -r s; do args+=(--set "$s"); done < "$sets"
  for s in "$@"; do args+=(--set "$s"); done
  timeout "$limit" "$build/hati" "$prm" "${args[@]}" \
    --set "Output/Output directory=$work/$tag" > "$work/$tag.log" 2>&1
}

# dt_crit (s) of a refused run: its message prints "dt_crit = ... = X s"
dt_crit() {
  sed -n 's/.*dt_crit = [^=]*= \([0-9.eE+-]*\) s.*/\1/p' "$work/$1.log" | head -1
}

sizes="20x4x4 36x7x7 56x10x10"
prm=parameter_files/beam_solid_prism.prm
echo
echo "Newmark, 5 steps (DT = 1e-4 s); factorisation: summary.json factorization_time (M_eff"
echo "to Trilinos, symbolic and numeric factorisation); set-up: the terminal's Newmark set-up"
echo "(forming M_eff, its factorisation and the consistent mass's for A_0)"
printf "%10s %8s %8s %18s %11s %12s %14s\n" "cells" "DoFs" "solver" "factorisation (s)" "set-up (s)" "step (ms)" "us/DoF/step"
for size in $sizes; do
  solid_model ${size//x/ } > "$work/sets"
  for solver in KLU MUMPS; do
    tag="newmark_${size}_$solver"
    if [ "$solver" = KLU ] && [ "$size" = 56x10x10 ] && [ "$all" != all ]; then
      printf "%10s %8s %8s %18s\n" "$size" "-" "$solver" "skipped (give 'all')"
      continue
    fi
    if run $prm "$work/sets" "$tag" "Time integration/Method=Newmark" \
      "Time integration/Time step=1e-4" "Time integration/End time=5e-4" \
      "Time integration/Newmark/Linear solver=$solver"; then
      /usr/bin/python3 - "$work/$tag/summary.json" "$size" "$solver" "$work/$tag.log" <<'PY'
import json, re, sys
s = json.load(open(sys.argv[1]))
step = s["stepping_wall_time"] / max(1, s["n_steps"])
m = re.search(r"setup \(assembly, factorisation\) *\| *1 *\| *([0-9.e+-]+)s", open(sys.argv[4]).read())
print("%10s %8d %8s %18.4g %11s %12.4g %14.4g" % (sys.argv[2], s["n_dofs"], sys.argv[3],
      s["factorization_time"], m.group(1) if m else "?", 1e3 * step, 1e6 * step / s["n_dofs"]))
PY
    elif [ $? -eq 124 ]; then
      printf "%10s %8s %8s %18s\n" "$size" "-" "$solver" "cut at ${limit} s"
    else
      cat "$work/$tag.log"
      exit 1
    fi
  done
done

echo
echo "CD-Lagrange, 200 steps at 0.9 dt_crit: the solid against a beam-only frame"
printf "%16s %8s %12s %12s %14s\n" "model" "DoFs" "dt (s)" "step (ms)" "ns/DoF/step"
explicit() { # tag, parameter file, --set file
  local tag=$1 prm=$2 sets=$3
  run "$prm" "$sets" "${tag}_probe" "Time integration/Method=CD-Lagrange" \
    "Time integration/Time step=1" "Time integration/End time=1" || true
  local dt
  dt=$(dt_crit "${tag}_probe")
  [ -n "$dt" ] || { cat "$work/${tag}_probe.log"; exit 1; }
  read -r dt T < <(/usr/bin/python3 -c "dt = 0.9 * $dt; print(dt, 200.5 * dt)")
  run "$prm" "$sets" "$tag" "Time integration/Method=CD-Lagrange" \
    "Time integration/Time step=$dt" "Time integration/End time=$T" ||
    { cat "$work/$tag.log"; exit 1; }
  /usr/bin/python3 - "$work/$tag/summary.json" "$tag" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print("%16s %8d %12.4g %12.4g %14.4g" % (sys.argv[2], s["n_dofs"], s["dt"],
      1e3 * s["stepping_wall_time"] / s["n_steps"], s["ns_per_dof_per_step"]))
PY
}
for size in $sizes; do
  solid_model ${size//x/ } > "$work/sets"
  explicit "solid$size" $prm "$work/sets"
done
# the cost of the tie's bilateral rows: the 5e4 solid with T0 clamped, untied
solid_model 36 7 7 > "$work/sets"
printf '%s\n' "Model/Frame/Ties=" "Model/Frame/Supports=T0: clamped" >> "$work/sets"
explicit "solid36x7x7-untied" $prm "$work/sets"
# the portal frame with about 450 DoFs per unit of scale (bench/implicit_step.sh)
for scale in 22 110 330; do
  c=$((8 * scale)); b=$((10 * scale)); x=$((8 * scale))
  echo "Model/Frame/Members=colA: A0, A1, column, steel, $c; colB: B0, B1, column, steel, $c; colC: C0, C1, column, steel, $c; colD: D0, D1, column, steel, $c; beamAB: A1, B1, beam, steel, $b; beamCD: C1, D1, beam, steel, $b; crossAC: A1, C1, beam, steel, $x; crossBD: B1, D1, beam, steel, $x" > "$work/sets"
  printf '%s\n' "Output/Output interval=0" "Output/History interval=1" >> "$work/sets"
  explicit "frame$scale" parameter_files/portal_frame_dynamic.prm "$work/sets"
done
