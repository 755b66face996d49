#!/usr/bin/python3
"""The bridge crane's true heights (issue #26, Model/Bridge crane/
Eccentricities, End carriage height; doc/user_guide.md 3.4 "True heights").

References, all independent of the crane's stiffness:
1. statics with a horizontal gravity component gx along X (Travel = tied,
   Hoist = rigid, Flange clearance = 0 so that the trolley and the crane
   have a static state along X): global moment equilibrium about the line
   of the runway rail heads along Y (z = z_r) gives
       w (V2 + V4 - V1 - V3) = gx sum_j m_j (z_j - z_r)
   (V_k the vertical crane wheel loads at x = -w, +w, +-; the masses are
   symmetric in X, so gz sum m_j x_j = 0; the horizontal reactions act on
   the line and the lateral ones along Y have no moment about it), the
   masses m_j at their heights z_j computed here from the sections; with
   the trolley at mid-span each wheel takes a quarter of it (symmetry in
   Y), to 1e-6 relative. The trolley alone on its rail heads, 2a apart:
   each trolley wheel changes by gx sum_t m_t (z_t - z_h) / (2 * 2a).
   With Eccentricities = false the same load leaves every vertical wheel
   load unchanged (every mass and wheel on the member axes: no lever arm).
2. vertical statics with true heights: the masses (with the posts) equal
   the hand sums to 1e-12, the crane wheel loads sum to M g and split by
   the lever rule, each trolley wheel carries a quarter of the trolley at
   mid-span, to 1e-8.
3. a braking-like step of the base acceleration along X (1 m/s^2, 0.25 s
   from the static state, CD-Lagrange and HATI, the trolley sliding in its
   flange play): with true heights a vertical crane wheel force rises by
   at least half the quasi-static overturning share of 1. (it rises by
   about five times that: the trolley strikes its flanges); with false
   every vertical crane wheel force stays at its static value to
   round-off (peak_mean_force, 1 ms window); HATI's largest rise within
   5 % of the fully explicit run's; the energy balance closes to 1e-10 of
   the largest energy.
4. settled static friction (doc/theory.md 6.2), Travel = braked, true
   heights, trolley at 0.3 of the span: held at zero slip from the
   unloaded geometry, the trolley's four braked wheels locked in +-68.6 kN
   (the top flange shortening between them as the girder bends, above
   mu N = 8.9 kN: no static state). Settled, under gravity alone no
   mechanism along a rail is loaded (small displacements: the wheels'
   normals are vertical, the free-body statics of the trolley and of the
   crane along X and Y), so every braked wheel's static friction force is
   zero (to 1e-9 of M g) and the wheel loads split by the lever rule
   (1e-8); with 1 m/s^2 of gravity along Y the four braked trolley wheels
   hold the trolley's m_t gy, a quarter each (the settled forces are the
   least-squares set on the trolley's mechanism along its rails, equal
   participations) to 1e-8, and the four braked crane wheels the whole
   crane's M gy, a quarter each; from that static state the crane under HATI
   (no record, 0.02 s) stays at rest: monitors' velocities below 1e-9 m/s
   and the energy balance closed to 1e-10; its contacts.csv has every
   contact's rows, the wheel forces those of the static state.
"""
import csv
import os

from hati_test import Context, read_csv, read_summary

ctx = Context()
static_prm = ctx.prm("bridge_crane_static.prm")
TRUE = ["Model/Bridge crane/Eccentricities=true"]
FALSE = ["Model/Bridge crane/Eccentricities=false"]

# the masses by hand (the defaults, as test_cases/bridge_crane.py) and
# their heights above the girder axes (m)
g, gx, S, rho, h_ec = 9.81, 1.0, 20.0, 7850.0, 0.5
w, a = 0.5 * 3.5, 0.5 * 2.0
A_g = 0.46 * 1.10 - 0.448 * 1.074
A_ec = 0.3 * 0.5 - 0.284 * 0.476
A_t = 0.2 * 0.3 - 0.184 * 0.28
z_h = 0.5 * 1.10 + 0.065          # trolley rail head: half the girder + the A55 rail
z_t = z_h + 0.5                   # trolley frame, trolley and hoist masses
z_r = -h_ec                       # runway rail head
m_axis = 2 * rho * A_g * S + 2 * 25.0 * S + 2 * rho * A_ec * 3.5   # girders, rails, end carriages at 0
m_cw_posts = 4 * rho * A_ec * h_ec                                 # centroid at -h_ec / 2
m_rail_posts = 4 * rho * A_t * z_h                                 # centroid at z_h / 2
m_tw_posts = 4 * rho * A_t * 0.5                                   # centroid at z_h + 0.25
m_frame = rho * A_t * (2 * 1.8 + 3 * 2.0) + 3000.0 + 20350.0       # at z_t
m_bridge = m_axis + m_cw_posts + m_rail_posts
m_trolley = m_frame + m_tw_posts
M = m_bridge + m_trolley
moment = gx * (m_axis * (0 - z_r) + m_cw_posts * (-h_ec / 2 - z_r) +
               m_rail_posts * (z_h / 2 - z_r) + m_tw_posts * (z_h + 0.25 - z_r) +
               m_frame * (z_t - z_r))
