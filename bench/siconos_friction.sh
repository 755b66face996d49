#!/usr/bin/env bash
# A rigid block sliding on a horizontal base under an acceleration pulse
# (Coulomb friction, spec A9): hati (CD-Lagrange, the block of
# parameter_files/friction_block.prm laid flat, static start on its two
# frictional contacts) against Siconos FrictionContact3D and against the
# exact stick-slip solution, at two friction coefficients: permanent slip
# (m) and the times the block starts and stops sliding (stick times).
#
# The pulse (along X, m/s^2): 0 until 0.1 s, ramp to A = 3 m/s^2 at 0.11 s,
# A until 0.3 s, ramp to 0 at 0.31 s, 0 after; the block slides relative to
# the base while |a_g| > mu g and stops when its relative velocity vanishes.
# Exact: piecewise-linear record, so the sliding velocity is a quadratic
# and the slip a cubic in time on each piece; the start and stop times are
# roots of linear and quadratic equations (as test_cases/sliding_block_elcentro.py).
# Siconos: the numerics solver of the FrictionContact3D problem
# (fc3d_nsgs, tolerance 1e-12) inside a Moreau-Jean time stepping (theta =
# 0.5, the step of hati) of a point mass on the plane, one contact, written
# below.
#
# Siconos is not a build dependency: on Debian/Ubuntu install it with
#   apt-get install -y python3-siconos
# Without it the script says so and compares hati with the exact solution
# alone.
# Usage: bench/siconos_friction.sh [build directory]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
[ -x "$build/hati" ] || ./scripts/setup.sh hati
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if ! /usr/bin/python3 -c "import siconos.numerics" 2> /dev/null; then
  echo "siconos_friction: the Python module siconos.numerics is not installed: only the"
  echo "  exact solution is compared (install Siconos with: apt-get install -y python3-siconos)"
fi
/usr/bin/python3 - "$build/hati" "$work" << 'PY'
import json
import math
import subprocess
import sys

import numpy as np

hati, work = sys.argv[1], sys.argv[2]
g = 9.81                 # the model's gravity
dt = 2e-5                # s, hati's and Siconos' step
t_end = 1.0
pulse = [(0.0, 0.0), (0.1, 0.0), (0.11, 3.0), (0.3, 3.0), (0.31, 0.0), (t_end, 0.0)]
times = np.array([p[0] for p in pulse])
values = np.array([p[1] for p in pulse])
with open(work + "/pulse.txt", "w") as f:
    f.write("# time (s), base acceleration along X (m/s^2)\n")
    for t, a in pulse:
        f.write("%.17g %.17g\n" % (t, a))


def a_g(t):
    return np.interp(t, times, values, left=0.0, right=0.0)


def exact(mu):
    """(slip at t_end, [(start, stop), ...]) of the rigid block relative to
    the base: u'' = -a_g - mu g sign(u') while sliding, u' = 0 while
    |a_g| <= mu g."""
    f = mu * g
    u, v, s, episodes, t_start = 0.0, 0.0, 0, [], None
    for (t0, a0), (t1, a1) in zip(pulse[:-1], pulse[1:]):
        A, B, T, tau = a0, (a1 - a0) / (t1 - t0), t1 - t0, 0.0
        while tau < T:
            if s == 0:
                ag = A + B * tau
                if abs(ag) > f:
                    s, t_start = (-1 if ag > 0 else 1), t0 + tau
                    continue
                crossings = [(c * f - A) / B for c in (1, -1)] if B != 0 else []
                crossings = [c for c in crossings if tau < c < T]
                if not crossings:
                    break
                tau = min(crossings)
                s, t_start = (-1 if A + B * tau > 0 else 1), t0 + tau
                continue
            ag = A + B * tau
            c1, c2 = -ag - f * s, -B / 2.0
            roots = []
            if c2 != 0:
                disc = c1 * c1 - 4 * c2 * v
                if disc >= 0:
                    r = math.sqrt(disc)
                    roots = [(-c1 - r) / (2 * c2), (-c1 + r) / (2 * c2)]
            elif c1 != 0:
                roots = [-v / c1]
            roots = [x for x in roots if 1e-15 < x <= T - tau]
            x = min(roots) if roots else T - tau
            u += v * x + c1 * x * x / 2 + c2 * x ** 3 / 3
            v = 0.0 if roots else v + c1 * x + c2 * x * x
            tau += x
            if roots:
                episodes.append((t_start, t0 + tau))
                ag = A + B * tau
                s = 0 if abs(ag) <= f else (-1 if ag > 0 else 1)
                if s != 0:
                    t_start = t0 + tau
    return u, episodes


def episodes_of(t, v, tol):
    """(start, stop) of the intervals where |v| > tol; v[k] is the velocity
    on the step that starts at t[k] (hati's history rows: V_{n+1/2} at t_n),
    so a slide starts within the step after its start and has stopped by
    its stop."""
    moving = np.abs(v) > tol
    result, start = [], None
    for k in range(len(t)):
        if moving[k] and start is None:
            start = t[k]
        if not moving[k] and start is not None:
            result.append((start, t[k]))
            start = None
    return result


