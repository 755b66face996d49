#!/usr/bin/env bash
# Speed-up of the explicit/implicit coupling (Method = HATI) over the fully
# explicit CD-Lagrange run, on a model made for it: a floor grid of steel box
# beams (11 x 11 nodes 4 m apart, 220 members of 8 coarse elements each,
# pinned along its edges: the large, coarse implicit zone) with one member
# meshed 10 times finer (the explicit zone, which alone sets the critical
# step), under a smooth vertical base acceleration pulse
# a_g(t) = 2 sin^2(pi t / 0.04) m/s^2 for t < 0.04 s (its shortest period,
# 0.02 s, spans 25 coarse steps DT = m dt at m = 100, dt = 8e-6 s).
# Runs fully explicit and HATI with m = 1, 10, 50, 100 (lumped implicit mass
# so that both sides model the same structure) and prints the wall time of
# the time stepping, the speed-up, the largest difference of the monitored
# vertical displacements (the middle of the fine member, explicit, and a
# grid node, implicit) against the explicit run as a fraction of its peak,
# and where the time of the coupled runs goes (TimerOutput-style parts from
# summary.json: explicit micro steps, implicit steps, interface solves).
# Goal (issue #8): speed-up above 10 at m >= 50 within 1 % of the explicit run.
# Usage: bench/hati_speedup.sh [build directory]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
[ -x "$build/hati" ] || ./scripts/setup.sh hati
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

/usr/bin/python3 - "$work" <<'PY'
import sys
import numpy as np
work = sys.argv[1]
n, a = 11, 4.0                    # nodes per side, spacing (m)
coarse, fine = 8, 80              # elements per member (0.5 m and 0.05 m)
nodes, members, supports = [], [], []
name = lambda i, j: "N%d_%d" % (i, j)
for i in range(n):
    for j in range(n):
        nodes.append("%s: %g, %g, 0" % (name(i, j), i * a, j * a))
        if i in (0, n - 1) or j in (0, n - 1):
            supports.append("%s: pinned" % name(i, j))
for i in range(n):
    for j in range(n):
        if i + 1 < n:
            members.append("x%d_%d: %s, %s, beam, steel, %d" % (i, j, name(i, j), name(i + 1, j), coarse))
        if j + 1 < n:
            members.append("y%d_%d: %s, %s, beam, steel, %d" % (i, j, name(i, j), name(i, j + 1), coarse))
# the fine member: x5_5 (from the centre node along x), renamed
members = [m.replace("x5_5: N5_5, N6_5, beam, steel, %d" % coarse,
                     "fine: N5_5, N6_5, beam, steel, %d" % fine) for m in members]
t = np.linspace(0.0, 0.2, 20001)
np.savetxt(work + "/pulse.txt", np.c_[t, np.where(t < 0.04, 2 * np.sin(np.pi * t / 0.04) ** 2, 0.0)])
prm = """subsection Model
  set Type = frame
  subsection Frame
    set Nodes = %s
    set Materials = steel: 2.1e11, 0.3, 7850
    set Sections = beam: box, 0.2, 0.4, 0.008, 0.012
    set Members = %s
    set Supports = %s
    set Monitor nodes = N5_5, N3_7
  end
  subsection Decomposition
    set Explicit members = fine
  end
end
subsection Loading
  set Gravity = 0, 0, 0
  set Accelerogram Z = %s/pulse.txt
  set Accelerogram units = m/s^2
end
subsection Time integration
  set Method = HATI
  set Time step = 8e-6
  set End time = 0.06
  subsection Newmark
    set Mass = lumped
  end
end
subsection Output
  set Output interval = 0
  set History interval = 1e-4
  set Progress interval = 1000
end
""" % ("; ".join(nodes), "; ".join(members), "; ".join(supports), work)
open(work + "/grid.prm", "w").write(prm)
PY

run() { # tag, extra --set arguments
  local tag=$1
  shift
  "$build/hati" "$work/grid.prm" --set "Output/Output directory=$work/$tag" "$@" > "$work/$tag.log" 2>&1 ||
    { cat "$work/$tag.log"; exit 1; }
}
run explicit --set "Time integration/Method=CD-Lagrange"
for m in 1 10 50 100; do
  run m$m --set "Time integration/HATI/Time step ratio=$m"
done

/usr/bin/python3 - "$work" <<'PY'
import json, sys
import numpy as np
work = sys.argv[1]
read = lambda tag: np.genfromtxt("%s/%s/history.csv" % (work, tag), delimiter=",", names=True)
summary = lambda tag: json.load(open("%s/%s/summary.json" % (work, tag)))
ref, sref = read("explicit"), summary("explicit")
print("model: %s" % sref["model"])
print("explicit subdomain %d DoFs, implicit %d DoFs, interface %d DoFs; dt = %.3g s (dt_crit %.3g s)"
      % (summary("m10")["n_dofs_explicit"], summary("m10")["n_dofs_implicit"],
         summary("m10")["n_interface_dofs"], summary("m10")["micro_dt"], sref["dt_crit"]))
print("%-14s %4s %10s %9s %10s %10s | %9s %9s %9s %8s" % (
    "run", "m", "stepping s", "speed-up", "err fine %", "err grid %",
    "explicit", "implicit", "interface", "setup"))
t_ref = sref["stepping_wall_time"]
print("%-14s %4s %10.3f %9s %10s %10s | %d DoFs, %d steps, %.2f ns/DoF/step" % (
    "CD-Lagrange", "-", t_ref, "1.00", "-", "-", sref["n_dofs"], sref["n_steps"],
    sref["ns_per_dof_per_step"]))
for m in (1, 10, 50, 100):
    h, s = read("m%d" % m), summary("m%d" % m)
    errs = []
    for c in ("N5_5uz", "N3_7uz"):
        r = np.interp(h["time"], ref["time"], ref[c])
        errs.append(100 * np.max(np.abs(h[c] - r)) / np.max(np.abs(ref[c])))
    t = s["stepping_wall_time"]
    print("%-14s %4d %10.3f %9.2f %10.3f %10.3f | %9.3f %9.3f %9.3f %8.3f" % (
        "HATI", m, t, t_ref / t, errs[0], errs[1], s["wall_time_explicit"],
        s["wall_time_implicit"], s["wall_time_interface"], s["wall_time_setup"]))
print("(stepping: the time-stepping loop without output; explicit / implicit / interface:\n"
      " the micro steps with the ramp superposition, the Newmark free steps and links, the\n"
      " interface solves and works, in s; setup: factorisation, ramp response, interface matrix)")
PY
