#!/usr/bin/python3
"""Newmark's (1965) rigid sliding block (spec A9): a rigid block on a
horizontal base with Coulomb friction under the El Centro 1940 record
(data/accelerograms/RSN6_IMPVALL.I_I-ELC180.AT2, along X), the block of
parameter_files/friction_block.prm laid flat (contacts normal +Z).

Reference: the exact stick-slip integration written below. The record is
piecewise linear between its samples (as hati reads it); relative to the
base the block obeys u'' = -a_g(t) - mu g sign(u') while it slides, and sticks
(u' = 0) while |a_g| <= mu g. On each linear piece the sliding velocity is
a quadratic and the displacement a cubic in time, so the times where
sliding starts (|a_g| = mu g) and stops (u' = 0) are located exactly (roots
of linear and quadratic equations). The permanent displacement of hati
(CD-Lagrange, dt = 2e-5 s) must be within 1 % of it, at two friction
coefficients; the friction energy balance closes at round-off.
"""
import math
import os

import numpy as np

from hati_test import Context, read_csv, read_summary

ctx = Context()
prm = ctx.prm("friction_block.prm")
record = os.path.join(ctx.source, "data", "accelerograms", "RSN6_IMPVALL.I_I-ELC180.AT2")
g = 9.81            # the model's gravity (normal force m g)
g_units = 9.80665   # the record's unit g (hati's standard gravity)


def read_at2(path):
    with open(path) as f:
        lines = f.readlines()
    header = lines[3].upper().replace(",", " ").split()
    npts = int(header[header.index("NPTS=") + 1])
    dt = float(header[header.index("DT=") + 1])
    values = np.array([float(x) for line in lines[4:] for x in line.split()])[:npts]
    return dt, values * g_units


def stick_slip(dt, a, mu, t_end):
    """Exact relative displacement at t_end of a rigid block on a base with
    the piecewise-linear acceleration a (samples every dt from t = 0; zero
    after the record). Returns (u(t_end), number of slip episodes)."""
    f = mu * g
    times = list(np.arange(len(a)) * dt) + [t_end]
    acc = list(a) + [0.0]
    u, v, s, episodes = 0.0, 0.0, 0, 0   # s: sliding direction (0: stuck)
    for i in range(len(times) - 1):
        t0, t1 = times[i], times[i + 1]
        A = acc[i]
        # zero after the record: the last piece goes from the last sample to 0 at once
        B = (acc[i + 1] - acc[i]) / (t1 - t0) if i + 1 < len(a) else 0.0
        if i + 1 >= len(a):
            A = 0.0
        tau, T = 0.0, t1 - t0
        while tau < T:
            if s == 0:
                # stuck: sliding starts where |a_g| exceeds f, opposite to a_g
                ag = A + B * tau
                if abs(ag) > f:
                    s, episodes = (-1 if ag > 0 else 1), episodes + 1
                    continue
                # the first crossing of |a_g| = f in the piece (outwards:
                # |a_g| < f before it); at it the sliding velocity starts as
                # -B x^2 / 2, of the sign of the direction
                crossings = [(c * f - A) / B for c in (1, -1)] if B != 0 else []
                crossings = [c for c in crossings if tau < c < T]
                if not crossings:
                    break
                tau = min(crossings)
                s, episodes = (-1 if A + B * tau > 0 else 1), episodes + 1
                continue
            # sliding with direction s from tau: v(x) = v - (A x' + B/2 x'^2) ... with x' from t0
            # velocity at tau + x: v + c1 x + c2 x^2, c1 = -(A + B tau) - f s, c2 = -B / 2
            ag = A + B * tau
            c1, c2 = -ag - f * s, -B / 2.0
            # stop: v + c1 x + c2 x^2 = 0 for the first x in (0, T - tau]
            roots = []
            if c2 != 0:
                disc = c1 * c1 - 4 * c2 * v
                if disc >= 0:
                    r = math.sqrt(disc)
                    roots = [(-c1 - r) / (2 * c2), (-c1 + r) / (2 * c2)]
            elif c1 != 0:
                roots = [-v / c1]
            roots = [x for x in roots if 1e-15 < x <= T - tau]
            x = min(roots) if roots else T - tau
            u += v * x + c1 * x * x / 2 + c2 * x ** 3 / 3
            v = 0.0 if roots else v + c1 * x + c2 * x * x
            tau += x
            if roots:
                # stopped: stuck if |a_g| <= f there, else it slides the other way at once
                ag = A + B * tau
                s = 0 if abs(ag) <= f else (-1 if ag > 0 else 1)
                if s != 0:
                    episodes += 1
    return u, episodes


dt_record, a_g = read_at2(record)
t_end = len(a_g) * dt_record + 1.0
flat = ["Model/Frame/Nodes=a: 0, 0, 0; b: 0.2, 0, 0",
        "Loading/Accelerogram X=" + record,
        "Time integration/Time step=2e-5",
        "Time integration/End time=%g" % t_end,
        "Output/History interval=0.05",
        "Analysis/Initial state=static"]
for mu in (0.1, 0.15):
    u_ref, n_slips = stick_slip(dt_record, a_g, mu, t_end)
    contacts = "ga: a, 0, 0, 1, 0, 0, mu=%g; gb: b, 0, 0, 1, 0, 0, mu=%g" % (mu, mu)
    out, _ = ctx.run(prm, "elcentro_mu%g" % mu, flat + ["Model/Frame/Contacts=" + contacts])
    h = read_csv(out + "/history.csv")
    u_hati = h["aux"][-1]
    print("     mu = %g: exact stick-slip permanent displacement %.6f m (%d slip episodes), "
          "hati %.6f m" % (mu, u_ref, n_slips, u_hati))
    ctx.check("El Centro, mu = %g: permanent displacement (m) vs exact stick-slip" % mu,
              u_hati, u_ref, rel=0.01)
    ctx.check("El Centro, mu = %g: both ends together (m)" % mu, abs(h["bux"][-1] - u_hati), 0.0,
              abs_tol=1e-6 * abs(u_ref))
    e = read_csv(out + "/energy.csv")
    scale = max(np.max(np.abs(e[k])) for k in ("kinetic", "external_work", "friction_dissipated"))
    ctx.check("El Centro, mu = %g: max |balance_drift| / largest energy" % mu,
              float(np.max(np.abs(e["balance_drift"]))) / scale, 0.0, abs_tol=1e-10)
    s = read_summary(out)
    ctx.check("El Centro, mu = %g: friction_unconverged" % mu, s["friction_unconverged"], 0,
              abs_tol=0)
ctx.finish()
