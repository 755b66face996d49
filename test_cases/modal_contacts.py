#!/usr/bin/python3
"""Modal analysis with closed contacts (doc/theory.md 7.3).

1. Two steel beams along X (clamped at their far ends, 4 elements each) meet
   at two coincident nodes m1, m2 tied by node-to-node contacts with zero
   gap: a one-sided one along +Z (like a trolley wheel) and two-sided ones
   without clearance along X and Y. Held closed, they join the translations
   of the two nodes and nothing else: the independent reference is the same
   two beams built as one frame sharing one node m with 'Hinged joints = m'
   (translations shared, rotations not). A third contact with a 1 cm gap
   (node-to-plane, under beam 1) must stay open. The frequencies agree to
   1e-9 relative (the same discrete model, up to round-off), with ARPACK (6
   modes) and with dense LAPACK (40 modes, ncv < 2 n + 2).
2. A node-to-plane contact with zero gap along +Z at the tip of a
   cantilever is a vertical support there: the same frequencies as the
   frame with 'tip: free, free, fixed, free, free, free', to 1e-9 relative.
   The same with oblique normals ((1, 1, 0) two-sided, (1, -1, 0.5)
   one-sided, (0, 1, 1) two-sided), so that the elimination substitutes
   earlier slaves and pivots.
3. The contacts are really used: the tied model's first frequency differs
   from the untied one (the two separate cantilevers) by more than 10 %."""
import os

from hati_test import Context, read_csv, read_summary

ctx = Context()

COMMON = """
subsection Analysis
  set Type            = modal
  set Number of modes = %(n)d
end
subsection Loading
  set Gravity = 0, 0, 0
end
subsection Model
  set Type = frame
  subsection Frame
    set Materials = steel: 2.1e11, 0.3, 7850
    set Sections  = rect: rectangle, 0.05, 0.1
%(frame)s
  end
end
"""

TIED = """
    set Nodes    = a: 0, 0, 0; m1: 1, 0, 0; m2: 1, 0, 0; b: 2.2, 0, 0
    set Members  = b1: a, m1, rect, steel, 4; b2: m2, b, rect, steel, 4
    set Supports = a: clamped; b: clamped
    set Contacts = wheel: m1, m2, 0, 0, 1, 0; along_x: m1, m2, 1, 0, 0, 0, two-sided; \\
                   along_y: m2, m1, 0, 1, 0, 0, two-sided; open: m1, 0, 0, 1, 0.01
"""
# the same hinge from oblique normals (an in-plane pair at 45 degrees, one
# of them one-sided with a Z part, a third in the YZ plane): each row, once
# the earlier slaves are substituted, pivots on another DoF and updates the
# earlier slaves
OBLIQUE = """
    set Nodes    = a: 0, 0, 0; m1: 1, 0, 0; m2: 1, 0, 0; b: 2.2, 0, 0
    set Members  = b1: a, m1, rect, steel, 4; b2: m2, b, rect, steel, 4
    set Supports = a: clamped; b: clamped
    set Contacts = d1: m1, m2, 1, 1, 0, 0, two-sided; d2: m2, m1, 1, -1, 0.5, 0; \\
                   d3: m1, m2, 0, 1, 1, 0, two-sided; open: m2, 0, 1, 0, 0.02
"""
HINGED = """
    set Nodes    = a: 0, 0, 0; m: 1, 0, 0; b: 2.2, 0, 0
    set Members  = b1: a, m, rect, steel, 4; b2: m, b, rect, steel, 4
    set Supports = a: clamped; b: clamped
    set Hinged joints = m
"""
UNTIED = """
    set Nodes    = a: 0, 0, 0; m1: 1, 0, 0; m2: 1, 0, 0; b: 2.2, 0, 0
    set Members  = b1: a, m1, rect, steel, 4; b2: m2, b, rect, steel, 4
    set Supports = a: clamped; b: clamped
"""
PLANE = """
    set Nodes    = root: 0, 0, 0; tip: 3, 0, 0
    set Members  = beam: root, tip, rect, steel, 8
    set Supports = root: clamped
    set Contacts = rest: tip, 0, 0, 1, 0
"""
PROPPED = """
    set Nodes    = root: 0, 0, 0; tip: 3, 0, 0
    set Members  = beam: root, tip, rect, steel, 8
    set Supports = root: clamped; tip: free, free, fixed, free, free, free
"""


def frequencies(tag, frame, n):
    prm = os.path.join(ctx.work, tag + ".prm")
    with open(prm, "w") as f:
        f.write(COMMON % {"n": n, "frame": frame})
    out, p = ctx.run(prm, tag)
    return read_csv(out + "/modes.csv")["frequency"], read_summary(out), p.stdout


for n in (6, 40):
    tied, s, stdout = frequencies("tied_%d" % n, TIED, n)
    hinged, _, _ = frequencies("hinged_%d" % n, HINGED, n)
    # wheel (1 row), along_x and along_y (two-sided without clearance: one
    # bilateral row each)
    ctx.check("%d modes: closed contact rows" % n, s["n_closed_contact_rows"], 3, abs_tol=0)
    ctx.check_true("%d modes: the terminal names the closed rows" % n,
                   "3 zero-gap contact rows held closed (3 independent" in stdout)
    for k in range(n):
        ctx.check("%d modes: mode %d (Hz) vs hinged frame" % (n, k + 1), tied[k], hinged[k],
                  rel=1e-9)

for n in (6, 40):
    oblique, s, _ = frequencies("oblique_%d" % n, OBLIQUE, n)
    hinged, _, _ = frequencies("hinged_%d" % n, HINGED, n)
    # rows: d1, d2, d3 one each (two-sided without clearance: bilateral);
    # 'open' has a gap
    ctx.check("oblique, %d modes: closed contact rows" % n, s["n_closed_contact_rows"], 3,
              abs_tol=0)
    for k in range(n):
        ctx.check("oblique, %d modes: mode %d (Hz) vs hinged frame" % (n, k + 1), oblique[k],
                  hinged[k], rel=1e-9)

untied, _, _ = frequencies("untied", UNTIED, 6)
ctx.check_true("the ties change the first frequency by > 10 %",
               tied[0] > 1.1 * untied[0], "(%.6g Hz tied, %.6g Hz untied)" % (tied[0], untied[0]))

plane, s, _ = frequencies("plane", PLANE, 8)
propped, _, _ = frequencies("propped", PROPPED, 8)
ctx.check("node-to-plane: closed contact rows", s["n_closed_contact_rows"], 1, abs_tol=0)
for k in range(8):
    ctx.check("node-to-plane: mode %d (Hz) vs supported tip" % (k + 1), plane[k], propped[k],
              rel=1e-9)
ctx.finish()
