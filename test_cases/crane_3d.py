#!/usr/bin/python3
"""The three-dimensional crane (issue #26): Model/Bridge crane/Girder model
= solid on coarse meshes (0.55 m plate elements, 37,674 DoFs, for the
statics and the default crane at rest under HATI).

1. Statics, tied wheels and rigid hoist, trolley at 0.3 of the span
   (reference: the lever rule, a statically determinate split of the
   weight, and the beam crane's masses): the solid crane's mass is the
   beam crane's plus its diaphragms (hand sum); the crane wheel loads sum
   to M g and share it by the lever rule, the trolley wheels carry a
   quarter of the trolley each, to 1e-6 relative; the end carriages' flange
   pairs that the girders' end rotations push are released within their
   play (zero static lateral force).
2. The girders against the beam crane's: with a rail of negligible
   stiffness (the beam crane counts its mass only), the trolley wheels'
   static deflection within 5 % of the beam crane's (measured: +2.4 % at
   0.55 m, +3.4 % at 0.4 m: shear and the top flange's local bending under
   the rail); with the default A55 rail the composite girder is stiffer
   (measured -12.6 % at 0.55 m, -11.7 % at 0.4 m; checked to be stiffer by
   5 to 20 %).
3. The braked crane (Coulomb friction at the wheels) with solid girders
   (0.55 m) and a rigid hoist from its settled static state (doc/theory.md
   6.2) under HATI with no record
   (reference: the static state is at rest, as the fully explicit crane,
   9e-6 m/s^2): velocities and accelerations of the monitors at round-off
   over the 0.004 s, and the energy balance closed with the interface work
   (E1). The trolley wheels' contacts act on rail nodes tied across the
   interface (doc/theory.md 6.1, 9.2). (With the rope the static state's
   Newton iteration takes 77 s at this size: run by hand, see the note.)
4. The tied crane at rest under HATI with the Craig-Bampton reduced
   girders (doc/theory.md 12.2; issue #27) at 0.55 m: accelerations below
   1e-4 g, no penetration beyond 1 nm, energy balance closed.
5. Modes against the beam crane's (reference: the beam crane, true
   heights, tied wheels, rigid hoist, trolley at mid-span; 0.4 m plates and
   a rail of negligible stiffness): its first six elastic modes paired by
   MAC on the frame nodes both models share, identified by type, within 5 %
   (the trolley's yaw on the top flanges within 10 %)."""
import csv
import glob
import os

import numpy as np

from hati_test import Context, read_csv, read_summary
from vtu_files import read_points

ctx = Context()
prm = ctx.prm("bridge_crane_3d.prm")
g, S, rho = 9.81, 20.0, 7850.0
COARSE = ["Model/Bridge crane/Girder element size=0.55"]
STATIC = ["Analysis/Type=static", "Loading/Accelerogram X=", "Loading/Accelerogram Z=",
          "Model/Bridge crane/Travel=tied",
          "Model/Bridge crane/Hoist=rigid", "Model/Bridge crane/Trolley position=0.3"]

# masses by hand (parameter_files/bridge_crane_static.prm), plus the
# diaphragms: 11 per girder (every 2 m and at both ends), (b - 2 t_w)
# (h - 2 t_f) t_w each
A_g = 0.46 * 1.10 - 0.448 * 1.074
A_ec = 0.3 * 0.5 - 0.284 * 0.476
A_t = 0.2 * 0.3 - 0.184 * 0.28
diaphragms = 2 * 11 * rho * 0.448 * 1.074 * 0.006
m_girders = 2 * rho * A_g * S + diaphragms
m_rails, m_ec = 2 * 25.0 * S, rho * A_ec * 3.5
m_bridge = m_girders + m_rails + 2 * m_ec
m_trolley = rho * A_t * (2 * 1.8 + 3 * 2.0) + 3000.0 + 20350.0
M = m_bridge + m_trolley

# ---- 1. statics -------------------------------------------------------------
out, p = ctx.run(prm, "static", STATIC + COARSE)
s = read_summary(out)
ctx.check("mass_bridge (kg), with the diaphragms", s["mass_bridge"], m_bridge, rel=1e-12)
w = s["static_wheel_loads"]
crane = [w["crane_wheel_%d" % k] for k in range(1, 5)]
trolley = [w["trolley_wheel_%d" % k] for k in range(1, 5)]
ctx.check("sum of crane wheel loads (N) = M g", sum(crane), M * g, rel=1e-6)
R_S = g * ((m_girders + m_rails) / 2 + m_ec + 0.3 * m_trolley)
ctx.check("rail at Y = S (N), lever rule", crane[2] + crane[3], R_S, rel=1e-6)
ctx.check("rail at Y = 0 (N), lever rule", crane[0] + crane[1], M * g - R_S, rel=1e-6)
for k in range(4):
    ctx.check("trolley wheel %d (N) = m_trolley g / 4" % (k + 1), trolley[k], m_trolley * g / 4,
              rel=1e-6)
