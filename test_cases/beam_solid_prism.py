#!/usr/bin/python3
"""A solid prism tied between two beams (parameter_files/beam_solid_prism.prm,
doc/theory.md 11): the ties (B1) eliminated as constraints (static,
Newmark) and enforced as bilateral velocity-level rows (CD-Lagrange).

- static, axial load: u_x(B1) = N (L_a / (E A_a) + L_p / (E A_p) + L_b /
  (E A_b)) (exact: uniform stress in the prism, theory 11.2), 1e-9;
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

out, _ = ctx.run(prm, "static_axial", ["Analysis/Type=static",
                                       "Model/Frame/Nodal loads=B1: %g, 0, 0" % N])
h = read_csv(out + "/history.csv")
ctx.check("static u_x(B1) against N sum L/(E A) (m)", float(h["B1ux"][0]),
          N * (1 / (E * A_rod) + 2 / (E * A_prism) + 1 / (E * A_rod)), rel=1e-9)
ctx.check("static u_x(B0) (tied node, from the face) (m)", float(h["B0ux"][0]),
          N * (1 / (E * A_rod) + 2 / (E * A_prism)), rel=1e-9)

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
