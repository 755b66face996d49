#!/usr/bin/env bash
# The 3D crane under the whole Rinaldi record with the Craig-Bampton reduced
# implicit part (issue #27; doc/theory.md 12.1-12.2):
# parameter_files/bridge_crane_3d.prm (0.4 m plates, HATI m = 5, DT = 2e-4
# s, reduction at 150 Hz) with End time = the record's 19.9 s (or the first
# argument's end time). Prints the wall time of the run and its parts from
# summary.json: the reduction's set-up (constraint modes, fixed-interface
# modes, reduced matrices), the other set-up (mesh, static state, HATI's
# factorisations and ramp responses), the stepping (explicit micro steps,
# reduced implicit steps, interface), the output inside the loop (history
# rows, section forces, stress envelope, VTU: each expands the reduced
# state, u = T q), and the peak memory (maximum resident set size). The
# unreduced run's cost is extrapolated from its stepping over 0.02 s (the
# second part; skip it with UNREDUCED=0). Goal (issue #27): 5 minutes for
# the whole record on this 2-core machine.
# Usage: bench/crane3d_record.sh [build directory] [end time, s]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
end=${2:-19.9}
[ -x "$build/hati" ] || ./scripts/setup.sh hati
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prm=parameter_files/bridge_crane_3d.prm
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"

run() { # tag, --set values...: the run's wall time and peak memory
  local tag=$1
  shift
  local args=()
  for s in "$@"; do args+=(--set "$s"); done
  /usr/bin/python3 - "$work/$tag" "$build/hati" "$prm" "${args[@]}" \
    --set "Output/Output directory=$work/$tag" <<'PY'
import resource, subprocess, sys, time
out, cmd = sys.argv[1], sys.argv[2:]
start = time.time()
with open(out + ".log", "w") as log:
    code = subprocess.call(cmd, stdout=log, stderr=subprocess.STDOUT)
peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024.0 ** 2
with open(out + ".time", "w") as f:
    f.write("%.1f %.2f\n" % (time.time() - start, peak))
sys.exit(code)
PY
}

run reduced "Time integration/End time=$end" || { tail -3 "$work/reduced.log"; exit 1; }
/usr/bin/python3 - "$work/reduced" "$end" <<'PY'
import json, sys
out, end = sys.argv[1], float(sys.argv[2])
s = json.load(open(out + "/summary.json"))
wall, peak = map(float, open(out + ".time").read().split())
r = s["reduction"]
# summary.json's wall_time is the time loop's: the rest of the process is set-up
setup = wall - s["stepping_wall_time"] - s["wall_time_output"]
print("3D crane, %d DoFs (%d implicit, reduced to %d boundary DoFs + %d modes up to %.1f Hz, "
      "cut-off %g Hz), %g s of record" % (s["n_dofs"], r["unreduced_dofs"], r["boundary_dofs"],
                                            r["modes"], r["highest_kept_frequency"],
                                            r["cutoff_frequency"], s["end_time"]))
rows = [("wall time of the run (process)", wall),
        ("  reduction set-up", r["set_up_time"]),
        ("    constraint modes", r["set_up_time_constraint_modes"]),
        ("    fixed-interface modes", r["set_up_time_modes"]),
        ("    reduced matrices", r["set_up_time_reduced_matrices"]),
        ("  other set-up (mesh, static state, HATI set-up)", setup - r["set_up_time"]),
        ("  stepping", s["stepping_wall_time"]),
        ("    explicit micro steps", s["wall_time_explicit"]),
        ("    implicit (reduced) steps", s["wall_time_implicit"]),
        ("    interface", s["wall_time_interface"]),
        ("  output in the loop (expansion, rows, VTU)", s["wall_time_output"])]
for name, t in rows:
    print("%-50s %9.1f s" % (name, t))
print("%-50s %9.2f GiB" % ("peak memory (max RSS)", peak))
print("%-50s %9.3f s per s of record" % ("stepping", s["stepping_wall_time"] / s["end_time"]))
PY
[ "${UNREDUCED:-1}" = 0 ] && exit 0
run unreduced "Time integration/End time=0.02" "Model/Decomposition/Implicit reduction=none" ||
  { tail -3 "$work/unreduced.log"; exit 1; }
/usr/bin/python3 - "$work/unreduced" "$end" <<'PY'
import json, sys
out, end = sys.argv[1], float(sys.argv[2])
s = json.load(open(out + "/summary.json"))
wall = float(open(out + ".time").read().split()[0])
rate = (s["stepping_wall_time"] + s["wall_time_output"]) / s["end_time"]
setup = wall - s["stepping_wall_time"] - s["wall_time_output"]
print("unreduced HATI: set-up %.1f s, %.2f s per s of record (stepping and output over "
      "%g s): %g s of record extrapolated to %.0f s (%.1f h)" % (
          setup, rate, s["end_time"], end, setup + rate * end, (setup + rate * end) / 3600))
PY
