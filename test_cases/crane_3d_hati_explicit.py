#!/usr/bin/python3
"""HATI against fully explicit CD-Lagrange around the first trolley uplift
of the solid-girder crane under Rinaldi (issue #26; reference: the fully
explicit run from the same state, whose step, 3.2e-7 s, resolves every
contact and plate mode; doc/user_guide.md 3.6).

The crane of bridge_crane_3d.prm on its coarsest plates (1.1 m), true
heights, tied wheels, rigid hoist, undamped, Rinaldi X + Z. The trolley's
wheels first lift off about 1.73 s into the record (1.78 s with the
girders reduced): a fully explicit run from t = 0 would take 5.4 million
steps of 4 ms, about 6 h, so the window is reached by restarts
(Analysis/Initial state = file, doc/theory.md 1.1):
1. HATI with the girders reduced (Craig-Bampton, 150 Hz) from the static
   state to 1.70 s, writing its state;
2. HATI unreduced from that state to 1.732 s, writing its state: the
   reduced state is not an equilibrium of the unreduced girders (their
   modes above 150 Hz), and the jolt of that start rings in the undamped
   plates; 32 ms later the window starts from a state of the unreduced
   model (after 5 ms only HATI and CD-Lagrange differed by 2-6 % at the
   trolley wheels);
3. from the state at 1.732 s, HATI unreduced (dt = 4e-5 s, DT = 2e-4 s)
   and CD-Lagrange at 3.2e-7 s (12,500 steps) over 4 ms, in which a
   trolley wheel loses contact (which ones do depends on the state at
   1.732 s to round-off: two did while the static state and the reduction
   were solved with KLU instead of MUMPS).

Checks (measured in the comments):
- the trolley wheels' displacement vectors from the window's start, u(t) -
  u(1.732 s), at HATI's macro steps, within 2 % of the explicit run's
  largest (the issue's tolerance);
- the girders' mid-span within 2 %; the crane wheels (not the issue's
  criterion: they move 0.1 mm in the window, of 1.2 mm, next to the
  interface at the girders' ends) within 4 % of their largest |u|;
- the same trolley wheels lose contact, their first losses within 1 ms
  (the issue's tolerance);
- both energy balances closed (E1, G5; HATI's restart goes on from the
  state's interface multiplier, theory 1.1)."""
import csv
import os

import numpy as np

from hati_test import Context, read_summary

ctx = Context()
prm = ctx.prm("bridge_crane_3d.prm")
RECORDS = os.path.join(ctx.source, "data", "accelerograms")
COMMON = ["Model/Bridge crane/Girder element size=1.1",
          "Loading/Accelerogram X=" + os.path.join(RECORDS, "Rinaldi228.AT2"),
          "Loading/Accelerogram Z=" + os.path.join(RECORDS, "RinaldiUP.AT2"),
          "Model/Bridge crane/Eccentricities=true",
          "Model/Bridge crane/Travel=tied", "Model/Bridge crane/Hoist=rigid",
          "Model/Bridge crane/Damping ratio=0", "Output/Output interval=0",
          "Output/Section force interval=1e20", "Output/Progress interval=60"]
UNREDUCED = COMMON + ["Model/Decomposition/Implicit reduction=none",
                      "Output/History interval=4e-5"]
# on the macro-step grid (2e-4 s), so that every run ends where asked
START, SETTLED, END = 1.70, 1.732, 1.736


def restart_from(out):
    return ["Analysis/Initial state=file",
            "Analysis/Initial state file=" + os.path.join(out, "state.bin")]


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


prefix, _ = ctx.run(prm, "reduced_prefix", COMMON + [
    "Time integration/End time=%g" % START, "Output/History interval=0.01",
    "Output/State interval=100"])
settle, _ = ctx.run(prm, "unreduced_settle", UNREDUCED + restart_from(prefix) + [
    "Time integration/End time=%g" % SETTLED, "Output/State interval=100"])
window = UNREDUCED + restart_from(settle) + ["Time integration/End time=%g" % END]
out_h, _ = ctx.run(prm, "hati", window)
out_e, _ = ctx.run(prm, "explicit", window + ["Time integration/Method=CD-Lagrange",
                                             "Time integration/Time step=3.2e-7"])

names_h, A = history(out_h)
names_e, B = history(out_e)
ctx.check_true("the same history columns", names_h == names_e)
# HATI writes its rows at the macro steps (2e-4 s): the explicit rows there
rows = [int(np.argmin(abs(B[:, 0] - t))) for t in A[:, 0]]
ctx.check("largest time offset of the compared rows (s)",
          max(abs(B[j, 0] - A[i, 0]) for i, j in enumerate(rows)), 0.0, abs_tol=1e-9)
B = B[rows]
ctx.check("compared rows from t (s)", A[0, 0], SETTLED, abs_tol=1e-9)
ctx.check("compared rows up to t (s)", A[-1, 0], END, abs_tol=1e-9)
dA, dB = A - A[0], B - B[0]  # from the window's start
monitors = sorted({n.rsplit(".", 1)[0] for n in names_h[1:] if n.endswith(".ux")})
for m in monitors:
    cols = [names_h.index(m + "." + c) for c in ("ux", "uy", "uz")]
    diff = np.max(np.linalg.norm(dA[:, cols] - dB[:, cols], axis=1))
    if m.startswith("cw"):  # measured 1.0 to 1.9 %
        peak = np.max(np.linalg.norm(B[:, cols], axis=1))
        ctx.check(m + ": max |u_HATI - u_explicit| / explicit peak |u|", diff / peak, 0.0,
                  abs_tol=0.04)
    elif m.startswith("tw") or "midspan" in m:  # measured 0.45 to 0.78 %, 0.48 to 1.6 %
        peak = np.max(np.linalg.norm(dB[:, cols], axis=1))
        ctx.check(m + ": max |du_HATI - du_explicit| / explicit peak |du|", diff / peak, 0.0,
                  abs_tol=0.02)

lh, le = first_losses(out_h), first_losses(out_e)
trolley_h = sorted(c for c in lh if c.startswith("trolley_wheel") and "lateral" not in c)
trolley_e = sorted(c for c in le if c.startswith("trolley_wheel") and "lateral" not in c)
ctx.check_true("the same trolley wheels lose contact", trolley_h == trolley_e,
               "%s %s" % (lh, le))
ctx.check_true("trolley wheels lose contact in the window", len(trolley_e) >= 1, str(le))
for c in trolley_e:  # measured: trolley wheel 1, 0.004 ms
    ctx.check(c + ": first loss of contact, HATI - explicit (s)", lh.get(c, 1.0) - le[c], 0.0,
              abs_tol=1e-3)
for out, tol in ((out_h, 1e-8), (out_e, 1e-6)):
    s = read_summary(out)
    ctx.check(os.path.basename(out) + ": energy balance relative", s["energy_balance_relative"],
              0.0, abs_tol=tol)
ctx.finish()
