#!/usr/bin/python3
"""Modes of the bridge crane with its zero-gap contacts closed (issue #6;
doc/theory.md 7.3, 7.4).

1. The generated crane (Model/Type = bridge crane, defaults, Analysis/Type =
   modal) equals the same crane written by hand as a frame
   (parameter_files/bridge_crane_by_hand.prm, the generator's mesh for
   Element length 2.5, Explicit element length 1, Explicit zone length 0):
   the same 12 frequencies to 1e-9 relative (identical discrete models up
   to round-off) and the same two 0 Hz modes (the crane along Y and the
   trolley along X are free within their flange play).
2. Mesh convergence of the generated crane at Element length 1, 0.5, 0.25
   (Explicit element length a quarter of it): for each of the first 6
   elastic modes the change from h = 0.5 to 0.25 is smaller than the change
   from 1 to 0.5, by a factor 4 +- 1 (second order), and below 2e-4
   relative (measured: at most 4.5e-5); each mode keeps its dominant
   direction.
3. Independent estimate of the first vertical mode: a two-mass model by
   hand (girders as simply supported Timoshenko beams carrying the trolley
   at mid-span, the hoist on the flexible trolley frame; the girders' mass
   by Rayleigh's 17/35 rule). It ignores the end carriages' flexibility
   (about 0.5 % on f), the wheels standing 0.9 m off mid-span (about 1.5 %
   on f) and the rotary inertia: 3 % tolerance (measured: 0.1 %).
4. The default damping of a transient run (Model/Bridge crane/Damping
   ratio = 0.02): summary.json holds damping_frequencies = the first
   vertical and the first horizontal elastic mode of the modal run (1e-9
   relative; the modes with the largest effective mass along Z, resp. X or
   Y), rayleigh_a0 and rayleigh_a1 = the formulas of theory.md 4.4 (1e-12);
   an explicit Time integration/Damping wins (no damping keys), Damping
   ratio = 0 gives none."""
import math

import numpy as np

from hati_test import Context, read_csv, read_summary

ctx = Context()
crane_prm = ctx.prm("bridge_crane_static.prm")
MODAL = ["Analysis/Type=modal", "Model/Bridge crane/Trolley position=0.5"]


def modes(prm, tag, sets):
    out, p = ctx.run(prm, tag, sets)
    return read_csv(out + "/modes.csv"), read_summary(out)


def elastic(m, f_min=1e-3):
    """Rows of the elastic modes (f > f_min Hz)."""
    return m[m["frequency"] > f_min]


def direction(row):
    """x, y or z: the largest effective mass, if at least 1e-3 of the free
    mass in that direction (as hati's default damping picks modes); '-' for
    a mode without net participation (antisymmetric, torsional)."""
    e = [row["effective_mass_x"], row["effective_mass_y"], row["effective_mass_z"]]
    d = int(np.argmax(e))
    return "xyz"[d] if row["effective_mass_ratio_" + "xyz"[d]] >= 1e-3 else "-"


# ---- 1. generated vs by hand ------------------------------------------------
mesh = ["Model/Bridge crane/Element length=2.5", "Model/Bridge crane/Explicit element length=1",
        "Model/Bridge crane/Explicit zone length=0"]
gen, s_gen = modes(crane_prm, "generated_coarse", MODAL + mesh + ["Analysis/Number of modes=12"])
hand, s_hand = modes(ctx.prm("bridge_crane_by_hand.prm"), "by_hand", [])
# n_dofs differs (the frame gives every member end its own DoFs, tied at the
# joints: 32 members by hand, 12 generated); nodes, elements and mass agree
ctx.check_true("by hand: the same nodes, elements and mass",
               s_gen["model"].split("; ")[-1].replace("12 members", "32 members")
               == s_hand["model"], "(%s | %s)" % (s_gen["model"], s_hand["model"]))
ctx.check("by hand: closed contact rows", s_hand["n_closed_contact_rows"],
          s_gen["n_closed_contact_rows"], abs_tol=0)
for k in range(12):
    f_g, f_h = gen["frequency"][k], hand["frequency"][k]
    if k < 2:
        ctx.check("mode %d: rigid (Hz), generated" % (k + 1), f_g, 0.0, abs_tol=1e-3)
        ctx.check("mode %d: rigid (Hz), by hand" % (k + 1), f_h, 0.0, abs_tol=1e-3)
    else:
        ctx.check("mode %d (Hz): generated vs by hand" % (k + 1), f_g, f_h, rel=1e-9)
        for d in "xyz":
            key = "effective_mass_" + d
            ctx.check("mode %d: effective mass %s (kg)" % (k + 1, d), gen[key][k], hand[key][k],
                      rel=1e-6, abs_tol=1e-2)
ctx.check_true("the two 0 Hz modes: the crane along Y and the trolley along X",
               sorted(direction(gen[k]) for k in range(2)) == ["x", "y"])

# ---- 2. mesh convergence ------------------------------------------------------
runs = []
for h in (1.0, 0.5, 0.25):
    m, s = modes(crane_prm, "h%g" % h,
                 MODAL + ["Model/Bridge crane/Element length=%g" % h,
                          "Model/Bridge crane/Explicit element length=%g" % (h / 4),
                          "Analysis/Number of modes=10"])
    e = elastic(m)
    print("h = %g m (%d DoFs): elastic modes %s Hz, directions %s"
          % (h, s["n_dofs"], ", ".join("%.6f" % f for f in e["frequency"][:6]),
             "".join(direction(r) for r in e[:6])))
    runs.append(e)
