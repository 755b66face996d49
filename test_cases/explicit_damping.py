#!/usr/bin/python3
"""Rayleigh damping in the explicit CD-Lagrange integrator (algorithms.md A7,
doc/theory.md 1.6) on the 3D portal frame (parameter_files/
portal_frame_dynamic.prm) under a base acceleration step, with a damping
ratio of 5 % at the first sway frequency (both frequencies of the damping
ratio set to it: a0 = zeta w1, a1 = zeta / w1), checked against:
- the implicit Newmark integrator with the same damping: the two top-sway
  histories (A1ux) agree, and so do the dissipated energies;
- the damped SDOF: the excursions about the static displacement decay by
  exp(-2 pi zeta / sqrt(1 - zeta^2)) per period;
- the critical step of the damped explicit scheme,
  (2 / w_max)(sqrt(1 + xi^2) - xi), xi = a1 w_max / 2 (w_max = 2 / the
  undamped dt_crit): a step above it is refused with a message naming the
  damping; mass damping alone leaves the step unchanged;
- the discrete energy balance of the explicit run, with the dissipated
  energy booked as the work of the damping force (round-off);
- frequency-range damping (A8, N4: Time integration/Damping/Type =
  frequency range, 5 % over 1-30 Hz): the printed critical step is
  (2/w_max)/sqrt(1 + sum alpha), the explicit run at 0.9 of it and Newmark
  (lumped mass) agree on the sway within 0.5 % of the peak and on the
  dissipated energy within 1 %, the decay of the sway matches the fitted
  ratio at the sway frequency, the balance (with damping_stored) closes to
  round-off in both, and summary.json reports the branches;
- frequency-range damping in the HATI coupling (G3' with the memory
  variables in the explicit state and the unit-ramp response): the split
  portal frame (parameter_files/portal_frame_split.prm, m = 10) against the
  fully explicit run, the histories of A1 and D1 within 0.5 % of the peak,
  the peaks within 0.5 %, the dissipated energy within 1 % and the coupled
  balance (interface work included) at round-off."""
import re
import subprocess

import numpy as np

from hati_test import Context, read_csv, read_summary

ctx = Context()
prm = ctx.prm("portal_frame_dynamic.prm")
zeta = 0.05
quiet = ["Output/Output interval=0", "Output/History interval=1e-3", "Time integration/End time=1"]

out, _ = ctx.run(prm, "static", ["Analysis/Type=static", "Loading/Gravity=-1, 0, 0",
                                 "Loading/Base acceleration=0, 0, 0"])
u_static = read_csv(out + "/history.csv")["A1ux"][0]

out, _ = ctx.run(prm, "modal", ["Analysis/Type=modal"])
modes = read_csv(out + "/modes.csv")
f1 = modes["frequency"][np.argmax(modes["effective_mass_ratio_x"])]
w1 = 2 * np.pi * f1
a0, a1 = zeta * w1, zeta / w1
print("first sway frequency %.6g Hz: a0 = %.6g 1/s, a1 = %.6g s" % (f1, a0, a1))
rayleigh = ["Time integration/Damping/Damping ratio=%g" % zeta,
            "Time integration/Damping/First frequency=%.15g" % f1,
            "Time integration/Damping/Second frequency=%.15g" % f1]
explicit = ["Time integration/Method=CD-Lagrange"]


def sway(out):
    h = read_csv(out + "/history.csv")
    return h["time"], h["A1ux"]


def peaks(t, x):
    """Maxima of x (sampled), refined by a parabola through three samples."""
    i = np.where((x[1:-1] > x[:-2]) & (x[1:-1] >= x[2:]))[0] + 1
    a, b, c = x[i - 1], x[i], x[i + 1]
    s = 0.5 * (a - c) / (a - 2 * b + c)
    return t[i] + s * (t[1] - t[0]), b - 0.25 * (a - c) * s


# 1. mass damping alone (a0 = 2 zeta w1) does not lower the step: dt = 2e-5
mass_only = ["Time integration/Damping/Mass coefficient=%.15g" % (2 * zeta * w1)]
out_m, p = ctx.run(prm, "explicit_mass", explicit + mass_only + quiet +
                   ["Time integration/Time step=2e-5"])
dt_crit0 = read_summary(out_m)["dt_crit"]
out_mi, _ = ctx.run(prm, "implicit_mass", mass_only + quiet + ["Time integration/Time step=2.5e-4"])
(te, ue), (ti, ui) = sway(out_m), sway(out_mi)
diff = np.max(np.abs(np.interp(ti, te, ue) - ui)) / np.max(np.abs(ui))
ctx.check("a0 only: explicit (dt 2e-5) vs Newmark A1ux, max diff / peak", diff, 0.0, abs_tol=0.02)

