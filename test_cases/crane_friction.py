#!/usr/bin/python3
"""The bridge crane with wheel friction (spec A9, Model/Bridge crane/Travel):

- static: the wheel loads with Travel = braked (sticking frictional wheel
  contacts) equal those with Travel = tied (supports and ties, the results
  before friction) to 1e-9: the lever rule does not depend on how the crane
  is held along its travel (reference: the tied crane, whose loads
  test_cases/bridge_crane.py checks against hand statics); contacts.csv of
  both static runs has the header's number of fields on every row, the
  static contact forces and the sticking state of the braked wheels;
- modal: the braked crane has no 0 Hz mode (the sticking wheels hold it
  along X and across the rails) and its first mode is the sway along X
  (effective mass ratio > 0.8), while the tied crane starts with two 0 Hz
  modes (free within the flange play);
- transient (HATI, Northridge, 0.2 s): friction converges
  (friction_unconverged = 0), the energy balance with friction_dissipated
  closes (drift <= 1e-9 of the largest energy), the wheels get
  slip_distance and peak_friction_force, contacts.csv the state column;
- Travel = free has no static state along X (one-line error), a friction
  coefficient out of range is refused by the entry's pattern.
"""
import os

import numpy as np

from hati_test import Context, read_csv, read_summary

ctx = Context()
static = ctx.prm("bridge_crane_static.prm")
hati = ctx.prm("bridge_crane_hati.prm")

loads, static_out = {}, {}
for travel in ("tied", "braked"):
    out, _ = ctx.run(static, "static_" + travel,
                     ["Model/Bridge crane/Travel=" + travel, "Analysis/Type=static"])
    loads[travel] = read_summary(out)["static_contact_forces"]
    static_out[travel] = out

# contacts.csv of the static runs (issue #24, 9: with friction the rows had
# 7 fields under a 10-column header): every row has the header's fields,
# force = the static contact force of summary.json, state stick where a
# loaded frictional contact holds (braked) and no friction columns (tied)
for travel in ("tied", "braked"):
    with open(os.path.join(static_out[travel], "contacts.csv")) as f:
        lines = f.read().splitlines()
    header = lines[0].split(",")
    table = [dict(zip(header, l.split(","))) for l in lines[1:]]
    ctx.check_true("static %s: contacts.csv has %d rows, each with the header's %d fields"
                   % (travel, len(table), len(header)),
                   len(table) > 0 and all(len(l.split(",")) == len(header) for l in lines[1:])
                   and len(header) == (10 if travel == "braked" else 7), str(lines[:3]))
    wrong = [(r["contact"], r["force"], loads[travel][r["contact"]]) for r in table
             if r["contact"] in loads[travel]
             and abs(float(r["force"]) - loads[travel][r["contact"]])
             > 1e-12 * abs(loads[travel][r["contact"]])]
    ctx.check_true("static %s: contacts.csv force = static_contact_forces (%d names)"
                   % (travel, sum(r["contact"] in loads[travel] for r in table)),
                   not wrong and any(r["contact"] in loads[travel] for r in table), str(wrong))
    loaded = [r for r in table if float(r["force"]) > 0]
    ctx.check_true("static %s: the loaded contacts are active" % travel,
                   loaded and all(int(r["active"]) > 0 for r in loaded)
                   and all(int(r["active"]) == 0 for r in table if float(r["force"]) == 0))
braked = {r.split(",")[1]: r.split(",")[-1] for r in
          open(os.path.join(static_out["braked"], "contacts.csv")).read().splitlines()[1:]}
ctx.check_true("static braked: the braked crane wheels stick, every state open or stick",
               braked.get("crane_wheel_1") == "stick" and braked.get("crane_wheel_3") == "stick"
               and set(braked.values()) <= {"open", "stick"}, str(braked))
for name in sorted(k for k in loads["tied"] if k.endswith(tuple("1234"))
                   and "lateral" not in k and "travel" not in k):
    ctx.check("static: %s load (N), braked = tied" % name, loads["braked"][name],
              loads["tied"][name], rel=1e-9)

modes = {}
for travel in ("tied", "braked"):
    out, _ = ctx.run(static, "modal_" + travel,
                     ["Model/Bridge crane/Travel=" + travel, "Analysis/Type=modal"])
    modes[travel] = read_csv(out + "/modes.csv")
ctx.check("modal tied: first frequency (Hz), free within the flange play", modes["tied"]["frequency"][0],
          0.0, abs_tol=1e-3)
ctx.check_true("modal braked: no 0 Hz mode (first frequency > 1 Hz)",
               modes["braked"]["frequency"][0] > 1.0, "(%.6g Hz)" % modes["braked"]["frequency"][0])
ctx.check_true("modal braked: the first mode is the sway along X (effective mass ratio > 0.8)",
               modes["braked"]["effective_mass_ratio_x"][0] > 0.8,
               "(%.3f)" % modes["braked"]["effective_mass_ratio_x"][0])

records = os.path.join(ctx.source, "data", "accelerograms")
out, _ = ctx.run(hati, "hati_braked", ["Model/Bridge crane/Travel=braked",
                                       "Time integration/End time=0.2",
                                       "Loading/Accelerogram X=" + records + "/Rinaldi228.AT2",
                                       "Loading/Accelerogram Z=" + records + "/RinaldiUP.AT2"])
s = read_summary(out)
ctx.check("transient braked: friction_unconverged", s["friction_unconverged"], 0, abs_tol=0)
e = read_csv(out + "/energy.csv")
scale = max(np.max(np.abs(e[k])) for k in ("kinetic", "internal", "external_work"))
ctx.check("transient braked: max |balance_drift| / largest energy",
          float(np.max(np.abs(e["balance_drift"]))) / scale, 0.0, abs_tol=1e-9)
ctx.check_true("transient braked: friction_dissipated >= 0",
               float(np.min(e["friction_dissipated"])) >= 0.0)
wheel = s["wheels"]["crane_wheel_1"]
ctx.check_true("transient braked: wheels have slip_distance and peak_friction_force",
               "slip_distance" in wheel and "peak_friction_force" in wheel, str(wheel))
c = read_csv(out + "/contacts.csv")
ctx.check_true("transient braked: contacts.csv states are open, stick or slip",
               set(np.unique(c["state"])) <= {"open", "stick", "slip"}, str(np.unique(c["state"])))

_, p = ctx.run(static, "free_static", ["Model/Bridge crane/Travel=free", "Analysis/Type=static"],
               expect_failure=True)
expected = ("hati: error: static analysis: the stiffness matrix is singular: the model can move as "
            "a rigid body (check the supports): a rigid translation along x costs no strain energy "
            "and no closed contact holds it.")
ctx.check_true("Travel = free, static: refused in one line", p.stderr.strip() == expected,
               "\n       got      %r\n       expected %r" % (p.stderr.strip(), expected))
_, p = ctx.run(static, "mu_range", ["Model/Bridge crane/Wheel friction coefficient=3"],
               expect_failure=True)
ctx.check_true("Wheel friction coefficient = 3: refused by its pattern",
               p.returncode == 1 and "[Double 0...2 (inclusive)]" in p.stderr, p.stderr.strip())
ctx.finish()
