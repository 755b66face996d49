#!/usr/bin/python3
"""The crane on runway springs (issue #55, Model/Bridge crane/Runway =
springs): each crane wheel runs on a node runway_<i> of mass Runway mass per
wheel, held to the ground by the runway's vertical, lateral and
longitudinal stiffness; summary.json runway_reaction.<wheel>.<direction>
gives the spring forces (max, min).

1. The crane of bridge_crane_hati.prm at rest on springs (no record):
   - the static wheel loads are those of the rigid runway (1e-9: four equal
     springs under the statically indeterminate crane change nothing);
   - every vertical spring force, at every history row, is the wheel's
     load plus the runway mass's own weight m_r g (1e-9), the lateral and
     longitudinal ones zero (below 1e-6 of it);
   - the explicit critical step is that of the rigid runway (the springs
     are slower than the crane's stiffest element).
2. Modal: a stiff crane (E = 1e13 Pa, the hoist rigid, the trolley at mid
   span, so that the wheels carry equal loads and the bounce does not
   rock) on soft vertical springs (k = 1e6 N/m per wheel; the lateral and
   longitudinal ones stiff): its vertical mode is the bounce of the crane
   and the runway masses on the four springs, f_b = sqrt(4 k / M) / 2 pi,
   in series with the crane's own vertical mode f_r on a rigid runway:
   1 / f^2 = 1 / f_b^2 + 1 / f_r^2 (1 %; measured 0.08 %).
3. Under the first 0.5 s of the Rinaldi record (HATI): the run completes,
   runway_reaction has the four crane wheels and their vertical force
   stays about the static one (within 20 %).
"""
import csv
import os

import numpy as np

from hati_test import Context, read_summary

ctx = Context()
g, m_r = 9.81, 500.0
wheels = ["crane_wheel_%d" % k for k in range(1, 5)]
quiet = ["Loading/Accelerogram X=", "Loading/Accelerogram Z=", "Output/Output interval=0",
         "Time integration/End time=0.05"]

# --- 1. at rest ---------------------------------------------------------------
rigid = read_summary(ctx.run(ctx.prm("bridge_crane_hati.prm"), "rest_rigid", quiet)[0])
springs = read_summary(ctx.run(ctx.prm("bridge_crane_hati.prm"), "rest_springs",
                               quiet + ["Model/Bridge crane/Runway=springs"])[0])
for w in rigid["static_wheel_loads"]:
    ctx.check("%s static load on springs = on the rigid runway (N)" % w,
              springs["static_wheel_loads"][w], rigid["static_wheel_loads"][w], rel=1e-9)
for w in wheels:
    W = springs["static_wheel_loads"][w] + m_r * g
    r = springs["runway_reaction"][w]
    ctx.check("%s vertical spring force max = wheel load + m_r g (N)" % w,
              r["vertical"]["max"], W, rel=1e-9)
    ctx.check("%s vertical spring force min = wheel load + m_r g (N)" % w,
              r["vertical"]["min"], W, rel=1e-9)
    for d in ("lateral", "longitudinal"):
        ctx.check("%s %s spring force at rest (N)" % (w, d),
                  max(abs(r[d]["max"]), abs(r[d]["min"])), 0.0, abs_tol=1e-6 * W)
ctx.check("critical step on springs = on the rigid runway (s)", springs["dt_crit"],
          rigid["dt_crit"], rel=1e-9)
ctx.check_true("no runway_reaction on the rigid runway", "runway_reaction" not in rigid)

# --- 2. modal: the bounce on soft springs -----------------------------------
stiff = ["Analysis/Type=modal", "Analysis/Number of modes=6", "Loading/Accelerogram X=",
         "Loading/Accelerogram Z=", "Model/Bridge crane/Hoist=rigid",
         "Model/Bridge crane/Trolley position=0.5",
         "Model/Bridge crane/Material=1e13, 0.3, 7850"]
k_v = 1e6
soft = ["Model/Bridge crane/Runway=springs",
        "Model/Bridge crane/Runway vertical stiffness=%g" % k_v,
        "Model/Bridge crane/Runway lateral stiffness=1e12",
        "Model/Bridge crane/Runway longitudinal stiffness=1e12"]


def vertical_mode(out):
    rows = list(csv.DictReader(open(os.path.join(out, "modes.csv"))))
    best = max(rows, key=lambda r: float(r["effective_mass_ratio_z"]))
    return float(best["frequency"])


out_r, _ = ctx.run(ctx.prm("bridge_crane_hati.prm"), "modal_rigid", stiff)
out_s, _ = ctx.run(ctx.prm("bridge_crane_hati.prm"), "modal_springs", stiff + soft)
s = read_summary(out_r)
M = float(s["model"].split("mass ")[-1].split(" kg")[0]) + 4 * m_r
f_r, f = vertical_mode(out_r), vertical_mode(out_s)
f_b = np.sqrt(4 * k_v / M) / (2 * np.pi)
ctx.check("vertical mode on springs = (1/f_b^2 + 1/f_r^2)^-1/2 (Hz)", f,
          1 / np.sqrt(1 / f_b**2 + 1 / f_r**2), rel=0.01)

# --- 3. under the record -------------------------------------------------------
records = os.path.join(ctx.source, "data", "accelerograms")
out, _ = ctx.run(ctx.prm("bridge_crane_hati.prm"), "record",
                 ["Output/Output interval=0", "Time integration/End time=0.5",
                  "Model/Bridge crane/Runway=springs",
                  "Loading/Accelerogram X=" + os.path.join(records, "Rinaldi228.AT2"),
                  "Loading/Accelerogram Z=" + os.path.join(records, "RinaldiUP.AT2")])
s = read_summary(out)
ctx.check_true("record: runway_reaction of the four crane wheels",
               sorted(s["runway_reaction"]) == wheels, str(sorted(s["runway_reaction"])))
for w in wheels:
    W = s["static_wheel_loads"][w] + m_r * g
    ctx.check("%s record: largest vertical spring force about the static one (N)" % w,
              s["runway_reaction"][w]["vertical"]["max"], W, rel=0.2)
ctx.finish()
