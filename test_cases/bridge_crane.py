#!/usr/bin/python3
"""The parametric bridge crane (parameter_files/bridge_crane_static.prm,
Model/Type = bridge crane): static wheel loads with the vertical contacts
closed.

- the generated masses equal the hand sums of the section areas (header of
  the .prm) to 1e-12;
- the crane wheel loads sum to the total weight M g to 1e-8 relative, the
  trolley wheel loads to the trolley's weight (internal contacts);
- the two runway rails share the weight by the lever rule from the trolley
  position (statically determinate), at two trolley positions, to 1e-8;
- the two wheels of a rail carry the same load (symmetry about X = 0);
- one-line errors: trolley off the span, explicit zone longer than a
  girder, negative flange clearance, damping ratio >= 1, a frequency-range
  ratio above 0.3, a damping band upside down;
- Damping type = frequency range in a fully explicit run: the branches of
  the specification's prototype, dt_crit = (2/w_max)/sqrt(1 + sum alpha),
  the energy balance at round-off (issue #16);
- the default crane at rest from its static state (no record): zero
  velocities at t = 0 and absolute accelerations below 0.1 m/s^2 under
  CD-Lagrange and HATI (issue #24, item 2)."""
import os
import subprocess

from hati_test import Context, read_summary

ctx = Context()
prm = ctx.prm("bridge_crane_static.prm")
g, S, rho = 9.81, 20.0, 7850.0
A_g = 0.46 * 1.10 - 0.448 * 1.074
A_ec = 0.3 * 0.5 - 0.284 * 0.476
A_t = 0.2 * 0.3 - 0.184 * 0.28
m_girders, m_rails, m_ec = 2 * rho * A_g * S, 2 * 25.0 * S, rho * A_ec * 3.5
m_bridge = m_girders + m_rails + 2 * m_ec
m_trolley = rho * A_t * (2 * 1.8 + 3 * 2.0) + 3000.0 + 20350.0
M = m_bridge + m_trolley

for p in (0.3, 0.75):
    out, _ = ctx.run(prm, "p%g" % p, ["Model/Bridge crane/Trolley position=%g" % p])
    s = read_summary(out)
    ctx.check("p = %g: mass_bridge (kg)" % p, s["mass_bridge"], m_bridge, rel=1e-12)
    ctx.check("p = %g: mass_trolley (kg)" % p, s["mass_trolley"], m_trolley, rel=1e-12)
    w = s["static_wheel_loads"]
    crane = [w["crane_wheel_%d" % k] for k in range(1, 5)]
    trolley = [w["trolley_wheel_%d" % k] for k in range(1, 5)]
    ctx.check("p = %g: sum of crane wheel loads (N) = M g" % p, sum(crane), M * g, rel=1e-8)
    ctx.check("p = %g: sum of trolley wheel loads (N)" % p, sum(trolley), m_trolley * g, rel=1e-8)
    R_S = g * ((m_girders + m_rails) / 2 + m_ec + p * m_trolley)
    ctx.check("p = %g: rail at Y = S (wheels 3, 4) (N), lever rule" % p, crane[2] + crane[3], R_S,
              rel=1e-8)
    ctx.check("p = %g: rail at Y = 0 (wheels 1, 2) (N), lever rule" % p, crane[0] + crane[1],
              M * g - R_S, rel=1e-8)
    ctx.check("p = %g: wheels 1 and 2 equal (symmetry), relative" % p,
              abs(crane[0] - crane[1]) / crane[0], 0.0, abs_tol=1e-8)


def expect_error(what, sets, *fragments):
    p = subprocess.run([ctx.hati, prm] + sum((["--set", x] for x in sets), []) +
                       ["--set", "Output/Output directory=" + os.path.join(ctx.work, "err")],
                       capture_output=True, text=True, timeout=120)
    err = p.stderr.strip()
    ok = (p.returncode > 0 and len(err.splitlines()) == 1 and err.startswith("hati: error:")
          and all(x in err for x in fragments))
    ctx.check_true(what, ok, "(exit %d) %s" % (p.returncode, err))


expect_error("trolley off the span", ["Model/Bridge crane/Trolley position=0.97"],
             "Trolley position", "off the span")
expect_error("explicit zone longer than a girder", ["Model/Bridge crane/Explicit zone length=25"],
             "Explicit zone length", "longer than a girder")
expect_error("negative flange clearance", ["Model/Bridge crane/Flange clearance=-0.01"],
             "'Model/Bridge crane/Flange clearance' [Double 0...0.5 (inclusive)]")
expect_error("damping ratio > 1", ["Model/Bridge crane/Damping ratio=1.5"],
             "'Model/Bridge crane/Damping ratio' [Double 0...1 (inclusive)]")
expect_error("damping ratio = 1 (Rayleigh)", ["Model/Bridge crane/Damping ratio=1",
                                              "Model/Bridge crane/Damping type=Rayleigh"],
             "Damping ratio", "[0, 1)")
