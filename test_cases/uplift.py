#!/usr/bin/python3
"""The uplift of a contact, summary.json contacts.<name>.max_uplift (issue
#54): the largest gap reached after the contact first closed.

1. The bouncing ball (bouncing_ball.prm, e = 0.8) dropped from
   z0 = g (N dt)^2 / 2, so that CD-Lagrange's step lands it exactly at the
   ground (its flight is exact at the steps: the leapfrog integrates a
   constant acceleration exactly). Its first apex after the first impact is
   the analytical e^2 z0 up to the start of the rebound from the half-step
   velocity: CD-Lagrange reverses V_{N-1/2} = g (t_N - dt/2), so the apex is
   (e g (t_N - dt/2) + g dt/2)^2 / (2 g), the sampled maximum of the steps
   within g dt^2 / 8 of it. Checked: at dt = 1e-4 against that discrete
   apex (3e-8 relative: g dt^2 / 8 is 2.4e-8 of it), at dt = 1e-6 against the analytical e^2 z0 (1e-6
   relative, the discrete offset (1 - e) dt / (e t_N) = 6e-7).
2. A stiff beam pinned at one end and resting on a one-sided support at the
   other, lifted off it by a known upward pulse of the base (Accelerogram Z,
   a trapezoid of -3 g): in the relative formulation the rigid beam rotates
   about the pin with a tip acceleration 1.5 (a(t) - g) once a(t) > g (the
   uniform beam: moment m (a - g) L^2 / 2 over inertia m L^3 / 3), and then
   flies under 1.5 g: max_uplift = z + v^2 / (3 g) after the pulse, z and v
   integrated exactly from the piecewise-linear pulse here (to 1e-9).
   Within 0.5 %: CD-Lagrange's lumped mass of 20 elements gives the beam
   the inertia m L^3 / 3 (1 + 1 / (2 n^2)) about the pin, 0.125 % more
   (with 4 elements 3 %, measured), and its bending (static tip deflection
   1e-5 m against an uplift of 0.11 m) is negligible.
"""
import numpy as np

from hati_test import Context, read_summary

ctx = Context()
g, e = 9.81, 0.8

# --- 1. the bouncing ball --------------------------------------------------
tN = 0.4
z0 = g * tN**2 / 2
for dt in (1e-4, 1e-6):
    out, _ = ctx.run(ctx.prm("bouncing_ball.prm"), "ball_%g" % dt,
                     ["Time integration/Time step=%g" % dt,
                      "Time integration/End time=0.8",
                      "Model/Point mass/Initial height=%.17g" % z0,
                      "Output/Output interval=0", "Output/History interval=0.01"])
    c = read_summary(out)["contacts"]["ground"]
    if dt == 1e-4:
        discrete = (e * g * (tN - dt / 2) + g * dt / 2) ** 2 / (2 * g)
        # the steps' maximum within g dt^2 / 8 = 2.4e-8 of the apex (relative)
        ctx.check("ball max_uplift at dt = 1e-4 = discrete apex (m)", c["max_uplift"],
                  discrete, rel=3e-8)
    else:
        ctx.check("ball max_uplift at dt = 1e-6 = e^2 z0 (m)", c["max_uplift"],
                  e**2 * z0, rel=1e-6)
    ctx.check("ball max_uplift_time = t_N + e v_N / g (s)", c["max_uplift_time"],
              tN + e * tN, abs_tol=2 * dt)

# --- 2. a beam lifted off its support by a pulse ---------------------------
L, a0 = 1.0, 3 * g
pulse = [(0.0, 0.0), (0.001, -a0), (0.05, -a0), (0.051, 0.0)]
record = ctx.work + "/pulse.txt"
with open(record, "w") as f:
    for t, a in pulse:
        f.write("%.17g %.17g\n" % (t, a))
PRM = """subsection Analysis
  set Type          = transient
  set Initial state = static
end
subsection Model
  set Type = frame
  subsection Frame
    set Nodes     = a: 0, 0, 0; b: %g, 0, 0
    set Materials = steel: 2.1e11, 0.3, 7850
    set Sections  = sq: rectangle, 0.1, 0.1
    set Members   = beam: a, b, sq, steel, 20
    set Supports  = a: fixed, fixed, fixed, fixed, free, fixed; b: free, fixed, free, fixed, free, fixed
    set Contacts  = tip: b, 0, 0, 1, 0
  end
end
subsection Loading
  set Gravity             = 0, 0, -%g
  set Accelerogram Z      = %s
  set Accelerogram units  = m/s^2
end
subsection Contact
  set Restitution coefficient = 0
end
subsection Time integration
  set Method    = CD-Lagrange
  set Time step = 2e-6
  set End time  = 0.2
end
subsection Output
  set History interval = 1e-3
end
""" % (L, g, record)
path = ctx.work + "/beam_pulse.prm"
open(path, "w").write(PRM)
out, _ = ctx.run(path, "beam_pulse")
c = read_summary(out)["contacts"]["tip"]

# the rigid beam's flight: the tip accelerates at 1.5 (a(t) - g) from the
# moment the upward base load exceeds gravity to the end of the pulse,
# integrated exactly (fine trapezoid of a piecewise-linear a: error 1e-12)
t = np.linspace(0.0, pulse[-1][0], 2000001)
a = -np.interp(t, [p[0] for p in pulse], [p[1] for p in pulse])
acc = np.where(a > g, 1.5 * (a - g), 0.0)
v = np.concatenate([[0.0], np.cumsum(0.5 * (acc[1:] + acc[:-1]) * np.diff(t))])
z = np.concatenate([[0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(t))])
height = z[-1] + v[-1] ** 2 / (2 * 1.5 * g)
ctx.check("beam tip max_uplift = z + v^2 / (3 g) after the pulse (m)", c["max_uplift"],
          height, rel=5e-3)
ctx.check("beam tip max_uplift_time = end of pulse + v / 1.5 g (s)", c["max_uplift_time"],
          t[-1] + v[-1] / (1.5 * g), rel=5e-3)
ctx.finish()
