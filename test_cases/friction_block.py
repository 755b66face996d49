#!/usr/bin/python3
"""Coulomb friction (spec A9) on a rigid block on a slope
(parameter_files/friction_block.prm: two frictional node-to-plane contacts,
mu = 0.3, a stiff short member with 50 kg at each node, rotations held).
References (exact, a rigid block on an inclined plane):

- tan(theta) > mu (20 deg): the block slides down the slope with
  a = g (sin theta - mu cos theta); the acceleration over the second half
  second, (v(1) - v(0.5)) / 0.5, to 1e-6 relative (CD-Lagrange with the
  exact local solution reproduces it to round-off); both contacts `slip`;
  the friction work equals mu N s (N = m g cos theta, s the distance slid)
  to 1e-4 and the energy balance with friction_dissipated closes at
  round-off (balance_drift <= 1e-9 of the largest energy over 1e5 steps:
  the same block without friction drifts by 1.2e-10); slip_distance
  in summary.json = the distance slid, peak_friction_force = mu N / 2 per
  contact; the terminal contact table gains the columns slip distance,
  friction force and its time, equal to summary.json (a frictionless run's
  table keeps its seven columns);
- tan(theta) < mu (10 deg), Initial state = static: the static state holds
  the tangential directions of the closed frictional contacts (the block on
  frictional contacts alone is not singular) and the block stays exactly at
  rest: after the first step (which carries the dt^2 g / 2 of the initial
  half step, doc/theory.md 1.1) its displacement does not change and its
  velocity is zero to round-off, both contacts `stick`;
- the static state at 20 deg (tan > mu) is refused in one line naming the
  contact; a frictionless block (mu = 0) on the slope has no static state;
- HATI (block explicit, a rod with a mass implicit) against the fully
  explicit run: displacement to 1e-4, slip distance to 2 %; at 10 deg
  (sticking) the superposed macro steps against the same run with every
  macro step redone (Superposition = false), to 1e-9;
- modal analysis: the sticking contacts hold the block, so the rod is a
  cantilever clamped at it (first frequency to 2 %);
- bad contact options and the event-driven method with friction are
  refused in one line naming the contact.
"""
import math

import numpy as np

from hati_test import Context, read_csv, read_summary

ctx = Context()
prm = ctx.prm("friction_block.prm")
g, mu, L, m_node = 9.81, 0.3, 0.2, 50.0
m_member = 7850 * 0.05 * 0.05 * L
m = 2 * m_node + m_member


def geometry(theta_deg, options="0, mu=0.3"):
    """--set entries for the block on a slope of theta_deg."""
    t = math.radians(theta_deg)
    n = "%.15g, 0, %.15g" % (-math.sin(t), math.cos(t))
    return ["Model/Frame/Nodes=a: 0, 0, 0; b: %.15g, 0, %.15g" % (L * math.cos(t), L * math.sin(t)),
            "Model/Frame/Contacts=ga: a, %s, 0, %s; gb: b, %s, 0, %s" % (n, options, n, options)]


def along_slope(h, theta_deg, node="a", what="u"):
    t = math.radians(theta_deg)
    return h[node + what + "x"] * math.cos(t) + h[node + what + "z"] * math.sin(t)


# -- sliding at 20 degrees ----------------------------------------------------
theta = 20.0
a_ref = g * (math.sin(math.radians(theta)) - mu * math.cos(math.radians(theta)))
out, run20 = ctx.run(prm, "slide20", ["Output/History interval=0.01"])
h = read_csv(out + "/history.csv")
v = along_slope(h, theta, "a", "v")
i_half = int(np.argmin(np.abs(h["time"] - 0.5)))
acc = (v[-1] - v[i_half]) / (h["time"][-1] - h["time"][i_half])
ctx.check("slide 20 deg: acceleration down the slope (m/s^2) vs g (sin - mu cos)", -acc, a_ref,
          rel=1e-6)
vb = along_slope(h, theta, "b", "v")
ctx.check("slide 20 deg: both ends move together (m/s)", float(np.max(np.abs(vb - v))), 0.0,
          abs_tol=1e-9)
c = read_csv(out + "/contacts.csv")
late = c[c["time"] > 0.1]
ctx.check_true("slide 20 deg: contacts.csv state = slip for both contacts after 0.1 s",
               bool(np.all(late["state"] == "slip")), "(%d rows)" % len(late))
ctx.check("slide 20 deg: slip_velocity at the end = |v| (m/s)", late["slip_velocity"][-1], abs(v[-1]),
          rel=1e-6)
e = read_csv(out + "/energy.csv")
s_slid = -along_slope(h, theta, "a", "u")[-1]
N = m * g * math.cos(math.radians(theta))
ctx.check("slide 20 deg: friction_dissipated (J) vs mu N s", e["friction_dissipated"][-1],
          mu * N * s_slid, rel=1e-4)
