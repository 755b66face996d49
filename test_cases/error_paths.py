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

# bad inputs that used to get through or got a wrong diagnosis (issue #7):
# each must give one line naming the entry and the cause
portal = os.path.join(ctx.source, "parameter_files", "portal_frame_dynamic.prm")
sections = "beam: box, 0.2, 0.4, 0.008, 0.012"
bad_frame = [
    ("a negative point mass", "Model/Frame/Point masses=A1: -500",
     ["Point masses", "A1", ">= 0"]),
    ("a duplicate section name",
     "Model/Frame/Sections=column: box, 0.3, 0.3, 0.01, 0.01; column: box, 0.3, 0.3, 0.01, "
     "0.01; " + sections, ["Sections", "'column' is defined twice"]),
    ("a duplicate material name", "Model/Frame/Materials=steel: 2.1e11, 0.3, 7850; steel: "
     "2e11, 0.3, 7850", ["Materials", "'steel' is defined twice"]),
    ("a node listed twice in Supports",
     "Model/Frame/Supports=A0: clamped; A0: clamped; B0: clamped; C0: clamped; D0: clamped",
     ["Supports", "'A0' is listed twice"]),
    ("a zero section orientation vector",
     "Model/Frame/Members=colA: A0, A1, column, steel, 8, 0, 0, 0; colB: B0, B1, column, "
     "steel, 8", ["Members", "colA", "orientation vector", "zero"]),
    ("an element count that overflows 32 bits",
     "Model/Frame/Members=colA: A0, A1, column, steel, 4294967297; colB: B0, B1, column, "
     "steel, 8", ["Members", "colA", "from 1 to 10000000", "4294967297"]),
    ("a zero section dimension (message names the entry, not a C++ function)",
     "Model/Frame/Sections=column: rectangle, 0, 0.3; " + sections,
     ["Sections", "'column'", "rectangle needs b > 0"]),
    ("E = 1e308: overflow named", "Model/Frame/Materials=steel: 1e308, 0.3, 7850",
     ["stiffness matrix", "not finite (overflow)"]),
    ("a node at 1e200: overflow named",
     "Model/Frame/Nodes=A0: 0, 0, 0; A1: 0, 0, 1e200; B0: 6, 0, 0; B1: 6, 0, 5; C0: 0, 4, 0; "
     "C1: 0, 4, 5; D0: 6, 4, 0; D1: 6, 4, 5", ["colA", "overflow", "node coordinates too large"]),
    ("a time step that would take 2e30 steps", "Time integration/Time step=1e-30",
     ["Maximum number of steps", "2e+30"]),
]
for what, assignment, fragments in bad_frame:
    expect_error(what, [portal, "--set", assignment, "--set",
                        "Output/Output directory=" + os.path.join(ctx.work, "bad")], *fragments)
expect_error("a bar element count above its maximum",
             [bar, "--set", "Model/Bar/Number of elements=200000000"], "Number of elements",
             "1e8")

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
