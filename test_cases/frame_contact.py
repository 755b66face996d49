#!/usr/bin/python3
"""A free frame (beam) dropped onto two node-to-plane contacts
(parameter_files/beam_drop.prm), CD-Lagrange, checked against rigid-body
mechanics: first impact after the free-fall time sqrt(2 g0 / g) (within one
step: position-level detection), the time-averaged contact force equals the
weight m g (momentum balance, up to the mean vertical momentum at the end),
the two symmetric contacts carry the same impulses, no penetration
velocity while a contact pushes, and the discrete energy balance."""
import numpy as np

from hati_test import Context, read_csv, read_summary

ctx = Context()
g, g0, m = 9.81, 0.01, 7850 * 0.05 * 0.1 * 2.0
dt, T = 5e-6, 0.3
out, _ = ctx.run(ctx.prm("beam_drop.prm"), "drop",
                 ["Time integration/End time=%g" % T, "Output/History interval=0",
                  "Output/Output interval=0"])
c = read_csv(out + "/contacts.csv")
left, right = c[c["contact"] == "left"], c[c["contact"] == "right"]
t0 = np.sqrt(2 * g0 / g)
first = left["time"][np.argmax(left["impulse"] > 0)]
ctx.check("first impact time (s)", first, t0, abs_tol=1.0001 * dt)
ctx.check("left and right impulses (symmetry), relative difference",
          abs(left["impulse"].sum() - right["impulse"].sum()) / left["impulse"].sum(), 0.0,
          abs_tol=1e-9)
total = left["impulse"].sum() + right["impulse"].sum()
# sum(lambda) = m g T + m vz_mean(T) exactly; the kinetic energy never exceeds
# the energy m g g0 released by the fall (plastic impacts, no other source), so
# |vz_mean| <= sqrt(2 g g0) and |sum / (m g T) - 1| <= sqrt(2 g g0) / (g T)
bound = np.sqrt(2 * g * g0) / (g * T)
ctx.check("time-averaged contact force / weight (-)", total / (m * g * T), 1.0, abs_tol=bound)
pushing = c["impulse"] > 0
ctx.check("min normal velocity while pushing (m/s)", np.min(c["normal_velocity"][pushing]), 0.0,
          abs_tol=1e-12)
s = read_summary(out)
ctx.check("energy balance relative error", s["energy_balance_relative"], 0.0, abs_tol=1e-10)
# penetration <= dt * largest approach speed of an end node; its lumped mass
# m / 16 cannot hold more kinetic energy than m g g0
v_max = np.sqrt(2 * m * g * g0 / (m / 16))
ctx.check_true("penetration bounded by dt * the largest node speed",
               s["max_penetration"] <= dt * v_max, "(%.3g m <= %.3g m)" % (s["max_penetration"], dt * v_max))
ctx.finish()
