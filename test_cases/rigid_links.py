#!/usr/bin/python3
"""Rigid links (Model/Frame/Rigid links, doc/theory.md 11.2) on
parameter_files/rigid_links.prm: a cantilever A-B, a rigid arm B -> C
0.3 m up, a beam C-D with a 100 kg mass at D.

- static (the link eliminated as constraints): the displacements and the
  rotation of B, C, D against Timoshenko beam theory (the element is exact
  for end loads: 1e-9 relative). Under Fx and Fz at D, the arm brings to B
  the force and the moment My = e Fx - a Fz (e = 0.3 m the arm, a = 0.5 m
  beam C-D); C follows B rigidly, u_C = u_B + theta_B x (0, 0, e).
- transient, reference the fully explicit run (CD-Lagrange, the link as six
  bilateral rows): Newmark (the link eliminated) and HATI (m = 5) with the
  link on each side of the decomposition -- across the interface with the
  explicit node the slave ('cd' explicit), the same link written the other
  way round (master C, slave B: hati turns it so that the explicit node is
  the slave; the same history to round-off), inside the explicit part (six
  bilateral rows, 'ab2' and 'cd' explicit) and inside the implicit part
  (eliminated, 'ab1' explicit): the histories of D and C within 2 % of
  their peak, the energy balance closed with the interface work."""
import numpy as np

from hati_test import Context, read_csv, read_summary

ctx = Context()
prm = ctx.prm("rigid_links.prm")

# --- static, Fx and Fz at D (Fy would add torsion and bending in y) ---
E, nu = 2.1e11, 0.3
G = E / (2 * (1 + nu))
A, I, As = 1.2e-2, 2e-4, 1e-2
L, e, a = 2.0, 0.3, 0.5
Fx, Fz = 2e4, -5e3
My = e * Fx - a * Fz
u_B = Fx * L / (E * A)
w_B = Fz * L**3 / (3 * E * I) + Fz * L / (G * As) - My * L**2 / (2 * E * I)
t_B = -Fz * L**2 / (2 * E * I) + My * L / (E * I)
u_C = u_B + t_B * e
u_D = u_C + Fx * a / (E * A)
w_D = w_B - t_B * a + Fz * a**3 / (3 * E * I) + Fz * a / (G * As)
t_D = t_B - Fz * a**2 / (2 * E * I)
out, _ = ctx.run(prm, "static", ["Analysis/Type=static",
                                 "Model/Frame/Nodal loads=D: %g, 0, %g, 0, 0, 0" % (Fx, Fz)])
r = read_csv(out + "/history.csv")
first = r[0]
for label, value, ref in (("u_x B", first["Bux"], u_B), ("u_z B", first["Buz"], w_B),
                          ("r_y B", first["Bury"], t_B), ("u_x C", first["Cux"], u_C),
                          ("u_z C = u_z B", first["Cuz"], w_B), ("r_y C", first["Cury"], t_B),
                          ("u_x D", first["Dux"], u_D), ("u_z D", first["Duz"], w_D),
                          ("r_y D", first["Dury"], t_D)):
    ctx.check("static: %s (m, rad)" % label, value, ref, rel=1e-9)

# --- transient: the fully explicit reference, Newmark and HATI ---
ref, _ = ctx.run(prm, "explicit", [])
hr = read_csv(ref + "/history.csv")
columns = ("Dux", "Duy", "Duz", "Curx", "Cuz")


def compare(tag, out, tolerance=0.02):
    h = read_csv(out + "/history.csv")
    for col in columns:
        r = np.interp(h["time"], hr["time"], hr[col])
        ctx.check("%s: %s, max |run - explicit| / peak" % (tag, col),
                  np.max(np.abs(h[col] - r)) / np.max(np.abs(r)), 0.0, abs_tol=tolerance)
    return h


out, _ = ctx.run(prm, "newmark", ["Time integration/Method=Newmark",
                                  "Time integration/Time step=5e-5"])
compare("Newmark", out)
hati = ["Time integration/Method=HATI", "Time integration/HATI/Time step ratio=5"]
cases = (("across, explicit slave", ["Model/Decomposition/Explicit members=cd"]),
         ("across, written master C", ["Model/Decomposition/Explicit members=cd",
                                       "Model/Frame/Rigid links=arm: C, B"]),
         ("inside the explicit part", ["Model/Decomposition/Explicit members=ab2, cd"]),
         ("inside the implicit part", ["Model/Decomposition/Explicit members=ab1"]))
histories = {}
for i, (tag, sets) in enumerate(cases):
    out, _ = ctx.run(prm, "hati_%d" % i, hati + sets)
    histories[tag] = compare("HATI m = 5, " + tag, out)
    s = read_summary(out)
    ctx.check("HATI, %s: energy balance (relative)" % tag, s["energy_balance_relative"],
              0.0, abs_tol=1e-10)
# the link written either way round is the same link: the coupling runs the
# same rows (D to round-off); the outputs read the description's slave
# through the link from its master, and the interface holds the link at the
# velocity level at the macro-step ends, so C differs by the position drift
# of G3' (a few 1e-5 of the peak)
h0, h1 = histories[cases[0][0]], histories[cases[1][0]]
for col in columns:
    ctx.check("HATI across: %s, master C against master B (relative to the peak)" % col,
              np.max(np.abs(h0[col] - h1[col])) / np.max(np.abs(h0[col])), 0.0,
              abs_tol=1e-12 if col[0] == "D" else 1e-3)
ctx.finish()
