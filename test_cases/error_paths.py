#!/usr/bin/python3
"""Error messages whose numbers are checked: a time step above the critical
one (the message must print dt_crit, checked against the analytical h / c
of the lumped linear bar, and its value with stiffness damping); a .prm
with a UTF-8 byte-order mark runs; --print-parameters and --help; refusals
by a bound and of a FIFO within a second (issue #19), no Trilinos output on
a singular static case. The bad inputs checked by the fragments of their
one-line message are the table test_cases/bad_inputs/cases.ini
(bad_inputs.py)."""
import os
import re
import subprocess
import time

import numpy as np

from hati_test import Context

ctx = Context()


def hati(*args):
    p = subprocess.run([ctx.hati, *args], capture_output=True, text=True, timeout=120,
                       cwd=ctx.work)
    return p.returncode, p.stderr.strip()


# the cases that check the message by its fragments are in the table
# test_cases/bad_inputs/cases.ini (test_cases/bad_inputs.py); here: the
# messages whose numbers are checked against the analytical values
bar = ctx.prm("bar_impact_1d.prm")

# time step above critical: refused, printing dt_crit = h / c (analytical)
rc, err = hati(bar, "--set", "Time integration/Time step=3e-6",
               "--set", "Output/Output directory=" + os.path.join(ctx.work, "crit"))
m = re.search(r"dt_crit = [^=]*= ([0-9.eE+-]+) s", err)
ctx.check_true("time step above critical refused", rc != 0 and m is not None, err)
if m:
    ctx.check("printed dt_crit (s)", float(m.group(1)), 0.01 / np.sqrt(2e11 / 7800), rel=1e-5)

# with stiffness damping a1 the limit is (2/w_max)(sqrt(1 + xi^2) - xi),
# xi = a1 w_max / 2, w_max = 2 c / h (algorithms.md A7); the message says so
a1 = 1e-6
rc, err = hati(bar, "--set", "Time integration/Time step=1.9e-6",
               "--set", "Time integration/Damping/Stiffness coefficient=%g" % a1,
               "--set", "Output/Output directory=" + os.path.join(ctx.work, "crit_damped"))
m = re.search(r"dt_crit = [^=]*= ([0-9.eE+-]+) s", err)
ctx.check_true("time step above the damped critical step refused, naming the damping",
               rc != 0 and m is not None and "damping" in err, err)
if m:
    w_max = 2 * np.sqrt(2e11 / 7800) / 0.01
    xi = a1 * w_max / 2
    ctx.check("printed damped dt_crit (s)", float(m.group(1)),
              2 / w_max * (np.sqrt(1 + xi * xi) - xi), rel=1e-5)

# a UTF-8 byte-order mark at the start of a .prm is accepted
with open(os.path.join(ctx.source, "parameter_files", "bouncing_ball.prm"), "rb") as f:
    text = f.read()
bom_prm = os.path.join(ctx.work, "bom.prm")
with open(bom_prm, "wb") as f:
    f.write(b"\xef\xbb\xbf" + text)
rc, err = hati(bom_prm, "--set", "Time integration/End time=0.1",
               "--set", "Output/Output directory=" + os.path.join(ctx.work, "bom"))
ctx.check_true("a .prm starting with a UTF-8 byte-order mark runs", rc == 0, err)

# the documented entry names exist
rc = subprocess.run([ctx.hati, "--print-parameters"], capture_output=True, text=True)
for entry in ("Initial height", "Restitution coefficient", "Time step", "End time",
              "Initial velocity", "Initial gap", "Number of elements"):
    ctx.check_true("--print-parameters lists '%s'" % entry, "set " + entry in rc.stdout)
ctx.check_true("--help exits 0", subprocess.run([ctx.hati, "--help"], capture_output=True).returncode == 0)