moment_trolley = gx * (m_tw_posts * 0.25 + m_frame * (z_t - z_h))


def loads(out):
    w_ = read_summary(out)["static_wheel_loads"]
    return ([w_["crane_wheel_%d" % k] for k in range(1, 5)],
            [w_["trolley_wheel_%d" % k] for k in range(1, 5)])


# 2. vertical statics with true heights
for p in (0.5, 0.3):
    out, _ = ctx.run(static_prm, "vertical_p%g" % p, TRUE + [
        "Model/Bridge crane/Trolley position=%g" % p])
    s = read_summary(out)
    ctx.check("p = %g: mass_bridge with the posts (kg)" % p, s["mass_bridge"], m_bridge,
              rel=1e-12)
    ctx.check("p = %g: mass_trolley with the posts (kg)" % p, s["mass_trolley"], m_trolley,
              rel=1e-12)
    crane, trolley = loads(out)
    ctx.check("p = %g: sum of crane wheel loads (N) = M g" % p, sum(crane), M * g, rel=1e-8)
    # lever rule: the rail posts stand at the trolley's wheels, centred on it
    R_S = g * (m_axis / 2 + m_cw_posts / 2 + p * (m_trolley + m_rail_posts))
    ctx.check("p = %g: rail at Y = S (wheels 3, 4) (N), lever rule" % p,
              crane[2] + crane[3], R_S, rel=1e-8)
    ctx.check("p = %g: sum of trolley wheel loads (N)" % p, sum(trolley), m_trolley * g,
              rel=1e-8)
    if p == 0.5:
        for k in range(4):
            ctx.check("p = 0.5: trolley wheel %d (N) = m_trolley g / 4" % (k + 1),
                      trolley[k], m_trolley * g / 4, rel=1e-8)

# 1. horizontal gravity component: the overturning moment over the wheelbase
HORIZONTAL = ["Model/Bridge crane/Flange clearance=0", "Loading/Gravity=%g, 0, -9.81" % gx]
for p in (0.5, 0.3):
    pos = ["Model/Bridge crane/Trolley position=%g" % p, "Model/Bridge crane/Flange clearance=0"]
    ref = {}
    for tag, heights in (("true", TRUE), ("false", FALSE)):
        out0, _ = ctx.run(static_prm, "vert_%s_p%g" % (tag, p), heights + pos)
        out1, _ = ctx.run(static_prm, "gx_%s_p%g" % (tag, p), heights + pos + HORIZONTAL)
        (c0, t0), (c1, t1) = loads(out0), loads(out1)
        dc = [c1[k] - c0[k] for k in range(4)]
        dt = [t1[k] - t0[k] for k in range(4)]
        if tag == "true":
            ctx.check("true, p = %g: w (dV2 + dV4 - dV1 - dV3) (N m) = gx sum m (z - z_r)" % p,
                      w * (dc[1] + dc[3] - dc[0] - dc[2]), moment, rel=1e-6)
            ctx.check("true, p = %g: rail at Y = S unchanged (no moment about X) (N)" % p,
                      dc[2] + dc[3], 0.0, abs_tol=1e-8 * M * g)
            if p == 0.5:
                for k in range(4):
                    sign = 1 if k % 2 == 1 else -1
                    ctx.check("true, p = 0.5: crane wheel %d change (N)" % (k + 1), dc[k],
                              sign * moment / (4 * w), rel=1e-6)
                for k in range(4):
                    sign = 1 if k >= 2 else -1   # trolley wheels 3, 4 on girder_2 at x = +a
                    ctx.check("true, p = 0.5: trolley wheel %d change (N)" % (k + 1), dt[k],
                              sign * moment_trolley / (2 * 2 * a), rel=1e-6)
        else:
            for k in range(4):
                ctx.check("false, p = %g: crane wheel %d change (N), no lever arm" % (p, k + 1),
                          dc[k], 0.0, abs_tol=1e-9 * M * g)
                ctx.check("false, p = %g: trolley wheel %d change (N)" % (p, k + 1), dt[k], 0.0,
                          abs_tol=1e-9 * M * g)


# 3. dynamics: a step of base acceleration along X from the static state
def vertical_rise(out):
    """Largest rise of a vertical crane wheel force above its static load
    (N): peak_mean_force (1 ms window) of summary.json's wheels."""
    s = read_summary(out)
    return max(s["wheels"]["crane_wheel_%d" % k]["peak_mean_force"] -
               s["static_wheel_loads"]["crane_wheel_%d" % k] for k in range(1, 5))


# the axis-model check needs the tied, rigid-hoist crane (the files' crane
# is braked, its load on the rope)
STEP = ["Model/Bridge crane/Travel=tied", "Model/Bridge crane/Hoist=rigid",
        "Loading/Accelerogram X=", "Loading/Accelerogram Z=",
        "Loading/Base acceleration=%g, 0, 0" % gx, "Time integration/End time=0.25",
        "Output/Output interval=0"]
