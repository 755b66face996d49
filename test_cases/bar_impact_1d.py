#!/usr/bin/python3
"""Elastic bar hitting a rigid wall, 1D, CD-Lagrange with e = 0, against the
analytical wave solution (algorithms.md 6.2): contact starts at g0 / v0,
lasts 2 L / c with c = sqrt(E / rho), constant force rho c A v0, the bar
leaves with velocity -v0 (total impulse 2 m v0), and the wall end has no
penetration velocity while in contact; summary.json counts one impact."""
import numpy as np

from hati_test import Context, contact_phases, read_csv, read_summary

ctx = Context()
L, A, E, rho, v0, g0 = 1.0, 1e-4, 2e11, 7800.0, 1.0, 1e-3
c0 = np.sqrt(E / rho)
mass = rho * A * L

for dt in (1.97e-6, 1e-6):  # Courant numbers 0.998 and 0.506 (h = 0.01 m)
    out, _ = ctx.run(ctx.prm("bar_impact_1d.prm"), "dt%g" % dt,
                     ["Time integration/Time step=%g" % dt, "Output/Output interval=0"])
    c = read_csv(out + "/contacts.csv")
    t = c["time"]
    starts, ends = contact_phases(c)
    ctx.check_true("[dt %g] a single contact phase" % dt, len(starts) == 1,
                   "(%d phases)" % len(starts))
    i0, i1 = starts[0], ends[0]
    # the contact starts at the first step with g <= 0: within one step of g0/v0
    ctx.check("[dt %g] contact start (s)" % dt, t[i0], g0 / v0, abs_tol=dt * 1.0001)
    # duration: impulses from t[i0] to t[i1], each over one step; the mesh
    # (h = 0.01 m, 100 elements) disperses the release front: 1 %
    ctx.check("[dt %g] contact duration (s)" % dt, t[i1] - t[i0] + dt, 2 * L / c0, rel=0.01)
    force = c["force"][i0:i1 + 1]
    n = len(force)
    # the plateau (middle half of the contact) has the 1D wave force
    ctx.check("[dt %g] contact force plateau (N)" % dt, np.mean(force[n // 4:3 * n // 4]),
              rho * c0 * A * v0, rel=1e-3)
    # exit velocity from the momentum balance: v_exit = v0 - sum(lambda) / m
    ctx.check("[dt %g] exit velocity (m/s)" % dt, v0 - c["impulse"].sum() / mass, -v0, rel=0.015)
    # no penetration velocity after impact (A5 with e = 0): while the wall
    # pushes, the normal velocity (gap rate) is zero to round-off
    vn = c["normal_velocity"][i0:i1 + 1]
    ctx.check("[dt %g] max |normal velocity| in contact (m/s)" % dt, np.max(np.abs(vn)), 0.0,
              abs_tol=1e-12)
    ctx.check_true("[dt %g] gap rate >= 0 after the impact" % dt,
                   np.min(c["normal_velocity"][i0:]) >= -1e-12)
    s = read_summary(out)
    ctx.check("[dt %g] penetration (m)" % dt, s["max_penetration"], 0.0, abs_tol=dt * v0)
    ctx.check("[dt %g] energy balance relative error" % dt, s["energy_balance_relative"], 0.0,
              abs_tol=1e-10)
    # one impact: the wall pushes without interruption for 2 L / c, then the
    # bar leaves for good (OutputWriter::track_contacts counts one)
    ctx.check("[dt %g] n_impacts" % dt, s["n_impacts"], 1, abs_tol=0)
ctx.finish()
