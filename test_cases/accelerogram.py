#!/usr/bin/python3
"""Recorded accelerograms (algorithms.md section 4): the three PEER NGA AT2
records of data/accelerograms are read with the number of samples, peak and
time of peak stated in data/accelerograms/SOURCES.md (computed there from
the values, independently of hati); the second AT2 header style and a
two-column file in cm/s^2 are read; a constant two-column record gives the
same response as the equivalent base acceleration step (to round-off); a
malformed file is an error naming the file and the line."""
import os
import re

import numpy as np

from hati_test import Context, read_csv

ctx = Context()
prm = ctx.prm("portal_frame_dynamic.prm")
data = os.path.join(ctx.source, "data", "accelerograms")
short = ["Time integration/End time=0.05", "Output/Output interval=0"]

# (file, samples, PGA in g, time of PGA in s) from SOURCES.md
for name, n, pga, t_pga in (("RSN6_IMPVALL.I_I-ELC180.AT2", 5372, 0.2808, 2.18),
                            ("Rinaldi228.AT2", 1991, 0.8741, 2.56),
                            ("RinaldiUP.AT2", 1991, 0.9582, 2.97)):
    _, p = ctx.run(prm, "read_" + name, short + ["Loading/Accelerogram Z=" + os.path.join(data, name)])
    m = re.search(r"(\d+) samples to t = ([0-9.]+) s, peak ([0-9.eE+-]+) m/s\^2 \(([0-9.eE+-]+) g\) "
                  r"at t = ([0-9.]+) s", p.stdout)
    ctx.check_true(name + ": summary line printed", m is not None)
    if m:
        ctx.check(name + ": number of samples", int(m.group(1)), n, abs_tol=0)
        ctx.check(name + ": last sample time (s)", float(m.group(2)), (n - 1) * 0.01, abs_tol=1e-9)
        ctx.check(name + ": PGA (g)", float(m.group(4)), pga, abs_tol=5e-5)
        ctx.check(name + ": time of PGA (s)", float(m.group(5)), t_pga, abs_tol=1e-9)

# the other AT2 header style, 8 values per line, and NPTS checked
def write(name, text):
    path = os.path.join(ctx.work, name)
    with open(path, "w") as f:
        f.write(text)
    return path

values = [0.01 * k for k in range(12)]
body = "\n".join(" ".join("%.7E" % v for v in values[i:i + 8]) for i in range(0, 12, 8)) + "\n"
alt = write("alt.AT2", "PEER STRONG MOTION DATABASE RECORD\nTEST\nACCELERATION IN G\n"
                       "   12   0.0200  NPTS, DT\n" + body)
_, p = ctx.run(prm, "alt", short + ["Loading/Accelerogram X=" + alt])
m = re.search(r"(\d+) samples to t = ([0-9.]+) s, peak ([0-9.eE+-]+) m/s\^2", p.stdout)
ctx.check("alternative AT2 header: samples", int(m.group(1)), 12, abs_tol=0)
ctx.check("alternative AT2 header: duration (s)", float(m.group(2)), 11 * 0.02, abs_tol=1e-12)
# printed with 6 significant digits
ctx.check("alternative AT2 header: peak (m/s^2)", float(m.group(3)), 0.11 * 9.80665, rel=1e-5)

# a constant record of 100 cm/s^2 equals the 1 m/s^2 step of the .prm
const = write("const.txt", "# time (s)  acceleration (cm/s^2)\n0 100\n10 100\n")
out_a, _ = ctx.run(prm, "step", ["Time integration/End time=0.3", "Output/Output interval=0"])
out_b, _ = ctx.run(prm, "record", ["Time integration/End time=0.3", "Output/Output interval=0",
                                   "Loading/Base acceleration=0, 0, 0",
                                   "Loading/Accelerogram X=" + const,
                                   "Loading/Accelerogram units=cm/s^2"])
ua, ub = read_csv(out_a + "/history.csv")["A1ux"], read_csv(out_b + "/history.csv")["A1ux"]
ctx.check("constant record vs step: max difference / peak", np.max(np.abs(ua - ub)) / np.max(np.abs(ua)),
          0.0, abs_tol=1e-12)

# malformed files
bad_n = write("bad_n.AT2", "H\nH\nH\nNPTS=   5, DT=   .0100 SEC\n 0.1 0.2 0.3\n")
_, p = ctx.run(prm, "bad_n", short + ["Loading/Accelerogram X=" + bad_n], expect_failure=True)
ctx.check_true("NPTS mismatch refused", p.returncode != 0 and "bad_n.AT2" in p.stderr
               and "NPTS = 5" in p.stderr, p.stderr.strip())
bad_line = write("bad_line.txt", "0 1\n0.1 2\n0.2 x\n")
_, p = ctx.run(prm, "bad_line", short + ["Loading/Accelerogram X=" + bad_line], expect_failure=True)
ctx.check_true("malformed line refused with file and line", p.returncode != 0
               and "bad_line.txt', line 3" in p.stderr, p.stderr.strip())
ctx.finish()
