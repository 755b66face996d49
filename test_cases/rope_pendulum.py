#!/usr/bin/python3
"""Ropes (Model/Frame/Ropes, spec R1, doc/theory.md 10) on
parameter_files/rope_pendulum.prm: a 1000 kg load on a 6 m rope of
k = 1e7 N/m hanging from the tip of a clamped arm.

1. Static state: T0 = m g (the load hangs alone), 1e-9 relative.
2. Modal analysis (rope tangent at the static state): the two pendulum
   modes at sqrt(g / L) / (2 pi) within 0.1 % (reference: the pendulum;
   the rope stretches by m g / k = 0.98 mm, 1.6e-4 of L).
3. Transient swing (CD-Lagrange from the static state, a base acceleration
   step of 0.01 g along x): the period from the zero crossings equals the
   modal period within 0.1 % (reference: the modal analysis of the same
   model); energy balance at round-off (1e-10 of the largest energy); the
   rope never slack.
4. A vertical base pulse that tosses the load (the hook point clamped, so
   the model is the load on its rope alone): a_g = -2 g for 0.1 s. The
   rope goes slack when cos(omega tau) = 1 - g / A after the pulse starts
   and the load flies until the rope is taut again: the first slack episode
   and the catch velocity against the exact piecewise solution (harmonic
   while taut, parabolic while slack; 1e-3 relative: the step is 2e-5 s),
   and the catching impulse int T dt over the taut episode against
   momentum conservation m (v_out - v_in) + m g dt_taut (1e-9 relative: the
   discrete momentum balance of CD-Lagrange is exact) and against the exact
   2 m v_catch + m g dt_taut (2e-3).
5. Refusals: Method = Newmark, and HATI with the rope in the implicit part,
   one line naming the rope.
6. The load on its rope from a clamped hook node (issue #24,
   item 14): static tension m g and the pendulum sqrt(g/L')/2pi (L' the
   stretched length) with and without a pre-stretched rest length."""
import math
import os

import numpy as np

from hati_test import Context, read_csv, read_summary

ctx = Context()
prm = ctx.prm("rope_pendulum.prm")
g, m, L, k = 9.81, 1000.0, 6.0, 1e7
f_pendulum = math.sqrt(g / L) / (2 * math.pi)

# 1-2. static tension and the modes
out, _ = ctx.run(prm, "modal")
s = read_summary(out)
ctx.check("static tension T0 (N) = m g", s["static_rope_tension"]["rope"], m * g, rel=1e-9)
f = s["frequencies"]
ctx.check("pendulum mode 1 (Hz) vs sqrt(g/L)/2pi", f[0], f_pendulum, rel=1e-3)
ctx.check("pendulum mode 2 (Hz) vs sqrt(g/L)/2pi", f[1], f_pendulum, rel=1e-3)
ctx.check("bounce mode (Hz) vs sqrt(k/m)/2pi, the arm in series",
          f[2], math.sqrt(k / m) / (2 * math.pi), rel=0.02)

# 3. the transient swing
out, _ = ctx.run(prm, "swing", ["Analysis/Type=transient", "Analysis/Initial state=static",
                                "Loading/Base acceleration=0.0981, 0, 0",
                                "Time integration/Time step=5e-5",
                                "Time integration/End time=20"])
h = read_csv(out + "/history.csv")
t, x = h["time"], h["loadux"] - h["hookux"]
x = x - 0.5 * (x.max() + x.min())
i = np.where((x[:-1] < 0) & (x[1:] >= 0))[0]
crossings = t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i])
period = np.mean(np.diff(crossings))
# the swing is about the tilted equilibrium, gravity sqrt(g^2 + a^2): 5e-5 relative
ctx.check("swing period (s) vs the modal period", period, 1 / f[0], rel=1e-3)
ctx.check("swing frequency (Hz) vs sqrt(g/L)/2pi", 1 / period, f_pendulum, rel=1e-3)
s = read_summary(out)
ctx.check("energy balance relative error (swing)", s["energy_balance_relative"], 0.0,
          abs_tol=1e-10)
ctx.check("rope slack time (s, swing)", s["rope_tension"]["rope"]["slack_time"], 0.0,
          abs_tol=0.0)

# 4. the toss: a_g = -A for 0.1 s from t1 = 0.05 s (two-column record, m/s^2)
A, t1, t2, dt, T_end = 2 * g, 0.05, 0.15, 2e-5, 0.6
record = os.path.join(ctx.work, "pulse.txt")
with open(record, "w") as r:
    r.write("0 0\n%.10g 0\n%.10g %.10g\n%.10g %.10g\n%.10g 0\n2 0\n"
            % (t1 - 1e-9, t1, -A, t2, -A, t2 + 1e-9))
out, _ = ctx.run(prm, "toss", ["Analysis/Type=transient", "Analysis/Initial state=static",
                               "Model/Frame/Supports=base: clamped; hook: clamped",
                               "Loading/Accelerogram Z=" + record,
                               "Loading/Accelerogram units=m/s^2",
                               "Time integration/Time step=%g" % dt,
                               "Time integration/End time=%g" % T_end,
                               "Output/History interval=0"])
