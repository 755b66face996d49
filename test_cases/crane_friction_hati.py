#!/usr/bin/python3
"""HATI with Coulomb friction (A9 in the explicit subdomain, G3' with the
frictional macro steps redone) against the fully explicit run of the same
crane (reference: CD-Lagrange on the whole crane, the same explicit step
dt = 2e-5 s; HATI m = 5), Travel = braked (the default), under Rinaldi 228
(X) and UP (Z) over the first 3.2 s (the strong motion starts at about
2.6 s):

- Hoist = rope (the default): no wheel lifts off; the crane slides on its
  braked wheels. Slip distances of every wheel within 2 % (issue #17's
  tolerance; measured 0.9 % at most), peak friction forces over the 1 ms
  window within 3 % (measured 2.2 %).
- Hoist = rigid: the wheels lift off at about 2.9 s. The first contact-loss
  episode of every wheel (the lift-off, 50-100 ms long) starts and ends
  within 2 ms of the explicit run's (measured 0.1 ms); the slip distances
  of the sliding wheels (> 0.1 m) within 2 % (measured 0.8 %). The later
  episodes are the wheels' chatter after landing, which frequency-range
  damping leaves undamped above 30 Hz: their number differs between any two
  step sizes or methods (15 against 29 on one wheel), so they are not
  matched one by one (doc/user_guide.md, the crane's damping).
The superposed macro steps (the wheels within reach stick) against the
same HATI run with every macro step redone (Superposition = false): to
6e-12 of the peaks (doc/theory.md A9); also at m = 2 (1 s), where the
reach must spread along the wheels' rigid links (doc/theory.md 9.6;
measured 5.9e-12, the same impacts).
The main example's own steps (dt = 8e-5 s, m = 1: no macro step redone)
against the same fully explicit run (rope, 3.2 s): slip distances within
2 %, peak friction and mean wheel forces within 3 % (measured 0.5 %,
0.9 %, 0.2 %).
Also: every friction cluster converged (friction_unconverged = 0) and the
energy balance closes to 1e-10 of the largest energy in both methods
(measured 3.5e-12 over 160 000 steps with friction).
"""
import csv
import os

import numpy as np

from hati_test import Context, read_csv, read_summary

ctx = Context()
records = os.path.join(ctx.source, "data", "accelerograms")
# the axis model (the files have true heights; the comparison is the same and
# half as long on the member axes)
# (m = 5 here: the main example's own steps, m = 1, redo no macro step;
# they are checked at the end)
common = ["Model/Bridge crane/Travel=braked", "Model/Bridge crane/Eccentricities=false",
          "Time integration/Time step=2e-5", "Time integration/HATI/Time step ratio=5",
          "Time integration/End time=3.2",
          "Output/Output interval=0",
          "Loading/Accelerogram X=" + os.path.join(records, "Rinaldi228.AT2"),
          "Loading/Accelerogram Z=" + os.path.join(records, "RinaldiUP.AT2")]


outputs = {}


def worst_translation(out, out_ref):
    """The largest |difference| / peak of the monitors' translations whose
    peak exceeds 1 um in the run @p out_ref, and its column."""
    h, h_ref = read_csv(out + "/history.csv"), read_csv(out_ref + "/history.csv")
    worst, worst_key = 0., ""
    for key in h_ref.dtype.names:
        peak = float(np.max(np.abs(h_ref[key])))
        if key[-2:] in ("ux", "uy", "uz") and peak > 1e-6:
            e = float(np.max(np.abs(h[key] - h_ref[key]))) / peak
            if e >= worst:
                worst, worst_key = e, key
    return worst, worst_key


def superposed_and_redone(tag, sets):
    """The main example with @p sets, superposed and with every macro step
    redone (Superposition = false): their output directories and summaries."""
    prm = ctx.prm("bridge_crane_hati.prm")
    out_s, _ = ctx.run(prm, tag, sets)
    out_r, _ = ctx.run(prm, tag + "_redone", sets + ["Time integration/HATI/Superposition=false"])
    return out_s, out_r, read_summary(out_s), read_summary(out_r)


def run_pair(hoist):
    """(summary, episodes) of the fully explicit and the HATI run."""
    result = []
    for method in ("full_explicit", "hati"):
        out, _ = outputs[(method, hoist)] = ctx.run(ctx.prm("bridge_crane_%s.prm" % method), "%s_%s" % (method, hoist),
                         common + ["Model/Bridge crane/Hoist=" + hoist])
        s = read_summary(out)
        episodes = {}
        with open(os.path.join(out, "contact_episodes.csv")) as f:
            for row in csv.DictReader(f):
                episodes.setdefault(row["contact"], []).append(
                    (float(row["start"]), float(row["end"]) if row["end"] else None))
        ctx.check("%s, %s: friction_unconverged" % (hoist, method),
                  s["friction_unconverged"], 0, abs_tol=0)
        ctx.check("%s, %s: energy balance / largest energy" % (hoist, method),
                  s["energy_balance_relative"], 0., abs_tol=1e-10)
        result.append((s, episodes))
    return result


