#!/usr/bin/python3
"""Error messages whose numbers are checked: a time step above the critical
one (the message must print dt_crit, checked against the analytical h / c
of the lumped linear bar, and its value with stiffness damping); a .prm
with a UTF-8 byte-order mark runs; --print-parameters and --help. The bad
inputs checked by the fragments of their one-line message are the table
test_cases/bad_inputs/cases.ini (bad_inputs.py)."""
import os
import re
import subprocess

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
ctx.finish()
