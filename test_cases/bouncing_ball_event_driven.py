#!/usr/bin/python3
"""Bouncing ball with the event-driven reference (CVODE root finding) against
the analytical impact times and post-impact velocities (algorithms.md 6.1),
and its refusal of the Zeno accumulation point and of large models."""
import numpy as np

from hati_test import Context, contact_phases, read_csv

ctx = Context()
g, z0, e = 9.81, 1.0, 0.8
t1 = np.sqrt(2 * z0 / g)
v1 = g * t1
t_impacts = [t1]
for k in range(1, 6):
    t_impacts.append(t_impacts[-1] + 2 * e**k * v1 / g)

out, _ = ctx.run(ctx.prm("bouncing_ball.prm"), "ed",
                 ["Time integration/Method=event-driven", "Time integration/End time=3",
                  "Time integration/Time step=1e-3", "Output/Output interval=0.1"])
c = read_csv(out + "/contacts.csv")
events = c[c["impulse"] > 0]
ctx.check("number of impacts before t = 3 s", len(events), 6, abs_tol=0)
for k in range(6):
    # root finding with CVODE tolerances 1e-12: impact times to ~1e-10 s
    ctx.check("impact time %d (s)" % (k + 1), events["time"][k], t_impacts[k], abs_tol=1e-9)
    # rebound velocity e^{k+1} v1; impulse m (1 + e) e^k v1
    ctx.check("rebound velocity %d (m/s)" % (k + 1), events["normal_velocity"][k],
              e ** (k + 1) * v1, rel=1e-8)
    ctx.check("impact impulse %d (N s)" % (k + 1), events["impulse"][k],
              (1 + e) * e**k * v1, rel=1e-8)

h = read_csv(out + "/history.csv")
flight = (h["time"] > t_impacts[0] + 0.01) & (h["time"] < t_impacts[1] - 0.01)
ctx.check("apex height after impact 1 (m)", z0 + h["balluz"][flight].max(), z0 * e**2,
          abs_tol=1e-5)  # sampled every 1e-3 s: |z - z_apex| <= g (5e-4)^2 / 2

# Zeno: the number of events explodes before t_inf; a clear refusal
_, p = ctx.run(ctx.prm("bouncing_ball.prm"), "zeno",
               ["Time integration/Method=event-driven", "Time integration/End time=5"],
               expect_failure=True)
ctx.check_true("Zeno accumulation refused", p.returncode != 0 and "Zeno" in p.stderr,
               p.stderr.strip())
# more DoFs than the reference handles: refused
_, p = ctx.run(ctx.prm("bar_impact_1d.prm"), "big",
               ["Time integration/Method=event-driven"], expect_failure=True)
ctx.check_true("large model refused", p.returncode != 0 and "DoFs" in p.stderr,
               p.stderr.strip())
ctx.finish()