scale = max(np.max(np.abs(e[k])) for k in ("kinetic", "internal", "external_work", "contact_work",
                                           "friction_dissipated"))
ctx.check("slide 20 deg: energy balance with friction, max |balance_drift| / largest energy",
          float(np.max(np.abs(e["balance_drift"]))) / scale, 0.0, abs_tol=1e-9)
s = read_summary(out)
ctx.check("slide 20 deg: friction_unconverged", s["friction_unconverged"], 0, abs_tol=0)
ctx.check_true("slide 20 deg: friction_iterations_max >= 1 is reported",
               s["friction_iterations_max"] >= 1, "(%d)" % s["friction_iterations_max"])
for name in ("ga", "gb"):
    ctx.check("slide 20 deg: %s slip_distance (m) = distance slid" % name,
              s["contacts"][name]["slip_distance"], s_slid, rel=1e-3)
ctx.check("slide 20 deg: peak_friction_force of both contacts (N) = mu N",
          s["contacts"]["ga"]["peak_friction_force"] + s["contacts"]["gb"]["peak_friction_force"],
          mu * N, rel=1e-3)


def table_rows(stdout):
    """The terminal contact table: its header and {name: [columns]}."""
    lines = stdout.splitlines()
    i = next(k for k, line in enumerate(lines) if line.startswith("  contacts:"))
    rows = {}
    for line in lines[i + 1:]:
        fields = line.split()
        if not line.startswith("    ") or not fields or fields[0].startswith("("):
            if rows:
                break
            continue
        rows[fields[0]] = fields[1:]
    return lines[i], rows


# the terminal table with friction: slip distance, friction force and its time
header, rows = table_rows(run20.stdout)
ctx.check_true("slide 20 deg: the contact table has the friction columns",
               header.endswith("  slip distance (m)  friction force (N)    at t (s)"), header)
for name in ("ga", "gb"):
    ctx.check("slide 20 deg: %s slip distance in the table (m) = slip_distance" % name,
              float(rows[name][7]), s["contacts"][name]["slip_distance"], rel=1e-5)
    ctx.check("slide 20 deg: %s friction force in the table (N) = peak_friction_force" % name,
              float(rows[name][8]), s["contacts"][name]["peak_friction_force"], rel=1e-5)
# a frictionless block: the table of frictionless runs, unchanged
_, run0 = ctx.run(prm, "slide20_mu0", ["Output/History interval=0", "Time integration/End time=0.01"]
                  + geometry(20, "0"))
header, rows = table_rows(run0.stdout)
ctx.check_true("frictionless: the contact table without friction columns",
               header == "  contacts:        name   impacts  peak force (N)    at t (s)  mean force "
               "(N)    at t (s)  time out of contact (s)  loss episodes"
               and all(len(r) == 7 for r in rows.values()), header)

# -- at rest at 10 degrees, from the static state -----------------------------
theta = 10.0
out, _ = ctx.run(prm, "rest10", geometry(theta) + ["Analysis/Initial state=static",
                                                   "Output/History interval=0"])
h = read_csv(out + "/history.csv")
u = along_slope(h, theta, "a", "u")
ctx.check("rest 10 deg: first-step offset (m) = the initial half step dt^2 g sin / 2 or less",
          abs(u[1] - u[0]), 0.0, abs_tol=1e-10 * g)
ctx.check("rest 10 deg: max |u(t) - u(t_1)| after the first step (m)",
          float(np.max(np.abs(u[1:] - u[1]))), 0.0, abs_tol=1e-15)
vmax = max(float(np.max(np.abs(h["a" + k][1:]))) for k in ("vx", "vy", "vz"))
ctx.check("rest 10 deg: max |v| after the first step (m/s)", vmax, 0.0, abs_tol=1e-14)
c = read_csv(out + "/contacts.csv")
ctx.check_true("rest 10 deg: contacts.csv state = stick after the first step",
               bool(np.all(c[c["time"] > 1e-4]["state"] == "stick")))
s = read_summary(out)
ctx.check("rest 10 deg: static normal forces sum (N) = m g cos",
          s["static_contact_forces"]["ga"] + s["static_contact_forces"]["gb"],
          m * g * math.cos(math.radians(theta)), rel=1e-8)
ctx.check("rest 10 deg: slip_distance (m)", s["contacts"]["ga"]["slip_distance"], 0.0,
          abs_tol=1e-15)

