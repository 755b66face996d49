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
/usr/bin/python3 - "$work/hati" "$work/explicit" <<'PY'
import csv, json, sys
import numpy as np


def history(d):
    rows = list(csv.reader(open(d + "/history.csv")))
    return rows[0], np.array([[float(x) for x in r] for r in rows[1:] if len(r) == len(rows[0])])


def first_losses(d):
    first = {}
    for r in csv.DictReader(open(d + "/contact_episodes.csv")):
        first.setdefault(r["contact"], float(r["start"]))
    return first


ha, A = history(sys.argv[1])
hb, B = history(sys.argv[2])
idx = [int(np.argmin(abs(B[:, 0] - t))) for t in A[:, 0]]
keep = [i for i, j in enumerate(idx) if abs(B[j, 0] - A[i, 0]) < 1e-9]
A, B = A[keep], B[[idx[i] for i in keep]]
print("rows compared: %d, t = %.4f to %.4f s" % (len(A), A[0, 0], A[-1, 0]))
dA, dB = A - A[0], B - B[0]
print("%-20s %14s %14s %8s" % ("monitor", "peak |du| (m)", "max diff (m)", "% peak"))
for m in sorted({n.rsplit(".", 1)[0] for n in ha[1:] if n.endswith(".ux")}):
    cols = [ha.index(m + "." + c) for c in ("ux", "uy", "uz")]
    peak = np.max(np.linalg.norm(dB[:, cols], axis=1))
    diff = np.max(np.linalg.norm(dA[:, cols] - dB[:, cols], axis=1))
    print("%-20s %14.4e %14.4e %8.3f" % (m, peak, diff, 100 * diff / peak))
lh, le = first_losses(sys.argv[1]), first_losses(sys.argv[2])
print("%-26s %12s %12s %10s" % ("first loss of contact", "HATI (s)", "explicit (s)", "diff (ms)"))
for c in sorted(set(lh) | set(le)):
    h, e = lh.get(c), le.get(c)
    print("%-26s %12s %12s %10s" % (c, "%.6f" % h if h else "-", "%.6f" % e if e else "-",
                                    "%.3f" % (1e3 * (h - e)) if h and e else "-"))
s = [json.load(open(d + "/summary.json")) for d in sys.argv[1:3]]
for name, x in zip(("HATI", "explicit"), s):
    print("%-9s n_dofs %d, steps %d, set-up %.1f s, stepping %.1f s, energy balance %.2e"
          % (name, x["n_dofs"], x["n_steps"], x["setup_wall_time"], x["stepping_wall_time"],
             x["energy_balance_relative"]))
print("speed-up (stepping): %.0f x; with set-up: %.0f x" % (
    s[1]["stepping_wall_time"] / s[0]["stepping_wall_time"],
    (s[1]["stepping_wall_time"] + s[1]["setup_wall_time"]) /
    (s[0]["stepping_wall_time"] + s[0]["setup_wall_time"])))
PY
