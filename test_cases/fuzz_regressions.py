#!/usr/bin/python3
"""Inputs found by fuzzing (bench/fuzz.sh) that crashed hati, hung it or made
a sanitizer report: each must now give a non-zero exit (no signal) within
the time limit and a single line `hati: error: ...` on stderr.

test_cases/fuzz_regressions/
  prm/*.prm            run as `hati file.prm` (from the repository root)
  gmsh/*.msh           read as Model/Frame/Mesh file of a frame
  accelerogram/*       read as Loading/Accelerogram X of a point mass
                       (.AT2: PEER format, other names: two columns)
An optional `<file>.expect` holds one fragment per line that the message
must contain; otherwise the message must name the mesh or accelerogram file
(gmsh, accelerogram). Run against the instrumented hati of build-fuzz/
(ctest -L errors there), the sanitizers check the same inputs."""
import glob
import os
import subprocess

from hati_test import Context

ctx = Context()
here = os.path.join(ctx.source, "test_cases", "fuzz_regressions")
# the instrumented build: OpenMPI leaks at exit are not ours
env = dict(os.environ, ASAN_OPTIONS="detect_leaks=0", UBSAN_OPTIONS="halt_on_error=1")


def write(name, text):
    path = os.path.join(ctx.work, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def expect_error(what, prm, input_file, default_fragments):
    out = os.path.join(ctx.work, "output", os.path.basename(input_file))
    try:
        p = subprocess.run([ctx.hati, prm, "--set", "Output/Output directory=" + out],
                           capture_output=True, timeout=120, cwd=ctx.source, env=env)
    except subprocess.TimeoutExpired:
        ctx.check_true(what, False, "(hang: no exit within 120 s)")
        return
    err = p.stderr.decode("utf-8", "replace").strip()
    lines = err.splitlines()
    fragments = default_fragments
    if os.path.exists(input_file + ".expect"):
        with open(input_file + ".expect") as f:
            fragments = [l.strip() for l in f if l.strip()]
    ok = (p.returncode > 0 and len(lines) == 1 and lines[0].startswith("hati: error:")
          and all(f in err for f in fragments))
    detail = "(exit %d) %s" % (p.returncode, err if len(err) < 2000 else err[:2000] + "...")
    ctx.check_true(what, ok, detail)


def inputs(kind):
    return sorted(f for f in glob.glob(os.path.join(here, kind, "*"))
                  if not f.endswith(".expect"))


n = 0
for f in inputs("prm"):
    expect_error("prm/" + os.path.basename(f), f, f, [])
    n += 1

for f in inputs("gmsh"):
    prm = write("gmsh_%s.prm" % os.path.basename(f), """
subsection Model
  set Type = frame
  subsection Frame
    set Mesh file = %s
    set Materials = steel: 2.1e11, 0.3, 7850
    set Sections = s: rectangle, 0.1, 0.2
  end
end
""" % f)
    expect_error("gmsh/" + os.path.basename(f), prm, f, ["mesh file", os.path.basename(f)])
    n += 1

for f in inputs("accelerogram"):
    prm = write("accelerogram_%s.prm" % os.path.basename(f), """
subsection Time integration
  set Time step = 1e-3
  set End time = 1e-3
end
subsection Loading
  set Accelerogram X = %s
end
""" % f)
    expect_error("accelerogram/" + os.path.basename(f), prm, f,
                 ["accelerogram file", os.path.basename(f)])
    n += 1

ctx.check_true("regression inputs found", n > 0, "(%d)" % n)
ctx.finish()