# -- HATI: the block explicit, a rod with a mass at its end implicit ----------
# the block a-b (explicit, with the frictional contacts) carries a rod b-c
# along the slope (implicit, 4 elements, 20 kg at c); the whole slides.
# Reference: the fully explicit run of the same model (CD-Lagrange at the
# micro step): displacement of a after 0.5 s to 1e-4, slip distance to 2 %
# (the spec's HATI-vs-explicit tolerance), states slip, energy balance.
t20 = math.radians(20.0)
rod = ["Model/Frame/Nodes=a: 0, 0, 0; b: %.15g, 0, %.15g; c: %.15g, 0, %.15g"
       % (L * math.cos(t20), L * math.sin(t20), 3 * L * math.cos(t20), 3 * L * math.sin(t20)),
       "Model/Frame/Members=body: a, b, block, steel, 1; rod: b, c, block, steel, 4",
       "Model/Frame/Point masses=a: 50; b: 50; c: 20", "Model/Frame/Monitor nodes=a, b, c",
       "Time integration/End time=0.5", "Output/History interval=0.01"]
out_cd, _ = ctx.run(prm, "rod_explicit", rod)
out_h, _ = ctx.run(prm, "rod_hati", rod + ["Time integration/Method=HATI",
                                           "Model/Decomposition/Explicit members=body",
                                           "Time integration/HATI/Time step ratio=10"])
h_cd, h_h = read_csv(out_cd + "/history.csv"), read_csv(out_h + "/history.csv")
u_cd, u_h = along_slope(h_cd, 20.0)[-1], along_slope(h_h, 20.0)[-1]
ctx.check("HATI vs explicit: displacement of a along the slope at 0.5 s (m)", u_h, u_cd,
          rel=1e-4)
s_cd, s_h = read_summary(out_cd), read_summary(out_h)
ctx.check("HATI vs explicit: slip distance of ga (m)", s_h["contacts"]["ga"]["slip_distance"],
          s_cd["contacts"]["ga"]["slip_distance"], rel=0.02)
ctx.check("HATI: friction_unconverged", s_h["friction_unconverged"], 0, abs_tol=0)
ctx.check_true("HATI: the macro steps with friction within reach are redone",
               s_h["redone_macro_steps"] == s_h["n_steps"],
               "(%d of %d)" % (s_h["redone_macro_steps"], s_h["n_steps"]))
c = read_csv(out_h + "/contacts.csv")
ctx.check_true("HATI: contacts.csv state = slip after 0.1 s",
               bool(np.all(c[c["time"] > 0.1]["state"] == "slip")))
e = read_csv(out_h + "/energy.csv")
scale = max(np.max(np.abs(e[k])) for k in ("kinetic", "external_work", "friction_dissipated"))
ctx.check("HATI: max |balance_drift| / largest energy", float(np.max(np.abs(e["balance_drift"])))
          / scale, 0.0, abs_tol=1e-9)

# -- HATI while the block sticks: superposed macro steps --------------------------
# the same block and rod at 10 deg (tan < mu), from rest under gravity: the
# rod swings on the sticking block. A macro step whose contacts stick over
# its micro steps is superposed (doc/theory.md A9) instead of redone.
# Reference: the same HATI run with Superposition = false (every macro step
# redone with the full multiplier): displacements of the rod's end c and of
# the block's node b to 1e-9 of their peaks (measured 5e-14 and 1e-11: the
# Gauss-Seidel tolerance); at most 5 % of the macro steps redone (measured
# 37 of 5000: at the rod's swing peaks gb reaches its cone and slips);
# contacts stick; energy balance closed.
t10 = math.radians(10.0)
rod10 = geometry(10.0) + [
    "Model/Frame/Nodes=a: 0, 0, 0; b: %.15g, 0, %.15g; c: %.15g, 0, %.15g"
    % (L * math.cos(t10), L * math.sin(t10), 3 * L * math.cos(t10), 3 * L * math.sin(t10)),
    "Model/Frame/Members=body: a, b, block, steel, 1; rod: b, c, block, steel, 4",
    "Model/Frame/Point masses=a: 50; b: 50; c: 20", "Model/Frame/Monitor nodes=a, b, c",
    "Time integration/End time=0.5", "Output/History interval=0.001",
    "Time integration/Method=HATI", "Model/Decomposition/Explicit members=body",
    "Time integration/HATI/Time step ratio=10"]
out_sup, _ = ctx.run(prm, "rod10_superposed", rod10)
out_red, _ = ctx.run(prm, "rod10_redone", rod10 + ["Time integration/HATI/Superposition=false"])
h_sup, h_red = read_csv(out_sup + "/history.csv"), read_csv(out_red + "/history.csv")
for key in ("cux", "cuz", "buz"):
    peak = float(np.max(np.abs(h_red[key])))
    ctx.check("HATI sticking: max |%s superposed - redone| / peak" % key,
              float(np.max(np.abs(h_sup[key] - h_red[key]))) / peak, 0.0, abs_tol=1e-9)
