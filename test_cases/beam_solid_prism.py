#!/usr/bin/python3
"""A solid prism tied between two beams (parameter_files/beam_solid_prism.prm,
doc/theory.md 11): the ties (B1) eliminated as constraints (static,
Newmark) and enforced as bilateral velocity-level rows (CD-Lagrange).

- static, axial load: u_x(B1) = N (L_a / (E A_a) + L_p / (E A_p) + L_b /
  (E A_b)) (exact: uniform stress in the prism, theory 11.2), 1e-9; a
  solid monitor (Monitor nodes `p: prism, x, y, z`) at its nearest node has
  u_x = N (L_a / (E A_a) + x / (E A_p)), u_y = -nu N y / (E A_p), u_z =
  -nu N z / (E A_p) (1e-9, 1e-8); the solid cuts (Solid cuts, theory 11.4)
  inside cells, on element faces and on the tied face carry N exactly
  (1e-9) and no other force;
- static, the parameter file's load (Fy, Fz, Mx at B1): the cuts against
  the statics of the part beyond them, Vy = Fy, Vz = Fz, T = Mx, My =
  -(3 - a) Fz, Mz = (3 - a) Fy, N = 0 (1e-8: the equivalent domain
  integral is the discrete equilibrium, measured below 1e-9); the cut on
  the tied face against beam b's section forces at its start (1e-8, the
  beam's sign convention); under self-weight Vz and My against the weight
  of the part beyond (1e-8);
- transient under the step load at B1 (force and torque): CD-Lagrange
  (lumped masses, tie rows) against Newmark (consistent masses, ties
  eliminated, DT = 1e-5 s): the histories of B1 within 2 % of their peak
  (independent schemes; the masses differ, lumped against consistent);
- CD-Lagrange: the discrete energy balance closes (1e-10 of the largest
  energy), the tie rows are not contacts (none counted, contacts.csv empty);
- CD-Lagrange from the static state under gravity: the structure stays at
  rest (the tie reactions carried from t = 0, theory 1.1);
- an explicit run of the model with Newmark's lumped mass and the ties
  eliminated is refused in one line."""
import os

import numpy as np

from hati_test import Context, read_csv, read_summary

ctx = Context()
prm = ctx.prm("beam_solid_prism.prm")
E, A_rod, A_prism = 2.1e11, 1.2e-2, 0.4 * 0.3
N = 1e5

# cuts of the prism (Solid cuts, theory 11.4): inside cells (x = 0.75, the
# cells are 0.5 long), on element faces (x = 1, 1.5) and on the tied end
# face x = 2; a solid monitor at the node nearest (1.1, 0.19, 0.14), the
# corner node (1, 0.2, 0.15) of the Q2 mesh
cuts = {"c075": 0.75, "c1": 1.0, "c15": 1.5, "c2": 2.0}
solid_outputs = ["Model/Frame/Solid cuts=" + "; ".join("%s: prism, x=%g" % c for c in cuts.items()),
                 "Model/Frame/Monitor nodes=A1, B0, B1; p: prism, 1.1, 0.19, 0.14",
                 "Model/Frame/Section force members=b"]
out, p = ctx.run(prm, "static_axial", ["Analysis/Type=static",
                                       "Model/Frame/Nodal loads=B1: %g, 0, 0" % N] + solid_outputs)
h = read_csv(out + "/history.csv")
ctx.check("static u_x(B1) against N sum L/(E A) (m)", float(h["B1ux"][0]),
          N * (1 / (E * A_rod) + 2 / (E * A_prism) + 1 / (E * A_rod)), rel=1e-9)
ctx.check("static u_x(B0) (tied node, from the face) (m)", float(h["B0ux"][0]),
          N * (1 / (E * A_rod) + 2 / (E * A_prism)), rel=1e-9)
# the solid monitor: the uniform stress N / A_p (exact, theory 11.2) gives
# u_x = N (L_a / (E A_a) + x / (E A_p)), u_y = -nu N / (E A_p) y and
# u_z = -nu N / (E A_p) z (the ties do not restrain the face's contraction)
ctx.check_true("the solid monitor's node and distance are printed",
               "monitor 'p' at the node (1, 0.2, 0.15) m" in p.stdout, "")
eps = N / (E * A_prism)
ctx.check("solid monitor p (node 1, 0.2, 0.15): u_x (m)", float(h["pux"][0]),
          N / (E * A_rod) + eps * 1.0, rel=1e-9)
ctx.check("solid monitor p: u_y = -nu eps y (m)", float(h["puy"][0]), -0.3 * eps * 0.2, rel=1e-8)
ctx.check("solid monitor p: u_z = -nu eps z (m)", float(h["puz"][0]), -0.3 * eps * 0.15, rel=1e-8)
ctx.check_true("solid monitor columns: translations only",
               "pux" in h.dtype.names and "purx" not in h.dtype.names, "")
# the cuts under the axial load: N = 1e5 N exactly (uniform stress), the
# rest zero (relative to N, N x 1 m)
f = read_csv(out + "/section_forces.csv")
for name in cuts:
    row = f[f["member"] == name][0]
    ctx.check("axial: cut %s N (N)" % name, row["N"], N, rel=1e-9)
    ctx.check("axial: cut %s largest |Vy|, |Vz|, |T|, |My|, |Mz| / N" % name,
              max(abs(row[k]) for k in ("Vy", "Vz", "T", "My", "Mz")) / N, 0.0, abs_tol=1e-9)

