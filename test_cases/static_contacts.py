#!/usr/bin/python3
"""Static equilibrium with closed contacts (parameter_files/beam_resting.prm):
a beam resting on two zero-gap node-to-plane contacts, with a point mass at a
quarter of its length, under gravity. The contacts are its only vertical
supports (K alone is singular along Z).

- Analysis/Type = static: the contact forces are the reactions of a simply
  supported beam (statically determinate, so exact): sum = (W + P) g to
  1e-8 relative, the lever rule for the point mass to 1e-8;
- Initial state = static, CD-Lagrange: the same forces in summary.json, and
  the beam starts at rest on its supports: the static state is solved under
  the lumped gravity load CD-Lagrange applies, so the mass node moves by
  less than 1e-3 of its static deflection; that state differs from the
  consistent static one by O(h^2) (the ratio of two meshes is checked)
  (a start from the undeformed state swings by about twice the static
  deflection, also checked), the
  time-averaged contact forces are the static ones to 1 %;
- a contact that would pull (the supports at x = 0 and x = a, with the
  weight beyond) is refused with a one-line error naming it; contacts with a
  positive gap are not closed (the singular-model error).
"""
import os
import subprocess

import numpy as np

from hati_test import Context, read_csv, read_summary

ctx = Context()
prm = ctx.prm("beam_resting.prm")
g, L, a, P = 9.81, 2.0, 0.5, 100.0
W = 7850 * 0.05 * 0.1 * L
R_left = W * g / 2 + P * g * (L - a) / L
R_right = W * g / 2 + P * g * a / L

out, _ = ctx.run(prm, "static", ["Analysis/Type=static"])
f = read_summary(out)["static_contact_forces"]
ctx.check("static: sum of contact forces (N) = (W + P) g", f["left"] + f["right"], (W + P) * g,
          rel=1e-8)
ctx.check("static: left reaction (N)", f["left"], R_left, rel=1e-8)
ctx.check("static: right reaction (N), lever rule", f["right"], R_right, rel=1e-8)
u_static = read_csv(out + "/history.csv")["muz"][0]
ctx.check_true("static: the beam deflects under its load", u_static < 0, "(u_m = %.4g m)" % u_static)

dt, T = 5e-6, 0.02
out, _ = ctx.run(prm, "transient")
s = read_summary(out)
ctx.check("transient: static left force in summary (N)", s["static_contact_forces"]["left"],
          R_left, rel=1e-8)
ctx.check("transient: static right force in summary (N)", s["static_contact_forces"]["right"],
          R_right, rel=1e-8)
h = read_csv(out + "/history.csv")
c = read_csv(out + "/contacts.csv")
# the transient (CD-Lagrange) starts from the static state under the load it
# applies, gravity with the lumped mass M_lumped r g (free fall exact), whose
# element moments differ from the consistent M r g of the static analysis
# by O(h^2): the initial deflection differs from the static one by O(h^2)
# (0.5 % here, 4 times less on a mesh twice as fine) and the beam then stays
# at rest (before, it swung by that difference about the static state)
ctx.check("transient: initial u_m = static deflection (m), O(h^2)", h["muz"][0], u_static,
          rel=0.01)
# resting on its supports from the start and staying at rest: no impact
# (the supports count as pushing before the first step)
ctx.check("transient: n_impacts at rest on closed supports", s["n_impacts"], 0, abs_tol=0)
swing = np.max(np.abs(h["muz"] - h["muz"][0]))
ctx.check("transient: max |u_m(t) - u_m(0)| / |u_static| (at rest)", swing / abs(u_static), 0.0,
          abs_tol=1e-3)
fine = ["Model/Frame/Members=left_part: a, m, rect, steel, 4; "
        "right_part: m, b, rect, steel, 12"]
out, _ = ctx.run(prm, "transient_fine", fine + ["Time integration/Time step=2e-6"])
hf = read_csv(out + "/history.csv")
out, _ = ctx.run(prm, "static_fine", fine + ["Analysis/Type=static"])
u_static_fine = read_csv(out + "/history.csv")["muz"][0]
ctx.check("transient: initial deflection difference ratio h / (h/2), O(h^2)",
          abs(h["muz"][0] - u_static) / abs(hf["muz"][0] - u_static_fine), 4.0, abs_tol=0.5)
for name, R in (("left", R_left), ("right", R_right)):
    mean = c["impulse"][c["contact"] == name].sum() / T
    ctx.check("transient: time-averaged %s force (N)" % name, mean, R, rel=0.01)
# without the static state the beam starts undeformed and swings
out, _ = ctx.run(prm, "from_zero", ["Analysis/Initial state=given"])
h0 = read_csv(out + "/history.csv")
swing0 = np.max(np.abs(h0["muz"] - h0["muz"][0]))
ctx.check_true("from the undeformed state it swings by more than half the static deflection",
               swing0 > 0.5 * abs(u_static), "(%.4g m against %.4g m)" % (swing0, abs(u_static)))


def expect_error(what, sets, *fragments):
    p = subprocess.run([ctx.hati, prm] + sum((["--set", x] for x in sets), []) +
                       ["--set", "Output/Output directory=" + os.path.join(ctx.work, "err")],
                       capture_output=True, text=True, timeout=120)
    err = p.stderr.strip()
    ok = (p.returncode > 0 and len(err.splitlines()) == 1 and err.startswith("hati: error:")
          and all(x in err for x in fragments))
    ctx.check_true(what, ok, "(exit %d) %s" % (p.returncode, err))


uplift = ["Model/Frame/Contacts=left: a, 0, 0, 1, 0; right: m, 0, 0, 1, 0"]
expect_error("static: a contact in tension is refused, named", ["Analysis/Type=static"] + uplift,
             "contact 'left'", "tension")
expect_error("initial state: a contact in tension is refused, named", uplift, "contact 'left'",
             "tension")
expect_error("contacts with a gap are not closed (singular)",
             ["Analysis/Type=static",
              "Model/Frame/Contacts=left: a, 0, 0, 1, 0.001; right: b, 0, 0, 1, 0.001"],
             "singular", "along z")
ctx.finish()