# the rope: sliding without lift-off
(e, _), (h, _) = run_pair("rope")
for name, we in e["wheels"].items():
    wh = h["wheels"][name]
    ctx.check_true("rope: %s stays on its rail in both runs" % name,
                   we["uplift_time"] == 0. and wh["uplift_time"] == 0.)
    ctx.check("rope: %s slip distance (m), HATI vs explicit" % name, wh["slip_distance"],
              we["slip_distance"], rel=0.02)
    ctx.check("rope: %s peak friction force (N), HATI vs explicit" % name,
              wh["peak_friction_force"], we["peak_friction_force"], rel=0.03)

# the superposed macro steps (doc/theory.md A9: the wheels within reach
# stick, the rope's forces change by less than 1e-8, 10.5) against the same HATI run with
# every macro step redone (Superposition = false): the monitors' translations
# (those above 1 um) to 1e-7 of their peaks (measured 6e-12), the slip
# distances (> 1 mm) and peak friction forces to 1e-8 (measured 3e-13 and
# 1e-12: the friction solver's tolerance); fewer than 70 % of the macro steps redone (measured
# 19 429 of 32 000: the braked crane slides from 0.65 s on, and a sliding
# wheel within reach is redone) against all of them
out_s = outputs[("hati", "rope")][0]
out_r, _ = ctx.run(ctx.prm("bridge_crane_hati.prm"), "hati_rope_redone",
                   common + ["Model/Bridge crane/Hoist=rope",
                             "Time integration/HATI/Superposition=false"])
s_s, s_r = read_summary(out_s), read_summary(out_r)
ctx.check_true("rope: Superposition = false redoes every macro step",
               s_r["hati_redone_macro_steps"] == s_r["n_steps"],
               "(%d of %d)" % (s_r["hati_redone_macro_steps"], s_r["n_steps"]))
ctx.check_true("rope: superposed, fewer than 70 % of the macro steps redone",
               s_s["hati_redone_macro_steps"] < 0.7 * s_s["n_steps"],
               "(%d of %d)" % (s_s["hati_redone_macro_steps"], s_s["n_steps"]))
worst, worst_key = worst_translation(out_s, out_r)
ctx.check("rope: superposed vs redone, worst monitor translation / peak (%s)" % worst_key,
          worst, 0., abs_tol=1e-7)
for name, wr in s_r["wheels"].items():
    ws = s_s["wheels"][name]
    if wr["slip_distance"] > 1e-3:
        ctx.check("rope: %s slip distance (m), superposed vs redone" % name,
                  ws["slip_distance"], wr["slip_distance"], rel=1e-8)
    ctx.check("rope: %s peak friction force (N), superposed vs redone" % name,
              ws["peak_friction_force"], wr["peak_friction_force"], rel=1e-8)

# the rope's superposition (doc/theory.md 10.5): the tied crane at true
# heights (the main example's geometry, Travel = tied: no friction), 1 s of
# the record, where the correction reaches the hoist through the rigid links
# (2 sqrt(3) k delta / T of 1e-12 to 1e-9: 61 % of the macro steps were
# redone with the former tolerance, 1e-12), against the same run with every
# macro step redone (Superposition = false): fewer than 5 % of the macro
# steps redone (measured 20 of 5000), the monitors' translations to 1e-7 of
# their peaks (measured 7.6e-12), the rope's least and largest tensions to
# 1e-8 (measured 5e-12), the energy balance to 1e-10 of the largest energy
# with the work of the rope forces on the corrected velocities booked
# (measured 1.9e-12; 1.9e-10 on 8 s without it)
tied = ["Model/Bridge crane/Travel=tied", "Model/Bridge crane/Hoist=rope",
        "Time integration/Time step=4e-5", "Time integration/HATI/Time step ratio=5",
        "Time integration/End time=1", "Output/Output interval=0",
        "Loading/Accelerogram X=" + os.path.join(records, "Rinaldi228.AT2"),
        "Loading/Accelerogram Z=" + os.path.join(records, "RinaldiUP.AT2")]
out_ts, out_tr, s_s, s_r = superposed_and_redone("hati_tied_rope", tied)
ctx.check_true("tied rope: superposed, fewer than 5 % of the macro steps redone",
               s_s["hati_redone_macro_steps"] < 0.05 * s_s["n_steps"],
               "(%d of %d)" % (s_s["hati_redone_macro_steps"], s_s["n_steps"]))