forces = s["static_contact_forces"]
for k in range(1, 5):
    name = "crane_wheel_%d_lateral" % k
    ctx.check(name + ": static force (N), released or zero", abs(forces.get(name, 0.0)), 0.0,
              abs_tol=1e-6 * M * g)


def trolley_deflection(out):
    with open(os.path.join(out, "history.csv"), newline="") as f:
        rows = list(csv.reader(f))
    return float(rows[1][rows[0].index("tw1.uz")])


# ---- 2. against the beam crane ----------------------------------------------
out_beam, _ = ctx.run(prm, "static_beam", STATIC + ["Model/Bridge crane/Girder model=beam"])
beam = trolley_deflection(out_beam)
out_thin, _ = ctx.run(prm, "static_thin_rail", STATIC + COARSE + [
    "Model/Bridge crane/Rail section=rectangle, 0.02, 0.02"])
thin = trolley_deflection(out_thin)
ctx.check("trolley wheel deflection, rail of negligible stiffness / beam crane", thin / beam,
          1.0, abs_tol=0.05)
composite = trolley_deflection(out)
ctx.check("trolley wheel deflection, A55 rail (composite) / beam crane", composite / beam,
          0.875, abs_tol=0.075)

# ---- 3. the default crane at rest under HATI ---------------------------------
# (0.55 m; until the static friction was settled, doc/theory.md 6.2, the
# braked crane's stuck static state there needed 17 kN of friction along Y
# at a braked crane wheel, more than mu N, and was refused: 0.4 m was used)
out, _ = ctx.run(prm, "rest_hati", COARSE + ["Model/Bridge crane/Hoist=rigid",
                                    "Model/Decomposition/Implicit reduction=none"] + [
    "Loading/Accelerogram X=", "Loading/Accelerogram Z=", "Time integration/End time=0.004",
    "Output/Output interval=0"])
s = read_summary(out)
with open(os.path.join(out, "history.csv"), newline="") as f:
    rows = list(csv.reader(f))
velocity_columns = [i for i, name in enumerate(rows[0]) if ".v" in name]
v0 = max(abs(float(rows[1][i])) for i in velocity_columns)
ctx.check("largest velocity of the t = 0 row (m/s, rad/s)", v0, 0.0, abs_tol=1e-9)
# at rest over the run: against g DT (DT = 2e-4 s), the velocity gravity
# gives in one macro step: measured 2.2e-9 m/s (1.1e-6 g DT; 8e-7 at 0.4 m);
# the accelerations against g: measured 2.5e-6 m/s^2 (2.6e-7 g; 1.8e-7 at
# 0.4 m), the fully explicit crane 9e-6 m/s^2. Before the static start was mended: 0.057
# m/s (29 g DT) and 57.7 m/s^2 (5.9 g); with only the wheels' static friction
# on the rail nodes missing 0.074 m/s^2 (7.5e-3 g)
DT = 2e-4  # s, m dt of bridge_crane_3d.prm
v = max(abs(float(row[i])) for row in rows[1:] for i in velocity_columns)
ctx.check("largest velocity over the run / (g DT)", v / (g * DT), 0.0, abs_tol=1e-5)
a = max(p["value"] for p in s["max_absolute_acceleration"].values())
ctx.check("largest monitor acceleration / g", a / g, 0.0, abs_tol=1e-5)
# measured 2.1e-9 (1.2e-9 at 0.4 m, 1.2e-8 with the former start-up
# transient): a coupling
# that did not conserve energy (G5) shows errors of order 1e-3 and more
ctx.check("energy balance relative to the largest energy", s["energy_balance_relative"], 0.0,
          abs_tol=1e-8)

