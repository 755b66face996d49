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
4. The two-mass impact of a wheel on its runway node, as the crane's wheels
   meet theirs (a node-to-node contact onto a node on the vertical runway
   stiffness, 2e8 N/m): a rigid "wheel" body of mass m_w (two 2000 kg
   nodes and their member, translating along Z only) dropped 50 mm onto a
   "runway" body of mass m_r (two 500 kg nodes) on two springs, the
   runway's own weight balanced by nodal loads (so that it starts at rest
   at u = 0). The plastic impact (A5) keeps the momentum, v' = m_w v /
   (m_w + m_r) with v = sqrt(2 g h); the pair then oscillates on K = 2 k
   about the static offset d = m_w g / K: the peak spring force is
   K (d + sqrt(d^2 + v'^2 M / K)), M = m_w + m_r, within 2 % (measured
   7e-6 at dt = 2e-6 s).
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
# --- 4. the two-mass impact on the runway stiffness -----------------------------
k, h = 2e8, 0.05
m_member = 7850 * 0.01 * 1.0  # the 0.1 x 0.1 x 1 m member of each body
m_w, m_rw = 2 * 2000 + m_member, 2 * 500 + m_member
PRM = """subsection Analysis
  set Type          = transient
  set Initial state = given
end
subsection Model
  set Type = frame
  subsection Frame
    set Nodes     = a: 0, 0, %(h)g; b: 1, 0, %(h)g; ra: 0, 0, 0; rb: 1, 0, 0
    set Materials = steel: 2.1e11, 0.3, 7850
    set Sections  = sq: rectangle, 0.1, 0.1
    set Members   = wheel: a, b, sq, steel, 1; runway: ra, rb, sq, steel, 1
    set Point masses = a: 2000; b: 2000; ra: 500; rb: 500
    set Supports  = a: fixed, fixed, free, fixed, fixed, fixed; \
                    b: fixed, fixed, free, fixed, fixed, fixed; \
                    ra: fixed, fixed, %(k)g, fixed, fixed, fixed; \
                    rb: fixed, fixed, %(k)g, fixed, fixed, fixed
    set Contacts  = la: a, ra, 0, 0, 1, %(h)g; lb: b, rb, 0, 0, 1, %(h)g
    set Nodal loads = ra: 0, 0, %(w).17g; rb: 0, 0, %(w).17g
    set Monitor nodes = a, ra
  end
end
subsection Loading
  set Gravity = 0, 0, -%(g)g
end
subsection Contact
  set Restitution coefficient = 0
end
subsection Time integration
  set Method    = CD-Lagrange
  set Time step = 2e-6
  set End time  = 0.15
end
subsection Output
  set History interval = 0
end
""" % dict(h=h, k=k, g=g, w=0.5 * m_rw * g)
path = ctx.work + "/two_masses.prm"
open(path, "w").write(PRM)
out, _ = ctx.run(path, "two_masses")
u = np.array([float(r["ra.uz"]) for r in csv.DictReader(open(out + "/history.csv"))])
K, M = 2 * k, m_w + m_rw
v1 = m_w * np.sqrt(2 * g * h) / M
d = m_w * g / K
ctx.check("two masses: peak spring force K (d + sqrt(d^2 + v'^2 M / K)) (N)", (-K * u).max(),
          K * (d + np.sqrt(d**2 + v1**2 * M / K)), rel=0.02)
ctx.finish()