h = read_csv(out + "/history.csv")
t, uz, vz = h["time"], h["loaduz"], h["loadvz"]
tension = k * np.maximum(0.0, -uz)  # hook clamped: extension = -uz
slack = np.where(tension == 0.0)[0]
first_slack = t[slack[0]]
taut_again = slack[np.argmax(np.diff(slack) > 1)] + 1 if np.any(np.diff(slack) > 1) else slack[-1] + 1
# exact: taut until cos(w tau) = 1 - g/A, then free flight (relative
# gravity A - g up during the pulse, -g after) until the extension is 0
w = math.sqrt(k / m)
tau = math.acos(1 - g / A) / w
ts = t1 + tau
v0 = (m * A / k) * w * math.sin(w * tau)  # upward speed when the rope goes slack
z_end = v0 * (t2 - ts) + 0.5 * (A - g) * (t2 - ts) ** 2  # height at the pulse end
v_end = v0 + (A - g) * (t2 - ts)
t_fall = (v_end + math.sqrt(v_end ** 2 + 2 * g * z_end)) / g  # back to z = 0
t_taut = t2 + t_fall
v_catch = math.sqrt(v_end ** 2 + 2 * g * z_end)
ctx.check("rope goes slack at (s)", first_slack, ts, abs_tol=2 * dt)
ctx.check("first slack episode (s)", t[taut_again] - first_slack, t_taut - ts, rel=1e-3)
ctx.check("catch velocity (m/s, downward)", -vz[taut_again - 1], v_catch, rel=1e-3)
# the taut episode after the catch: its rope impulse against the momentum
start = taut_again
end = start + np.argmax(tension[start:] == 0.0)
impulse = np.sum(tension[start:end]) * dt  # CD: the force of step n acts over dt
momentum = m * (vz[end - 1] - vz[start - 1]) + m * g * (end - start) * dt
ctx.check("catching impulse (N s) vs momentum change + weight", impulse, momentum, rel=1e-9)
ctx.check("catching impulse (N s) vs 2 m v_catch + m g dt_taut", impulse,
          2 * m * v_catch + m * g * (end - start) * dt, rel=2e-3)
s = read_summary(out)
ctx.check("energy balance relative error (toss)", s["energy_balance_relative"], 0.0,
          abs_tol=1e-10)
ctx.check_true("summary slack_time >= the first episode",
               s["rope_tension"]["rope"]["slack_time"] >= t_taut - ts - 2 * dt,
               "(%g s)" % s["rope_tension"]["rope"]["slack_time"])

# 6. the simplest rope model (issue #24, item 14): a load hanging on its rope
# from a clamped hook node (the arm clamped at both ends, one element: no
# free DoF but the load's, which only the rope holds); the static Newton must find
# the rope carrying the weight (statics: T0 = m g) and the modal analysis the
# pendulum (reference: sqrt(g / L') / 2 pi with L' = L + m g / k the
# stretched length; the rope's own bounce sqrt(k / m) / 2 pi). Also with a
# pre-stretched rest length (a rope shorter than the chord).
fixed_hook = ["Model/Frame/Members=arm: base, hook, arm, steel, 1",
              "Model/Frame/Supports=base: clamped; hook: clamped"]
for tag, rope, rest in [("fixed_hook", "rope: hook, load, 5e6", L),
                        ("fixed_hook_prestretched", "rope: hook, load, 5e6, 5.9", 5.9)]:
    kf = 5e6
    stretched = rest + m * g / kf
    for analysis in ("static", "modal"):
        out, _ = ctx.run(prm, tag + "_" + analysis,
                         fixed_hook + ["Model/Frame/Ropes=" + rope, "Analysis/Type=" + analysis,
                                       "Analysis/Number of modes=3"])
        s = read_summary(out)
        ctx.check("%s %s: static tension T0 (N) = m g" % (tag, analysis),
                  s["static_rope_tension"]["rope"], m * g, rel=1e-9)
        if analysis == "modal":
            f = s["frequencies"]
            f_p = math.sqrt(g / stretched) / (2 * math.pi)
            ctx.check("%s: pendulum mode 1 (Hz) vs sqrt(g/L')/2pi" % tag, f[0], f_p, rel=1e-6)
            ctx.check("%s: pendulum mode 2 (Hz) vs sqrt(g/L')/2pi" % tag, f[1], f_p, rel=1e-6)
            ctx.check("%s: bounce mode (Hz) vs sqrt(k/m)/2pi" % tag, f[2],
                      math.sqrt(kf / m) / (2 * math.pi), rel=1e-6)

# 5. refusals
for tag, sets, expected in [
        ("newmark", ["Analysis/Type=transient", "Time integration/Method=Newmark"],
         "hati: error: Time integration/Method = Newmark: the rope 'rope' is a nonlinear"),
        ("hati_implicit", ["Analysis/Type=transient", "Time integration/Method=HATI",
                           "Model/Frame/Members=arm: base, hook, arm, steel, 2",
                           "Model/Decomposition/Explicit region=0, 0.4"],
         "hati: error: Model/Decomposition: the rope 'rope' lies in the implicit subdomain")]:
    _, p = ctx.run(prm, tag, sets, expect_failure=True)
    lines = p.stderr.strip().splitlines()
    ctx.check_true("refusal (%s): one line" % tag,
                   p.returncode == 1 and len(lines) == 1 and lines[0].startswith(expected),
                   repr(p.stderr.strip()))
# issue #59, finding 9: an element whose every DoF is held (the arm clamped
# at both ends, one element) never vibrates and is left out of the critical
# step: the rope on its fixed hook sets it, dt_crit = 2 / sqrt(k / m) =
# 2 / sqrt(1e7 / 1000) = 0.02 s (hand; the arm gave 1.9e-4 s before)
import re
_, p = ctx.run(ctx.prm("rope_pendulum.prm"), "clamped_arm", [
    "Analysis/Type=transient", "Model/Frame/Supports=base: clamped; hook: clamped",
    "Model/Frame/Members=arm: base, hook, arm, steel, 1", "Time integration/End time=0.01",
    "Time integration/Time step=1e-3"])
m = re.search(r"dt_crit = ([0-9.e+-]+) s", p.stdout)
ctx.check("clamped arm: dt_crit from the rope alone (s)", float(m.group(1)) if m else math.nan,
          2 / math.sqrt(1e7 / 1000), rel=1e-3)
ctx.finish()