# 2. the Rayleigh damping at dt = 2e-5 is refused: a1 lowers the critical step
out_r, p = ctx.run(prm, "refused", explicit + rayleigh + quiet + ["Time integration/Time step=2e-5"],
                   expect_failure=True)
m = re.search(r"dt_crit = [^=]*= ([0-9.eE+-]+) s", p.stderr)
ctx.check_true("Rayleigh damping, dt = 2e-5 s refused, the message names the damping",
               p.returncode != 0 and m is not None and "damping" in p.stderr, p.stderr.strip())
w_max = 2.0 / dt_crit0
xi = a1 * w_max / 2
dt_crit = 2.0 / w_max * (np.sqrt(1 + xi * xi) - xi)
print("undamped dt_crit %.6g s, w_max %.6g rad/s, xi = %.6g: damped dt_crit %.6g s"
      % (dt_crit0, w_max, xi, dt_crit))
if m:
    ctx.check("printed damped dt_crit (s) vs (2/w_max)(sqrt(1+xi^2)-xi)", float(m.group(1)),
              dt_crit, rel=1e-5)

# 3. the damped explicit run (0.9 dt_crit) against Newmark (dt = 2.5e-4)
dt = 0.9 * dt_crit
out_e, _ = ctx.run(prm, "explicit", explicit + rayleigh + quiet +
                   ["Time integration/Time step=%.12g" % dt])
out_i, _ = ctx.run(prm, "implicit", rayleigh + quiet + ["Time integration/Time step=2.5e-4"])
(te, ue), (ti, ui) = sway(out_e), sway(out_i)
diff = np.max(np.abs(np.interp(ti, te, ue) - ui)) / np.max(np.abs(ui))
# lumped vs consistent mass (also in C), first vs second order damping: 2 %
ctx.check("Rayleigh: explicit vs Newmark A1ux, max diff / peak", diff, 0.0, abs_tol=0.02)

# decay of the sway excursions about the static displacement (the sway is
# negative: peaks of -(u - u_static)), one period apart
ratio = np.exp(-2 * np.pi * zeta / np.sqrt(1 - zeta ** 2))
for name, t, u in (("explicit", te, ue), ("Newmark", ti, ui)):
    tp, xp = peaks(t, -(u - u_static))
    r = xp[1:] / xp[:-1]
    print("%s: %d peaks, successive ratios %s" % (name, len(xp), np.array2string(r, precision=4)))
    ctx.check_true("%s: at least 5 sway peaks in 1 s" % name, len(xp) >= 5)
    worst = r[np.argmax(np.abs(r - ratio))]
    ctx.check("%s: worst ratio of successive peaks vs exp(-2 pi zeta/sqrt(1-zeta^2))" % name,
              worst, ratio, rel=0.1)

se, si = read_summary(out_e), read_summary(out_i)
ctx.check("explicit energy balance relative error", se["energy_balance_relative"], 0.0,
          abs_tol=1e-9)
ctx.check("Newmark energy balance relative error", si["energy_balance_relative"], 0.0,
          abs_tol=1e-9)
de, di = read_csv(out_e + "/energy.csv")["dissipated"][-1], read_csv(out_i + "/energy.csv")["dissipated"][-1]
ctx.check("dissipated energy at t = 1 s (J), explicit vs Newmark", de, di, rel=0.01)
ctx.check("Rayleigh: damping_stored column is 0", np.max(np.abs(read_csv(out_e + "/energy.csv")["damping_stored"])), 0.0, abs_tol=0.0)

# 4. frequency-range damping (A8 explicit, N4 implicit), 5 % over 1-30 Hz
band = ["Time integration/Damping/Type=frequency range",
        "Time integration/Damping/Damping ratio=%g" % zeta,
        "Time integration/Damping/Lower frequency=1",
        "Time integration/Damping/Upper frequency=30"]
out_f, _ = ctx.run(prm, "explicit_band_probe", explicit + band + quiet +
                   ["Time integration/Time step=1e-6", "Time integration/End time=1e-6"])
sf = read_summary(out_f)
alpha, tau = np.array(sf["damping_branches"]["alpha"]), np.array(sf["damping_branches"]["tau"])
ctx.check_true("summary.json: damping_type, 3 branches, fit error < 10 %",
               sf["damping_type"] == "frequency range" and len(alpha) == 3 and len(tau) == 3
               and 0 < sf["damping_fit_error"] < 0.1, str(sf["damping_fit_error"]))
