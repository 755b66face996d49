#!/usr/bin/python3
"""HATI with a Craig-Bampton reduced implicit part (issue #27; C1,
doc/theory.md 12.1-12.2: Model/Decomposition/Implicit reduction =
Craig-Bampton) on parameter_files/beam_solid_prism.prm (a step force and
torque at B1 from t = 0, 0.02 s, m = 5).

Reference: HATI with the unreduced implicit part, same steps (the
reduction changes only the implicit part's basis).
1. beam 'b' explicit, beam 'a' and the prism implicit (the tie at B0: six
   interface rows, the reduction's six boundary DoFs): the histories of B1
   (u_y, u_z, r_x), B0 (u_z) and A1 (u_z) converge to the unreduced run as
   the cut-off rises (200, 1000, 3000 Hz: 2, 8, 23 fixed-interface modes),
   the error at 3000 Hz below 1e-4 of the peak (measured 1.0e-5 .. 7.4e-5)
   and each cut-off's at most half the one below (measured ratios 0.05 to
   0.2); the energy balance closes with the interface work in reduced
   coordinates (1e-10 of the largest energy; measured 5e-15 .. 3e-14);
   summary.json `reduction`: modes, boundary_dofs = 6, the kept modes below
   the cut-off, the free-interface frequency check within 0.5 % below a
   quarter of the cut-off (measured at most 0.05 %; at 200 Hz, two modes
   kept, the 97.9 Hz mode is 2.9 % high).
2. the reverse (the prism explicit, both beams implicit): twelve interface
   rows plus the three DoFs of the point load at B1 (u_y, u_z, r_x) as
   boundary DoFs (15), B1 within 1e-5 of the peak at 3000 Hz.
3. a static start (gravity, beam 'b' resting on a contact, the case of
   test_cases/beam_solid_rest_hati.py): the reduced initial state
   (doc/theory.md 12.2) is at rest, velocities below 1e-5 g DT (measured
   3.8e-8, the unreduced run 2.0e-8).
4. the output rows (doc/theory.md 12.2): the history rows between two
   rows of `Section force interval` and of the VTU recover only the DoFs
   they read (monitors, section-force members) and the cuts' section forces
   as `(L T) q` (Model::output_functionals()). Reference:
   the same run with a full expansion at every row (Section force interval
   = History interval, a VTU snapshot at every row): history.csv, the
   section force envelope and the rows of section_forces.csv they share
   equal to 1e-12 of the peak; and the stress envelope of rows without VTU,
   expanded later by batches (U = T Q), equal to the full rows' (every
   cell's peak and its time, summary.json, section_forces.csv) to 1e-12.
5. Reduction modal damping ratio = 0.05 (doc/theory.md 12.3; its ratios
   and Newmark's use of the damping matrix are checked against the state
   space and the damped oscillator in unit.craig_bampton): the energy balance
   closes with the damping's dissipation (1e-10; measured 1.6e-14), which
   the undamped run of section 1 does not have, and summary.json
   `reduction.modal_damping_ratio` (null in section 1)."""
import re

import numpy as np

from hati_test import Context, read_csv, read_summary
from vtu_files import read_vtu

ctx = Context()
prm = ctx.prm("beam_solid_prism.prm")
g = 9.81
BASE = ["Time integration/End time=0.02", "Time integration/Method=HATI",
        "Time integration/HATI/Time step ratio=5"]
CB = "Model/Decomposition/Implicit reduction=Craig-Bampton"
CUTOFFS = (200.0, 1000.0, 3000.0)


def errors(out, ref, columns):
    """max |reduced - unreduced| / peak per column."""
    h, r = read_csv(out + "/history.csv"), read_csv(ref + "/history.csv")
    return [np.max(np.abs(h[c] - r[c])) / np.max(np.abs(r[c])) for c in columns]


