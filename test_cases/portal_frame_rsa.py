#!/usr/bin/python3
"""The response-spectrum analysis of a linear frame against the time
histories of seven spectrum-compatible records of its target (issue #57):
the statistical agreement a linear structure must show.

The 3D portal frame of portal_frame_elcentro.prm without gravity, Newmark
with Rayleigh damping of 5 % at its first sway mode (7.46 Hz) and at 20 Hz,
under seven artificial records along X matched to EN 1998-1 type 1, ground
C, a_g = 3 m/s^2, 5 % (Artificial records, their EC8 check passing). The
suite runs the response-spectrum analysis of the same model itself
(Suite/Response spectrum comparison). References, each the mean over the
seven members of the time-history peak, computed here from the members'
files:
- the roof displacements A1.ux and D1.ux (history.csv, relative to the
  base) against response_spectrum.csv's CQC values;
- the base shear: the peak over time of the sum of the four columns' shear
  at their foot (section_forces.csv, Vz at x = 0: local z is -X for a
  column along Z) against base.Fx;
each within 15 % (a mean of seven records scatters by some 10 % about the
target, and the RSA is the peak of the linear response in the mean sense).
And the suite's own comparison (rsa_comparison.csv, suite_summary.json
rsa_comparison): the columns' section-force envelope and the roof's
absolute acceleration within 15 %, with ratio = response spectrum / time
history as written."""
import csv
import json
import os

import numpy as np

from hati_test import Context

ctx = Context()
PRM = """subsection Analysis
  set Type          = transient
  set Initial state = given
end
subsection Model
  set Type = frame
  subsection Frame
    set Nodes     = A0: 0, 0, 0; A1: 0, 0, 5; B0: 6, 0, 0; B1: 6, 0, 5; C0: 0, 4, 0; C1: 0, 4, 5; D0: 6, 4, 0; D1: 6, 4, 5
    set Materials = steel: 2.1e11, 0.3, 7850
    set Sections  = column: box, 0.3, 0.3, 0.01, 0.01; beam: box, 0.2, 0.4, 0.008, 0.012
    set Members   = colA: A0, A1, column, steel, 8; colB: B0, B1, column, steel, 8; colC: C0, C1, column, steel, 8; colD: D0, D1, column, steel, 8; beamAB: A1, B1, beam, steel, 10; beamCD: C1, D1, beam, steel, 10; crossAC: A1, C1, beam, steel, 8; crossBD: B1, D1, beam, steel, 8
    set Supports  = A0: clamped; B0: clamped; C0: clamped; D0: clamped
    set Point masses = A1: 500; B1: 500; C1: 500; D1: 500
    set Monitor nodes = A1, D1
    set Section force members = colA, colB, colC, colD
  end
end
subsection Loading
  set Gravity = 0, 0, 0
end
subsection Time integration
  set Method    = Newmark
  set Time step = 2e-3
  set End time  = 12
  subsection Damping
    set Damping ratio    = 0.05
    set First frequency  = 7.46
    set Second frequency = 20
  end
end
subsection Output
  set Output interval  = 0
  set History interval = 0.004
  set Section force interval = 0.004
end
subsection Design spectrum
  set Type                     = EC8 type 1
  set Ground type              = C
  set Peak ground acceleration = 3
  set Damping ratio            = 0.05
  set Period range             = 0.02, 4
end
subsection Artificial records
  set Number             = 7
  set Duration           = 12
  set Strong motion      = 6
  set Seed               = 57
  set Components         = X
  set Matching tolerance = 0.05
  set Time step          = 0.005
end
subsection Suite
  set Records   = artificial
  set Statistic = mean
  set Fundamental period = 0.134
end
"""
path = os.path.join(ctx.work, "portal_suite.prm")
with open(path, "w") as f:
    f.write(PRM)
out, p = ctx.run(path, "suite")
members = sorted(d for d in os.listdir(out) if d.startswith("art"))
ctx.check("seven members", len(members), 7, abs_tol=0)
with open(os.path.join(out, "response_spectrum", "response_spectrum.csv")) as f:
    rsa = {r["quantity"]: float(r["combined"]) for r in csv.DictReader(f)}
peaks = {"A1.ux": [], "D1.ux": [], "base shear": []}
for m in members:
    with open(os.path.join(out, m, "history.csv")) as f:
        h = list(csv.DictReader(f))
    for name in ("A1.ux", "D1.ux"):
        peaks[name].append(max(abs(float(r[name])) for r in h))
    # the base shear at each row: the columns' feet (element 0, x = 0)
    shear = {}
    with open(os.path.join(out, m, "section_forces.csv")) as f:
        for r in csv.DictReader(f):
            if r["element"] == "0" and float(r["x"]) == 0.0:
                shear[r["time"]] = shear.get(r["time"], 0.0) - float(r["Vz"])
    peaks["base shear"].append(max(abs(v) for v in shear.values()))
for name, reference in (("A1.ux", "A1.ux"), ("D1.ux", "D1.ux"), ("base shear", "base.Fx")):
    mean = float(np.mean(peaks[name]))
    print("  %s: time-history peaks %s, mean %.6g; response spectrum %.6g (ratio %.3f)"
          % (name, ", ".join("%.4g" % v for v in peaks[name]), mean, rsa[reference],
             rsa[reference] / mean))
    ctx.check("CQC %s against the mean of the seven time-history peaks" % name,
              rsa[reference], mean, rel=0.15)
with open(os.path.join(out, "suite_summary.json")) as f:
    summary = json.load(f)
ctx.check_true("the suite passes its EC8 check",
               summary["design_spectrum_check"]["passes_ec8"] is True)
comparison = summary["rsa_comparison"]["quantities"]
with open(os.path.join(out, "rsa_comparison.csv")) as f:
    rows = {r["quantity"]: r for r in csv.DictReader(f)}
for quantity in ("section_force.N", "section_force.My", "A1.max_absolute_acceleration",
                 "D1.max_absolute_acceleration"):
    r = rows[quantity]
    th, rs = float(r["time_history"]), float(r["response_spectrum"])
    ctx.check("rsa_comparison.csv %s: ratio = response spectrum / time history"
              % quantity, float(r["ratio"]), rs / th, rel=1e-12)
    ctx.check("rsa_comparison.csv %s: within 15 %%" % quantity, rs, th, rel=0.15)
    ctx.check("suite_summary.json rsa_comparison %s" % quantity,
              comparison[quantity]["ratio"], float(r["ratio"]), rel=1e-12)
ctx.check_true("the terminal prints the comparison",
               "response spectrum against the time histories" in p.stdout)
ctx.check_true("rsa_comparison.png drawn",
               os.path.getsize(os.path.join(out, "rsa_comparison.png")) > 10000)
ctx.finish()
