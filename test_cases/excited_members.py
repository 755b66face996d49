#!/usr/bin/python3
"""Loading/Excited members on parameter_files/portal_frame_dynamic.prm
(base acceleration step a_g = 1 m/s^2 along X, 500 kg on each top corner).

The load -M_S r a_g of a member set S is assembled from S's elements and the
point masses on S's nodes. The columns (S1) and the beams (S2) split the
elements; the four point masses sit on joints of both sets, so they are
loaded twice. Hence, by linearity, for every response u

    u(S1) + u(S2) - u(all) = u(point masses alone),

where the right-hand side is an independent run without base acceleration
and with the nodal loads -m a_g on the four corners (another code path: the
Nodal loads entry). Checked to round-off for a static analysis (K u = F),
for Newmark (consistent mass) and for CD-Lagrange (lumped mass). Also:
listing every member equals the empty (default) list, the restricted
response is a proper part of the whole, and the one-line errors."""
import os
import subprocess

import numpy as np

from hati_test import Context, read_csv

ctx = Context()
prm = ctx.prm("portal_frame_dynamic.prm")
columns = "colA, colB, colC, colD"
beams = "beamAB, beamCD, crossAC, crossBD"
corner_loads = "A1: -500, 0, 0; B1: -500, 0, 0; C1: -500, 0, 0; D1: -500, 0, 0"
cases = {
    "all": [],
    "listed": ["Loading/Excited members=%s, %s" % (columns, beams)],
    "columns": ["Loading/Excited members=" + columns],
    "beams": ["Loading/Excited members=" + beams],
    "masses": ["Loading/Base acceleration=0, 0, 0", "Model/Frame/Nodal loads=" + corner_loads],
}
analyses = {
    "static": ["Analysis/Type=static"],
    "Newmark": ["Time integration/End time=0.3"],
    "CD-Lagrange": ["Time integration/Method=CD-Lagrange", "Time integration/Time step=2e-5",
                    "Time integration/End time=0.02", "Output/History interval=1e-3"],
}
for analysis, sets in analyses.items():
    u = {}
    for case, extra in cases.items():
        out, _ = ctx.run(prm, "%s_%s" % (analysis, case), sets + extra)
        h = read_csv(out + "/history.csv")
        u[case] = np.column_stack([h[n] for n in h.dtype.names if n != "time"])
    scale = np.max(np.abs(u["all"]))
    ctx.check_true("%s: a non-zero response" % analysis, scale > 0, "(max %.4g)" % scale)
    ctx.check("%s: max |u(listed) - u(all)| / max |u(all)|" % analysis,
              np.max(np.abs(u["listed"] - u["all"])) / scale, 0.0, abs_tol=1e-12)
    ctx.check("%s: max |u(S1) + u(S2) - u(all) - u(masses)| / max |u(all)|" % analysis,
              np.max(np.abs(u["columns"] + u["beams"] - u["all"] - u["masses"])) / scale, 0.0,
              abs_tol=1e-9)
    # the columns' share is a proper part: neither nothing nor everything
    ratio = np.max(np.abs(u["columns"])) / scale
    ctx.check_true("%s: columns-only response is a proper part of the whole" % analysis,
                   0.05 < ratio < 0.95, "(ratio %.4f)" % ratio)


def expect_error(what, args, *fragments):
    p = subprocess.run([ctx.hati] + args + ["--set", "Output/Output directory=" +
                                            os.path.join(ctx.work, "err")],
                       capture_output=True, text=True, timeout=120)
    err = p.stderr.strip()
    ok = (p.returncode > 0 and len(err.splitlines()) == 1 and err.startswith("hati: error:")
          and all(f in err for f in fragments))
    ctx.check_true(what, ok, "(exit %d) %s" % (p.returncode, err))


expect_error("unknown excited member", [prm, "--set", "Loading/Excited members=colA, colZ"],
             "Loading/Excited members", "colZ")
expect_error("excited members on a model without members",
             [ctx.prm("bar_impact_1d.prm"), "--set", "Loading/Excited members=colA"],
             "Loading/Excited members", "bar")
ctx.finish()
