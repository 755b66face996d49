#!/usr/bin/python3
"""Analysis/Type = response spectrum (doc/theory.md 14) against references
computed here, independently of hati:

1. A single-DoF oscillator (a point mass of 1000 kg on an axial bar whose
   only free DoF is the end's ux; the bar's own mass 1e-11 kg), at periods
   on the four branches of the EC8 type 1 spectrum (ground C) and one along
   Z on the vertical spectrum: the peak displacement S_a(T) / omega^2, the
   absolute acceleration S_a and the base force m S_a to 1e-10, S_a from
   EN 1998-1 (3.2.2.2, 3.2.2.3) written out here.
2. The missing mass: a cut-off below the oscillator's frequency keeps no
   mode and gives the static response to the zero-period acceleration,
   m a_0 / k, and the base force m a_0 (1e-8); a cut-off above every mode of
   a cantilever gives the same results with and without the missing mass
   (1e-8 of each row's largest value).
3. The cantilever of cantilever_modal.prm under a flat spectrum along Y
   (a table, S_a = 3 m/s^2): the tip displacement and the root moment
   against the sum over its analytical (Euler-Bernoulli) modes, CQC with
   Der Kiureghian's coefficient computed here; without the missing mass
   (the modes up to 33 Hz) and with it (the static rest of the uniform
   inertia load, q L^4 / (8 EI) and q L^2 / 2 less the kept modes' static
   parts): within 0.3 % (10 elements; the root moment's element-end
   forces take the first element's inertia as nodal, O(h^2 / L^2)).
4. A beam on two one-sided contacts with zero gap (gravity, held along X
   and Y): along Z each contact carries half the base force in every mode
   (the symmetric modes; the antisymmetric ones have no participation), so
   each contact's combined force is base.Fz / 2 (1e-8), two paths of hati
   (the contacts' multipliers, the participation factors); its static force
   is half the weight (1e-10); uplift is predicted when the combined change
   exceeds it (a strong spectrum) and not under a weak one.
5. The directional rules by hand from the per-direction columns of
   response_spectrum.csv: SRSS, 100-40-40, 100-30-30 (1e-12).
6. The crane (bridge_crane_hati.prm): the kept modes' effective mass plus
   the missing mass (computed from the missing-mass load itself) is the
   crane's mass per direction (1e-8), the trolley wheels' lift-off is
   flagged where min_force < 0.
7. The 3D crane (solid girders, 0.4 m plates): the same mass sum, and the
   largest cell value of stress_envelope.vtu is the girders'
   max_von_mises of response_spectrum.csv (the combined components' von
   Mises stress, at least each direction's).
8. A solid's stress against a static analysis: a box girder whose mass is
   one point mass answers a flat spectrum as the static load m S_a at the
   mass (1e-5): tip deflection and the girder's von Mises stress."""
import csv
import json
import math
import os

from hati_test import Context, read_summary

ctx = Context()

SDOF = """
subsection Analysis
  set Type = response spectrum
end
subsection Model
  set Type = frame
  subsection Frame
    set Nodes     = a: 0, 0, 0; b: 1, 0, 0
    set Materials = bar: %(E)r, 0.3, 1e-9
    set Sections  = s: general, 1e-2, 1e-6, 1e-6, 1e-6, 0, 0
    set Members   = bar: a, b, s, bar, 1
    set Supports  = a: clamped; b: %(free)s
    set Point masses = b: 1000
    set Monitor nodes = b
  end
end
subsection Loading
  set Gravity = 0, 0, 0
end
subsection Design spectrum
  set Type = EC8 type 1
  set Ground type = C
  set Peak ground acceleration = 2
end
subsection Response spectrum
  set Directions = %(direction)s
  set Cutoff frequency = %(cutoff)r
end
"""
FREE = {"X": "free, fixed, fixed, fixed, fixed, fixed",
        "Z": "fixed, fixed, free, fixed, fixed, fixed"}
MASS = 1000.0
AREA, LENGTH = 1e-2, 1.0


