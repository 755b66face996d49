#!/usr/bin/python3
"""Compare a HATI run with a fully explicit run of the same model (the
benches of the solid-girder crane, bench/crane3d_*.sh): the monitors'
displacement vectors from the first compared row, u(t) - u(t_0), at HATI's
macro steps, their largest difference in % of the explicit run's peak; each
contact's first loss of contact in both runs, of any length and lasting at
least HATI's micro step (the explicit run resolves losses of a few us that
HATI's micro step cannot see) and its time out of contact; the wall times
and energy balances of the two runs and the speed-up.
Usage: compare_hati_explicit.py HATI_OUTPUT_DIR EXPLICIT_OUTPUT_DIR"""
import csv
import json
import sys

import numpy as np


def history(d):
    rows = list(csv.reader(open(d + "/history.csv")))
    return rows[0], np.array([[float(x) for x in r] for r in rows[1:] if len(r) == len(rows[0])])


def time_out(d):
    out = {}
    for r in csv.DictReader(open(d + "/contact_episodes.csv")):
        out[r["contact"]] = out.get(r["contact"], 0.0) + float(r["duration"])
    return out


def first_losses(d, shortest=0.0):
    first = {}
    for r in csv.DictReader(open(d + "/contact_episodes.csv")):
        if float(r["duration"]) >= shortest:
            first.setdefault(r["contact"], float(r["start"]))
    return first


ha, A = history(sys.argv[1])
hb, B = history(sys.argv[2])
# HATI writes its rows at the macro steps: the explicit rows at those times
idx = [int(np.argmin(abs(B[:, 0] - t))) for t in A[:, 0]]
keep = [i for i, j in enumerate(idx) if abs(B[j, 0] - A[i, 0]) < 1e-9]
A, B = A[keep], B[[idx[i] for i in keep]]
print("rows compared: %d, t = %.4f to %.4f s" % (len(A), A[0, 0], A[-1, 0]))
A, B = A - A[0], B - B[0]
print("%-20s %14s %14s %8s" % ("monitor", "peak |du| (m)", "max diff (m)", "% peak"))
for m in sorted({n.rsplit(".", 1)[0] for n in ha[1:] if n.endswith(".ux")}):
    cols = [m + "." + c for c in ("ux", "uy", "uz")]
    if not all(c in ha and c in hb for c in cols):
        continue
    a = A[:, [ha.index(c) for c in cols]]
    b = B[:, [hb.index(c) for c in cols]]
    peak = np.linalg.norm(b, axis=1).max()
    d = np.linalg.norm(a - b, axis=1).max()
    print("%-20s %14.4e %14.4e %8.3f" % (m, peak, d, 100 * d / max(peak, 1e-300)))
s = [json.load(open(d + "/summary.json")) for d in sys.argv[1:3]]
# summary.json dt of a HATI run is its macro step DT = m dt
micro_step = s[0]["dt"] / s[0].get("time_step_ratio", 1)
for shortest, title in ((0.0, "first loss of contact"),
                        (micro_step, "the same, >= %g s" % micro_step)):
    fa, fb = first_losses(sys.argv[1], shortest), first_losses(sys.argv[2], shortest)
    print("%-26s %12s %12s %10s" % (title, "HATI (s)", "explicit (s)", "diff (ms)"))
    for c in sorted(set(fa) | set(fb)):
        h, e = fa.get(c), fb.get(c)
        print("%-26s %12s %12s %10s" % (c, "%.6f" % h if h else "-", "%.6f" % e if e else "-",
                                        "%.3f" % (1e3 * (h - e)) if h and e else "-"))
ta, tb = time_out(sys.argv[1]), time_out(sys.argv[2])
print("%-26s %12s %12s" % ("time out of contact (ms)", "HATI", "explicit"))
for c in sorted(set(ta) | set(tb)):
    print("%-26s %12.3f %12.3f" % (c, 1e3 * ta.get(c, 0.0), 1e3 * tb.get(c, 0.0)))
for name, x in zip(("HATI", "explicit"), s):
    print("%-9s n_dofs %d, steps %d, set-up %.1f s, stepping %.1f s, wall %.1f s, "
          "energy balance %.2e" % (name, x["n_dofs"], x["n_steps"], x["setup_wall_time"],
                                   x["stepping_wall_time"], x["wall_time"],
                                   x["energy_balance_relative"]))
print("speed-up (stepping): %.0f x; with set-up: %.0f x" % (
    s[1]["stepping_wall_time"] / s[0]["stepping_wall_time"],
    (s[1]["stepping_wall_time"] + s[1]["setup_wall_time"]) /
    (s[0]["stepping_wall_time"] + s[0]["setup_wall_time"])))