# issue #19, finding 2: no runaway. Refusals by a bound, or of a FIFO, come
# at once: at most 1 s more than hati takes to start (`--help`, measured here
# as the best of three, as is each case), instead of minutes at 100 % CPU (a
# span of 1e6 m meshed quadratically) or a hang (open() of a FIFO blocks)
def best_seconds(args, cwd):
    best, p = None, None
    for _ in range(3):
        start = time.monotonic()
        try:
            p = subprocess.run([ctx.hati, *args], capture_output=True, text=True, timeout=20,
                               cwd=cwd)
        except subprocess.TimeoutExpired:
            return 20.0, None
        elapsed = time.monotonic() - start
        best = elapsed if best is None else min(best, elapsed)
    return best, p


start_up, _ = best_seconds(["--help"], ctx.work)
crane = ctx.prm("bridge_crane_hati.prm")
fifo = os.path.join(ctx.work, "record.AT2")
if not os.path.exists(fifo):
    os.mkfifo(fifo)
frame_mesh = ["--set", "Model/Frame/Nodes=", "--set", "Model/Frame/Members=",
              "--set", "Model/Frame/Member properties=east: s, steel; west: s, steel; "
              "north: s, steel; south: s, steel"]
for what, args, fragment in [
        ("crane Span = 1e6 m", [crane, "--set", "Model/Bridge crane/Span=1e6"],
         "'Model/Bridge crane/Span' [Double 1...200 (inclusive)]"),
        ("crane End carriage wheelbase = 1e6 m",
         [crane, "--set", "Model/Bridge crane/End carriage wheelbase=1e6"],
         "'Model/Bridge crane/End carriage wheelbase' [Double 0...50 (inclusive)]"),
        ("an accelerogram that is a FIFO",
         [ctx.prm("portal_frame_elcentro.prm"), "--set", "Loading/Accelerogram X=" + fifo],
         "Loading/Accelerogram X: '%s' is not a regular file (a FIFO)" % fifo),
        ("a mesh file that is a FIFO",
         [ctx.prm("frame_joints.prm"), *frame_mesh, "--set", "Model/Frame/Mesh file=" + fifo],
         "Model/Frame/Mesh file: '%s' is not a regular file (a FIFO)" % fifo)]:
    seconds, p = best_seconds(args + ["--set", "Output/Output directory=" +
                                      os.path.join(ctx.work, "refused")], ctx.work)
    err = p.stderr.strip() if p else "(no exit within 20 s)"
    ctx.check_true("%s refused with one line naming the entry" % what,
                   p is not None and p.returncode == 1 and len(err.splitlines()) == 1
                   and err.startswith("hati: error: ") and fragment in err, err)
    ctx.check_true("%s refused within 1 s of the start-up time" % what,
                   seconds < start_up + 1.0,
                   "(%.2f s, start-up %.2f s)" % (seconds, start_up))

# finding 8: a singular static case solved by CG + AMG: ML's coarse solver
# fails; neither its "ERROR:" line nor its amesos-failure.dat reaches the
# user (working directory, standard output and error)
singular = os.path.join(ctx.work, "singular_cwd")
os.makedirs(singular, exist_ok=True)
p = subprocess.run([ctx.hati, ctx.prm("cantilever_static.prm"),
                    "--set", "Model/Frame/Supports=root: pinned",
                    "--set", "Time integration/Newmark/Linear solver=iterative",
                    "--set", "Output/Output directory=" + os.path.join(singular, "out")],
                   capture_output=True, text=True, timeout=120, cwd=singular)
err = p.stderr.strip()
ctx.check_true("singular K with CG + AMG: one line naming the singular stiffness",
               p.returncode == 1 and len(err.splitlines()) == 1
               and "the stiffness matrix is singular" in err, err)
ctx.check_true("singular K with CG + AMG: no amesos-failure.dat in the working directory",
               not os.path.exists(os.path.join(singular, "amesos-failure.dat")),
               str(os.listdir(singular)))
ctx.check_true("singular K with CG + AMG: no Trilinos ERROR line on the standard output",
               "ERROR" not in p.stdout, p.stdout[-500:])
ctx.finish()
