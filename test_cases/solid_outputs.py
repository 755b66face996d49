#!/usr/bin/python3
"""The outputs of the solids of a frame (issue #25): a steel prism 2 x 0.4 x
0.3 m between two beams (ties at its ends x = 0 and x = 2), the first beam
clamped, the second pulled along its axis by N = 1e5 N, no gravity:

- static: the stress is uniform, sigma_xx = N / A, so the von Mises stress
  is N / A everywhere: in summary.json `solids.prism.max_von_mises` (1e-6
  relative), in every cell of stress_envelope.vtu and at every node of
  solids-00000.vtu (Float32: 1e-6); solids.pvd and the VTU files parse, with
  the point count of the cells subdivided `Solid element degree` times and
  the field names of the contract;
- Newmark, a short run with the load applied suddenly: solids.pvd lists as
  many snapshots as solution.pvd, at the same times; the time of the
  largest von Mises stress (summary.json and stress_envelope.vtu) is a time
  of the run; the terminal summary has a line for the prism;
- a frame without solids writes no solids files and no `solids` entry.

The parameter file is written into the work folder: parameter_files/ holds
no frame with solids (every one of them is run by regression_digests.sh).
"""
import os

import numpy as np

from hati_test import Context, read_csv, read_summary
from vtu_files import read_pvd, read_vtu

ctx = Context()
N, A = 1e5, 0.4 * 0.3
sigma = N / A
degree, n_cells = 2, 4 * 2 * 2

prm = os.path.join(ctx.work, "solid_prism.prm")
with open(prm, "w") as f:
    f.write("""subsection Analysis
  set Type = static
end
subsection Loading
  set Gravity = 0, 0, 0
end
subsection Model
  set Type = frame
  subsection Frame
    set Nodes     = A0: -1, 0, 0; A1: 0, 0, 0; B0: 2, 0, 0; B1: 3, 0, 0
    set Materials = steel: 2.1e11, 0.3, 7850
    set Sections  = rod: general, 1.2e-2, 2e-4, 1e-4, 2e-4, 5e-3, 5e-3
    set Members   = a: A0, A1, rod, steel, 2; b: B0, B1, rod, steel, 2
    set Supports  = A0: clamped
    set Solids    = prism: box, 0, -0.2, -0.15, 2, 0.2, 0.15, 4, 2, 2, steel
    set Solid element degree = %d
    set Ties      = ta: A1, prism, x=0; tb: B0, prism, x=2
    set Nodal loads = B1: %g, 0, 0
    set Monitor nodes = B0, B1
  end
end
""" % (degree, N))


def check_envelope(tag, out, reference=None, times=None):
    n_points, n, fields = read_vtu(os.path.join(out, "stress_envelope.vtu"))
    ok = (n == n_cells and n_points == 8 * n_cells
          and set(fields) == {"max_von_mises", "max_von_mises_time"})
    ctx.check_true(tag + ": stress_envelope.vtu: the cells and the fields",
                   ok, "(%d cells, %d points, fields %s)" % (n, n_points, sorted(fields)))
    if not ok:
        return np.zeros(1), np.zeros(1)
    # one value per cell, at its eight vertices
    vm, when = (fields[k][1].reshape(n_cells, 8) for k in ("max_von_mises", "max_von_mises_time"))
    ctx.check_true(tag + ": the envelope is constant over each cell",
                   np.all(vm == vm[:, :1]) and np.all(when == when[:, :1]), "")
    vm, when = vm[:, 0], when[:, 0]
    if reference is not None:
        ctx.check(tag + ": envelope von Mises, every cell (Pa) = N/A",
                  np.max(np.abs(vm - reference)), 0.0, abs_tol=1e-6 * reference)
    if times is not None:
        gap = max(np.min(np.abs(np.asarray(times) - t)) for t in when)
        ctx.check(tag + ": envelope times are times of the run (s)", gap, 0.0,
                  abs_tol=1e-7 * max(times))
    return vm, when