# ---- 1. the solid implicit and reduced ---------------------------------------
FORWARD = BASE + ["Time integration/Time step=1e-5", "Model/Decomposition/Explicit members=b"]
columns = ("B1uy", "B1uz", "B1urx", "B0uz", "A1uz")
ref, _ = ctx.run(prm, "unreduced", FORWARD)
previous = None
print("cut-off (Hz)  modes  " + "  ".join("%8s" % c for c in columns))
for f_c in CUTOFFS:
    out, _ = ctx.run(prm, "reduced_%g" % f_c,
                     FORWARD + [CB, "Model/Decomposition/Reduction cutoff frequency=%g" % f_c])
    s = read_summary(out)
    r = s["reduction"]
    e = errors(out, ref, columns)
    print("%12g  %5d  " % (f_c, r["modes"]) + "  ".join("%8.2e" % x for x in e))
    ctx.check_true("%g Hz: six boundary DoFs (the tie's rows)" % f_c,
                   r["boundary_dofs"] == 6 and r["point_load_dofs"] == 0, str(r))
    ctx.check_true("%g Hz: modes kept up to the cut-off" % f_c,
                   r["modes"] > 0 and r["highest_kept_frequency"] <= f_c, str(r))
    ctx.check("%g Hz: energy balance with the interface work (relative)" % f_c,
              s["energy_balance_relative"], 0.0, abs_tol=1e-10)
    check = r["frequency_check"]
    for fr, fu in zip(check["reduced"], check["unreduced"]):
        if fu < 0.25 * f_c:
            ctx.check("%g Hz: free-interface frequency %.4g Hz, reduced / unreduced" % (f_c, fu),
                      fr / fu, 1.0, rel=5e-3)
    if previous is not None:
        for c, a, b in zip(columns, e, previous):
            ctx.check_true("%g Hz: %s error at most half the lower cut-off's" % (f_c, c),
                           a <= 0.5 * b, "(%.3g after %.3g)" % (a, b))
    previous = e
for c, x in zip(columns, previous):
    ctx.check("3000 Hz: %s, max |reduced - unreduced| / peak" % c, x, 0.0, abs_tol=1e-4)

# ---- 2. the beams implicit and reduced, the point load a boundary DoF --------
REVERSE = BASE + ["Time integration/Time step=4e-6", "Model/Decomposition/Explicit members=prism"]
ref, _ = ctx.run(prm, "reverse_unreduced", REVERSE)
out, _ = ctx.run(prm, "reverse_reduced",
                 REVERSE + [CB, "Model/Decomposition/Reduction cutoff frequency=3000"])
r = read_summary(out)["reduction"]
ctx.check_true("reverse: 12 interface rows and 3 point-load DoFs as boundary DoFs",
               r["boundary_dofs"] == 15 and r["point_load_dofs"] == 3, str(r))
for c, x in zip(("B1uy", "B1uz", "B1urx"), errors(out, ref, ("B1uy", "B1uz", "B1urx"))):
    ctx.check("reverse, 3000 Hz: %s, max |reduced - unreduced| / peak" % c, x, 0.0,
              abs_tol=1e-5)
ctx.check("reverse: energy balance (relative)",
          read_summary(out)["energy_balance_relative"], 0.0, abs_tol=1e-10)

# ---- 3. a static start stays at rest ------------------------------------------
REST = [
    "Analysis/Initial state=static",
    "Model/Frame/Nodes=A0: -1, 0, 0; A1: 0, 0, 0; B0: 2, 0, 0; B1: 3, 0, 0; "
    "C0: 2, 0, 0.2; C1: 3, 0, 0.2",
    "Model/Frame/Sections=rod: general, 1.2e-2, 2e-4, 1e-4, 2e-4, 5e-3, 5e-3; "
    "thin: general, 1e-3, 2e-7, 2e-7, 4e-7, 5e-4, 5e-4",
    "Model/Frame/Members=a: A0, A1, rod, steel, 4; b: B0, B1, rod, steel, 4; "
    "c: C0, C1, thin, steel, 4",
    "Model/Frame/Supports=A0: clamped; C1: clamped",
    "Model/Frame/Point masses=B1: 200, 20, 20, 20; C0: 200, 1, 1, 1",
    "Model/Frame/Nodal loads=",
    "Model/Frame/Contacts=rest: C0, B0, 0, 0, 1, 0",
    "Model/Frame/Monitor nodes=A1, B0, B1, C0",
    "Loading/Gravity=0, 0, -%g" % g,
    "Time integration/End time=0.01", "Output/Output interval=0",
    "Output/History interval=5e-5", "Time integration/Method=HATI",
    "Time integration/Time step=1e-5", "Time integration/HATI/Time step ratio=5",
    "Model/Decomposition/Explicit members=b, c", CB,
    "Model/Decomposition/Reduction cutoff frequency=1000"]
