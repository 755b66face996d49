#!/usr/bin/python3
"""The explicit/implicit coupling, Method = HATI (algorithms.md G1-G4, G3'),
against independent references:
- the spec's reference bar (parameter_files/bar_split_wave.prm) with a lumped
  implicit mass: tip error against a fine fully explicit run (dt = 0.05 h)
  and interface work, compared with the numpy prototype of G3'
  (gc_bar_macro.py, sampled at the macro-step ends like history.csv:
  0.160 / 0.499 / 1.580 % and W_G / W_ext = -3.86e-4 / -5.92e-4 / -1.15e-3 for
  m = 1, 2, 5); m = 1 agrees with the single-domain runs to discretisation
  error; at fixed m the coupled solution converges to the fine one as dt -> 0;
- the split portal frame (parameter_files/portal_frame_split.prm): top sway
  within 1 % of the peak of the fully explicit run for m = 10 (2500 macro
  steps) and m = 20 (2000 macro steps); 1e4 macro steps stay bounded;
- the reference bar with frequency-range damping (5 % over 0.1-10 Hz, the
  memory variables in the superposition): tip error against the damped fine
  explicit run as the prototype gc_bar_damped_macro.py gives it (0.029 /
  0.029 / 0.175 / 0.717 % for m = 1, 2, 5, 10);
- every run: the energy balance with interface_work closes to 1e-10 and the
  interface velocity jump at the macro-step ends is zero to round-off;
- bad decompositions get one-line errors naming the cause."""
import subprocess

import numpy as np

from hati_test import Context, read_csv, read_summary

ctx = Context()
bar = ctx.prm("bar_split_wave.prm")
frame = ctx.prm("portal_frame_split.prm")
no_vtu = "Output/Output interval=0"


def check_balance(tag, out, vscale_floor=0.0):
    """Energy balance and interface velocity jump; the jump is relative to
    the largest monitored velocity, or to vscale_floor (m/s) for a run that
    stays at rest."""
    s = read_summary(out)
    ctx.check(tag + ": energy balance with interface work (relative)",
              s["energy_balance_relative"], 0.0, abs_tol=1e-10)
    h = read_csv(out + "/history.csv")
    vscale = max(np.max(np.abs(h[c])) for c in h.dtype.names if ".v" in c or c.endswith("vx"))
    vscale = max(vscale, vscale_floor)
    ctx.check(tag + ": interface velocity jump / velocity scale",
              s["interface_velocity_jump"] / vscale, 0.0, abs_tol=1e-10)
    return s


# --- the reference bar -------------------------------------------------------
out_ref, _ = ctx.run(bar, "bar_reference", ["Time integration/Method=CD-Lagrange",
                                            "Time integration/Time step=5e-4", no_vtu])
ref = read_csv(out_ref + "/history.csv")
peak = np.max(np.abs(ref["impact_endux"][ref["time"] >= 0.1]))


def tip_error(out):
    """max |u_tip - u_ref| / peak over the history rows with t >= 0.1 s."""
    h = read_csv(out + "/history.csv")
    sel = h["time"] >= 0.1 - 1e-12
    r = np.interp(h["time"][sel], ref["time"], ref["impact_endux"])
    return np.max(np.abs(h["impact_endux"][sel] - r)) / peak, h


prototype = {1: (0.160, -3.86e-4), 2: (0.499, -5.92e-4), 5: (1.580, -1.15e-3)}
for m, (err_ref, work_ref) in prototype.items():
    out, _ = ctx.run(bar, "bar_m%d" % m, ["Time integration/HATI/Time step ratio=%d" % m, no_vtu])
    err, h = tip_error(out)
    # two digits of the prototype: 3 % of its value
    ctx.check("bar m = %d: tip error vs fine explicit (%%)" % m, 100 * err, err_ref, rel=0.03)
    e = read_csv(out + "/energy.csv")
    ctx.check("bar m = %d: interface_work / external_work" % m,
              e["interface_work"][-1] / e["external_work"][-1], work_ref, rel=0.05)
    s = check_balance("bar m = %d" % m, out)
    ctx.check_true("bar m = %d: summary keys" % m,
                   s["time_step_ratio"] == m and s["n_dofs_explicit"] == 51 and
                   s["n_dofs_implicit"] == 50 and s["n_interface_dofs"] == 1 and
                   all(k in s for k in ("wall_time_explicit", "wall_time_implicit",
                                        "wall_time_interface")), str(s))
    if m == 1:
        h1 = h