worst, worst_key = worst_translation(out_ts, out_tr)
ctx.check("tied rope: superposed vs redone, worst monitor translation / peak (%s)"
          % worst_key, worst, 0., abs_tol=1e-7)
for bound in ("min", "max"):
    ctx.check("tied rope: %s rope tension (N), superposed vs redone" % bound,
              s_s["rope_tension"]["hoist_rope"][bound],
              s_r["rope_tension"]["hoist_rope"][bound], rel=1e-8)
for s, label in ((s_s, "superposed"), (s_r, "redone")):
    ctx.check("tied rope, %s: energy balance / largest energy" % label,
              s["energy_balance_relative"], 0., abs_tol=1e-10)

# the smallest macro step, m = 2 (the main example, braked + rope, 1 s):
# the unit-ramp response of two micro steps reaches the wheels' rigid links
# but not, by the stiffness alone, the wheels behind them, which a link
# moves within the same micro step: the reach spreads along bilateral rows
# (RampSuperposition::find_reach(); before, the wheels were taken as out of
# reach, every macro step was superposed and the wheels chattered: 134,063
# impacts in 4 s instead of 7). Reference: the same run with every macro
# step redone (Superposition = false)
m2 = ["Time integration/Time step=4e-5", "Time integration/HATI/Time step ratio=2",
      "Time integration/End time=1",
      "Output/Output interval=0",
      "Loading/Accelerogram X=" + os.path.join(records, "Rinaldi228.AT2"),
      "Loading/Accelerogram Z=" + os.path.join(records, "RinaldiUP.AT2")]
out_ms, out_mr, s_s, s_r = superposed_and_redone("hati_m2", m2)
worst, worst_key = worst_translation(out_ms, out_mr)
ctx.check("m = 2: superposed vs redone, worst monitor translation / peak (%s)" % worst_key,
          worst, 0., abs_tol=1e-7)
ctx.check("m = 2: impacts, superposed vs redone", s_s["n_impacts"], s_r["n_impacts"], abs_tol=0)

# the main example's own steps (dt = 8e-5 s, the explicit part's critical
# step 8.84e-5 s, and m = 1: no macro step redone) against the fully
# explicit run at dt = 2e-5 s above (reference), the rope: slip distances
# within 2 % (measured 0.5 %), peak friction forces within 3 % (measured
# 0.9 %), peak mean wheel forces within 3 % (measured 0.2 %)
e = read_summary(outputs[("full_explicit", "rope")][0])
out, _ = ctx.run(ctx.prm("bridge_crane_hati.prm"), "hati_rope_file_steps",
                 [c for c in common if not c.startswith("Time integration/")]
                 + ["Time integration/End time=3.2", "Model/Bridge crane/Hoist=rope"])
s = read_summary(out)
ctx.check("file steps: micro step (s)", s["micro_dt"], 8e-5, rel=1e-12)
ctx.check("file steps: time_step_ratio", s["time_step_ratio"], 1, abs_tol=0)
ctx.check("file steps: redone macro steps", s["hati_redone_macro_steps"], 0, abs_tol=0)
ctx.check("file steps: energy balance / largest energy", s["energy_balance_relative"], 0.,
          abs_tol=1e-10)
for name, we in e["wheels"].items():
    wh = s["wheels"][name]
    if we["slip_distance"] > 1e-3:
        ctx.check("file steps: %s slip distance (m), HATI vs explicit" % name,
                  wh["slip_distance"], we["slip_distance"], rel=0.02)
    ctx.check("file steps: %s peak friction force (N), HATI vs explicit" % name,
              wh["peak_friction_force"], we["peak_friction_force"], rel=0.03)
    ctx.check("file steps: %s peak mean force (N), HATI vs explicit" % name,
              wh["peak_mean_force"], we["peak_mean_force"], rel=0.03)

# the rigid hoist: lift-off and landing
(e, ee), (h, eh) = run_pair("rigid")
for name, we in e["wheels"].items():
    wh = h["wheels"][name]
    a, b = ee.get(name, []), eh.get(name, [])
    lifts = bool(a) and bool(b)
    ctx.check_true("rigid: %s lifts off in both runs" % name, lifts, "%s %s" % (a[:1], b[:1]))
    if lifts:
        ctx.check("rigid: %s first lift-off start (s)" % name, b[0][0], a[0][0], abs_tol=2e-3)
        if a[0][1] is not None and b[0][1] is not None:
            ctx.check("rigid: %s first landing (s)" % name, b[0][1], a[0][1], abs_tol=2e-3)
    if we["slip_distance"] > 0.1:
        ctx.check("rigid: %s slip distance (m), HATI vs explicit" % name,
                  wh["slip_distance"], we["slip_distance"], rel=0.02)
ctx.finish()
