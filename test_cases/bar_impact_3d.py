#!/usr/bin/python3
"""3D bar hitting a rigid wall (code_aster SDNV100 geometry), CD-Lagrange,
e = 0, against the analytical 1D wave solution. The lateral faces slide on
frictionless supports, so the bar is in uniaxial strain and the wave speed is
the P-wave speed c_P = sqrt(E (1 - nu) / (rho (1 + nu) (1 - 2 nu))), not the
bar speed sqrt(E / rho) (which needs free lateral contraction, and then the
impact front disperses). Checked: contact start g0 / v0, duration 2 L / c_P,
force rho c_P A v0, exit velocity -v0."""
import numpy as np

from hati_test import Context, contact_phases, read_csv, read_summary

ctx = Context()
L, b, E, nu, rho, v0, g0 = 0.2, 0.02, 2e11, 0.3, 8000.0, 100.0, 2e-3
A = b * b
cP = np.sqrt(E * (1 - nu) / (rho * (1 + nu) * (1 - 2 * nu)))
dt = 5e-7
out, _ = ctx.run(ctx.prm("bar_impact_3d.prm"), "sdnv100",
                 ["Time integration/Time step=%g" % dt, "Output/Output interval=0"])
c = read_csv(out + "/contacts.csv")
t = c["time"]
starts, ends = contact_phases(c)
ctx.check_true("a single contact phase", len(starts) == 1, "(%d phases)" % len(starts))
i0, i1 = starts[0], ends[0]
ctx.check("contact start (s)", t[i0], g0 / v0, abs_tol=dt * 1.0001)
# 40 elements along L, dt = 0.6 dt_crit: release front smeared over ~2 steps
ctx.check("contact duration (s)", t[i1] - t[i0] + dt, 2 * L / cP, rel=0.03)
force = c["force"][i0:i1 + 1]
n = len(force)
ctx.check("contact force plateau (N)", np.mean(force[n // 4:3 * n // 4]), rho * cP * A * v0,
          rel=1e-3)
ctx.check("exit velocity (m/s)", v0 - c["impulse"].sum() / (rho * A * L), -v0, rel=0.03)
ctx.check("max |normal velocity| in contact (m/s)",
          np.max(np.abs(c["normal_velocity"][i0:i1 + 1])), 0.0, abs_tol=1e-9)
s = read_summary(out)
ctx.check("energy balance relative error", s["energy_balance_relative"], 0.0, abs_tol=1e-10)
h = read_csv(out + "/history.csv")
ctx.check("free end still at v0 before the wave arrives (m/s)",
          h["free_endvx"][np.searchsorted(h["time"], g0 / v0 + 0.5 * L / cP)], v0, rel=1e-9)
ctx.finish()