dt_band = 2.0 / w_max / np.sqrt(1 + alpha.sum())
ctx.check("frequency range: dt_crit (s) vs (2/w_max)/sqrt(1 + sum alpha)", sf["dt_crit"], dt_band,
          rel=1e-9)
out_fe, _ = ctx.run(prm, "explicit_band", explicit + band + quiet +
                    ["Time integration/Time step=%.12g" % (0.9 * dt_band)])
out_fi, _ = ctx.run(prm, "implicit_band", band + quiet +
                    ["Time integration/Time step=1e-4", "Time integration/Newmark/Mass=lumped"])
(te, ue), (ti, ui) = sway(out_fe), sway(out_fi)
diff = np.max(np.abs(np.interp(ti, te, ue) - ui)) / np.max(np.abs(ui))
ctx.check("frequency range: explicit vs Newmark (lumped) A1ux, max diff / peak", diff, 0.0,
          abs_tol=0.005)
c = 1 + (alpha * 1j * w1 * tau / (1 + 1j * w1 * tau)).sum()
xi1 = c.imag / (2 * c.real)
ratio = np.exp(-2 * np.pi * xi1 / np.sqrt(1 - xi1 ** 2))
print("fitted ratio at the sway frequency %.6g Hz: %.6g" % (f1, xi1))
for name, t, u in (("explicit", te, ue), ("Newmark", ti, ui)):
    tp, xp = peaks(t, -(u - u_static))
    r = xp[1:] / xp[:-1]
    print("frequency range, %s: successive ratios %s" % (name, np.array2string(r, precision=4)))
    worst = r[np.argmax(np.abs(r - ratio))]
    ctx.check("frequency range, %s: worst ratio of successive peaks vs the fitted ratio" % name,
              worst, ratio, rel=0.1)
for name, o in (("explicit", out_fe), ("Newmark", out_fi)):
    e = read_csv(o + "/energy.csv")
    scale = max(np.max(np.abs(e[k])) for k in ("kinetic", "internal", "external_work"))
    ctx.check("frequency range, %s: max |balance_drift| / largest energy term" % name,
              np.max(np.abs(e["balance_drift"])) / scale, 0.0, abs_tol=1e-11)
    ctx.check_true("frequency range, %s: the branches store energy (damping_stored > 0)" % name,
                   np.max(e["damping_stored"]) > 1e-4 * scale)
de = read_csv(out_fe + "/energy.csv")["dissipated"][-1]
di = read_csv(out_fi + "/energy.csv")["dissipated"][-1]
ctx.check("frequency range: dissipated energy at t = 1 s (J), explicit vs Newmark", de, di,
          rel=0.01)

# 5. frequency-range damping in HATI (m = 10) against fully explicit CD-Lagrange
split = ctx.prm("portal_frame_split.prm")
split_quiet = ["Output/Output interval=0", "Output/History interval=2e-4"]
out_h, _ = ctx.run(split, "hati_band", band + split_quiet)
out_x, _ = ctx.run(split, "hati_band_explicit", band + split_quiet + explicit)
hh, hx = read_csv(out_h + "/history.csv"), read_csv(out_x + "/history.csv")
for node in ("A1ux", "D1ux"):
    diff = np.max(np.abs(np.interp(hx["time"], hh["time"], hh[node]) - hx[node]))
    peak_x = np.max(np.abs(hx[node]))
    ctx.check("frequency range, HATI m = 10 vs fully explicit: %s max diff / peak" % node,
              diff / peak_x, 0.0, abs_tol=0.005)
    ctx.check("frequency range, HATI m = 10 vs fully explicit: peak |%s| (m)" % node,
              np.max(np.abs(hh[node])), peak_x, rel=0.005)
eh = read_csv(out_h + "/energy.csv")
scale = max(np.max(np.abs(eh[k])) for k in ("kinetic", "internal", "external_work"))
ctx.check("frequency range, HATI: max |balance_drift| / largest energy term",
          np.max(np.abs(eh["balance_drift"])) / scale, 0.0, abs_tol=1e-11)
ctx.check_true("frequency range, HATI: the branches store energy (damping_stored > 0)",
               np.max(eh["damping_stored"]) > 1e-4 * scale)
ctx.check("frequency range: dissipated energy at the end (J), HATI vs fully explicit",
          eh["dissipated"][-1], read_csv(out_x + "/energy.csv")["dissipated"][-1], rel=0.01)
ctx.finish()
