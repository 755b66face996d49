#!/usr/bin/python3
"""3D frame element against beam theory (algorithms.md 6.4): cantilever tip
deflection (Euler-Bernoulli and with shear deformation), tip rotation,
torsion, axial; the first three bending frequencies of a cantilever
(beta_1 L = 1.8751) and of a simply supported beam (k pi) in both bending
planes within 0.5 % with 10 elements. The element has exact interpolation:
static results of end-loaded members are exact (tolerance 1e-9)."""
import numpy as np

from hati_test import Context, read_csv

ctx = Context()
E, nu, rho = 2.1e11, 0.3, 7850.0
G = E / (2 * (1 + nu))
b, h = 0.05, 0.1
A = b * h
Iy, Iz = b * h**3 / 12, h * b**3 / 12
As = 5.0 / 6.0 * A
# torsion constant of the rectangle (series approximation used by hati,
# accurate to 0.5 %; here it is the reference for the T L / (G J) check)
a_, c_ = max(b, h), min(b, h)
J = a_ * c_**3 * (1 / 3 - 0.21 * (c_ / a_) * (1 - (c_ / a_) ** 4 / 12))

static = ctx.prm("cantilever_static.prm")
L = 2.0


def tip(tag, sets):
    out, _ = ctx.run(static, tag, sets)
    return read_csv(out + "/history.csv")[0]


# Timoshenko (rectangle with shear areas 5/6 A): bending in X-Z by -P along Z
P = 1000.0
r = tip("timoshenko_z", [])
ctx.check("tip deflection w, Timoshenko (m)", r["tipuz"], -(P * L**3 / (3 * E * Iy) + P * L / (G * As)), rel=1e-9)
ctx.check("tip rotation ry (rad)", r["tipury"], P * L**2 / (2 * E * Iy), rel=1e-9)
# Euler-Bernoulli (no shear areas), bending in X-Y by +P along Y
eb = "Model/Frame/Sections=rect: general, %r, %r, %r, %r, 0, 0" % (A, Iy, Iz, J)
r = tip("eb_y", [eb, "Model/Frame/Nodal loads=tip: 0, 1000, 0"])
ctx.check("tip deflection v, Euler-Bernoulli (m)", r["tipuy"], P * L**3 / (3 * E * Iz), rel=1e-9)
ctx.check("tip rotation rz, Euler-Bernoulli (rad)", r["tipurz"], P * L**2 / (2 * E * Iz), rel=1e-9)
# tip moment about Y: rotation M L / (E Iy), deflection -M L^2 / (2 E Iy)
M = 500.0
r = tip("moment", [eb, "Model/Frame/Nodal loads=tip: 0, 0, 0, 0, 500, 0"])
ctx.check("tip rotation under a moment (rad)", r["tipury"], M * L / (E * Iy), rel=1e-9)
ctx.check("tip deflection under a moment (m)", r["tipuz"], -M * L**2 / (2 * E * Iy), rel=1e-9)
# torsion and axial
r = tip("torsion", ["Model/Frame/Nodal loads=tip: 0, 0, 0, 300, 0, 0"])
ctx.check("torsion rotation T L / (G J) (rad)", r["tipurx"], 300.0 * L / (G * J), rel=1e-9)
r = tip("axial", ["Model/Frame/Nodal loads=tip: 5e4, 0, 0"])
ctx.check("axial elongation N L / (E A) (m)", r["tipux"], 5e4 * L / (E * A), rel=1e-9)
# section forces of the cantilever: |My| = P (L - x), |Vz| = P
out, _ = ctx.run(static, "forces", [])
s = read_csv(out + "/section_forces.csv")
ctx.check("root bending moment |My| (N m)", abs(s["My"][0]), P * L, rel=1e-9)
ctx.check("shear force |Vz| (N)", np.max(np.abs(np.abs(s["Vz"]) - P)), 0.0, abs_tol=1e-6)
ctx.check("moment along the member max | |My| - P (L - x) | (N m)",
          np.max(np.abs(np.abs(s["My"]) - P * (L - s["x"]))), 0.0, abs_tol=1e-6)

