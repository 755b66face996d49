#!/usr/bin/env bash
# Speed-up of HATI over the fully explicit run on the default bridge crane
# (parameter_files/bridge_crane_hati.prm and bridge_crane_full_explicit.prm:
# Northridge Rinaldi 228 along X and UP along Z, static start on the
# wheels, 2 % Rayleigh damping), END_TIME seconds of earthquake (default 10).
# Prints the wall time of both runs and the speed-up, where the time of the
# coupled run goes (explicit micro steps, implicit steps, interface: from
# summary.json), and, per wheel, the contact-loss episodes of both runs with
# the largest differences of their start and end times, the time out of
# contact and the peak impulse (scripts/compare_runs.py, episodes at the
# step resolution from contact_episodes.csv). It also draws the paper's
# Fig. 9 (tw1.uz, full explicit vs HATI, with a zoom) as crane_fig9.png.
# Goal (issue #6): speed-up >= 5 (aim 10), contact-loss times within 2 ms,
# peak forces within 5 %.
# On a shared virtual machine the wall times of identical runs vary by 10-20 %
# with the load of the host: REPEAT=N runs the pair N times back to back and
# prints the speed-up of every pair and their median (the pairs share the
# state of the machine better than runs minutes apart).
# Usage: [REPEAT=N] bench/crane_speedup.sh [END_TIME [build directory]]
set -euo pipefail
cd "$(dirname "$0")/.."
end_time=${1:-10}
build=${2:-build}
repeat=${REPEAT:-1}
[ -x "$build/hati" ] || ./scripts/setup.sh hati
out=output/bench_crane
mkdir -p "$out"
pairs=""
for i in $(seq "$repeat"); do
  for run in full_explicit hati; do
    echo "== bridge_crane_$run.prm, $end_time s (run $i of $repeat)"
    "$build/hati" "parameter_files/bridge_crane_$run.prm" \
      --set "Time integration/End time=$end_time" \
      --set "Output/Output interval=0" \
      --set "Output/Output directory=$out/$run" | grep -E "dt_crit|HATI|done|steps of"
  done
  pairs="$pairs $(/usr/bin/python3 -c 'import json, sys
e, h = (json.load(open(sys.argv[1] + "/" + r + "/summary.json"))["stepping_wall_time"]
        for r in ("full_explicit", "hati"))
print("%.3f:%.3f" % (e, h))' "$out")"
done
if [ "$repeat" -gt 1 ]; then
  /usr/bin/python3 - $pairs <<'PY'
import statistics, sys
pairs = [tuple(map(float, p.split(":"))) for p in sys.argv[1:]]
print("\npair  full explicit (s)  HATI (s)  speed-up")
for i, (e, h) in enumerate(pairs, 1):
    print("%4d  %17.2f  %8.2f  %8.2f" % (i, e, h, e / h))
ratios = [e / h for e, h in pairs]
print("speed-up over %d pairs: median %.2f, range %.2f-%.2f" % (
    len(pairs), statistics.median(ratios), min(ratios), max(ratios)))
PY
fi
/usr/bin/python3 - "$out" <<'PY'
import json, os, sys
out = sys.argv[1]
s = {r: json.load(open(os.path.join(out, r, "summary.json"))) for r in ("full_explicit", "hati")}
e, h = s["full_explicit"], s["hati"]
print("\n%-16s %10s %12s %12s %10s" % ("run", "dt (s)", "DoFs", "stepping (s)", "speed-up"))
print("%-16s %10.3g %12d %12.2f %10s" % ("full explicit", e["dt"], e["n_dofs"],
                                          e["stepping_wall_time"], "1"))
print("%-16s %10.3g %5d E+%4d I %12.2f %10.2f" % (
    "HATI m=%d" % h["time_step_ratio"], h["micro_dt"], h["n_dofs_explicit"],
    h["n_dofs_implicit"], h["stepping_wall_time"],
    e["stepping_wall_time"] / h["stepping_wall_time"]))
total = h["wall_time_explicit"] + h["wall_time_implicit"] + h["wall_time_interface"]
print("HATI time: explicit micro steps %.2f s (%.0f %%), implicit steps %.2f s (%.0f %%), "
      "interface %.2f s (%.0f %%); redone macro steps %d of %d, ramp active sets %d"
      % (h["wall_time_explicit"], 100 * h["wall_time_explicit"] / total,
         h["wall_time_implicit"], 100 * h["wall_time_implicit"] / total,
         h["wall_time_interface"], 100 * h["wall_time_interface"] / total,
         h["redone_macro_steps"], h["n_steps"], h["ramp_patterns"]))
print("\n%-16s %7s %4s %10s %10s %10s %10s %12s %12s" % (
    "wheel", "impacts", "", "uplift (s)", "", "peak imp.", "(N s)", "peak mean", "force (N)"))
worst_imp, worst_mean = 0.0, 0.0
for name, we in e["wheels"].items():
    wh = h["wheels"][name]
    d = abs(wh["peak_impulse"] - we["peak_impulse"]) / we["peak_impulse"] if we["peak_impulse"] else 0
    worst_imp = max(worst_imp, d)
    dm = (abs(wh["peak_mean_force"] - we["peak_mean_force"]) / we["peak_mean_force"]
          if we.get("peak_mean_force") else 0)
    worst_mean = max(worst_mean, dm)
    print("%-16s %7d %4d %10.5f %10.5f %10.5g %10.5g %12.6g %12.6g" % (
        name, we["n_impacts"], wh["n_impacts"], we["uplift_time"], wh["uplift_time"],
        we["peak_impulse"], wh["peak_impulse"], we.get("peak_mean_force", 0),
        wh.get("peak_mean_force", 0)))
print("largest difference of the wheels' peak impulse (one step): %.2f %%" % (100 * worst_imp))
print("largest difference of the wheels' peak mean force over %g s: %.2f %%"
      % (h.get("contact_force_window", 0.0), 100 * worst_mean))

def episodes(run):
    result = {}
    with open(os.path.join(out, run, "contact_episodes.csv")) as f:
        next(f)
        for line in f:
            name, start, end, _ = line.strip().split(",")
            result.setdefault(name, []).append((float(start), float(end) if end else None))
    return result
ea, eb = episodes("full_explicit"), episodes("hati")
worst, count, mismatch = 0.0, 0, []
for name in e["wheels"]:
    a, b = ea.get(name, []), eb.get(name, [])
    if len(a) != len(b):
        mismatch.append(name)
    for (s0, e0), (s1, e1) in zip(a, b):
        count += 1
        worst = max(worst, abs(s1 - s0))
        if e0 is not None and e1 is not None:
            worst = max(worst, abs(e1 - e0))
print("wheels' contact-loss episodes: %d matched, largest difference of start/end times "
      "%.3g ms%s" % (count, 1e3 * worst,
                     "; different episode counts: " + ", ".join(mismatch) if mismatch else ""))
PY
/usr/bin/python3 scripts/compare_runs.py "$out/full_explicit" "$out/hati" --monitor tw1.uz \
  --png "$out/crane_fig9.png" | tail -1