# ---- 4. at rest with the Craig-Bampton reduced girders ------------------------
# (doc/theory.md 12.2; 0.55 m, tied wheels, rigid hoist, cut-off 20 Hz: the 96
# interface rows alone, the cheapest reduction, 60 s of set-up). Reference:
# the reduced static state is the full one's coordinates, at rest up to how
# well the reduced part's interface forces balance (measured 1.5e-5 g at the
# crane wheels, 1.5e-5 g at 0.4 m; before the contacts kept in the active set
# to 1 nm, 0.4 m opened a trolley wheel in the first micro step: 0.073 g and
# a 7.7 um penetration, doc/theory.md 1.1)
out, _ = ctx.run(prm, "rest_reduced", COARSE + [
    "Model/Bridge crane/Travel=tied", "Model/Bridge crane/Hoist=rigid",
    "Model/Decomposition/Implicit reduction=Craig-Bampton",
    "Model/Decomposition/Reduction cutoff frequency=20",
    "Loading/Accelerogram X=", "Loading/Accelerogram Z=", "Time integration/End time=0.004",
    "Output/Output interval=0"])
s = read_summary(out)
r = s["reduction"]
ctx.check_true("reduced: 96 boundary DoFs (16 ties of 6 rows), no mode below 20 Hz",
               r["boundary_dofs"] == 96 and r["modes"] == 0, str(r))
a = max(p["value"] for p in s["max_absolute_acceleration"].values())
ctx.check("reduced: largest monitor acceleration / g", a / g, 0.0, abs_tol=1e-4)
ctx.check("reduced: largest penetration (m)", s["max_penetration"], 0.0, abs_tol=1e-9)
ctx.check("reduced: energy balance relative to the largest energy",
          s["energy_balance_relative"], 0.0, abs_tol=1e-8)
# the frequency check of the floating girders (doc/theory.md 12.2; its
# Lanczos run at a tiny negative shift did not converge on them): it runs,
# finds the girders' rigid-body modes, and each reduced free-interface
# frequency is an upper bound of the unreduced one (Rayleigh-Ritz)
check = r.get("frequency_check", {})
ctx.check_true("reduced: the frequency check ran, no warning of it (the one of the cut-off "
               "below 3 x the damping band's 30 Hz stays)",
               len(check.get("reduced", [])) == 5 and
               not [w for w in s["warnings"] if "frequency check" in w],
               "%s %s" % (check, s["warnings"]))
if len(check.get("reduced", [])) == 5:
    ctx.check_true("reduced: rigid-body modes of the floating implicit part",
                   check["rigid_body_modes"] >= 6, str(check["rigid_body_modes"]))
    ctx.check_true("reduced: reduced frequencies >= unreduced (Rayleigh-Ritz upper bounds)",
                   all(a >= b * (1 - 1e-9) for a, b in zip(check["reduced"],
                                                          check["unreduced"])), str(check))

# ---- 5. modes against the beam crane's ---------------------------------------
# A rail of negligible stiffness (the beam crane counts its mass only; its
# area 1e-4 m^2 at the rail head adds 0.7 % to the girder's I_y) with the
# A55's foot. The end carriages are tied to the walls of the girders' end
# faces: tied to the end diaphragms' faces too, the 6 mm plate's bending
# made the joint soft, and the X sway fell from 5.69 Hz at 0.55 m to 3.81 Hz
# at 0.15 m, 37 % below the beam crane's 6.08 Hz (doc/theory.md 11.2).
# Measured (0.4 / 0.25 / 0.15 m, the note of issue #26 has 0.1 m): vertical
# -2.7 / -3.7 / -6.4 % (the top flange's bending under the rail, centred
# between the webs), the others -1.2 to -3.5 %, the trolley's yaw -6.8 /
# -7.4 / -7.8 % (its wheels' lateral forces at the rail heads twist the
# boxes and bend their top flanges), MAC >= 0.94.
MODAL = ["Analysis/Type=modal", "Analysis/Number of modes=10",
         "Model/Bridge crane/Eccentricities=true", "Model/Bridge crane/Travel=tied",
         "Model/Bridge crane/Hoist=rigid", "Model/Bridge crane/Trolley position=0.5",
         "Loading/Accelerogram X=", "Loading/Accelerogram Z="]
out_b, _ = ctx.run(prm, "modal_beam", MODAL + ["Model/Bridge crane/Girder model=beam"])
out_s, _ = ctx.run(prm, "modal_solid", MODAL + [
    "Model/Bridge crane/Girder element size=0.4",
    "Model/Bridge crane/Rail section=general, 1e-4, 1e-8, 1e-8, 1e-8, 0, 0"])


