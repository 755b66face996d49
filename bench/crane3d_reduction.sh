#!/usr/bin/env bash
# Accuracy of the Craig-Bampton reduced implicit part against the cut-off
# (issue #27; doc/theory.md 12.1-12.2) on the 3D crane of
# parameter_files/bridge_crane_3d.prm at a coarse mesh (default 0.55 m plate
# elements; tied wheels and a rigid hoist: at 0.55 m the braked crane's
# static state is refused), under Rinaldi X + Z from t = 0 to the end time
# (default 0.2 s): HATI with the unreduced implicit part is the reference;
# for each cut-off (default 50 100 150 300 Hz) the kept modes, the largest
# |reduced - unreduced| over the run divided by the peak of the reference,
# for the monitors' displacements (girder mid-spans, trolley and crane
# wheels, hoist; the worst component is printed) and the wheel-contact
# forces, the set-up of the reduction and the stepping time.
# Usage: bench/crane3d_reduction.sh [build directory] [size, m] [end time, s] [cut-offs]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
size=${2:-0.55}
end=${3:-0.2}
cutoffs=${4:-50 100 150 300}
[ -x "$build/hati" ] || ./scripts/setup.sh hati
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prm=parameter_files/bridge_crane_3d.prm
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
common=(--set "Model/Bridge crane/Girder element size=$size"
  --set "Model/Bridge crane/Travel=tied" --set "Model/Bridge crane/Hoist=rigid"
  --set "Time integration/End time=$end" --set "Output/Output interval=0"
  --set "Output/History interval=0.001")
"$build/hati" $prm "${common[@]}" --set "Model/Decomposition/Implicit reduction=none" \
  --set "Output/Output directory=$work/none" > "$work/none.log" 2>&1 ||
  { tail -3 "$work/none.log"; exit 1; }
for f in $cutoffs; do
  "$build/hati" $prm "${common[@]}" --set "Model/Decomposition/Implicit reduction=Craig-Bampton" \
    --set "Model/Decomposition/Reduction cutoff frequency=$f" \
    --set "Output/Output directory=$work/cb$f" > "$work/cb$f.log" 2>&1 ||
    { tail -3 "$work/cb$f.log"; exit 1; }
done
/usr/bin/python3 - "$work" $cutoffs <<'PY'
import csv, json, sys
work, cutoffs = sys.argv[1], sys.argv[2:]

def history(d):
    rows = list(csv.reader(open(d + "/history.csv")))
    return rows[0], [[float(x) for x in r] for r in rows[1:]]

def forces(d):
    f = {}
    for r in csv.DictReader(open(d + "/contacts.csv")):
        f.setdefault(r["contact"], []).append(float(r["force"]))
    return f

names, ref = history(work + "/none")
fref = forces(work + "/none")
sref = json.load(open(work + "/none/summary.json"))
cols = [i for i, n in enumerate(names) if "." in n and n.split(".")[1] in ("ux", "uy", "uz")]
print("unreduced: %d implicit DoFs, stepping %.1f s" % (sref["n_dofs_implicit"],
                                                     sref["stepping_wall_time"]))
print("%8s %6s %8s %-28s %9s %-18s %9s %9s %9s %9s" % (
    "cut-off", "modes", "f_max", "worst displacement", "err/peak", "worst wheel force",
    "err/peak", "travel/lat", "set-up", "stepping"))
for f in cutoffs:
    d = work + "/cb" + f
    _, h = history(d)
    s = json.load(open(d + "/summary.json"))
    worst = (0.0, "")
    for i in cols:
        peak = max(abs(r[i]) for r in ref)
        if peak == 0.0:
            continue
        e = max(abs(a[i] - b[i]) for a, b in zip(h, ref)) / peak
        worst = max(worst, (e, names[i]))
    fc = forces(d)
    # the wheels' vertical contacts (their travel and lateral flange rows
    # carry small, noisy forces: the worst of those in the last column)
    worst_f, worst_o = (0.0, ""), (0.0, "")
    for c, v in fref.items():
        peak = max(abs(x) for x in v)
        if peak > 0.0 and c in fc and len(fc[c]) == len(v):
            e = (max(abs(a - b) for a, b in zip(fc[c], v)) / peak, c)
            if c.endswith(("_travel", "_lateral")):
                worst_o = max(worst_o, e)
            else:
                worst_f = max(worst_f, e)
    r = s["reduction"]
    print("%8s %6d %8.1f %-28s %9.2e %-18s %9.2e %9.2e %8.1fs %8.1fs" % (
        f, r["modes"], r["highest_kept_frequency"], worst[1], worst[0], worst_f[1], worst_f[0],
        worst_o[0], r["set_up_time"], s["stepping_wall_time"]))
PY
