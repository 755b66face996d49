#!/usr/bin/python3
"""Bouncing ball with CD-Lagrange against the analytical solution
(algorithms.md 6.1): impact times t_{k+1} = t_k + 2 e^k v1 / g, apex heights
z0 e^{2k}, Zeno time t_inf = t1 (1 + e) / (1 - e), rest impulse m g dt,
first-order convergence of the impact times in dt, and the number of
impacts in summary.json (n_impacts) against the analytical impacts."""
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
# peak_mean_force: the largest impulse within Output/Contact force window
# (1 ms = 10 steps) over the window; the first impact (the fastest) is one
# step with the impulse m (1 + e) v1, up to O(g dt / v1) = 2e-4
ctx.check("peak_mean_force over 1 ms (N) = m (1 + e) v1 / 1 ms",
          s["contacts"]["ground"]["peak_mean_force"], m * (1 + e) * v1 / 1e-3, rel=1e-3)
ctx.check("peak_mean_force time (s) = t1", s["contacts"]["ground"]["peak_mean_force_time"],
          t1, abs_tol=4 * dt)
ctx.check_true("max penetration bounded by dt v1", s["max_penetration"] <= dt * v1 * 1.01,
               "(%.3g m <= %.3g m)" % (s["max_penetration"], dt * v1))

# n_impacts (OutputWriter::track_contacts: the contact going from no impulse
# to an impulse) against the analytical impacts before the Zeno point. The
# flight after impact k lasts 2 e^k v1 / g; when it lasts less than about
# two steps the discrete impacts merge into persistent contact (at most one
# impulse per step, and an active contact keeps pushing while its velocity
# stays below g dt / (1 + e)).


def analytical_impacts(min_flight):
    """Number of analytical impacts t_k < t_inf whose previous flight lasts
    more than min_flight (the first impact always counts)."""
    n, k = 1, 1
    while 2 * e**k * v1 / g > min_flight:
        n, k = n + 1, k + 1
    return n


n_ref = analytical_impacts(2 * dt)
# tolerance: the impacts that a change of the threshold by one step (1 dt or
# 3 dt instead of 2 dt) adds or removes (3 here); measured 37 for 38
n_tol = max(analytical_impacts(dt) - n_ref, n_ref - analytical_impacts(3 * dt))
ctx.check("n_impacts vs analytical impacts with flights > 2 dt", s["n_impacts"], n_ref,
          abs_tol=n_tol)
# contacts.csv has every step here: one impulse run per impact, exactly
ctx.check("n_impacts vs impulse runs in contacts.csv", s["n_impacts"], len(contact_phases(c)[0]),
          abs_tol=0)

# --- first-order convergence of the impact times over three time steps ----
errors = []
steps = [1e-3, 2.5e-4, 6.25e-5]
for dt in steps:
    out, _ = ctx.run(ctx.prm("bouncing_ball.prm"), "conv%g" % dt,
                     ["Time integration/Time step=%g" % dt, "Time integration/End time=3",
                      "Output/Output interval=0"])
    _, times = impact_times(out)
    errors.append(np.max(np.abs(times[:5] - np.array(t_impacts))))
    # to t = 3 s: the six analytical impacts t_1 ... t_6 = 2.876 s (t_7 =
    # 3.117 s), flights >= 0.29 s, none merges: exactly 6
    ctx.check("[dt %g] n_impacts to t = 3 s" % dt, read_summary(out)["n_impacts"], 6, abs_tol=0)
    print("dt %-8g max error of the first five impact times %.4g s" % (dt, errors[-1]))
orders = [np.log(errors[i] / errors[i + 1]) / np.log(steps[i] / steps[i + 1]) for i in range(2)]
for i, p in enumerate(orders):
    ctx.check("convergence order %d" % (i + 1), p, 1.0, abs_tol=0.35)

# summary.json max_absolute_acceleration: in free flight before the first
# impact (t = 0.4516 s) the velocity differences between history rows give
# the gravity exactly (CD-Lagrange is exact for a constant acceleration)
out, _ = ctx.run(ctx.prm("bouncing_ball.prm"), "free_flight", ["Time integration/End time=0.4"])
a = read_summary(out)["max_absolute_acceleration"]["ball"]["value"]
ctx.check("free flight: max absolute acceleration (m/s^2) = g", a, 9.81, rel=1e-9)

ctx.finish()
