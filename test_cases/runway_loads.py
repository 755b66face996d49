#!/usr/bin/python3
"""The loads a crane hands to its runway (issue #54): per crane wheel
summary.json wheels.<wheel>.runway_load.vertical_max, .vertical_min,
.lateral_max, .longitudinal_max (each the largest, or smallest, mean over
Output/Contact force window) and runway_loads.csv with the same table.

1. The crane of bridge_crane_hati.prm at rest on its static state, without
   record: every window's mean is the static wheel load, so vertical_max =
   vertical_min = static_wheel_loads (1e-9 relative), no flange or
   friction load (below 1e-6 of the wheel load), and runway_loads.csv
   holds the summary's numbers.
2. The braked crane (all four crane wheels braked, rigid hoist) under a
   horizontal base acceleration along the runway (X) rising smoothly to
   a0 = 0.5 m/s^2 in 2 s (a half cosine: its residual vibration is
   pi^2 / (omega T)^2 of the static response, below 0.3 % for the crane's
   longitudinal modes above 5 Hz) and held for 1 s, below the friction
   limit mu g = 1.47 m/s^2: once settled the wheels' friction carries the
   crane's whole inertia, so the longitudinal loads sum to M a0 (1 %), M
   the mass on the crane wheels, sum(static wheel loads) / g.
"""
import csv

import numpy as np

from hati_test import Context, read_summary

ctx = Context()
g = 9.81
wheels = ["crane_wheel_%d" % k for k in range(1, 5)]
base = ["Loading/Accelerogram X=", "Loading/Accelerogram Z=", "Output/Output interval=0",
        "Output/History interval=0.01", "Output/Section force interval=0.01"]

# --- 1. at rest -------------------------------------------------------------
out, _ = ctx.run(ctx.prm("bridge_crane_hati.prm"), "rest",
                 base + ["Time integration/End time=0.2"])
s = read_summary(out)
rows = {r["wheel"]: r for r in csv.DictReader(open(out + "/runway_loads.csv"))}
ctx.check_true("runway_loads.csv has the four crane wheels", sorted(rows) == wheels,
               str(sorted(rows)))
for w in wheels:
    W = s["static_wheel_loads"][w]
    load = s["wheels"][w]["runway_load"]
    ctx.check("%s vertical_max = static wheel load (N)" % w, load["vertical_max"], W, rel=1e-9)
    ctx.check("%s vertical_min = static wheel load (N)" % w, load["vertical_min"], W, rel=1e-9)
    ctx.check("%s lateral_max at rest (N)" % w, load["lateral_max"], 0.0, abs_tol=1e-6 * W)
    ctx.check("%s longitudinal_max at rest (N)" % w, load["longitudinal_max"], 0.0,
              abs_tol=1e-6 * W)
    for key in ("vertical_max", "vertical_min", "lateral_max", "longitudinal_max"):
        ctx.check("%s runway_loads.csv %s = summary.json (N)" % (w, key),
                  float(rows[w][key]), load[key], rel=1e-9, abs_tol=1e-12)

# --- 2. braked, under a settled horizontal acceleration ----------------------
a0, ramp = 0.5, 2.0
t = np.arange(0.0, 3.0 + 1e-9, 0.01)
a = np.where(t < ramp, 0.5 * a0 * (1 - np.cos(np.pi * t / ramp)), a0)
record = ctx.work + "/ramp.txt"
np.savetxt(record, np.column_stack([t, a]), fmt="%.17g")
out, _ = ctx.run(ctx.prm("bridge_crane_hati.prm"), "braked",
                 base[2:] + ["Loading/Accelerogram X=" + record, "Loading/Accelerogram Z=",
                             "Loading/Accelerogram units=m/s^2",
                             "Model/Bridge crane/Hoist=rigid",
                             "Model/Bridge crane/Braked crane wheels=all",
                             "Time integration/End time=3"])
s = read_summary(out)
M = sum(s["static_wheel_loads"][w] for w in wheels) / g
total = sum(s["wheels"][w]["runway_load"]["longitudinal_max"] for w in wheels)
ctx.check("sum of longitudinal_max = M a0 (N)", total, M * a0, rel=0.01)
ctx.check_true("no wheel slips (slip distance < 1e-6 m)",
               all(s["wheels"][w]["slip_distance"] < 1e-6 for w in wheels),
               str([s["wheels"][w]["slip_distance"] for w in wheels]))
ctx.finish()
