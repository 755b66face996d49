#!/usr/bin/python3
"""Time integration/Newmark/Linear solver = auto | KLU | MUMPS (issue #25):
the portal frame (parameter_files/portal_frame_dynamic.prm, 456 DoFs) run
with KLU and with MUMPS gives the same results, and the terminal names the
solver in use:
- Newmark transient, HATI (portal_frame_split.prm: the implicit
  subdomain's effective matrix and the interface columns), static and modal
  analyses, each once with Linear solver = KLU and once with MUMPS: the
  outputs agree to 1e-9 of the peak of each column;
- auto and the former name direct resolve to KLU on this small model;
- an unknown value is refused in one line naming the entry."""
import os
import subprocess

import numpy as np

from hati_test import Context, read_csv

ctx = Context()
entry = "Time integration/Newmark/Linear solver"
# every monitored component loaded (all three axes), so that no column of
# the outputs is at round-off level
load = ["Loading/Base acceleration=1, 2, -3"]
cases = {
    "newmark": (ctx.prm("portal_frame_dynamic.prm"), "history.csv",
                ["Time integration/End time=0.3", "Output/Output interval=0"] + load),
    "hati": (ctx.prm("portal_frame_split.prm"), "history.csv",
             ["Time integration/End time=0.1", "Output/Output interval=0"] + load),
    "static": (ctx.prm("portal_frame_dynamic.prm"), "history.csv",
               ["Analysis/Type=static", "Loading/Gravity=1, 2, -9.81",
                "Loading/Base acceleration=0, 0, 0"]),
    "modal": (ctx.prm("portal_frame_dynamic.prm"), "modes.csv", ["Analysis/Type=modal"]),
}


def compare(what, a, b):
    """max over the columns of max |a - b| / max |a| (a column that is zero
    with one solver must be zero with the other)."""
    worst, name = 0.0, ""
    for column in a.dtype.names:
        peak = np.max(np.abs(a[column]))
        diff = np.max(np.abs(a[column] - b[column]))
        ratio = diff / peak if peak > 0 else (0.0 if diff == 0 else np.inf)
        if ratio > worst:
            worst, name = ratio, column
    # independent factorisations (KLU, MUMPS) of the same matrices: they
    # differ by round-off only (measured below 1e-12)
    ctx.check("%s: KLU vs MUMPS, max |diff| / column peak (%s)" % (what, name or "-"),
              worst, 0.0, abs_tol=1e-9)


for what, (prm, csv, sets) in cases.items():
    results = {}
    for solver in ("KLU", "MUMPS"):
        out, p = ctx.run(prm, "%s_%s" % (what, solver), sets + ["%s=%s" % (entry, solver)])
        results[solver] = read_csv(os.path.join(out, csv))
        if what in ("newmark", "static"):
            ctx.check_true("%s: the terminal names the %s solver" % (what, solver),
                           "%s solver)" % solver in p.stdout)
    ctx.check_true("%s: the same rows with KLU and MUMPS" % what,
                   len(results["KLU"]) == len(results["MUMPS"]) and len(results["KLU"]) > 0)
    compare(what, results["KLU"], results["MUMPS"])

# auto (the default) and direct (the former name) are KLU on 456 DoFs
newmark_prm, _, newmark_sets = cases["newmark"]
for value in ("auto", "direct"):
    _, p = ctx.run(newmark_prm, "newmark_" + value,
                   newmark_sets + ["Time integration/End time=0.01", "%s=%s" % (entry, value)])
    ctx.check_true("Linear solver = %s: Newmark prints the KLU solver" % value,
                   "KLU solver)" in p.stdout)

# an unknown value: one line naming the entry (deal.II's message for a
# parameter file names it without its subsections, with the line)
with open(newmark_prm) as f:
    text = f.read()
bad_prm = os.path.join(ctx.work, "bad_solver.prm")
with open(bad_prm, "w") as f:
    f.write(text.replace("set Linear solver = direct", "set Linear solver = klu"))
for what, args, name in [("--set", [newmark_prm, "--set", "%s=Pardiso" % entry], entry),
                         ("a parameter file", [bad_prm], "Linear solver")]:
    p = subprocess.run([ctx.hati, *args, "--set",
                        "Output/Output directory=" + os.path.join(ctx.work, "refused")],
                       capture_output=True, text=True, timeout=120, cwd=ctx.work)
    err = p.stderr.strip()
    ctx.check_true("unknown linear solver in %s: exit 1, one line naming the entry" % what,
                   p.returncode == 1 and len(err.splitlines()) == 1
                   and err.startswith("hati: error: ") and name in err
                   and "auto|KLU|MUMPS|direct|iterative" in err, err)

ctx.finish()
