#!/usr/bin/python3
"""HATI on the solid-girder crane with heavy girders through a macro step
whose continuity corrections stalled (doc/theory.md 9.6 item 8).

The crane of bridge_crane_3d.prm with 50 mm plates (Girder section box,
0.46 x 1.10 m, webs and flanges 50 mm), 1.1 m plate elements, true
heights, tied wheels, rigid hoist, undamped, girders reduced
(Craig-Bampton 150 Hz), Rinaldi X + Z, to 1.25 s. At t = 1.2242 s a crane
wheel's contact next to the interface made the frozen-closure corrections
with the ramp's H^-1 cycle between 4.5 % and 100 % of the velocity scale,
and the run stopped ("did not converge in 60 corrections"). With Newton's
corrections on the frozen pass's own Jacobian it goes on.

Checks (references: the coupling's own invariants, independent of the
corrections that reach them):
- the run reaches End time;
- Newton's corrections were used (summary.json hati_jacobian_macro_steps,
  measured 103 of them);
- the energy balance of the coupled run (E1, G5) is closed to 1e-9 of the
  largest energy (measured 2.6e-11): a correction that left a velocity jump
  at the interface would show in it as the interface work;
- a macro step kept with a residual (no root) stays within the accepted
  1 % of the velocity scale, and a frozen closure within 0.1 mm of its gap
  (measured 0.25 % and 6.9 um)."""
import os

from hati_test import Context, read_summary

ctx = Context()
prm = ctx.prm("bridge_crane_3d.prm")
RECORDS = os.path.join(ctx.source, "data", "accelerograms")
END = 1.25
out, _ = ctx.run(prm, "heavy_girders", [
    "Model/Bridge crane/Girder element size=1.1",
    "Model/Bridge crane/Girder section=box, 0.46, 1.10, 0.05, 0.05",
    "Loading/Accelerogram X=" + os.path.join(RECORDS, "Rinaldi228.AT2"),
    "Loading/Accelerogram Z=" + os.path.join(RECORDS, "RinaldiUP.AT2"),
    "Model/Bridge crane/Eccentricities=true", "Model/Bridge crane/Travel=tied",
    "Model/Bridge crane/Hoist=rigid", "Model/Bridge crane/Damping ratio=0",
    "Output/Output interval=0", "Output/Section force interval=1e20",
    "Output/History interval=0.01", "Time integration/End time=%g" % END])
s = read_summary(out)
ctx.check("end time reached (s)", s["end_time"], END, abs_tol=1e-12)
ctx.check_true("Newton's corrections on the frozen pass's Jacobian were used",
               s["hati_jacobian_macro_steps"] >= 1,
               "(%d macro steps)" % s["hati_jacobian_macro_steps"])
ctx.check("energy balance relative", s["energy_balance_relative"], 0.0, abs_tol=1e-9)
ctx.check("largest kept continuity residual / velocity scale",
          s["hati_largest_discontinuous_residual"], 0.0, abs_tol=1e-2)
ctx.check("largest frozen closure gap (m)", s["hati_largest_frozen_closure_gap"], 0.0,
          abs_tol=1e-4)
ctx.finish()
