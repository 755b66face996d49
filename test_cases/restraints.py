#!/usr/bin/python3
"""Seismic restraints against uplift (issue #55, Model/Bridge crane/Uplift
restraints): a one-sided contact <wheel>_restraint whose normal points down
and whose gap is the Restraint clearance.

1. The mechanism, on a rigid body: two nodes 1 m apart, each 100 kg plus
   half of the stiff member between them, held in every DoF but uz (a
   pure translation, no strain), resting on two ground contacts with two
   restraints ("lids", normal -z, gap h = 10 mm) above them; a base pulse
   of -2 g along Z for T = 0.04 s lifts it (net g upward: v0 = g T, z0 =
   g T^2 / 2; CD-Lagrange with dt = 1e-6 s):
   - with the lids it stops at h: the ground contacts' max_uplift is h
     within 1e-6 m (max_penetration below 1e-6 m: v dt = 3.3e-7 m);
   - the lid's impulse (plastic) is the momentum its node carried: its
     lumped mass times the velocity of the step before less g dt (the free
     velocity it cancels, A5), 1e-6 relative, and the analytical m
     sqrt(v0^2 - 2 g (h - z0)) within 1e-4 (the step's g dt / v = 3e-5);
   - without the lids it flies to the analytical z0 + v0^2 / (2 g) (1e-4).
2. The bridge crane of bridge_crane_hati.prm with Uplift restraints = both:
   - at rest the restraints are open: the static wheel loads are those of
     the unrestrained crane (1e-12) and no restraint has an impact;
   - under a vertical base pulse of -3 g for 50 ms that lifts the
     unrestrained crane wheels by up to 49 mm, every restrained wheel's
     max_uplift is the Restraint clearance within the run's
     max_penetration (the v dt of its impact), each of the eight
     restraints has impacts, and the unrestrained run lifts crane_wheel_3
     above three times the clearance.
"""
import csv
import os

import numpy as np

from hati_test import Context, read_summary

ctx = Context()
g, a0, T, h = 9.81, 2 * 9.81, 0.04, 0.01

# --- 1. a rigid body stopped by its restraints --------------------------------
pulse = ctx.work + "/pulse.txt"
with open(pulse, "w") as f:
    f.write("0 %.17g\n%.17g %.17g\n" % (-a0, T, -a0))
PRM = """subsection Analysis
  set Type          = transient
  set Initial state = static
end
subsection Model
  set Type = frame
  subsection Frame
    set Nodes     = a: 0, 0, 0; b: 1, 0, 0
    set Materials = steel: 2.1e11, 0.3, 7850
    set Sections  = sq: rectangle, 0.1, 0.1
    set Members   = body: a, b, sq, steel, 1
    set Point masses = a: 100; b: 100
    set Supports  = a: fixed, fixed, free, fixed, fixed, fixed; b: fixed, fixed, free, fixed, fixed, fixed
    set Contacts  = %s
    set Monitor nodes = a, b
  end
end
subsection Loading
  set Gravity             = 0, 0, -%g
  set Accelerogram Z      = %s
  set Accelerogram units  = m/s^2
end
subsection Contact
  set Restitution coefficient = 0
end
subsection Time integration
  set Method    = CD-Lagrange
  set Time step = 1e-6
  set End time  = 0.1
end
subsection Output
  set History interval = 0
end
"""
ground = "ga: a, 0, 0, 1, 0; gb: b, 0, 0, 1, 0"
lids = "; lid_a: a, 0, 0, -1, %g; lid_b: b, 0, 0, -1, %g" % (h, h)
path = ctx.work + "/lid.prm"
open(path, "w").write(PRM % (ground + lids, g, pulse))
out, _ = ctx.run(path, "lids")
s = read_summary(out)
m_node = 100 + 7850 * 0.01 * 1.0 / 2  # point mass + half the member (lumped)
ctx.check("ground contact max_uplift = restraint gap (m)", s["contacts"]["ga"]["max_uplift"],
          h, abs_tol=1e-6)