# the prism's own load case (B1: Fy = 5e3, Fz = -1e4 N, Mx = 2e3 N m),
# static: at a cut x = a, statics of the part beyond it (B1 at x = 3):
# N = 0, Vy = Fy, Vz = Fz, T = Mx, My = -(3 - a) Fz, Mz = (3 - a) Fy
Fy, Fz, Mx = 5e3, -1e4, 2e3
out, _ = ctx.run(prm, "static_cuts", ["Analysis/Type=static"] + solid_outputs)
f = read_csv(out + "/section_forces.csv")
for name, a in cuts.items():
    row = f[f["member"] == name][0]
    ctx.check("bending: cut %s x (m)" % name, row["x"], a, abs_tol=0.0)
    # the equivalent domain integral is the discrete equilibrium: exact up
    # to the solver (measured below 1e-9 relative)
    for k, ref in (("Vy", Fy), ("Vz", Fz), ("T", Mx), ("My", -(3 - a) * Fz), ("Mz", (3 - a) * Fy)):
        ctx.check("bending: cut %s %s (N, N m)" % (name, k), row[k], ref, rel=1e-8)
    ctx.check("bending: cut %s N / |Fz|" % name, row["N"] / abs(Fz), 0.0, abs_tol=1e-9)
# the beam b at its start (the tie at x = 2): the same forces as the cut
# on the tied face (the beam's convention, theory 5.6)
beam = f[(f["member"] == "b") & (f["x"] == 0.0)][0]
face = f[f["member"] == "c2"][0]
for k in ("Vy", "Vz", "T", "My", "Mz"):
    ctx.check("beam b at x = 0 against cut c2: %s" % k, face[k], beam[k], rel=1e-8)
# self-weight (static, gravity -9.81 m/s^2 along Z, no load): Vz = -g m
# and My = g sum m_i (x_i - a) of the part beyond the cut (the prism beyond
# a, beam b, the 200 kg at B1): the layer's own weight is taken off
# (theory 11.4), exact up to the solver
out, _ = ctx.run(prm, "static_weight", ["Analysis/Type=static", "Model/Frame/Nodal loads=",
                                        "Loading/Gravity=0, 0, -9.81"] + solid_outputs)
f = read_csv(out + "/section_forces.csv")
m_rod, rho_A = 7850 * A_rod * 1.0, 7850 * A_prism
for name, a in cuts.items():
    row = f[f["member"] == name][0]
    masses = ((rho_A * (2 - a), (2 + a) / 2), (m_rod, 2.5), (200.0, 3.0))
    ctx.check("self-weight: cut %s Vz (N)" % name, row["Vz"],
              -9.81 * sum(m for m, _ in masses), rel=1e-8)
    ctx.check("self-weight: cut %s My (N m)" % name, row["My"],
              9.81 * sum(m * (x - a) for m, x in masses), rel=1e-8)

end = ["Time integration/End time=0.03"]
newmark, _ = ctx.run(prm, "newmark", end + ["Time integration/Method=Newmark",
                                            "Time integration/Time step=1e-5"])
explicit, p = ctx.run(prm, "explicit", end)
hn, he = read_csv(newmark + "/history.csv"), read_csv(explicit + "/history.csv")
for col in ("B1uy", "B1uz", "B1urx", "B0uz", "A1uz"):
    t = he["time"]
    ref = np.interp(t, hn["time"], hn[col])
    peak = np.max(np.abs(ref))
    ctx.check("CD-Lagrange vs Newmark %s, max |difference| / peak" % col,
              np.max(np.abs(he[col] - ref)) / peak, 0.0, abs_tol=0.02)
s = read_summary(explicit)
ctx.check("CD-Lagrange energy balance (relative)", s["energy_balance_relative"], 0.0,
          abs_tol=1e-10)
ctx.check("tie rows are not contacts: n_contacts", s["n_contacts"], 0, abs_tol=0)
ctx.check_true("the terminal counts no contact", "contacts: 0" in p.stdout)
c = read_csv(explicit + "/contacts.csv") if os.path.getsize(explicit + "/contacts.csv") > 80 else []
ctx.check("contacts.csv rows", len(c), 0, abs_tol=0)

rest, _ = ctx.run(prm, "rest", ["Time integration/End time=0.005",
                                "Analysis/Initial state=static",
                                "Loading/Gravity=0, 0, -9.81",
                                "Model/Frame/Nodal loads="])
hr = read_csv(rest + "/history.csv")
drift = max(np.max(np.abs(hr[c] - hr[c][0])) for c in ("B1uz", "B0uz", "A1uz"))
ctx.check("at rest from the static state under gravity: largest drift of u_z (m)",
          drift, 0.0, abs_tol=1e-12)
ctx.check("... with a static deflection u_z(B1) (m) below zero", min(0.0, float(hr["B1uz"][0])),
          float(hr["B1uz"][0]), abs_tol=0.0)

_, p = ctx.run(prm, "lumped", end + ["Time integration/Method=Newmark",
                                     "Time integration/Time step=1e-5",
                                     "Time integration/Newmark/Mass=lumped"],
               expect_failure=True)
err = p.stderr.strip().splitlines()
ctx.check_true("Newmark with Mass = lumped refused in one line",
               p.returncode != 0 and len(err) >= 1 and "lumped" in err[-1], err[-1:] )
ctx.finish()
