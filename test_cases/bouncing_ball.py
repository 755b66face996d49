#!/usr/bin/python3
"""Bouncing ball with CD-Lagrange against the analytical solution
(algorithms.md 6.1): impact times t_{k+1} = t_k + 2 e^k v1 / g, apex heights
z0 e^{2k}, Zeno time t_inf = t1 (1 + e) / (1 - e), rest impulse m g dt, and
first-order convergence of the impact times in dt."""
import numpy as np

from hati_test import Context, contact_phases, read_csv, read_summary

ctx = Context()
g, z0, e, m = 9.81, 1.0, 0.8, 1.0
t1 = np.sqrt(2 * z0 / g)
v1 = g * t1
t_impacts = [t1]
for k in range(1, 5):
    t_impacts.append(t_impacts[-1] + 2 * e**k * v1 / g)
t_inf = t1 * (1 + e) / (1 - e)


def impact_times(out):
    c = read_csv(out + "/contacts.csv")
    starts, _ = contact_phases(c)
    return c, c["time"][starts]


# --- dt = 1e-4: impact times, apexes, Zeno rest, rest impulse -------------
dt = 1e-4
out, _ = ctx.run(ctx.prm("bouncing_ball.prm"), "dt1e-4",
                 ["Time integration/Time step=%g" % dt, "Output/Output interval=0"])
c, times = impact_times(out)
for k in range(5):
    # first-order scheme: the error stays within a few steps (measured 0.8-2.4 dt)
    ctx.check("impact time %d (s)" % (k + 1), times[k], t_impacts[k], abs_tol=4 * dt)

h = read_csv(out + "/history.csv")
z = z0 + h["balluz"]
for k in range(1, 4):
    flight = (h["time"] > t_impacts[k - 1] + 0.01) & (h["time"] < t_impacts[k] - 0.01)
    # apex error O(dt v): penetration dt v1 ~ 4.4e-4 m is never corrected
    ctx.check("apex height after impact %d (m)" % k, z[flight].max(), z0 * e ** (2 * k),
              abs_tol=2e-3)

# Zeno rest: from the last row without impulse on, every step has an impulse
on = c["impulse"] > 0
last_free = np.where(~on)[0][-1]
t_rest = c["time"][last_free + 1]
# event capturing: rest within O(dt) of t_inf (measured 16 dt at dt = 1e-4)
ctx.check("Zeno rest time (s)", t_rest, t_inf, abs_tol=40 * dt)
rest = c["time"] > t_inf + 0.05
ctx.check("rest impulse m g dt (N s)", np.mean(c["impulse"][rest]), m * g * dt, rel=1e-9)
ctx.check("rest impulse spread (N s)", np.ptp(c["impulse"][rest]), 0.0, abs_tol=1e-12)
ctx.check("rest force m g (N)", np.mean(c["force"][rest]), m * g, rel=1e-9)

s = read_summary(out)
# discrete energy balance (doc/theory.md E1) holds to round-off
ctx.check("energy balance relative error", s["energy_balance_relative"], 0.0, abs_tol=1e-10)
ctx.check_true("max penetration bounded by dt v1", s["max_penetration"] <= dt * v1 * 1.01,
               "(%.3g m <= %.3g m)" % (s["max_penetration"], dt * v1))

# --- first-order convergence of the impact times over three time steps ----
errors = []
steps = [1e-3, 2.5e-4, 6.25e-5]
for dt in steps:
    out, _ = ctx.run(ctx.prm("bouncing_ball.prm"), "conv%g" % dt,
                     ["Time integration/Time step=%g" % dt, "Time integration/End time=3",
                      "Output/Output interval=0"])
    _, times = impact_times(out)
    errors.append(np.max(np.abs(times[:5] - np.array(t_impacts))))
    print("dt %-8g max error of the first five impact times %.4g s" % (dt, errors[-1]))
orders = [np.log(errors[i] / errors[i + 1]) / np.log(steps[i] / steps[i + 1]) for i in range(2)]
for i, p in enumerate(orders):
    ctx.check("convergence order %d" % (i + 1), p, 1.0, abs_tol=0.35)

ctx.finish()