ctx.check_true("max_penetration below 1e-6 m", s["max_penetration"] < 1e-6,
               "(%.3g m)" % s["max_penetration"])
rows = [r for r in csv.DictReader(open(out + "/contacts.csv")) if r["contact"] == "lid_a"]
impulse = np.array([float(r["impulse"]) for r in rows])
k = int(np.argmax(impulse > 0))
history = list(csv.DictReader(open(out + "/history.csv")))
times = np.array([float(r["time"]) for r in history])
i = int(np.argmin(abs(times - float(rows[k]["time"]))))
v_before = float(history[i - 1]["a.vz"])
ctx.check("lid impulse = m (v_before - g dt), the momentum cancelled (N s)", impulse[k],
          m_node * (v_before - g * 1e-6), rel=1e-6)
v0, z0 = (a0 - g) * T, 0.5 * (a0 - g) * T**2
ctx.check("lid impulse = m sqrt(v0^2 - 2 g (h - z0)) (N s)", impulse[k],
          m_node * np.sqrt(v0**2 - 2 * g * (h - z0)), rel=1e-4)
open(path, "w").write(PRM % (ground, g, pulse))
out, _ = ctx.run(path, "free")
ctx.check("without restraints: max_uplift = z0 + v0^2 / 2g (m)",
          read_summary(out)["contacts"]["ga"]["max_uplift"], z0 + v0**2 / (2 * g), rel=1e-4)

# --- 2. the crane's restraints ---------------------------------------------
clearance = 0.01
crane_pulse = ctx.work + "/crane_pulse.txt"
with open(crane_pulse, "w") as f:
    f.write("0 0\n0.001 -29.43\n0.05 -29.43\n0.051 0\n")
wheels = ["%s_wheel_%d" % (kind, k) for kind in ("crane", "trolley") for k in range(1, 5)]
base = ["Output/Output interval=0", "Loading/Accelerogram X="]
rest = {}
for restraints in ("none", "both"):
    out, _ = ctx.run(ctx.prm("bridge_crane_hati.prm"), "rest_" + restraints,
                     base + ["Loading/Accelerogram Z=", "Time integration/End time=0.05",
                             "Model/Bridge crane/Uplift restraints=" + restraints])
    rest[restraints] = read_summary(out)
for w in wheels:
    ctx.check("%s: static load with restraints = without (N)" % w,
              rest["both"]["static_wheel_loads"][w], rest["none"]["static_wheel_loads"][w],
              rel=1e-12)
    ctx.check_true("%s_restraint open at rest (no impact)" % w,
                   rest["both"]["contacts"][w + "_restraint"]["n_impacts"] == 0)
runs = {}
for restraints in ("none", "both"):
    out, _ = ctx.run(ctx.prm("bridge_crane_hati.prm"), "pulse_" + restraints,
                     base + ["Loading/Accelerogram Z=" + crane_pulse,
                             "Loading/Accelerogram units=m/s^2",
                             "Time integration/End time=0.3",
                             "Model/Bridge crane/Uplift restraints=" + restraints,
                             "Model/Bridge crane/Restraint clearance=%g" % clearance])
    runs[restraints] = read_summary(out)
held = runs["both"]
for w in wheels:
    ctx.check("%s max_uplift = Restraint clearance (m, within max_penetration)" % w,
              held["contacts"][w]["max_uplift"], clearance,
              abs_tol=held["max_penetration"] + 1e-12)
    ctx.check_true("%s_restraint has impacts" % w,
                   held["contacts"][w + "_restraint"]["n_impacts"] > 0,
                   "(%d)" % held["contacts"][w + "_restraint"]["n_impacts"])
ctx.check_true("without restraints crane_wheel_3 lifts above 3 x the clearance",
               runs["none"]["contacts"]["crane_wheel_3"]["max_uplift"] > 3 * clearance,
               "(%.4g m)" % runs["none"]["contacts"]["crane_wheel_3"]["max_uplift"])
ctx.check_true("no restraint contact without restraints",
               not any(c.endswith("_restraint") for c in runs["none"]["contacts"]))
ctx.finish()
