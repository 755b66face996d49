#!/usr/bin/python3
"""HATI against fully explicit CD-Lagrange on the solid-girder crane
(issue #26; reference: the fully explicit run of the same model, whose step
resolves every contact and plate mode; doc/user_guide.md 3.6).

The crane of bridge_crane_3d.prm at 0.55 m plate elements, true heights,
tied wheels, rigid hoist, undamped, unreduced; from its static state a base
acceleration along X stepping to 30 g in 1 ms (written here), which lifts
the crane wheels on one rail after 2.9 ms. HATI (dt = 4e-5 s, DT = 2e-4 s)
against CD-Lagrange at 2e-6 s over 3.6 ms.

What makes it fit the suite: the fully explicit step on the default 6/13 mm
plates is 3.3e-7 s at 10 ms a step (half an hour for the 0.05 s of
bench/crane3d_hati_vs_explicit.sh, which gave 0.005 % at the trolley wheels
and lift-offs 0.5 ms apart on the default girders). Here the girders' webs
and flanges are 50 mm (dt_crit 2.42e-6 s; the plate elements still 11
thicknesses in their plane) and the window is the first lift-off only:
about a minute (the explicit run about 30 s, HATI 20 s with its static
state and factorisation).

Checks:
- the monitors' displacement vectors from the static state, u(t) - u(0),
  at HATI's macro steps, against the explicit run's peak |u| (1.4 mm at
  the trolley wheels and mid-span, 0.24 mm at the crane wheels): the trolley
  wheels, hoist and girders' mid-span within 2 % (the issue's tolerance;
  measured 0.007 %, 0.005 %, 0.07 %), the crane wheels within 3 %
  (measured 1.2 %: they lift off in the window);
- the first loss of contact of the crane wheels on the lifting rail within
  0.2 ms (the issue asks 1 ms), and the same wheels lift in both runs;
- both energy balances closed (E1, G5)."""
import csv
import os

import numpy as np

from hati_test import Context, read_summary

ctx = Context()
prm = ctx.prm("bridge_crane_3d.prm")
pulse = os.path.join(ctx.work, "step_30g.txt")
with open(pulse, "w") as f:
    f.write("# time (s)  base acceleration (g): 30 g along X reached over 1 ms\n"
            "0 0\n0.001 30\n1 30\n")
COMMON = ["Model/Bridge crane/Girder element size=0.55",
          "Model/Bridge crane/Girder section=box, 0.46, 1.10, 0.05, 0.05",
          "Model/Bridge crane/Eccentricities=true",
          "Model/Bridge crane/Travel=tied", "Model/Bridge crane/Hoist=rigid",
          "Model/Bridge crane/Damping ratio=0",
          "Model/Decomposition/Implicit reduction=none",
          "Loading/Accelerogram X=" + pulse, "Loading/Accelerogram Z=",
          "Time integration/End time=0.0036", "Output/Output interval=0",
          "Output/History interval=4e-5", "Output/Section force interval=0"]


def history(out):
    with open(os.path.join(out, "history.csv"), newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], np.array([[float(x) for x in r] for r in rows[1:] if len(r) == len(rows[0])])


def first_losses(out):
    first = {}
    with open(os.path.join(out, "contact_episodes.csv"), newline="") as f:
        for r in csv.DictReader(f):
            first.setdefault(r["contact"], float(r["start"]))
    return first


out_h, _ = ctx.run(prm, "hati", COMMON)
out_e, _ = ctx.run(prm, "explicit", COMMON + ["Time integration/Method=CD-Lagrange",
                                             "Time integration/Time step=2e-6"])
names_h, A = history(out_h)
names_e, B = history(out_e)
ctx.check_true("the same history columns", names_h == names_e)
# HATI writes its rows at the macro steps (2e-4 s): the explicit rows there
rows = [int(np.argmin(abs(B[:, 0] - t))) for t in A[:, 0]]
ctx.check("largest time offset of the compared rows (s)",
          max(abs(B[j, 0] - A[i, 0]) for i, j in enumerate(rows)), 0.0, abs_tol=1e-9)
B = B[rows]
A, B = A - A[0], B - B[0]  # from each run's static state
ctx.check("compared rows up to t (s)", A[-1, 0], 0.0036, abs_tol=1e-9)
monitors = sorted({n.rsplit(".", 1)[0] for n in names_h[1:] if n.endswith(".ux")})
for m in monitors:
    cols = [names_h.index(m + "." + c) for c in ("ux", "uy", "uz")]
    peak = np.max(np.linalg.norm(B[:, cols], axis=1))
    diff = np.max(np.linalg.norm(A[:, cols] - B[:, cols], axis=1))
    ctx.check(m + ": max |u_HATI - u_explicit| / explicit peak", diff / peak, 0.0,
              abs_tol=0.03 if m.startswith("cw") else 0.02)

lh, le = first_losses(out_h), first_losses(out_e)
ctx.check_true("the same wheels lose contact", sorted(lh) == sorted(le), "%s %s" % (lh, le))
lifting = [c for c in ("crane_wheel_2", "crane_wheel_4") if c in le]
ctx.check_true("crane wheels 2 and 4 lift off", len(lifting) == 2, str(le))
# measured: 2.88 ms (HATI, whose micro step is 0.04 ms) and 2.87 ms
for c in lifting:
    ctx.check(c + ": first loss of contact, HATI - explicit (s)", lh.get(c, 1.0) - le[c], 0.0,
              abs_tol=2e-4)
for out in (out_h, out_e):
    s = read_summary(out)
    ctx.check(os.path.basename(out) + ": energy balance relative", s["energy_balance_relative"],
              0.0, abs_tol=1e-8)
ctx.finish()
