#!/usr/bin/python3
"""Restart from a state file (Output/State interval, Analysis/Initial state
= file; doc/theory.md 1.1 "Restart"). Reference: the same run unbroken.

The crane of bridge_crane_full_explicit.prm / bridge_crane_hati.prm under
Rinaldi, undamped (frequency-range damping's memory is not part of the
state), run to 0.5 s writing state.bin, then restarted from it to 1 s,
against the run from 0 to 1 s:
- CD-Lagrange, tied crane (contacts, rigid links): the restart goes on as
  the unbroken run to round-off (its V_{1/2} is the unbroken one's:
  measured 1.1e-11 of the largest velocity, 4.9e-14 of the displacements);
- CD-Lagrange, braked crane with its rope (friction, R1): to the friction
  solver's tolerance (measured 1.2e-10 of the velocities);
- CD-Lagrange, tied crane with Rayleigh damping (A7, dt = 1.6e-6 s, 0.1
  s, restart, 0.2 s): the state's R holds the damping force the restart's
  first half step takes from V_n, so the restart goes on to round-off
  (measured 1.6e-15 of the displacements, 1.7e-12 of the velocities;
  1.3e-12 and 5.2e-10 when R held the last step's damping force);
- HATI, tied crane: the restarted coupling goes on from the state's
  multiplier and its implicit part from its own values of the interface
  DoFs (RunState::implicit_interface): measured 4.1e-14 of the
  displacements, 1.5e-11 of the velocities (6.9e-7 and 2.3e-4 while the
  implicit part took the explicit side's values);
- HATI's state restarted with CD-Lagrange: the energies at the restart
  equal HATI's to the interface DoFs' difference (the slave DoFs of the
  rigid links, which HATI's whole system eliminates, filled from their
  masters), the balance closed;
- the times of the restarted rows continue the record (t from 0.5 s), and
  a state of another model, past End time or truncated is refused with
  the parameter and the file named;
- issue #59 (the 1D bar, 1 ms with a state at 0.5 ms): a state of another
  Young's modulus is refused naming the entry and both moduli; a restart
  into the state's own output folder is refused before it touches it (the
  state stays byte for byte); a temporary `.state.bin.tmp` left by a
  killed run is removed at the next run's start.
(Every flipped byte, FIFOs, /dev/zero and directories: unit.state_file.)"""
import csv
import os
import subprocess

import numpy as np

from hati_test import Context, read_summary

ctx = Context()
RECORDS = os.path.join(ctx.source, "data", "accelerograms")
UNDAMPED = ["Loading/Accelerogram X=" + os.path.join(RECORDS, "Rinaldi228.AT2"),
            "Loading/Accelerogram Z=" + os.path.join(RECORDS, "RinaldiUP.AT2"),
            "Model/Bridge crane/Damping ratio=0", "Output/Output interval=0",
            "Output/History interval=2e-4", "Output/Section force interval=0"]
TIED = ["Model/Bridge crane/Travel=tied", "Model/Bridge crane/Hoist=rigid"]


def history(out):
    with open(os.path.join(out, "history.csv"), newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], np.array([[float(x) for x in r] for r in rows[1:] if len(r) == len(rows[0])])