def run_hati(mu):
    out = "%s/hati_mu%g" % (work, mu)
    contacts = "ga: a, 0, 0, 1, 0, 0, mu=%g; gb: b, 0, 0, 1, 0, 0, mu=%g" % (mu, mu)
    sets = ["Model/Frame/Nodes=a: 0, 0, 0; b: 0.2, 0, 0",
            "Model/Frame/Contacts=" + contacts,
            "Analysis/Initial state=static",
            "Loading/Accelerogram X=" + work + "/pulse.txt",
            "Loading/Accelerogram units=m/s^2",
            "Time integration/Time step=%g" % dt,
            "Time integration/End time=%g" % t_end,
            "Output/History interval=%g" % dt,
            "Output/Output directory=" + out]
    cmd = [hati, "parameter_files/friction_block.prm"]
    for s in sets:
        cmd += ["--set", s]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("siconos_friction: hati failed:\n" + p.stdout + p.stderr)
    with open(out + "/history.csv") as f:
        names = f.readline().strip().split(",")
    h = np.loadtxt(out + "/history.csv", delimiter=",", skiprows=1)
    col = {n: h[:, i] for i, n in enumerate(names)}
    s = json.load(open(out + "/summary.json"))
    slip = s["contacts"]["ga"]["slip_distance"]
    return col["a.ux"][-1], slip, episodes_of(col["time"], col["a.vx"], 1e-9), s["wall_time"]


def run_siconos(mu):
    """Moreau-Jean (theta = 0.5) on a unit point mass on the plane z = 0, one
    FrictionContact3D problem per step solved by Siconos (NSGS)."""
    import siconos.numerics as sn
    m, theta, h = 1.0, 0.5, dt
    W = np.eye(3) / m
    x, v = np.zeros(3), np.zeros(3)     # relative to the base: x, y, z
    options = sn.SolverOptions(sn.SICONOS_FRICTION_3D_NSGS)
    options.dparam[sn.SICONOS_DPARAM_TOL] = 1e-12
    options.iparam[sn.SICONOS_IPARAM_MAX_ITER] = 1000
    n = int(round(t_end / h))
    t_hist, vx, slip, worst = [0.0], [0.0], 0.0, 0.0
    for k in range(n):
        t0, t1 = k * h, (k + 1) * h

        def force(t):
            return np.array([-m * a_g(t), 0.0, -m * g])

        v_free = v + h / m * (theta * force(t1) + (1 - theta) * force(t0))
        # local frame: normal z first, then the tangents x and y
        q = np.array([v_free[2], v_free[0], v_free[1]])
        problem = sn.FrictionContactProblem(3, W, q, np.array([mu]))
        r, u = np.zeros(3), np.zeros(3)
        info = sn.fc3d_nsgs(problem, r, u, options)
        worst = max(worst, options.dparam[sn.SICONOS_DPARAM_RESIDU])
        if info != 0:
            sys.exit("siconos_friction: fc3d_nsgs failed at t = %g" % t1)
        v_new = v_free + np.array([r[1], r[2], r[0]]) / m
        x = x + h * (theta * v_new + (1 - theta) * v)
        v = v_new
        slip += h * math.hypot(v[0], v[1])
        t_hist.append(t1)
        vx[-1] = v[0]   # the velocity on the step from t0, as hati writes it
        vx.append(0.0)
    return x[0], slip, episodes_of(np.array(t_hist), np.array(vx), 1e-9), worst


try:
    import siconos.numerics  # noqa: F401
    have_siconos = True
except ImportError:
    have_siconos = False

print("block on a horizontal base, pulse 3 m/s^2 along X from 0.1 to 0.31 s, dt = %g s" % dt)
for mu in (0.15, 0.25):
    u_ref, ep_ref = exact(mu)
    rows = [("exact", u_ref, abs(u_ref), ep_ref)]
    u_h, slip_h, ep_h, wall = run_hati(mu)
    rows.append(("hati CD-Lagrange", u_h, slip_h, ep_h))
    if have_siconos:
        u_s, slip_s, ep_s, residual = run_siconos(mu)
        rows.append(("Siconos fc3d NSGS", u_s, slip_s, ep_s))
    print("\nmu = %g (mu g = %.4f m/s^2)" % (mu, mu * g))
    print("  %-20s %16s %14s %10s %10s %10s" % ("", "displacement (m)", "slip (m)", "rel. err",
                                              "starts (s)", "stops (s)"))
    for name, u, slip, ep in rows:
        err = abs(u - u_ref) / abs(u_ref)
        print("  %-20s %16.8f %14.8f %10.2e %10s %10s"
              % (name, u, slip, err, ",".join("%.5f" % a for a, _ in ep),
                 ",".join("%.5f" % b for _, b in ep)))
    if have_siconos:
        print("  Siconos: largest fc3d residual %.1e" % residual)
PY