def mode_shapes(out):
    """Frequencies, effective mass ratios (x, z) and the translations at each
    distinct frame node (coincident nodes that move apart, e.g. a wheel and
    its rail node, are left out)."""
    rows = read_csv(os.path.join(out, "modes.csv"))
    files = sorted(glob.glob(os.path.join(out, "mode-*.vtu")))
    shapes = [read_points(f) for f in files]
    points = shapes[0][0]
    groups = {}
    for i, x in enumerate(np.round(points, 4)):
        groups.setdefault(tuple(x), []).append(i)
    keep = [g[0] for g in groups.values()
            if all(np.allclose(f["displacement"][g], f["displacement"][g[0]], rtol=0,
                               atol=1e-9 * abs(f["displacement"]).max()) for _, f in shapes)]
    keep = sorted(keep)
    return ([float(r["frequency"]) for r in rows],
            [(float(r["effective_mass_ratio_x"]), float(r["effective_mass_ratio_z"]))
             for r in rows],
            points[keep], [f["displacement"][keep] for _, f in shapes])


f_b, m_b, x_b, u_b = mode_shapes(out_b)
f_s, m_s, x_s, u_s = mode_shapes(out_s)
near = [(i, int(np.argmin(np.linalg.norm(x_s - x, axis=1)))) for i, x in enumerate(x_b)]
near = [(i, j) for i, j in near if np.linalg.norm(x_s[j] - x_b[i]) < 0.1]
ib, js = [i for i, _ in near], [j for _, j in near]
ctx.check_true("modal: frame nodes common to both models (>= 20)", len(near) >= 20,
               str(len(near)))


def mac(a, b):
    return (a @ b) ** 2 / ((a @ a) * (b @ b))


# the beam crane's modes 3-8 (1 and 2: free along X and within the flanges'
# play along Y) by type, from its mode shapes; the last one within 10 %
types = ["vertical, girders in phase", "horizontal (X), girders in antiphase",
         "sway along X, girders in phase", "vertical, girders in antiphase",
         "racking, girders in antiphase along Y", "trolley yaw against the girders"]
pair = {}
for k, name in enumerate(types):
    m = 2 + k
    a = u_b[m][ib].ravel()
    macs = [(mac(a, u_s[n][js].ravel()), n) for n in range(len(u_s))
            if f_s[n] > 0.5 and n not in pair.values()]
    best, n = max(macs)
    pair[m] = n
    ctx.check_true("modal: beam mode %d (%s, %.3f Hz): solid mode %d, %.3f Hz, MAC %.4f >= 0.9"
                   % (m + 1, name, f_b[m], n + 1, f_s[n], best), best >= 0.9)
    ctx.check("modal: mode %d frequency, solid / beam" % (m + 1), f_s[n] / f_b[m], 1.0,
              abs_tol=0.10 if k == 5 else 0.05)
# the solids' mode shapes (solids_modes.pvd): the first vertical mode's top
# flange under the rail against the rail node tied to it (frame VTU), the
# same mass-normalised shape (measured 1.005 at 0.4 m)
n3 = pair[2]
frame_points, frame_fields = read_points(os.path.join(out_s, "mode-%03d.vtu" % (n3 + 1)))
solid_points, solid_fields = read_points(os.path.join(out_s, "solids-mode-%03d.vtu" % (n3 + 1)))
rail = int(np.argmin(np.linalg.norm(frame_points - [-1.0, 10.0, 0.62], axis=1)))
below = frame_points[rail] - [0.0, 0.0, frame_points[rail][2] - 0.55]
flange = int(np.argmin(np.linalg.norm(solid_points - below, axis=1)))
ctx.check("modal: solids_modes.pvd, vertical mode: u_z of the top flange / of the rail node",
          solid_fields["displacement"][flange][2] / frame_fields["displacement"][rail][2], 1.0,
          abs_tol=0.02)
ctx.check_true("modal: solids_modes.pvd lists a file per mode",
               os.path.exists(os.path.join(out_s, "solids_modes.pvd")) and
               len(glob.glob(os.path.join(out_s, "solids-mode-*.vtu"))) == len(f_s))
ctx.check_true("modal: vertical mode's effective mass along Z > 0.8 (beam, solid)",
               m_b[2][1] > 0.8 and m_s[pair[2]][1] > 0.8, "%s %s" % (m_b[2], m_s[pair[2]]))
ctx.check_true("modal: X sway's effective mass along X > 0.15 (beam, solid)",
               m_b[4][0] > 0.15 and m_s[pair[4]][0] > 0.15, "%s %s" % (m_b[4], m_s[pair[4]]))
ctx.finish()