def energies(out):
    with open(os.path.join(out, "energy.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: float(v) for k, v in rows[0].items()}


def restart(tag, prm, sets, middle=0.5):
    """The run to `middle` (s) with its state, the restart to 2 middle, the
    run to 2 middle."""
    first, _ = ctx.run(prm, tag + "_first", sets + ["Time integration/End time=%g" % middle,
                                                    "Output/State interval=%g" % (middle / 2)])
    state = os.path.join(first, "state.bin")
    rest, _ = ctx.run(prm, tag + "_restart", sets + [
        "Time integration/End time=%g" % (2 * middle), "Analysis/Initial state=file",
        "Analysis/Initial state file=" + state])
    whole, _ = ctx.run(prm, tag + "_whole", sets + ["Time integration/End time=%g" % (2 * middle)])
    return state, rest, whole


def compare(tag, rest, whole, displacement_tol, velocity_tol, middle=0.5):
    names, B = history(rest)
    names_w, A = history(whole)
    ctx.check_true(tag + ": the same history columns", names == names_w)
    ctx.check(tag + ": first row of the restart at t (s)", B[0, 0], middle, abs_tol=1e-12)
    rows = [int(np.argmin(abs(A[:, 0] - t))) for t in B[:, 0]]
    ctx.check(tag + ": largest time offset of the compared rows (s)",
              max(abs(A[j, 0] - B[i, 0]) for i, j in enumerate(rows)), 0.0, abs_tol=1e-12)
    A = A[rows]
    for kind, tol in (("u", displacement_tol), ("v", velocity_tol)):
        cols = [j for j, n in enumerate(names) if n.rsplit(".", 1)[-1].startswith(kind)]
        peak = np.max(abs(A[:, cols]))
        diff = np.max(abs(A[:, cols] - B[:, cols]))
        ctx.check("%s: max |%s_restart - %s_whole| / largest" % (tag, kind, kind), diff / peak,
                  0.0, abs_tol=tol)
    s = read_summary(rest)
    ctx.check(tag + ": restart energy balance relative", s["energy_balance_relative"], 0.0,
              abs_tol=1e-9)
    ctx.check(tag + ": summary start_time (s)", s["start_time"], middle, abs_tol=1e-12)


explicit = ctx.prm("bridge_crane_full_explicit.prm")
hati = ctx.prm("bridge_crane_hati.prm")
_, rest, whole = restart("explicit_tied", explicit, UNDAMPED + TIED)
compare("explicit_tied", rest, whole, 1e-10, 1e-9)
_, rest, whole = restart("explicit_braked", explicit, UNDAMPED)
compare("explicit_braked", rest, whole, 1e-8, 1e-7)
RAYLEIGH = [s for s in UNDAMPED if not s.startswith("Model/Bridge crane/Damping ratio")] + [
    "Model/Bridge crane/Damping type=Rayleigh", "Time integration/Time step=1.6e-6"]
_, rest, whole = restart("explicit_rayleigh", explicit, RAYLEIGH + TIED, middle=0.1)
compare("explicit_rayleigh", rest, whole, 1e-13, 2e-11, middle=0.1)
# (HATI at dt = 4e-5 s, m = 5: a macro step that the tests' history
# interval, 2e-4 s, holds a whole number of times; the file's steps are
# 8e-5 s, m = 1)
HATI_STEPS = ["Time integration/Time step=4e-5", "Time integration/HATI/Time step ratio=5"]
hati_state, rest, whole = restart("hati_tied", hati, UNDAMPED + TIED + HATI_STEPS)
compare("hati_tied", rest, whole, 1e-11, 1e-9)

# HATI's state restarted fully explicit: the same energies at the restart
cross, _ = ctx.run(hati, "hati_to_explicit", UNDAMPED + TIED + [
    "Time integration/Method=CD-Lagrange", "Time integration/Time step=2e-5",
    "Time integration/End time=0.6", "Analysis/Initial state=file",
    "Analysis/Initial state file=" + hati_state])
# (a single-domain run holds one value per DoF: the interface DoFs take the
# explicit side's displacements, where HATI's restart gives its implicit
# part its own (G3' makes the velocities continuous, not the
# displacements): measured 5.3e-7 of the internal energy)
ctx.check("HATI state -> CD-Lagrange: internal energy at 0.5 s (J)",
          energies(cross)["internal"], energies(rest)["internal"], rel=2e-6)
ctx.check("HATI state -> CD-Lagrange: energy balance relative",
          read_summary(cross)["energy_balance_relative"], 0.0, abs_tol=1e-9)

# refusals, each naming the parameter and the file
truncated = os.path.join(ctx.work, "truncated.bin")
with open(hati_state, "rb") as f:
    data = f.read()
with open(truncated, "wb") as f:
    f.write(data[:-8])
for what, prm, sets, expected in (
        ("another model", ctx.prm("portal_frame_dynamic.prm"), [], "DoFs"),
        ("past End time", hati, ["Time integration/End time=0.4"], "not before"),
        ("truncated", hati, [], "truncated")):
    state = truncated if what == "truncated" else hati_state
    steps = HATI_STEPS if prm == hati else []
    _, p = ctx.run(prm, "refused", sets + UNDAMPED + TIED + steps + ["Analysis/Initial state=file",
                                          "Analysis/Initial state file=" + state],
                   expect_failure=True)
    ctx.check_true("refused, %s: one line naming the file" % what,
                   p.returncode != 0 and expected in p.stderr and state in p.stderr
                   and "Analysis/Initial state file" in p.stderr, p.stderr.strip())

# issue #59: the bar's state, refused for another E and in its own folder
bar = ctx.prm("bar_impact_1d.prm")
BAR = ["Output/Output interval=0", "Output/History interval=1e-5"]
bar_first, _ = ctx.run(bar, "bar_first", BAR + ["Time integration/End time=5e-4",
                                               "Output/State interval=2.5e-4"])
bar_state = os.path.join(bar_first, "state.bin")
with open(bar_state, "rb") as f:
    bar_bytes = f.read()
RESTART = BAR + ["Analysis/Initial state=file", "Analysis/Initial state file=" + bar_state]
_, p = ctx.run(bar, "bar_other_E", RESTART + ["Model/Bar/Young's modulus=2.1e11"],
               expect_failure=True)
ctx.check_true("another Young's modulus refused naming it and both values",
               p.returncode != 0 and "another model: Model/Bar/Young's modulus: '2e11' in "
               "the state, '2.1e11' in this run" in p.stderr and bar_state in p.stderr,
               p.stderr.strip())
own = subprocess.run([ctx.hati, bar, "--set", "Output/Output directory=" + bar_first] +
                     [a for x in RESTART for a in ("--set", x)],
                     capture_output=True, text=True, timeout=300)
with open(bar_state, "rb") as f:
    kept = f.read() == bar_bytes
ctx.check_true("a restart into the state's own folder refused, the state kept",
               own.returncode != 0 and "inside this run's output folder" in own.stderr and
               kept and os.path.exists(os.path.join(bar_first, "history.csv")),
               own.stderr.strip())
_, p = ctx.run(bar, "bar_restart", RESTART + ["Time integration/End time=1e-3"])
ctx.check_true("the same state restarts elsewhere", p.returncode == 0, p.stderr[-300:])
# a killed run's temporary, beside its whole state: gone at the next start
stale = os.path.join(bar_first, ".state.bin.tmp")
with open(stale, "wb") as f:
    f.write(bar_bytes[:100])
subprocess.run([ctx.hati, bar, "--set", "Output/Output directory=" + bar_first] +
               [a for x in BAR + ["Time integration/End time=1e-4"] for a in ("--set", x)],
               capture_output=True, text=True, timeout=300)
ctx.check_true("a stale .state.bin.tmp removed at the next run's start",
               not os.path.exists(stale))
ctx.finish()
