#!/usr/bin/python3
"""Bad input gives a one-line error that names the file/line or parameter and
a non-zero exit code, never a crash: a value failing its pattern (in a file
and through --set), an unknown entry, a missing file, an unknown option, and
a time step above the critical one (the message must print dt_crit, checked
against the analytical h / c of the lumped linear bar, and its value with
stiffness damping), damping with the event-driven method."""
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


def expect_error(what, args, *fragments):
    rc, err = hati(*args)
    lines = err.splitlines()
    ok = (rc not in (0,) and rc > 0 and len(lines) == 1 and lines[0].startswith("hati: error:")
          and all(f in err for f in fragments))
    ctx.check_true(what, ok, "(exit %d) %s" % (rc, err))


def write(name, text):
    path = os.path.join(ctx.work, name)
    with open(path, "w") as f:
        f.write(text)
    return path


bad_value = write("bad_value.prm", "subsection Time integration\n  set Time step = abc\nend\n")
expect_error("value failing its pattern, in a file", [bad_value], "Line <2>", "bad_value.prm",
             "Time step", "abc")
unknown = write("unknown.prm", "subsection Contact\n  set Restitution = 1\nend\n")
expect_error("unknown entry, in a file", [unknown], "Line <2>", "unknown.prm", "Restitution")
bar = ctx.prm("bar_impact_1d.prm")
expect_error("value failing its pattern, --set", [bar, "--set", "Contact/Restitution coefficient=1.5"],
             "Contact/Restitution coefficient", "1.5")
expect_error("unknown entry, --set", [bar, "--set", "Contact/Bogus=1"], "Contact/Bogus")
expect_error("missing parameter file", ["does_not_exist.prm"], "does_not_exist.prm")
expect_error("unknown option", [bar, "--bogus"], "bogus")
expect_error("negative end time", [bar, "--set", "Time integration/End time=-1"], "End time")

# frames: a member naming a missing node, a zero-length member, and a model
# without supports (singular stiffness: a clear message, not a Trilinos crash)
frame = ctx.prm("cantilever_static.prm")
expect_error("frame member naming a missing node",
             [frame, "--set", "Model/Frame/Members=beam: root, nowhere, rect, steel, 4"],
             "Model/Frame/Members", "beam", "nowhere")
expect_error("zero-length frame member",
             [frame, "--set", "Model/Frame/Nodes=root: 0, 0, 0; tip: 0, 0, 0"],
             "Model/Frame/Members", "zero length")
expect_error("frame without supports (singular)", [frame, "--set", "Model/Frame/Supports="],
             "singular", "supports")
expect_error("malformed frame section", [frame, "--set", "Model/Frame/Sections=rect: rectangle, 0.05"],
             "Model/Frame/Sections", "rect")
expect_error("Newmark on a model with contacts",
             [bar, "--set", "Time integration/Method=Newmark"], "contacts")

expect_error("Rayleigh damping with the event-driven method",
             [ctx.prm("bouncing_ball.prm"), "--set", "Time integration/Method=event-driven",
              "--set", "Time integration/Damping/Mass coefficient=0.1"], "Damping", "event-driven")
portal = ctx.prm("portal_frame_dynamic.prm")
expect_error("Newmark Beta < Gamma / 2 (conditionally stable)",
             [portal, "--set", "Time integration/Newmark/Beta=0.1"], "Beta", "Gamma")

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

# the documented entry names exist
rc = subprocess.run([ctx.hati, "--print-parameters"], capture_output=True, text=True)
for entry in ("Initial height", "Restitution coefficient", "Time step", "End time",
              "Initial velocity", "Initial gap", "Number of elements"):
    ctx.check_true("--print-parameters lists '%s'" % entry, "set " + entry in rc.stdout)
ctx.check_true("--help exits 0", subprocess.run([ctx.hati, "--help"], capture_output=True).returncode == 0)
ctx.finish()