out, _ = ctx.run(prm, "rest_reduced", REST)
h = read_csv(out + "/history.csv")
v = max(np.max(np.abs(h[n])) for n in h.dtype.names
        if n.endswith(("vx", "vy", "vz", "vrx", "vry", "vrz")))
ctx.check("static start, reduced: largest velocity / (g DT)", v / (g * 5e-5), 0.0, abs_tol=1e-5)
ctx.check("static start, reduced: impacts", read_summary(out)["n_impacts"], 0, abs_tol=0)

# ---- 4. partial recovery at the history rows = full expansion ----------------
ROWS = FORWARD + [CB, "Model/Decomposition/Reduction cutoff frequency=3000",
                  "Model/Frame/Solid cuts=c1: prism, x=0.75; c2: prism, x=1.5",
                  "Model/Frame/Section force members=a", "Output/Output interval=0"]
# (Section force interval = 1 s: full rows at t = 0 and at the end only, so
# that the envelope's peaks come from the history rows between them)
partial, _ = ctx.run(prm, "rows_partial", ROWS + ["Output/Section force interval=1"])
# (a VTU snapshot at every row: a full expansion at every row, the envelope
# updated at once)
full, _ = ctx.run(prm, "rows_full", ROWS + ["Output/Section force interval=1e-4",
                                            "Output/Output interval=1e-4"])
hp, hf = read_csv(partial + "/history.csv"), read_csv(full + "/history.csv")
ctx.check_true("rows: the same history rows", len(hp) == len(hf) and len(hp) > 100, str(len(hp)))
# each column against its peak, at least 1e-3 of the largest peak of its
# kind (displacements u..., velocities v...): the axial columns (ux, vx) are
# round-off of zero here (1e-17 m of 3e-3 m), whose two summation orders
# (the rows of T against BLAS dgemv, whose order depends on the kernels
# OpenBLAS picks) differ by 2e-4 of themselves
def kind(c):
    return re.search(r"([uv])r?[xyz]$", c).group(1)
columns = [c for c in hf.dtype.names if c != "time"]
largest = {k: max(np.max(np.abs(hf[c])) for c in columns if kind(c) == k)
           for k in ("u", "v")}
worst = max(np.max(np.abs(hp[c] - hf[c])) /
            max(np.max(np.abs(hf[c])), 1e-3 * largest[kind(c)], 1e-300) for c in columns)
ctx.check("rows: history, partial against full recovery / peak", worst, 0.0, abs_tol=1e-12)
ep = read_summary(partial)["section_force_envelope"]
ef = read_summary(full)["section_force_envelope"]
# the history rows take the cuts' section forces from the reduced
# coordinates, (L T) q (Model::output_functionals()), the full rows from the
# expanded displacement: the same sums in another order. The axial force N
# is zero here (the loads at B1 are transverse and a torque): its envelope
# is round-off of the cut's terms (some 1e7 N each), compared to 1e-10 of
# the 1e4 N load (measured 2e-8 N)
for k in ("N", "My", "Mz"):
    ctx.check("rows: section force envelope %s, partial / full" % k,
              ep[k]["max_abs"], ef[k]["max_abs"], rel=1e-12,
              abs_tol=1e-6 if k == "N" else 0.)