# self-weight q = rho A g: consistent loads give the exact nodal deflection
# of the Euler-Bernoulli cantilever, w = -q L^4 / (8 E Iy) (a load vector
# that lost the inertia coupled to the clamped node would be 0.4 % low)
r = tip("self_weight", [eb, "Model/Frame/Nodal loads=", "Loading/Gravity=0, 0, -9.81"])
ctx.check("self-weight tip deflection -q L^4 / (8 E Iy) (m)", r["tipuz"],
          -rho * A * 9.81 * L**4 / (8 * E * Iy), rel=1e-9)

# section forces under self-weight (a span load): |Vz| = q (L - x),
# |My| = q (L - x)^2 / 2, zero at the free tip
out, _ = ctx.run(static, "self_weight_forces", ["Model/Frame/Nodal loads=", "Loading/Gravity=0, 0, -9.81"])
s = read_csv(out + "/section_forces.csv")
q = rho * A * 9.81
ctx.check("self-weight: max | |Vz| - q (L - x) | (N)", np.max(np.abs(np.abs(s["Vz"]) - q * (L - s["x"]))),
          0.0, abs_tol=1e-8 * q * L)
ctx.check("self-weight: max | |My| - q (L - x)^2 / 2 | (N m)",
          np.max(np.abs(np.abs(s["My"]) - q * (L - s["x"]) ** 2 / 2)), 0.0, abs_tol=1e-8 * q * L**2)

# explicit integration of a frame with a stiff support spring: the critical
# step includes the spring (0.999 dt_crit stays bounded)
import re
spring = ["Analysis/Type=transient", "Time integration/Method=CD-Lagrange",
          "Model/Frame/Supports=root: clamped; tip: free, free, 1e12, free, free, free",
          "Output/Output interval=0", "Output/History interval=1e-4"]
_, p = ctx.run(static, "spring_refused", spring + ["Time integration/Time step=1"],
               expect_failure=True)
m = re.search(r"dt_crit = [^=]*= ([0-9.eE+-]+) s", p.stderr)
ctx.check_true("explicit frame: time step above critical refused", m is not None, p.stderr.strip())
dt_crit = float(m.group(1))
out, _ = ctx.run(static, "spring", spring + ["Time integration/Time step=%.10g" % (0.999 * dt_crit),
                                             "Time integration/End time=%.10g" % (3000 * dt_crit)])
h = read_csv(out + "/history.csv")
# static tip deflection with the spring is ~P/k = 1e-9 m; an instability would grow without bound
ctx.check("explicit frame with a stiff spring at 0.999 dt_crit: max |w_tip| (m)",
          np.max(np.abs(h["tipuz"])), 0.0, abs_tol=1e-6)

# natural frequencies, 10 Euler-Bernoulli elements, L = 4 m
Lm = 4.0
modal = ctx.prm("cantilever_modal.prm")


def frequencies(tag, sets):
    out, _ = ctx.run(modal, tag, sets)
    return read_csv(out + "/modes.csv")["frequency"]


def check_modes(label, f_num, betas):
    for plane, I in (("Y", Iz), ("Z", Iy)):
        for k, bl in enumerate(betas):
            f_ref = bl**2 / (2 * np.pi) * np.sqrt(E * I / (rho * A * Lm**4))
            f = f_num[np.argmin(np.abs(f_num - f_ref))]
            ctx.check("%s bending in %s, mode %d (Hz)" % (label, plane, k + 1), f, f_ref, rel=0.005)


check_modes("cantilever", frequencies("cantilever", []), [1.8751040687, 4.6940911330, 7.8547574382])
check_modes("simply supported",
            frequencies("simply_supported",
                        ["Model/Frame/Supports=root: fixed, fixed, fixed, fixed, free, free; "
                         "tip: free, fixed, fixed, fixed, free, free"]),
            [np.pi, 2 * np.pi, 3 * np.pi])
ctx.finish()