s_sup, s_red = read_summary(out_sup), read_summary(out_red)
ctx.check_true("HATI sticking: Superposition = false redoes every macro step",
               s_red["hati_redone_macro_steps"] == s_red["n_steps"],
               "(%d of %d)" % (s_red["hati_redone_macro_steps"], s_red["n_steps"]))
ctx.check_true("HATI sticking: at most 5 % of the macro steps redone",
               s_sup["hati_redone_macro_steps"] <= 0.05 * s_sup["n_steps"],
               "(%d of %d)" % (s_sup["hati_redone_macro_steps"], s_sup["n_steps"]))
c = read_csv(out_sup + "/contacts.csv")
ctx.check_true("HATI sticking: contacts.csv state = stick in 99 % of the rows",
               float(np.mean(c["state"] == "stick")) >= 0.99,
               "(%d of %d)" % (int(np.sum(c["state"] == "stick")), len(c)))
ctx.check("HATI sticking: peak friction force of gb (N), superposed vs redone",
          s_sup["contacts"]["gb"]["peak_friction_force"],
          s_red["contacts"]["gb"]["peak_friction_force"], rel=1e-9)
ctx.check("HATI sticking: energy balance / largest energy", s_sup["energy_balance_relative"], 0.0,
          abs_tol=1e-10)

# -- modal: the sticking contacts hold the block ---------------------------------
# the block a-b is held in every translation by its two sticking contacts
# (and in rotation by its supports), so the rod b-c is a cantilever clamped
# at b: first bending frequency (Rayleigh, tip mass M, rod mass m_r)
# f = sqrt(3 E I / (l^3 (M + 0.2357 m_r))) / (2 pi), within 2 % (Timoshenko
# element and the approximation of the rod's mass)
out, _ = ctx.run(prm, "modal", rod[:3] + ["Analysis/Type=modal"])
modes = read_csv(out + "/modes.csv")
E, I, l_rod = 2.1e11, 0.05 ** 4 / 12, 2 * L
f_ref = math.sqrt(3 * E * I / (l_rod ** 3 * (20.0 + 0.2357 * 7850 * 0.05 ** 2 * l_rod))) / (2 * math.pi)
ctx.check("modal: first frequency (Hz) = the rod clamped at the sticking block", modes["frequency"][0],
          f_ref, rel=0.02)

# -- refusals -------------------------------------------------------------------
def refused(tag, sets, expected):
    _, p = ctx.run(prm, tag, sets, expect_failure=True)
    line = p.stderr.strip()
    ctx.check_true("refused (%s): one line, exit code 1" % tag,
                   p.returncode == 1 and line.count("\n") == 0, "(%r)" % line)
    ctx.check_true("refused (%s): message" % tag, line.startswith(expected),
                   "\n       got      %r\n       expected %r..." % (line, expected))


refused("static20", ["Analysis/Type=static"],
        "hati: error: static analysis: the closed contact 'ga' does not stick: its tangential force ")
refused("frictionless", geometry(20, "0") + ["Analysis/Type=static"],
        "hati: error: static analysis: the stiffness matrix is singular: the model can move as a "
        "rigid body (check the supports): a rigid translation along y costs no strain energy "
        "and no closed contact holds it")
refused("event_driven", ["Time integration/Method=event-driven"],
        "hati: error: Time integration/Method = event-driven: the contact 'ga' has Coulomb "
        "friction (mu > 0), which the event-driven reference does not handle; use CD-Lagrange")
refused("mu_negative", geometry(20, "0, mu=-0.1"),
        "hati: error: Model/Frame/Contacts: contact 'ga': mu=-0.1: expected the friction "
        "coefficient, a number >= 0")
refused("mu_text", geometry(20, "0, mu=abc"),
        "hati: error: Model/Frame/Contacts: contact 'ga': mu=abc: expected the friction "
        "coefficient, a number >= 0")
refused("rolls_bad", geometry(20, "0, mu=0.3, rolls=w"),
        "hati: error: Model/Frame/Contacts: contact 'ga': rolls=w: expected the rolling axis x, y "
        "or z")
refused("option_unknown", geometry(20, "0, mu=0.3, slides=x"),
        "hati: error: Model/Frame/Contacts: contact 'ga': unknown option 'slides=x', expected "
        "mu=<coefficient> or rolls=<x|y|z>")
refused("rolls_normal",
        ["Model/Frame/Nodes=a: 0, 0, 0; b: 0.2, 0, 0",
         "Model/Frame/Contacts=ga: a, 0, 0, 1, 0, 0, mu=0.3, rolls=z; gb: b, 0, 0, 1, 0, 0, mu=0.3"],
        "hati: error: Model/Frame/Contacts: contact 'ga': the rolling axis (rolls=) lies along "
        "the contact normal; it must lie in the contact plane")
ctx.finish()