quasi_static = moment / (4 * w)   # a wheel's share at p = 0.5 (the files' 0.3: about the same)
rise = {}
for method, prm in (("CD-Lagrange", "bridge_crane_full_explicit.prm"),
                    ("HATI", "bridge_crane_hati.prm")):
    for tag, heights in (("true", TRUE), ("false", FALSE)):
        out, _ = ctx.run(ctx.prm(prm), "step_%s_%s" % (method, tag), heights + STEP)
        s = read_summary(out)
        ctx.check("%s, %s: energy balance / largest energy" % (method, tag),
                  s["energy_balance_relative"], 0.0, abs_tol=1e-10)
        rise[method, tag] = vertical_rise(out)
        if tag == "true":
            ctx.check_true("%s, true: a crane wheel force rises by %.1f N >= 0.5 x %.1f N "
                           "(half the quasi-static overturning share)"
                           % (method, rise[method, tag], quasi_static),
                           rise[method, tag] >= 0.5 * quasi_static)
        else:
            ctx.check("%s, false: crane wheel force rise (N), uncoupled" % method,
                      rise[method, tag], 0.0, abs_tol=1e-9 * M * g)
# HATI against the fully explicit run (reference) on the coupled response
ctx.check("HATI, true: largest crane wheel force rise (N) against CD-Lagrange's",
          rise["HATI", "true"], rise["CD-Lagrange", "true"], rel=0.05)


# 4. settled static friction: the braked crane with true heights
BRAKED = TRUE + ["Model/Bridge crane/Travel=braked", "Model/Bridge crane/Trolley position=0.3"]
out, _ = ctx.run(static_prm, "braked_settled", BRAKED)
s = read_summary(out)
crane, trolley = loads(out)
for name, f in sorted(s["static_friction_forces"].items()):
    ctx.check("braked, gravity: static friction force of %s (N)" % name, f, 0.0,
              abs_tol=1e-9 * M * g)
R_S = g * (m_axis / 2 + m_cw_posts / 2 + 0.3 * (m_trolley + m_rail_posts))
ctx.check("braked: rail at Y = S (wheels 3, 4) (N), lever rule", crane[2] + crane[3], R_S,
          rel=1e-8)
ctx.check("braked: sum of trolley wheel loads (N)", sum(trolley), m_trolley * g, rel=1e-8)
gy = 1.0
out, _ = ctx.run(static_prm, "braked_gy", BRAKED + ["Loading/Gravity=0, %g, -9.81" % gy])
friction = read_summary(out)["static_friction_forces"]
for k in range(1, 5):
    ctx.check("braked, gy = 1: trolley wheel %d static friction (N) = m_t gy / 4" % k,
              friction["trolley_wheel_%d" % k], m_trolley * gy / 4, rel=1e-8)
    # the braked crane wheels hold the whole crane along Y (with the default
    # flange play the flange pairs are released)
    ctx.check("braked, gy = 1: crane wheel %d static friction (N) = M gy / 4" % k,
              friction["crane_wheel_%d" % k], M * gy / 4, rel=1e-8)
out, _ = ctx.run(ctx.prm("bridge_crane_hati.prm"), "braked_rest",
                 BRAKED + ["Model/Bridge crane/Hoist=rigid",
                           "Loading/Accelerogram X=", "Loading/Accelerogram Z=",
                           "Time integration/End time=0.02", "Output/Output interval=0"])
s = read_summary(out)
ctx.check("braked at rest, HATI: energy balance / largest energy",
          s["energy_balance_relative"], 0.0, abs_tol=1e-10)
history = read_csv(out + "/history.csv")
# (numpy drops the dots of the columns' names: tw1.vx is tw1vx)
speed = max(float(abs(history[name]).max()) for name in history.dtype.names
            if name.endswith(("vx", "vy", "vz")))
ctx.check("braked at rest, HATI: largest monitor velocity (m/s)", speed, 0.0, abs_tol=1e-9)
# contacts.csv of HATI with true heights (its explicit subdomain holds the
# contacts but only its own rigid-link rows; the file was left empty): a row
# per contact at every row time, the vertical wheels' forces equal to the
# static contact forces (reference: the static state; at rest to the
# static solve's round-off: measured 1.2e-12)
with open(os.path.join(out, "contacts.csv"), newline="") as f:
    rows = list(csv.DictReader(f))
names = set(s["static_contact_forces"])
times = sorted(set(float(r["time"]) for r in rows))
ctx.check_true("braked at rest, HATI: contacts.csv has every contact at each of its %d row "
               "times" % len(times),
               len(times) >= 30 and all(sum(r["contact"] == n for r in rows) == len(times)
                                       for n in names), "%d rows" % len(rows))
worst = max([abs(float(r["force"]) / s["static_contact_forces"][r["contact"]] - 1.)
             for r in rows if r["contact"] in names] or [1.])
ctx.check("braked at rest, HATI: contacts.csv force / static contact force - 1", worst, 0.,
          abs_tol=1e-9)

ctx.finish()
