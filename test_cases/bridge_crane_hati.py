#!/usr/bin/python3
"""The paper's comparison (Fig. 9) on the crane: fully explicit versus HATI
give the same contact-loss episodes of the trolley wheels.

parameter_files/bridge_crane_paper_case.prm (trolley contacts only, the
crane wheels pinned, gravity and a vertical ground acceleration on the
girders and end carriages), with a 1 s vertical excitation strong enough
to lift the trolley: a(t) = 1.2 g sin(2 pi 3.6 t), near the crane's first
vertical mode (3.6 Hz with the trolley at 0.5 of the span, bridge_crane_modal).

The reference is the fully explicit run (CD-Lagrange on the whole crane,
dt = 1.6e-6 s, below its dt_crit of 1.8e-6 s); HATI runs with its own
explicit step dt = 6e-6 s (the explicit subdomain's dt_crit is 7.5e-6 s)
and m = 20 (DT = 1.2e-4 s). Checked:
- the trolley lifts off: both runs have at least one contact-loss episode
  per trolley wheel, and the same number;
- every episode start and end agree within 1 ms (the issue asks 2 ms;
  measured 0.1-0.2 ms, a few dt of the larger step times the coupling
  error);
- the time out of contact (uplift_time) agrees within 2 %;
- the largest landing impulse (peak_impulse, N s: the plastic impact is
  resolved in one step, so the force impulse/dt depends on dt while the
  impulse does not) agrees within 5 %, and so does the peak contact force
  averaged over 1 ms (peak_mean_force);
- the energy balance of both runs closes (relative error < 1e-9), and the
  coupled run keeps the interface velocities equal (< 1e-7 m/s: the macro
  steps redone around the impacts iterate to 1e-8 of the velocity scale).

Then the file as it is (Rinaldi UP times 4) over its first 1.4 s under
HATI: every trolley wheel lifts off once, from 1.28772 s to 1.29738 s in the
fully explicit run of the same file (CD-Lagrange, dt = 1.6e-6 s, the
command in the file's header, measured): start and end within 1 ms, as
above (the paper's case must show the paper's phenomenon: with the record
unscaled the trolley does not lift)."""
import math
import os

from hati_test import Context, read_summary

ctx = Context()
pulse = os.path.join(ctx.work, "vertical_pulse.txt")
with open(pulse, "w") as f:
    f.write("# vertical ground acceleration (g): 1.2 sin(2 pi 3.6 t), 0 <= t <= 1 s\n")
    for i in range(1001):
        t = i * 1e-3
        f.write("%.6f %.12f\n" % (t, 1.2 * math.sin(2 * math.pi * 3.6 * t)))

prm = ctx.prm("bridge_crane_paper_case.prm")
common = ["Loading/Accelerogram Z=" + pulse, "Loading/Accelerogram scale factor=1",
          "Time integration/End time=1",
          "Output/Output interval=0", "Output/History interval=0.001"]
runs = {}
for method, dt in (("CD-Lagrange", 1.6e-6), ("HATI", 6e-6)):
    out, _ = ctx.run(prm, method, common + ["Time integration/Method=" + method,
                                            "Time integration/Time step=%g" % dt])
    episodes = {}
    with open(os.path.join(out, "contact_episodes.csv")) as f:
        next(f)
        for line in f:
            name, start, end, _ = line.strip().split(",")
            episodes.setdefault(name, []).append((float(start), float(end) if end else None))
    runs[method] = (read_summary(out), episodes)

(se, ee), (sh, eh) = runs["CD-Lagrange"], runs["HATI"]
for s, label in ((se, "explicit"), (sh, "HATI")):
    ctx.check("%s: energy balance (relative)" % label, s["energy_balance_relative"], 0.0,
              abs_tol=1e-9)
# macro steps redone around the impacts iterate the continuity to 1e-8 of
# the velocity scale (about 1 m/s here)
ctx.check("HATI: interface velocity jump (m/s)", sh["interface_velocity_jump"], 0.0,
          abs_tol=1e-7)
for k in range(1, 5):
    name = "trolley_wheel_%d" % k
    a, b = ee.get(name, []), eh.get(name, [])
    ctx.check_true("%s: the trolley lifts off (explicit)" % name, len(a) >= 1,
                   "(%d episodes)" % len(a))
    ctx.check("%s: number of contact-loss episodes" % name, len(b), len(a), abs_tol=0)
    for i, ((s0, e0), (s1, e1)) in enumerate(zip(a, b)):
        ctx.check("%s: episode %d start (s)" % (name, i + 1), s1, s0, abs_tol=1e-3)
        ctx.check_true("%s: episode %d ends in both runs" % (name, i + 1),
                       e0 is not None and e1 is not None)
        if e0 is not None and e1 is not None:
            ctx.check("%s: episode %d end (s)" % (name, i + 1), e1, e0, abs_tol=1e-3)
    we, wh = se["wheels"][name], sh["wheels"][name]
    ctx.check("%s: uplift_time (s)" % name, wh["uplift_time"], we["uplift_time"], rel=0.02)
    ctx.check("%s: peak_impulse (N s)" % name, wh["peak_impulse"], we["peak_impulse"],
              rel=0.05)
    # the peak force averaged over Output/Contact force window (1 ms: 625
    # explicit steps, 167 HATI micro steps) does not depend on dt (the issue
    # asks 5 %)
    ctx.check("%s: peak_mean_force over 1 ms (N)" % name, wh["peak_mean_force"],
              we["peak_mean_force"], rel=0.05)

record = os.path.join(ctx.source, "data", "accelerograms", "RinaldiUP.AT2")
out, _ = ctx.run(prm, "record", ["Loading/Accelerogram Z=" + record,
                                 "Time integration/End time=1.4", "Output/Output interval=0"])
with open(os.path.join(out, "contact_episodes.csv")) as f:
    next(f)
    rows = [line.strip().split(",") for line in f]
for k in range(1, 5):
    name = "trolley_wheel_%d" % k
    mine = [(float(r[1]), float(r[2])) for r in rows if r[0] == name and r[2]]
    ctx.check("record x 4: %s contact-loss episodes by 1.4 s" % name, len(mine), 1, abs_tol=0)
    if mine:
        ctx.check("record x 4: %s lifts off at (s)" % name, mine[0][0], 1.28772, abs_tol=1e-3)
        ctx.check("record x 4: %s lands at (s)" % name, mine[0][1], 1.29738, abs_tol=1e-3)
ctx.finish()