sp, sf = read_csv(partial + "/section_forces.csv"), read_csv(full + "/section_forces.csv")
shared = np.isin(sf["time"], sp["time"])
ctx.check_true("rows: section_forces.csv rows shared", np.count_nonzero(shared) == len(sp),
               "%d of %d" % (np.count_nonzero(shared), len(sp)))
def rows_against_full(tag, rows, mask=slice(None)):
    """section_forces.csv rows against the full run's: My, Mz to 1e-12 of
    the peak, N (round-off, see above) to 1e-10 of the 1e4 N load."""
    for c in ("N", "My", "Mz"):
        peak = 1e4 if c == "N" else np.max(np.abs(sf[c]))
        ctx.check("%s: section_forces.csv %s against the full rows' / %s" %
                  (tag, c, "load" if c == "N" else "peak"),
                  np.max(np.abs(rows[c] - sf[c][mask])) / peak, 0.0,
                  abs_tol=1e-10 if c == "N" else 1e-12)


rows_against_full("rows", sp, shared)

# the stress envelope's rows without VTU are expanded later, by batches of
# 16 (U = T Q, CraigBamptonReduction::expand_many(); doc/theory.md 12.2):
# the same envelope as the full rows', to round-off (BLAS dgemm against
# dgemv: the same terms summed in another order), at the same times
deferred, _ = ctx.run(prm, "rows_deferred", ROWS + ["Output/Section force interval=1e-4"])
_, n_cells, fd = read_vtu(deferred + "/stress_envelope.vtu")
_, _, ff = read_vtu(full + "/stress_envelope.vtu")
vm_d, vm_f = fd["max_von_mises"][1], ff["max_von_mises"][1]
ctx.check_true("deferred envelope: stress_envelope.vtu has the cells", n_cells == 16 and
               vm_f.size == 8 * n_cells and vm_d.size == vm_f.size, str(n_cells))
ctx.check("deferred envelope: von Mises of every cell against the full rows' / peak",
          np.max(np.abs(vm_d - vm_f)) / np.max(vm_f), 0.0, abs_tol=1e-12)
ctx.check("deferred envelope: times of every cell's peak (s)",
          np.max(np.abs(fd["max_von_mises_time"][1] - ff["max_von_mises_time"][1])), 0.0,
          abs_tol=1e-12)
pd, pf = (read_summary(o)["solids"]["prism"]["max_von_mises"] for o in (deferred, full))
ctx.check("deferred envelope: summary solids.prism.max_von_mises (Pa)",
          pd["value"], pf["value"], rel=1e-12)
ctx.check("deferred envelope: its time (s)", pd["time"], pf["time"], abs_tol=1e-12)
rows_against_full("deferred envelope", read_csv(deferred + "/section_forces.csv"))

# ---- 5. modal damping of the reduced part ------------------------------------
out, _ = ctx.run(prm, "modal_damping", FORWARD + [
    CB, "Model/Decomposition/Reduction cutoff frequency=1000",
    "Model/Decomposition/Reduction modal damping ratio=0.05"])
s = read_summary(out)
ctx.check("modal damping: summary reduction.modal_damping_ratio",
          s["reduction"]["modal_damping_ratio"], 0.05, rel=1e-15)
ctx.check_true("modal damping: null without it (section 1)",
               read_summary(ctx.work + "/reduced_1000")["reduction"]["modal_damping_ratio"]
               is None)
ctx.check("modal damping: energy balance with the dissipation (relative)",
          s["energy_balance_relative"], 0.0, abs_tol=1e-10)
e, e_undamped = read_csv(out + "/energy.csv"), read_csv(ctx.work + "/reduced_1000/energy.csv")
ctx.check_true("modal damping: energy dissipated (J), none without it",
               e["dissipated"][-1] > 1e-3 * np.max(np.abs(e["external_work"]))
               and e_undamped["dissipated"][-1] == 0.0,
               "(%.4g J against %.4g J)" % (e["dissipated"][-1], e_undamped["dissipated"][-1]))
ctx.finish()