# --- static: uniform stress
out, p = ctx.run(prm, "static")
s = read_summary(out)
peak = s["solids"]["prism"]["max_von_mises"]
ctx.check("static: summary max_von_mises (Pa) = N/A", peak["value"], sigma, rel=1e-6)
ctx.check("static: its time (s)", peak["time"], 0.0, abs_tol=0.0)
x = peak["point"]
ctx.check_true("static: its point lies in the prism",
               len(x) == 3 and 0 <= x[0] <= 2 and abs(x[1]) <= 0.2 and abs(x[2]) <= 0.15,
               "(%s)" % x)
check_envelope("static", out, reference=sigma)
snapshots = read_pvd(os.path.join(out, "solids.pvd"))
ctx.check_true("static: solids.pvd lists solids-00000.vtu at t = 0",
               snapshots == [(0.0, "solids-00000.vtu")], "(%s)" % snapshots)
n_points, n, point = read_vtu(os.path.join(out, "solids-00000.vtu"))
ctx.check_true("static: solids-00000.vtu points and cells (cells subdivided p times)",
               n_points == n_cells * (degree + 1) ** 3 and n == n_cells * degree ** 3,
               "(%d points, %d cells)" % (n_points, n))
ctx.check_true("static: its point fields",
               {k: c for k, (c, _) in point.items()} ==
               {"displacement": 3, "velocity": 3, "stress": 9, "von_mises": 1},
               "(%s)" % {k: c for k, (c, _) in point.items()})
ctx.check("static: nodal von Mises, every node (Pa) = N/A",
          np.max(np.abs(point["von_mises"][1] - sigma)), 0.0, abs_tol=1e-6 * sigma)
stress = point["stress"][1].reshape(-1, 9)
ctx.check("static: nodal stress_xx, every node (Pa) = N/A",
          np.max(np.abs(stress[:, 0] - sigma)), 0.0, abs_tol=1e-6 * sigma)
ctx.check_true("static: the terminal prints the prism's largest von Mises stress",
               any("prism" in line and "MPa" in line for line in p.stdout.splitlines()),
               "")

# --- Newmark: the load applied suddenly
out, p = ctx.run(prm, "newmark", ["Analysis/Type=transient", "Time integration/Method=Newmark",
                                  "Time integration/Time step=1e-4",
                                  "Time integration/End time=2e-3",
                                  "Output/Output interval=5e-4"])
s = read_summary(out)
times = list(read_csv(out + "/history.csv")["time"])
beams = read_pvd(os.path.join(out, "solution.pvd"))
solids = read_pvd(os.path.join(out, "solids.pvd"))
ctx.check_true("newmark: solids.pvd lists as many snapshots as solution.pvd, same times",
               len(beams) == 5 and [t for t, _ in solids] == [t for t, _ in beams],
               "(%d and %d)" % (len(solids), len(beams)))
ctx.check_true("newmark: every snapshot of solids.pvd exists and parses",
               all(read_vtu(os.path.join(out, f))[0] == n_cells * (degree + 1) ** 3
                   for _, f in solids), "")
peak = s["solids"]["prism"]["max_von_mises"]
gap = min(abs(t - peak["time"]) for t in times)
ctx.check("newmark: summary time of the largest von Mises is a row time (s)", gap, 0.0,
          abs_tol=1e-12)
ctx.check_true("newmark: the largest von Mises stress exceeds 0",
               peak["value"] > 0.1 * sigma, "(%.6g Pa)" % peak["value"])
vm, _ = check_envelope("newmark", out, times=times)
ctx.check("newmark: largest of the envelope (Pa) = summary", float(np.max(vm)), peak["value"],
          rel=1e-6)
ctx.check_true("newmark: the terminal prints the prism's largest von Mises stress",
               any("prism" in line and "MPa" in line for line in p.stdout.splitlines()), "")

# --- a frame without solids: no solids outputs
out, _ = ctx.run(ctx.prm("cantilever_static.prm"), "no_solids")
files = set(os.listdir(out))
ctx.check_true("no solids: no solids.pvd, solids-*.vtu, stress_envelope.vtu",
               not any(f.startswith("solids") or f.startswith("stress_envelope") for f in files),
               "(%s)" % sorted(files))
ctx.check_true("no solids: no summary entry `solids`", "solids" not in read_summary(out), "")
ctx.finish()