def ec8(T, vertical=False):
    """EN 1998-1 type 1, ground C, a_g = 2 m/s^2, 5 % damping (eta = 1)."""
    if vertical:  # Table 3.4, type 1: a_vg = 0.9 a_g, T_B, T_C, T_D = 0.05, 0.15, 1
        a, S, p, TB, TC, TD = 0.9 * 2.0, 1.0, 3.0, 0.05, 0.15, 1.0
    else:  # Table 3.2, ground C: S = 1.15, T_B = 0.2, T_C = 0.6, T_D = 2
        a, S, p, TB, TC, TD = 2.0, 1.15, 2.5, 0.2, 0.6, 2.0
    if T <= TB:
        return a * S * (1 + T / TB * (p - 1))
    if T <= TC:
        return a * S * p
    if T <= TD:
        return a * S * p * TC / T
    return a * S * p * TC * TD / T ** 2


def rows(out):
    with open(os.path.join(out, "response_spectrum.csv")) as f:
        return {r["quantity"]: r for r in csv.DictReader(f)}


def value(table, name, column="combined"):
    return float(table[name][column])


def write(name, text):
    path = os.path.join(ctx.work, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def sdof(T, direction, cutoff=33.0, tag=None):
    k = MASS * (2 * math.pi / T) ** 2
    # along X the bar's axial stiffness E A / L, along Z its bending 12 E I / L^3
    E = k * LENGTH / AREA if direction == "X" else k * LENGTH ** 3 / (12 * 1e-6)
    prm = write("sdof.prm", SDOF % {"E": E, "free": FREE[direction],
                                    "direction": direction, "cutoff": cutoff})
    out, _ = ctx.run(prm, tag or "sdof_%s_%g" % (direction, T))
    return out, k


# 1. the oscillator on the EC8 branches
for T, direction in ((0.1, "X"), (0.4, "X"), (1.2, "X"), (3.0, "X"), (0.5, "Z")):
    out, k = sdof(T, direction)
    table = rows(out)
    Sa = ec8(T, direction == "Z")
    omega2 = k / MASS
    c = direction.lower()
    ctx.check("T = %g s %s: peak displacement S_a / omega^2 (m)" % (T, direction),
              value(table, "b.u" + c, direction), Sa / omega2, rel=1e-10)
    ctx.check("T = %g s %s: absolute acceleration S_a (m/s^2)" % (T, direction),
              value(table, "b.a" + c, direction), Sa, rel=1e-10)
    ctx.check("T = %g s %s: base force m S_a (N)" % (T, direction),
              value(table, "base.F" + c, direction), MASS * Sa, rel=1e-10)
    ctx.check("T = %g s %s: the bar's axial force k u = m S_a (N)" % (T, direction),
              value(table, "bar.N", direction) if direction == "X" else MASS * Sa,
              MASS * Sa, rel=1e-9)

# 2. the missing mass: no mode below a cut-off of 5 Hz (T = 0.1 s: 10 Hz)
out, k = sdof(0.1, "X", cutoff=5.0, tag="sdof_below_cutoff")
table = rows(out)
summary = read_summary(out)["response_spectrum"]
a0 = 2.0 * 1.15
ctx.check("cut-off below the mode: modes used", summary["modes_used"], 0, abs_tol=0)
ctx.check("cut-off below the mode: missing mass ratio", summary["missing_mass_ratio"]["X"],
          1.0, rel=1e-12)
ctx.check("cut-off below the mode: static displacement m a_0 / k (m)",
          value(table, "b.ux"), MASS * a0 / k, rel=1e-8)
ctx.check("cut-off below the mode: base force m a_0 (N)", value(table, "base.Fx"),
          MASS * a0, rel=1e-8)
ctx.check("cut-off below the mode: absolute acceleration a_0 (m/s^2)",
          value(table, "b.ax"), a0, rel=1e-8)

# a cut-off above every mode of the cantilever (60 free DoFs): the missing
# mass adds nothing
cantilever = ctx.prm("cantilever_modal.prm")
flat = write("flat.csv", "period,pseudo_acceleration\n0.001,3\n100,3\n")
common = ["Analysis/Type=response spectrum", "Design spectrum/Type=table",
          "Design spectrum/Table file=" + flat, "Design spectrum/Period range=0.001, 100"]
with_mm, _ = ctx.run(cantilever, "all_modes_missing_mass",
                     common + ["Response spectrum/Cutoff frequency=1e7",
                               "Response spectrum/Directions=X, Y, Z"])
without_mm, _ = ctx.run(cantilever, "all_modes_no_missing_mass",
                        common + ["Response spectrum/Cutoff frequency=1e7",
                                  "Response spectrum/Directions=X, Y, Z",
                                  "Response spectrum/Missing mass=false"])
a, b = rows(with_mm), rows(without_mm)
worst = 0.0
# each row against its largest value; rows of round-off (the torsion of a
# beam that nothing twists, 1e-9 N m) left out: below 1e-6 of the largest
# value of their unit
largest = {}
for name, r in a.items():
    largest[r["unit"]] = max(largest.get(r["unit"], 0.0), float(r["combined"]))
for name in a:
    scale = max(abs(float(a[name][c])) for c in ("X", "Y", "Z", "combined"))
    if scale <= 1e-6 * largest[a[name]["unit"]]:
        continue
    for column in ("X", "Y", "Z", "combined"):
        x, y = float(a[name][column]), float(b[name][column])
        worst = max(worst, abs(x - y) / scale)
ctx.check("every mode kept: with and without the missing mass (largest relative "
          "difference)", worst, 0.0, abs_tol=1e-8)
ctx.check("every mode kept: modes used = the 60 free DoFs",
          read_summary(with_mm)["response_spectrum"]["modes_used"], 60, abs_tol=0)

# 3. the cantilever under the flat spectrum along Y against its analytical modes
E, rho, A, Iz, L = 2.1e11, 7850.0, 5e-3, 1.0416666666667e-6, 4.0
m = rho * A  # kg/m
betas = []
for k in range(12):
    # roots of cos(x) cosh(x) = -1 by Newton from the asymptote
    x = (k + 0.5) * math.pi if k > 0 else 1.875
    for _ in range(50):
        f = math.cos(x) * math.cosh(x) + 1
        df = -math.sin(x) * math.cosh(x) + math.cos(x) * math.sinh(x)
        x -= f / df
    betas.append(x / L)
Sa, xi = 3.0, 0.05


def cqc(values, omegas):
    s = 0.0
    for i, ri in enumerate(values):
        for j, rj in enumerate(values):
            r = omegas[j] / omegas[i]
            rho_ij = 8 * xi ** 2 * (1 + r) * r ** 1.5 / (
                (1 - r * r) ** 2 + 4 * xi ** 2 * r * (1 + r) ** 2)
            s += rho_ij * ri * rj
    return math.sqrt(s)


tip, moment, omegas = [], [], []
tip_static, moment_static = [], []
for beta in betas:
    bl = beta * L
    sigma = (math.cosh(bl) + math.cos(bl)) / (math.sinh(bl) + math.sin(bl))
    omega = beta ** 2 * math.sqrt(E * Iz / m)
    # phi = cosh - cos - sigma (sinh - sin): int phi^2 = L, int phi = 2 sigma / beta,
    # phi(L) = 2 (-1)^(k+1) (sign from the formula), phi''(0) = 2 beta^2
    phi_L = math.cosh(bl) - math.cos(bl) - sigma * (math.sinh(bl) - math.sin(bl))
    gamma = m * (2 * sigma / beta) / math.sqrt(m * L)
    q = gamma * Sa / omega ** 2
    if omega / (2 * math.pi) <= 33.0:
        omegas.append(omega)
        tip.append(q * phi_L / math.sqrt(m * L))
        moment.append(q * E * Iz * 2 * beta ** 2 / math.sqrt(m * L))
    tip_static.append(gamma / omega ** 2 * phi_L / math.sqrt(m * L))
    moment_static.append(gamma / omega ** 2 * E * Iz * 2 * beta ** 2 / math.sqrt(m * L))
kept = len(omegas)
modal_tip, modal_moment = cqc(tip, omegas), cqc(moment, omegas)
# the missing mass: the static response to the uniform load m a_0 less the
# kept modes' static parts (a_0 = S_a: a flat spectrum)
missing_tip = Sa * (m * L ** 4 / (8 * E * Iz) - sum(tip_static[:kept]))
missing_moment = Sa * (m * L ** 2 / 2 - sum(moment_static[:kept]))
for missing in (False, True):
    out, _ = ctx.run(cantilever, "cantilever_flat_%s" % missing,
                     common + ["Response spectrum/Directions=Y",
                               "Response spectrum/Missing mass=%s" % str(missing).lower()])
    table = rows(out)
    ref_tip = math.hypot(modal_tip, missing_tip) if missing else modal_tip
    ref_moment = math.hypot(modal_moment, missing_moment) if missing else modal_moment
    ctx.check("cantilever, flat S_a, missing mass %s: tip uy (m)" % missing,
              value(table, "tip.uy"), ref_tip, rel=3e-3)
    ctx.check("cantilever, flat S_a, missing mass %s: largest Mz (root, N m)" % missing,
              value(table, "beam.Mz"), ref_moment, rel=3e-3)
ctx.check("cantilever: analytical modes up to 33 Hz in Y", kept, 2, abs_tol=0)

# 4. the beam on two contacts
beam = ["Analysis/Type=response spectrum", "Design spectrum/Type=EC8 type 1",
        "Design spectrum/Peak ground acceleration=%g",
        "Model/Frame/Supports=root: fixed, fixed, free, fixed, free, free; "
        "tip: free, fixed, free, free, free, free",
        "Model/Frame/Contacts=ra: root, 0, 0, 1, 0; rb: tip, 0, 0, 1, 0",
        "Loading/Gravity=0, 0, -9.81", "Response spectrum/Directions=Z"]
weight = m * L * 9.81
for pga, uplift in ((0.5, False), (40.0, True)):
    out, _ = ctx.run(cantilever, "beam_on_contacts_%g" % pga,
                     [s % pga if "%g" in s else s for s in beam])
    table = rows(out)
    contacts = read_summary(out)["response_spectrum"]["contacts"]
    fz = value(table, "base.Fz")
    for name in ("ra", "rb"):
        ctx.check("a_g = %g: contact %s's force change = base.Fz / 2 (N)" % (pga, name),
                  value(table, name + ".force"), fz / 2, rel=1e-8)
        ctx.check("a_g = %g: contact %s's static force = half the weight (N)"
                  % (pga, name), contacts[name]["static_force"], weight / 2, rel=1e-10)
        ctx.check("a_g = %g: %s max_force - min_force = 2 x the change" % (pga, name),
                  contacts[name]["max_force"] - contacts[name]["min_force"],
                  2 * value(table, name + ".force"), rel=1e-12)
        ctx.check_true("a_g = %g: %s uplift_predicted is %s" % (pga, name, uplift),
                       contacts[name]["uplift_predicted"] == uplift,
                       "(min_force %g N)" % contacts[name]["min_force"])

# 5. the directional rules from the columns
for rule, c in (("SRSS", None), ("100-40-40", 0.4), ("100-30-30", 0.3)):
    out, _ = ctx.run(cantilever, "directions_" + rule,
                     common + ["Response spectrum/Directions=X, Y, Z",
                               "Response spectrum/Directional combination=" + rule])
    worst, bound = 0.0, True
    for name, r in rows(out).items():
        p = [float(r[d]) for d in "XYZ"]
        ref = (math.sqrt(sum(x * x for x in p)) if c is None
               else max(p[i] + c * (sum(p) - p[i]) for i in range(3)))
        if name.startswith("beam."):
            # a section force: combined station by station, so the largest
            # combined value lies between the largest column and the rule
            # applied to the columns' largest values
            bound = bound and max(p) * (1 - 1e-12) <= float(r["combined"]) <= ref * (1 + 1e-12)
        elif ref > 0:
            worst = max(worst, abs(float(r["combined"]) - ref) / ref)
    ctx.check("directional rule %s by hand (largest relative difference)" % rule,
              worst, 0.0, abs_tol=1e-12)
    ctx.check_true("directional rule %s: section forces within their bounds" % rule, bound)

# 6. the crane: effective plus missing mass = the crane's mass
crane = ctx.prm("bridge_crane_hati.prm")
out, p = ctx.run(crane, "crane",
                 ["Analysis/Type=response spectrum", "Design spectrum/Type=EC8 type 1",
                  "Design spectrum/Peak ground acceleration=2",
                  "Loading/Accelerogram X=", "Loading/Accelerogram Z="])
s = read_summary(out)
rs = s["response_spectrum"]
crane_mass = float(s["model"].split("mass ")[-1].split(" kg")[0])
for axis in "XYZ":
    # the model's description prints the mass to 6 digits
    ctx.check("crane %s: total mass = the crane's mass (kg)" % axis,
              rs["total_mass"][axis], crane_mass, rel=1e-5)
    ctx.check("crane %s: effective + missing mass ratio" % axis,
              rs["effective_mass_ratio"][axis] + rs["missing_mass_ratio"][axis], 1.0,
              rel=1e-8)
wheels = rs["contacts"]
for name, c in wheels.items():
    ctx.check_true("crane %s: uplift_predicted iff one-sided and min_force < 0" % name,
                   c["uplift_predicted"] == (not c["two_sided"] and c["min_force"] < 0),
                   "(static %.6g, min %.6g N)" % (c["static_force"], c["min_force"]))
ctx.check_true("crane: the trolley wheels are predicted to lift off (a_g = 2 m/s^2)",
               all(wheels["trolley_wheel_%d" % i]["uplift_predicted"] for i in range(1, 5)))
ctx.check_true("crane: the terminal prints the contact table",
               "uplift predicted" in p.stdout)
# 7. the 3D crane (solid girders, 0.4 m plates): the stress envelope
from vtu_files import read_vtu  # noqa: E402

out, p = ctx.run(ctx.prm("bridge_crane_3d.prm"), "crane_3d",
                 ["Analysis/Type=response spectrum", "Design spectrum/Type=EC8 type 1",
                  "Design spectrum/Peak ground acceleration=2",
                  "Loading/Accelerogram X=", "Loading/Accelerogram Z=",
                  "Model/Decomposition/Implicit reduction=none"])
table = rows(out)
rs = read_summary(out)["response_spectrum"]
for axis in "XYZ":
    ctx.check("3D crane %s: effective + missing mass ratio" % axis,
              rs["effective_mass_ratio"][axis] + rs["missing_mass_ratio"][axis], 1.0,
              rel=1e-8)
points, cells, fields = read_vtu(os.path.join(out, "stress_envelope.vtu"))
envelope = max(fields["max_von_mises"][1])
girders = max(value(table, "girder_%d.max_von_mises" % g) for g in (1, 2))
# the VTU holds Float32 values
ctx.check("3D crane: the largest cell of stress_envelope.vtu = the girders' "
          "max_von_mises (Pa)", envelope, girders, rel=1e-6)
for g in (1, 2):
    r = table["girder_%d.max_von_mises" % g]
    ctx.check_true("3D crane girder_%d: combined von Mises >= each direction's" % g,
                   float(r["combined"]) >= max(float(r[d]) for d in "XYZ"))
    ctx.check_true("3D crane girder_%d: a stress of tens of MPa (not zero, not absurd)" % g,
                   1e6 < float(r["combined"]) < 3.55e8, "(%s Pa)" % r["combined"])
# 8. a solid's stress against an independent path: the beam / box girder of
# beam_solid_cantilever.prm with every density 1e-3 kg/m^3, so that its
# mass is the 500 kg point mass at 'tip': one mode along Z carries all of
# it, and its response to a flat S_a is the static response to the force
# m S_a at the mass (a static analysis with that nodal load, its solids'
# von Mises stress from SolidStressOutput's envelope). Tolerance 1e-5: the
# structure's own mass (1.1e-7 of the total) is not in the static load.
solid = ctx.prm("beam_solid_cantilever.prm")
light = ["Model/Frame/Materials=steel: 2.1e11, 0.3, 1e-3",
         "Model/Decomposition/Explicit members="]
out, _ = ctx.run(solid, "solid_rsa",
                 light + common + ["Model/Frame/Nodal loads=",
                                   "Response spectrum/Directions=Z",
                                   "Response spectrum/Missing mass=false",
                                   "Response spectrum/Cutoff frequency=1000"])
table = rows(out)
static, _ = ctx.run(solid, "solid_static",
                    light + ["Analysis/Type=static",
                             "Model/Frame/Nodal loads=tip: 0, 0, %r" % (-500.0 * 3.0)])
s = read_summary(static)
with open(os.path.join(static, "history.csv")) as f:
    uz = abs(float(list(csv.DictReader(f))[-1]["tip.uz"]))
ctx.check("point-mass girder: tip uz = the static deflection under m S_a (m)",
          value(table, "tip.uz"), uz, rel=1e-5)
ctx.check("point-mass girder: girder max_von_mises = the static one under m S_a (Pa)",
          value(table, "girder.max_von_mises"), s["solids"]["girder"]["max_von_mises"]["value"],
          rel=1e-5)
ctx.finish()