expect_error("frequency-range damping ratio above 0.3",
             ["Model/Bridge crane/Damping type=frequency range",
              "Model/Bridge crane/Damping ratio=0.5"],
             "Model/Bridge crane/Damping ratio", "[0, 0.3]", "frequency range")
expect_error("damping band upside down",
             ["Model/Bridge crane/Damping type=frequency range",
              "Model/Bridge crane/Damping band=30, 0.5"],
             "Model/Bridge crane/Damping band", "0 < lower < upper")

# issue #16: Damping type = frequency range (A8) as the crane's default
# damping of a fully explicit run. References: the branches of the
# specification's scipy prototype (nnls) for 2 % over 0.5-30 Hz; the stable
# step (2 / w_max) / sqrt(1 + sum alpha) against the undamped run's
# 2 / w_max of the same mesh; the energy balance at round-off.
explicit = ctx.prm("bridge_crane_full_explicit.prm")
records = os.path.join(ctx.source, "data", "accelerograms")
short = ["Time integration/End time=0.05", "Output/Output interval=0",
         "Model/Bridge crane/Travel=tied", "Model/Bridge crane/Hoist=rigid",
         "Model/Bridge crane/Eccentricities=false",
         "Loading/Accelerogram X=" + os.path.join(records, "Rinaldi228.AT2"),
         "Loading/Accelerogram Z=" + os.path.join(records, "RinaldiUP.AT2")]
out, _ = ctx.run(explicit, "undamped", short + ["Model/Bridge crane/Damping ratio=0"])
undamped = read_summary(out)
out, _ = ctx.run(explicit, "frequency_range",
                 short + ["Model/Bridge crane/Damping type=frequency range",
                          "Time integration/Time step=4e-5"])
s = read_summary(out)
ctx.check_true("frequency range: damping_type", s["damping_type"] == "frequency range",
               s["damping_type"])
for a, ref in zip(s["damping_branches"]["alpha"],
                  (0.066373834779, 0.053493976171, 0.07522797496)):
    ctx.check("frequency range: alpha (prototype)", a, ref, rel=1e-9)
ctx.check("frequency range: damping_fit_error", s["damping_fit_error"], 0.0233644780751,
          rel=1e-8)
sum_alpha = sum(s["damping_branches"]["alpha"])
ctx.check("frequency range: dt_crit = (2/w_max)/sqrt(1 + sum alpha) (s)", s["dt_crit"],
          undamped["dt_crit"] / (1 + sum_alpha) ** 0.5, rel=1e-9)
ctx.check_true("frequency range: dt = 4e-5 s is %.0f times the 2 %% Rayleigh step 1.8e-6 s"
               % (4e-5 / 1.8e-6), s["dt"] == 4e-5 and s["status"] == "completed")
# round-off: the static state's closed gaps carry some 7e-14 m of the solver's
# round-off under the 1e5 N wheel loads, 1e-8 J or 4e-12 of the largest
# energy (2920 J, the static strain energy), booked at the first step
ctx.check("frequency range: energy balance relative to the largest energy",
          s["energy_balance_relative"], 0.0, abs_tol=1e-11)

# issue #24, item 2: the default crane (braked wheels, the load on its rope)
# from its static state with no record at all stays at rest (reference: the
# static equilibrium; the accelerations of a structure at rest are 0). The
# t = 0 row must have zero velocities (the closed contacts carry their
# static forces from the first half step) and no monitor's absolute
# acceleration may pass 0.1 m/s^2 (a resting wheel fell 0.036 m/s into its
# rail at the first step: 73 to 122 m/s^2 at the crane wheels).
import csv
for tag, prm_file in (("rest_explicit", "bridge_crane_full_explicit.prm"),
                      ("rest_hati", "bridge_crane_hati.prm")):
    out, _ = ctx.run(ctx.prm(prm_file), tag,
                     ["Model/Bridge crane/Travel=braked", "Model/Bridge crane/Hoist=rope",
                      "Loading/Accelerogram X=", "Loading/Accelerogram Z=",
                      "Time integration/End time=0.3", "Output/Output interval=0"])
    with open(os.path.join(out, "history.csv"), newline="") as f:
        rows = list(csv.reader(f))
    velocity_columns = [i for i, name in enumerate(rows[0]) if ".v" in name]
    v0 = max(abs(float(rows[1][i])) for i in velocity_columns)
    ctx.check("%s: largest velocity of the t = 0 row (m/s, rad/s)" % tag, v0, 0.0,
              abs_tol=1e-12)
    peaks = read_summary(out)["max_absolute_acceleration"]
    values = {k: (v["value"] if isinstance(v, dict) else v) for k, v in peaks.items()}
    worst = max(values, key=values.get)
    ctx.check("%s: largest max_absolute_acceleration (m/s^2, %s)" % (tag, worst),
              values[worst], 0.0, abs_tol=0.1)
ctx.finish()
