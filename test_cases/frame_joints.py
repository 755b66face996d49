#!/usr/bin/python3
"""Frames with joints where three and four members meet (deal.II 9.4 cannot
share such vertices; hati ties separate member ends with constraints), run
with the executable given (test_cases/debug/frame_joints_debug.cc checks
the same frames against the Debug deal.II library). References: hand solutions of the plane cross and
the T-joint (parameter_files/frame_joints.prm)."""
import numpy as np

from hati_test import Context, read_csv

ctx = Context()
E, nu = 2.1e11, 0.3
G = E / (2 * (1 + nu))
Iy, J, L, P = 4.1666666666667e-6, 2.86e-6, 2.0, 1000.0
prm = ctx.prm("frame_joints.prm")

# four-member joint: C does not rotate, four fixed-guided members
out, _ = ctx.run(prm, "cross", [])
r = read_csv(out + "/history.csv")[0]
ctx.check("cross: w_C = -P L^3 / (48 E Iy) (m)", r["Cuz"], -P * L**3 / (48 * E * Iy), rel=1e-9)
ctx.check("cross: no rotation at C (rad)", abs(r["Curx"]) + abs(r["Cury"]), 0.0, abs_tol=1e-15)

# T-joint: 'east' along X bends with (w, ry); 'north' and 'south' along Y bend
# symmetrically (rx_C = 0) and twist with ry_C. Stiffness of (w, ry) at C:
#   [[3 * 12 E I / L^3, 6 E I / L^2], [6 E I / L^2, 4 E I / L + 2 G J / L]]
out, _ = ctx.run(prm, "tee", [
    "Model/Frame/Members=east: C, E, s, steel, 3; north: C, N, s, steel, 3; south: C, S, s, steel, 3",
    "Model/Frame/Supports=E: clamped; N: clamped; S: clamped"])
r = read_csv(out + "/history.csv")[0]
EI = E * Iy
K = np.array([[36 * EI / L**3, 6 * EI / L**2], [6 * EI / L**2, 4 * EI / L + 2 * G * J / L]])
w, th = np.linalg.solve(K, [P, 0.0])
ctx.check("T-joint: |w_C| (m)", abs(r["Cuz"]), abs(w), rel=1e-9)
ctx.check("T-joint: |ry_C| (rad)", abs(r["Cury"]), abs(th), rel=1e-9)
ctx.check("T-joint: rx_C (rad)", r["Curx"], 0.0, abs_tol=1e-15)
ctx.finish()