for k in range(6):
    f1, f2, f3 = (r["frequency"][k] for r in runs)
    d12, d23 = abs(f2 - f1), abs(f3 - f2)
    ctx.check_true("mode %d: change shrinks under refinement" % (k + 1), d23 < d12,
                   "(|f(0.5) - f(1)| = %.3g Hz, |f(0.25) - f(0.5)| = %.3g Hz)" % (d12, d23))
    # second order: the change drops about 4 times per halving (h^2, the
    # rail mass lumped on the girder nodes); the remaining error is then
    # about d23 / 3
    ctx.check("mode %d: |f(1) - f(0.5)| / |f(0.5) - f(0.25)|" % (k + 1), d12 / d23, 4.0,
              abs_tol=1.0)
    ctx.check("mode %d: f(0.25) vs f(0.5) (Hz)" % (k + 1), f3, f2, rel=2e-4)
    ctx.check_true("mode %d: same dominant direction on the three meshes" % (k + 1),
                   len({direction(r[k]) for r in runs}) == 1)

# ---- 3. first vertical mode by hand -------------------------------------------
E, G, rho, g = 2.1e11, 2.1e11 / 2.6, 7850.0, 9.81
S = 20.0
A_g = 0.46 * 1.10 - 0.448 * 1.074
I_g = (0.46 * 1.10 ** 3 - 0.448 * 1.074 ** 3) / 12          # about the horizontal axis
As_g = 2 * 0.006 * (1.10 - 0.013)                            # webs (box shear area)
k_girders = 2 / (S ** 3 / (48 * E * I_g) + S / (4 * G * As_g))
A_t = 0.2 * 0.3 - 0.184 * 0.28
I_t = (0.2 * 0.3 ** 3 - 0.184 * 0.28 ** 3) / 12
# hoist at the middle of the 2 m cross beam (ends on the trolley sides at the
# middle of their 1.8 m span between the wheels): two springs in series
flex_t = 2.0 ** 3 / (48 * E * I_t) + 0.5 * 1.8 ** 3 / (48 * E * I_t)
k_trolley = 1 / flex_t
m_girders = 17 / 35 * (2 * rho * A_g * S + 2 * 25.0 * S)
m_frame = rho * A_t * (2 * 1.8 + 3 * 2.0) + 3000.0
m_hoist = 20350.0
Kh = np.array([[k_girders + k_trolley, -k_trolley], [-k_trolley, k_trolley]])
Mh = np.diag([m_girders + m_frame, m_hoist])
w2 = np.sort(np.linalg.eigvals(np.linalg.solve(Mh, Kh)).real)
f_hand = math.sqrt(w2[0]) / (2 * math.pi)
fine = runs[-1]
first_z = next(r for r in fine if direction(r) == "z")
ctx.check("first vertical mode (Hz) vs two-mass model by hand", first_z["frequency"], f_hand,
          rel=0.03)

# ---- 4. default Rayleigh damping (Damping type = Rayleigh) ---------------------
# dt below the damped dt_crit (1.5e-6 s; 4.4e-5 s undamped: the a1 K part
# costs the explicit step a factor 30, doc/theory.md 1.6)
TRANSIENT = ["Analysis/Type=transient", "Model/Bridge crane/Trolley position=0.5",
             "Model/Bridge crane/Damping type=Rayleigh",
             "Time integration/End time=1e-5", "Time integration/Time step=5e-7",
             "Output/Output interval=0"]
out, p = ctx.run(crane_prm, "damped", TRANSIENT)
s = read_summary(out)
default, _ = modes(crane_prm, "default_mesh", MODAL + ["Analysis/Number of modes=20"])
e = elastic(default)
f_v = next(r["frequency"] for r in e if direction(r) == "z")
f_h = next(r["frequency"] for r in e if direction(r) in "xy")
ctx.check("damping_frequencies[0] = first vertical mode (Hz)", s["damping_frequencies"][0], f_v,
          rel=1e-9)
ctx.check("damping_frequencies[1] = first horizontal mode (Hz)", s["damping_frequencies"][1],
          f_h, rel=1e-9)
w1, w2 = 2 * math.pi * f_v, 2 * math.pi * f_h
ctx.check("rayleigh_a0 (1/s) = 2 zeta w1 w2 / (w1 + w2)", s["rayleigh_a0"],
          2 * 0.02 * w1 * w2 / (w1 + w2), rel=1e-8)
ctx.check("rayleigh_a1 (s) = 2 zeta / (w1 + w2)", s["rayleigh_a1"], 2 * 0.02 / (w1 + w2),
          rel=1e-8)
ctx.check_true("the terminal prints the default damping", "default Rayleigh damping" in p.stdout)
for tag, extra in (("user_damping", ["Time integration/Damping/Mass coefficient=0.1"]),
                   ("zero_ratio", ["Model/Bridge crane/Damping ratio=0"])):
    out, p = ctx.run(crane_prm, tag, TRANSIENT + extra)
    s = read_summary(out)
    ctx.check_true("%s: no default damping" % tag,
                   "rayleigh_a0" not in s and "default Rayleigh damping" not in p.stdout)
ctx.finish()
