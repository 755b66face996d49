#!/usr/bin/python3
"""Suites of records (issue #18): a member whose record file is broken fails
alone (its row in suite.csv has the error, the other members complete, the
suite ends with one error line and exit code 1); a suite stopped by SIGTERM
while its second member runs is resumed by running it again: the first
member is reused (its files untouched), only the rest run."""
import csv
import os
import shutil
import signal
import subprocess

from hati_test import Context

ctx = Context()
data = os.path.join(ctx.source, "data", "accelerograms")
elc = os.path.join(data, "RSN6_IMPVALL.I_I-ELC180.AT2")
r228 = os.path.join(data, "Rinaldi228.AT2")
broken = os.path.join(ctx.source, "test_cases", "bad_inputs", "truncated.AT2")
prm = ctx.prm("portal_frame_elcentro.prm")
base = ["Output/Output interval=0", "Output/History interval=0.002"]


def command(out, sets):
    cmd = [ctx.hati, prm, "--set", "Output/Output directory=" + out]
    for s in base + sets:
        cmd += ["--set", s]
    return cmd


def rows(out):
    with open(os.path.join(out, "suite.csv"), newline="") as f:
        return {r["member"]: r for r in csv.DictReader(f)}


# a broken record fails alone
out = os.path.join(ctx.work, "broken")
shutil.rmtree(out, ignore_errors=True)
p = subprocess.run(command(out, ["Time integration/End time=0.2",
                                 "Suite/Records=elc: %s; bad: %s; rin: %s" % (elc, broken, r228)]),
                   capture_output=True, text=True, timeout=120)
print(p.stdout[-800:], p.stderr)
ctx.check_true("broken record: exit code 1", p.returncode == 1, str(p.returncode))
errors = [l for l in p.stderr.splitlines() if l.startswith("hati: error:")]
ctx.check_true("broken record: one error line naming the member",
               len(errors) == 1 and "suite: 1 of 3 members failed (bad_s1_0: " in errors[0])
r = rows(out)
ctx.check_true("broken record: the others completed",
               r["elc_s1_0"]["status"] == "completed" and r["rin_s1_0"]["status"] == "completed")
ctx.check_true("broken record: its row says failed with the reader's error",
               r["bad_s1_0"]["status"] == "failed" and "truncated.AT2" in r["bad_s1_0"]["error"]
               and "Loading/Accelerogram X" in r["bad_s1_0"]["error"], r["bad_s1_0"]["error"])
ctx.check_true("broken record: no results in its row",
               r["bad_s1_0"]["A1.max_absolute_acceleration"] == "")

# interrupted after the first member, then resumed
out = os.path.join(ctx.work, "resume")
shutil.rmtree(out, ignore_errors=True)
sets = ["Time integration/End time=8",
        "Suite/Records=first: %s; second: %s; third: %s" % (elc, r228, elc),
        "Suite/Scale factors=0.5"]
proc = subprocess.Popen(command(out, sets), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                        text=True)
for line in proc.stdout:
    print(line, end="")
    if "member 1/3 done" in line:
        proc.send_signal(signal.SIGTERM)
        break
rest, err = proc.communicate(timeout=120)
print(rest, err)
ctx.check_true("SIGTERM: exit code 143", proc.returncode == 143, str(proc.returncode))
r = rows(out)
names = ["first_s0.5_0", "second_s0.5_0", "third_s0.5_0"]
before = [r[n]["status"] for n in names]
# the signal lands while the second member runs (or, on a loaded machine,
# after it): the first is complete, the last is not
ctx.check_true("SIGTERM: first completed, the rest interrupted or not run",
               before[0] == "completed" and before[2] in ("interrupted", "not run")
               and all(b in ("completed", "interrupted", "not run") for b in before)
               and before.count("interrupted") <= 1, str(before))
first_history = os.path.join(out, "first_s0.5_0", "history.csv")
stamp = os.stat(first_history).st_mtime_ns
p = subprocess.run(command(out, sets), capture_output=True, text=True, timeout=120)
print(p.stdout[-800:], p.stderr)
ctx.check_true("resumed: exit code 0", p.returncode == 0, str(p.returncode))
r = rows(out)
after = [r[n]["status"] for n in names]
expected = ["reused" if b == "completed" else "completed" for b in before]
ctx.check_true("resumed: the completed members reused, the rest run", after == expected,
               str(after))
ctx.check_true("resumed: the first member's files untouched",
               os.stat(first_history).st_mtime_ns == stamp)
ctx.check_true("resumed: only the members not complete ran",
               p.stdout.count(": completed,") == before.count("interrupted") + before.count("not run"))
ctx.check("resumed: the reused member's results kept",
          float(r["first_s0.5_0"]["A1.max_absolute_acceleration"]), 
          float(r["third_s0.5_0"]["A1.max_absolute_acceleration"]), rel=0.0)
ctx.finish()