# frequency-range damping (A8 explicit, N4 implicit, 5 % over 0.1-10 Hz):
# the memory variables in the superposition (G3'); tip error against the
# damped fine explicit run sampled at 600 points of [0.1, 3] s as the
# prototype gc_bar_damped_macro.py does (0.029 / 0.029 / 0.175 / 0.717 %
# for m = 1, 2, 5, 10; it samples every micro step, history.csv the
# macro-step ends: within 15 %), and the balance
band = ["Time integration/Damping/Type=frequency range",
        "Time integration/Damping/Damping ratio=0.05",
        "Time integration/Damping/Lower frequency=0.1",
        "Time integration/Damping/Upper frequency=10", no_vtu]
out_dref, _ = ctx.run(bar, "bar_band_reference", band + ["Time integration/Method=CD-Lagrange",
                                                         "Time integration/Time step=5e-4"])
dref = read_csv(out_dref + "/history.csv")
samples = np.linspace(0.1, 3.0, 600)
dref_tip = np.interp(samples, dref["time"], dref["impact_endux"])
for m, err_ref in ((1, 0.029), (2, 0.029), (5, 0.175), (10, 0.717)):
    out, _ = ctx.run(bar, "bar_band_m%d" % m,
                     band + ["Time integration/HATI/Time step ratio=%d" % m])
    h = read_csv(out + "/history.csv")
    err = np.max(np.abs(np.interp(samples, h["time"], h["impact_endux"]) - dref_tip)) / \
        np.max(np.abs(dref_tip))
    ctx.check("bar m = %d, frequency range: tip error vs damped fine explicit (%%)" % m,
              100 * err, err_ref, rel=0.15)
    check_balance("bar m = %d, frequency range" % m, out)
    e = read_csv(out + "/energy.csv")
    ctx.check_true("bar m = %d, frequency range: the branches store energy" % m,
                   np.max(e["damping_stored"]) > 1e-3 * np.max(e["external_work"]))

# m = 1 against the single-domain runs at the same step: all within the
# discretisation error of the fine reference (measured 0.16, 0.23, 0.34 %)
for method in ("CD-Lagrange", "Newmark"):
    out, _ = ctx.run(bar, "bar_" + method, ["Time integration/Method=" + method, no_vtu])
    err, h = tip_error(out)
    ctx.check("bar %s, dt = 0.5 h: tip error vs fine explicit (%%)" % method, 100 * err, 0.0,
              abs_tol=0.5)
    if method == "CD-Lagrange":
        diff = np.max(np.abs(h1["impact_endux"] - h["impact_endux"])) / peak
        ctx.check("bar HATI m = 1 vs CD-Lagrange, same dt (% of peak)", 100 * diff, 0.0,
                  abs_tol=0.5)

# convergence as dt -> 0 at fixed m = 2 (measured 0.50, 0.20, 0.075 %)
errors = []
for dt in (5e-3, 2.5e-3, 1.25e-3):
    out, _ = ctx.run(bar, "bar_conv_%g" % dt, ["Time integration/HATI/Time step ratio=2",
                                               "Time integration/Time step=%g" % dt, no_vtu])
    errors.append(tip_error(out)[0])
for a, b in zip(errors, errors[1:]):
    ctx.check_true("bar m = 2: error ratio when dt halves >= 1.8", a / b >= 1.8,
                   "%.4g %% -> %.4g %%: ratio %.3f" % (100 * a, 100 * b, a / b))

# --- the split portal frame --------------------------------------------------
out_e, _ = ctx.run(frame, "frame_explicit", ["Time integration/Method=CD-Lagrange",
                                             "Time integration/End time=0.8", no_vtu])
he = read_csv(out_e + "/history.csv")
for m, T in ((10, 0.5), (20, 0.8)):
    out, _ = ctx.run(frame, "frame_m%d" % m, ["Time integration/HATI/Time step ratio=%d" % m,
                                              "Time integration/End time=%g" % T, no_vtu])
    h = read_csv(out + "/history.csv")
    s = check_balance("frame m = %d" % m, out)
    ctx.check_true("frame m = %d: at least 2000 macro steps" % m, s["n_steps"] >= 2000,
                   str(s["n_steps"]))
    ref_peak = np.max(np.abs(he["A1ux"][he["time"] <= T + 1e-12]))
    for node in ("A1", "D1"):  # A1 on the interface (explicit copy), D1 implicit
        diff = np.max(np.abs(h[node + "ux"] - np.interp(h["time"], he["time"], he[node + "ux"])))
        ctx.check("frame m = %d: %s.ux vs fully explicit / peak" % (m, node), diff / ref_peak,
                  0.0, abs_tol=0.01)

# damping on both sides (A7 explicit, Newmark implicit): the fully explicit,
# fully implicit and coupled runs model the same damped frame
damped = ["Time integration/Damping/Mass coefficient=3",
          "Time integration/Damping/Stiffness coefficient=1e-6", no_vtu]
