#!/usr/bin/python3
"""HATI with Coulomb friction (A9 in the explicit subdomain, G3' with the
frictional macro steps redone) against the fully explicit run of the same
crane (reference: CD-Lagrange on the whole crane, the same explicit step
dt = 2e-5 s; HATI m = 5), Travel = braked (the default), under Rinaldi 228
(X) and UP (Z) over the first 3.2 s (the strong motion starts at about
2.6 s):

- Hoist = rope (the default): no wheel lifts off; the crane slides on its
  braked wheels. Slip distances of every wheel within 2 % (issue #17's
  tolerance; measured 0.9 % at most), peak friction forces over the 1 ms
  window within 3 % (measured 2.2 %).
- Hoist = rigid: the wheels lift off at about 2.9 s. The first contact-loss
  episode of every wheel (the lift-off, 50-100 ms long) starts and ends
  within 2 ms of the explicit run's (measured 0.1 ms); the slip distances
  of the sliding wheels (> 0.1 m) within 2 % (measured 0.8 %). The later
  episodes are the wheels' chatter after landing, which frequency-range
  damping leaves undamped above 30 Hz: their number differs between any two
  step sizes or methods (15 against 29 on one wheel), so they are not
  matched one by one (doc/user_guide.md, the crane's damping).
Also: every friction cluster converged (friction_unconverged = 0) and the
energy balance closes to 1e-10 of the largest energy in both methods
(measured 3.5e-12 over 160 000 steps with friction).
"""
import csv
import os

from hati_test import Context, read_summary

ctx = Context()
records = os.path.join(ctx.source, "data", "accelerograms")
common = ["Model/Bridge crane/Travel=braked",
          "Time integration/Time step=2e-5",
          "Time integration/End time=3.2",
          "Output/Output interval=0",
          "Loading/Accelerogram X=" + os.path.join(records, "Rinaldi228.AT2"),
          "Loading/Accelerogram Z=" + os.path.join(records, "RinaldiUP.AT2")]


def run_pair(hoist):
    """(summary, episodes) of the fully explicit and the HATI run."""
    result = []
    for method in ("full_explicit", "hati"):
        out, _ = ctx.run(ctx.prm("bridge_crane_%s.prm" % method), "%s_%s" % (method, hoist),
                         common + ["Model/Bridge crane/Hoist=" + hoist])
        s = read_summary(out)
        episodes = {}
        with open(os.path.join(out, "contact_episodes.csv")) as f:
            for row in csv.DictReader(f):
                episodes.setdefault(row["contact"], []).append(
                    (float(row["start"]), float(row["end"]) if row["end"] else None))
        ctx.check("%s, %s: friction_unconverged" % (hoist, method),
                  s["friction_unconverged"], 0, abs_tol=0)
        ctx.check("%s, %s: energy balance / largest energy" % (hoist, method),
                  s["energy_balance_relative"], 0., abs_tol=1e-10)
        result.append((s, episodes))
    return result


# the rope: sliding without lift-off
(e, _), (h, _) = run_pair("rope")
for name, we in e["wheels"].items():
    wh = h["wheels"][name]
    ctx.check_true("rope: %s stays on its rail in both runs" % name,
                   we["uplift_time"] == 0. and wh["uplift_time"] == 0.)
    ctx.check("rope: %s slip distance (m), HATI vs explicit" % name, wh["slip_distance"],
              we["slip_distance"], rel=0.02)
    ctx.check("rope: %s peak friction force (N), HATI vs explicit" % name,
              wh["peak_friction_force"], we["peak_friction_force"], rel=0.03)

# the rigid hoist: lift-off and landing
(e, ee), (h, eh) = run_pair("rigid")
for name, we in e["wheels"].items():
    wh = h["wheels"][name]
    a, b = ee.get(name, []), eh.get(name, [])
    lifts = bool(a) and bool(b)
    ctx.check_true("rigid: %s lifts off in both runs" % name, lifts, "%s %s" % (a[:1], b[:1]))
    if lifts:
        ctx.check("rigid: %s first lift-off start (s)" % name, b[0][0], a[0][0], abs_tol=2e-3)
        if a[0][1] is not None and b[0][1] is not None:
            ctx.check("rigid: %s first landing (s)" % name, b[0][1], a[0][1], abs_tol=2e-3)
    if we["slip_distance"] > 0.1:
        ctx.check("rigid: %s slip distance (m), HATI vs explicit" % name,
                  wh["slip_distance"], we["slip_distance"], rel=0.02)
ctx.finish()
