"""Helpers of the application tests: run hati on a parameter file with
overrides into a fresh directory, read its CSV/JSON outputs, and check
numbers against reference values with explicit tolerances."""
import json
import os
import shutil
import subprocess
import sys
import time

import numpy as np


class Context:
    def __init__(self):
        if len(sys.argv) < 4:
            sys.exit("usage: test.py HATI SOURCE_DIR WORK_DIR")
        self.hati, self.source, self.work = (os.path.abspath(a) for a in sys.argv[1:4])
        self.failures = 0
        os.makedirs(self.work, exist_ok=True)

    def prm(self, name):
        return os.path.join(self.source, "parameter_files", name)

    def run(self, prm, tag, sets=(), expect_failure=False):
        """Run hati; returns (output directory, completed process)."""
        out = os.path.join(self.work, tag)
        shutil.rmtree(out, ignore_errors=True)
        cmd = [self.hati, prm, "--set", "Output/Output directory=" + out]
        for s in sets:
            cmd += ["--set", s]
        start = time.monotonic()
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
        print("run %s: %.1f s" % (tag, time.monotonic() - start))
        if expect_failure:
            return out, p
        if p.returncode != 0:
            print(p.stdout, p.stderr)
            raise SystemExit("hati failed on %s (%s)" % (prm, tag))
        return out, p

    def check(self, what, value, reference, rel=None, abs_tol=None):
        """|value - reference| <= max(rel |reference|, abs_tol)."""
        tol = max(rel * abs(reference) if rel is not None else 0.0,
                  abs_tol if abs_tol is not None else 0.0)
        err = abs(value - reference)
        ok = err <= tol and np.isfinite(value)
        self.failures += 0 if ok else 1
        print("%-4s %-48s value %.10g reference %.10g error %.3g tolerance %.3g"
              % ("ok" if ok else "FAIL", what, value, reference, err, tol))
        return ok

    def check_true(self, what, condition, detail=""):
        self.failures += 0 if condition else 1
        print("%-4s %s %s" % ("ok" if condition else "FAIL", what, detail))

    def finish(self):
        if self.failures:
            raise SystemExit("%d check(s) failed" % self.failures)
        print("all checks passed")


def read_csv(path):
    return np.atleast_1d(np.genfromtxt(path, delimiter=",", names=True, dtype=None, encoding=None))


TIMING_KEYS = ("wall_time", "stepping_wall_time", "setup_wall_time", "static_state_wall_time",
               "ns_per_dof_per_step", "factorization_time",
               "wall_time_explicit", "wall_time_implicit", "wall_time_interface",
               "wall_time_setup")


def read_summary(out):
    """summary.json of the run in `out`; every timing entry must be >= 0
    (issue #19: wall-time figures from one monotonic clock)."""
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    for key in TIMING_KEYS:
        value = s.get(key)
        if isinstance(value, (int, float)) and not value >= 0:
            raise SystemExit("FAIL %s/summary.json: %s = %r is negative" % (out, key, value))
    return s


def contact_phases(contacts):
    """Times at which an impulse run starts and the index arrays of the runs
    (consecutive rows with impulse > 0)."""
    on = contacts["impulse"] > 0
    starts = np.where(on & ~np.concatenate(([False], on[:-1])))[0]
    ends = np.where(on & ~np.concatenate((on[1:], [False])))[0]
    return starts, ends