runs = {}
for method in ("CD-Lagrange", "Newmark", "HATI"):
    extra = ["Time integration/Time step=2e-4"] if method == "Newmark" else []
    runs[method], _ = ctx.run(frame, "frame_damped_" + method,
                              damped + ["Time integration/Method=" + method] + extra)
hd = {k: read_csv(v + "/history.csv") for k, v in runs.items()}
ed = {k: read_csv(v + "/energy.csv") for k, v in runs.items()}
damped_peak = np.max(np.abs(hd["CD-Lagrange"]["A1ux"]))
for method in ("Newmark", "HATI"):
    diff = np.max(np.abs(hd[method]["A1ux"] - np.interp(hd[method]["time"],
                                                        hd["CD-Lagrange"]["time"],
                                                        hd["CD-Lagrange"]["A1ux"])))
    ctx.check("damped frame: %s vs CD-Lagrange A1.ux / peak" % method, diff / damped_peak, 0.0,
              abs_tol=0.01)
    ctx.check("damped frame: %s dissipated energy vs CD-Lagrange (J)" % method,
              ed[method]["dissipated"][-1], ed["CD-Lagrange"]["dissipated"][-1], rel=0.02)
check_balance("damped frame HATI m = 10", runs["HATI"])

# gravity on both sides from the static state (Initial state = static): the
# run starts at rest on the static deflection (Lambda_0 = the static
# interface force) and stays there to round-off: the static state is solved
# under the loads the integrators apply (gravity with the lumped mass on the
# explicit side; before, the consistent static load left an oscillation of
# 0.15 % of the deflection)
out, _ = ctx.run(frame, "frame_gravity_static",
                 ["Loading/Gravity=0, 0, -9.81", "Loading/Base acceleration=0, 0, 0",
                  "Analysis/Initial state=static", "Time integration/End time=0.1", no_vtu])
h = read_csv(out + "/history.csv")
for node in ("A1", "D1"):
    ctx.check("gravity from the static state: %s.uz drift / static deflection" % node,
              np.max(np.abs(h[node + "uz"] - h[node + "uz"][0])) / abs(h[node + "uz"][0]), 0.0,
              abs_tol=1e-10)
# at rest: the jump relative to the velocity that would cover the static
# deflection in the 0.1 s of the run
check_balance("gravity from the static state", out,
              vscale_floor=abs(h["A1uz"][0]) / 0.1)

# a hinged interface (A1, B1 hinged: the translations only are shared)
out, _ = ctx.run(frame, "frame_hinged", ["Model/Frame/Hinged joints=A1, B1", no_vtu,
                                         "Time integration/End time=0.2"])
out_r, _ = ctx.run(frame, "frame_hinged_explicit", ["Model/Frame/Hinged joints=A1, B1", no_vtu,
                                                    "Time integration/End time=0.2",
                                                    "Time integration/Method=CD-Lagrange"])
h, r = read_csv(out + "/history.csv"), read_csv(out_r + "/history.csv")
ctx.check_true("hinged interface: 6 interface DoFs (translations of A1, B1)",
               read_summary(out)["n_interface_dofs"] == 6, str(read_summary(out)["n_interface_dofs"]))
ctx.check("hinged interface: A1.ux vs fully explicit / peak",
          np.max(np.abs(h["A1ux"] - np.interp(h["time"], r["time"], r["A1ux"]))) /
          np.max(np.abs(r["A1ux"])), 0.0, abs_tol=0.01)

# 1e4 macro steps (m = 20, 4 s): bounded (the undamped step response peaks at
# about twice the static sway: within 5 % of the explicit run's peak) and the
# energy balance still closed
out, _ = ctx.run(frame, "frame_long", ["Time integration/HATI/Time step ratio=20",
                                       "Time integration/End time=4", no_vtu,
                                       "Output/History interval=4e-3"])
h = read_csv(out + "/history.csv")
s = check_balance("frame 1e4 macro steps", out)
ctx.check_true("frame: 1e4 macro steps", s["n_steps"] == 10000, str(s["n_steps"]))
ctx.check("frame 1e4 macro steps: peak sway / explicit peak", np.max(np.abs(h["A1ux"])) /
          np.max(np.abs(he["A1ux"])), 1.0, abs_tol=0.05)


