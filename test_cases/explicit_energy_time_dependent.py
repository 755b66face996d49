#!/usr/bin/python3
"""CD-Lagrange under time-dependent loads at the application level: the
discrete energy balance (doc/theory.md E1, the work of the time-dependent
loads booked trapezoidally) holds to round-off, as the unit test
test_cases/unit_cd_lagrange_energy.cc checks on hand-built systems.

1. portal_frame_elcentro.prm (El Centro 1940 along X) integrated with
   CD-Lagrange for 0.5 s, damping removed (CD-Lagrange refuses Rayleigh
   damping): with gravity and the static initial state of the .prm, and
   without gravity, so that the energy scale is the seismic energy alone and
   the record's work is a large part of it. The roof displacement is also
   compared with an independent Newmark run (implicit, consistent mass,
   dt = 5e-4 s) so that the record is known to act.
2. portal_frame_dynamic.prm with a base acceleration step that starts on a
   time step (t = 500 dt, where (n + 1) dt - dt < n dt in floating point): the
   work of the step is booked from the step on (an amplitude taken at
   t_{n+1} - dt instead of n dt missed it: relative error 1e-6)."""
import os

import numpy as np

from hati_test import Context, read_csv, read_summary

ctx = Context()
# round-off: 25000 steps of a 456-DoF frame, measured 1.5e-15 to 6.6e-13
TOL = 1e-9


def check_balance(label, out):
    """E1 at the end (summary.json) and at every energy.csv row."""
    s = read_summary(out)
    ctx.check("[%s] |energy_balance_relative|" % label, abs(s["energy_balance_relative"]), 0.0,
              abs_tol=TOL)
    e = read_csv(out + "/energy.csv")
    scale = max(np.max(np.abs(e[c])) for c in ("kinetic", "internal", "external_work",
                                               "contact_work"))
    ctx.check("[%s] max |total(t) - total(0)| / largest energy" % label,
              np.max(np.abs(e["balance_drift"])) / scale, 0.0, abs_tol=TOL)
    return e, scale


elcentro = ctx.prm("portal_frame_elcentro.prm")
# the .prm names the record relative to the repository root
record = os.path.join(ctx.source, "data", "accelerograms", "RSN6_IMPVALL.I_I-ELC180.AT2")
short = ["Time integration/End time=0.5", "Time integration/Damping/Damping ratio=0",
         "Output/Output interval=0", "Output/History interval=1e-3",
         "Loading/Accelerogram X=" + record]
explicit = ["Time integration/Method=CD-Lagrange", "Time integration/Time step=2e-5"]

# --- 1a: as in the .prm (gravity, static initial state) ---------------------
out, _ = ctx.run(elcentro, "elcentro_gravity", short + explicit)
s = read_summary(out)
ctx.check_true("[El Centro, gravity] method CD-Lagrange", s["method"] == "CD-Lagrange")
check_balance("El Centro, gravity", out)

# --- 1b: without gravity: the energy is the seismic energy -------------------
no_gravity = ["Loading/Gravity=0, 0, 0"]
out, _ = ctx.run(elcentro, "elcentro", short + explicit + no_gravity)
e, scale = check_balance("El Centro", out)
# the record does work: the largest |external work| is a large part of the
# largest energy (else the balance would hold trivially)
ctx.check_true("[El Centro] the record does work",
               np.max(np.abs(e["external_work"])) > 0.1 * scale,
               "(max |X| %.4g J, largest energy %.4g J)"
               % (np.max(np.abs(e["external_work"])), scale))
out_nm, _ = ctx.run(elcentro, "elcentro_newmark",
                    short + no_gravity + ["Time integration/Time step=5e-4"])
h, h_nm = read_csv(out + "/history.csv"), read_csv(out_nm + "/history.csv")
peak = np.max(np.abs(h_nm["A1ux"]))
ctx.check_true("[El Centro] same output times",
               np.allclose(h["time"], h_nm["time"], rtol=0, atol=1e-12))
# lumped (CD-Lagrange) vs consistent (Newmark) mass and the two schemes'
# period errors ((omega dt)^2/12 ~ 5e-5 for Newmark at 7.46 Hz): measured
# 0.4 % of the peak roof drift, tolerance 2 %
ctx.check("[El Centro] max |A1.ux CD - Newmark| / peak", np.max(np.abs(h["A1ux"] - h_nm["A1ux"]))
          / peak, 0.0, abs_tol=0.02)
ctx.check_true("[El Centro] the roof moves (peak A1.ux > 1e-6 m)", peak > 1e-6,
               "(%.4g m)" % peak)

# --- 2: base acceleration step starting on a time step ----------------------
dt, start = 2e-6, 1e-3
n = round(start / dt)
ctx.check_true("step start on the time step n = %d with (n + 1) dt - dt < n dt" % n,
               n * dt >= start and (n + 1) * dt - dt < start)
out, _ = ctx.run(ctx.prm("portal_frame_dynamic.prm"), "step_on_time_step",
                 ["Time integration/Method=CD-Lagrange", "Time integration/Time step=%g" % dt,
                  "Time integration/End time=3e-3", "Loading/Base acceleration start=%g" % start,
                  "Output/Output interval=0"])
e, scale = check_balance("step at t = %g s" % start, out)
ctx.check_true("[step] the step does work", np.max(np.abs(e["external_work"])) > 0.1 * scale)
ctx.finish()