# --- the bar impact with the impacting half explicit ---------------------------
# analytical (bar_impact_1d.prm): contact from g0 / v0 = 1 ms for 2 L / c,
# plateau force rho c A v0; the prototype gives 0.60-0.80 % on the duration
impact = ctx.prm("bar_split_impact.prm")
c0 = np.sqrt(2e11 / 7800)
for m, region in ((1, "0.5, 1"), (5, "0.5, 1"), (10, "0.5, 1"), (10, "0.95, 1"), (20, "0.9, 1")):
    tag = "impact m = %d, explicit %s" % (m, region)
    out, _ = ctx.run(impact, "impact_m%d_%s" % (m, region[:4]),
                     ["Time integration/HATI/Time step ratio=%d" % m,
                      "Model/Decomposition/Explicit region=" + region, no_vtu])
    c = read_csv(out + "/contacts.csv")
    on = np.where(c["impulse"] > 0)[0]
    dt = 2e-7
    ctx.check(tag + ": contact start (s)", c["time"][on[0]], 1e-3, abs_tol=1.5 * dt)
    ctx.check(tag + ": contact duration (s)", c["time"][on[-1]] - c["time"][on[0]] + dt,
              2 / c0, rel=0.01)
    f = c["force"][on[0]:on[-1] + 1]
    n = len(f)
    ctx.check(tag + ": plateau force (N)", np.mean(f[n // 4:3 * n // 4]), 7800 * c0 * 1e-4,
              rel=0.02)
    s = check_balance(tag, out)
    ctx.check_true(tag + ": one impact", s["n_impacts"] == 1, str(s["n_impacts"]))
    # the contact is 50 nodes from the interface at x = 0.5, 5 at x = 0.95
    within_reach = region != "0.5, 1"
    ctx.check_true(tag + ": macro steps redone only with the contact within reach",
                   (s["redone_macro_steps"] > 0) == within_reach, str(s["redone_macro_steps"]))

# the 3D solid (code_aster SDNV100, laterally constrained: P-wave speed) with
# the impacting half explicit, m = 2: contact 2 L / c_P, force rho c_P A v0
out, _ = ctx.run(ctx.prm("bar_impact_3d.prm"), "solid_m2",
                 ["Time integration/Method=HATI", "Model/Decomposition/Explicit region=0.1, 0.2",
                  "Time integration/HATI/Time step ratio=2", "Time integration/Time step=1e-7",
                  no_vtu])
c = read_csv(out + "/contacts.csv")
on = np.where(c["impulse"] > 0)[0]
E, nu, rho = 2e11, 0.3, 8000.0
c_p = np.sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * rho))
ctx.check("solid m = 2: contact duration (s)", c["time"][on[-1]] - c["time"][on[0]] + 1e-7,
          2 * 0.2 / c_p, rel=0.015)
f = c["force"][on[0]:on[-1] + 1]
ctx.check("solid m = 2: plateau force (N)", np.mean(f[len(f) // 4:3 * len(f) // 4]),
          rho * c_p * 4e-4 * 100, rel=0.01)
check_balance("solid m = 2", out)

# --- bad decompositions --------------------------------------------------------
def expect_error(what, prm, sets, *fragments):
    cmd = [ctx.hati, prm, "--set", "Output/Output directory=" + ctx.work + "/err"]
    for x in sets:
        cmd += ["--set", x]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    lines = p.stderr.strip().splitlines()
    ok = (p.returncode > 0 and len(lines) == 1 and lines[0].startswith("hati: error:")
          and all(f in p.stderr for f in fragments))
    ctx.check_true(what, ok, "(exit %d) %s" % (p.returncode, p.stderr.strip()))


expect_error("a contact in the implicit subdomain", bar,
             ["Model/Bar/Wall=true", "Model/Decomposition/Explicit region=0, 0.5"],
             "contact 'contact' lies in the implicit subdomain")
expect_error("an empty explicit subdomain", bar, ["Model/Decomposition/Explicit region=5, 6"],
             "explicit subdomain is empty")
expect_error("an empty implicit subdomain", bar, ["Model/Decomposition/Explicit region=-1, 2"],
             "implicit subdomain is empty")
expect_error("no interface", frame,
             ["Model/Frame/Members=m1: A0, A1, column, steel, 2; m2: B0, B1, column, steel, 2",
              "Model/Frame/Point masses=", "Model/Frame/Monitor nodes=A1",
              "Model/Frame/Supports=A0: clamped; B0: clamped",
              "Model/Decomposition/Explicit members=m1"], "no interface")
expect_error("an explicit step above the explicit dt_crit", frame,
             ["Time integration/Time step=2e-4"], "explicit subdomain", "dt_crit")
expect_error("a time step ratio of 0", bar, ["Time integration/HATI/Time step ratio=0"],
             "'Time integration/HATI/Time step ratio' [Integer range 1...10000 (inclusive)]")
expect_error("an unknown explicit member", frame,
             ["Model/Decomposition/Explicit members=colZ"], "no member named 'colZ'")
ctx.finish()
