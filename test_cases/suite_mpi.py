#!/usr/bin/python3
"""Suites of records (issue #18): a suite of 3 members (the portal frame of
portal_frame_elcentro.prm, 0.4 s under El Centro, Rinaldi 228 + UP and
Rinaldi 228 alone, with its response spectra) run serially and with
`mpirun -np 2` gives the same suite.csv rows except the wall time, and the
members' CSV files are bitwise identical; suite_summary.json's envelope and
mean, with the governing member, equal a hand calculation on suite.csv (the
mean by rerunning with Statistic = mean, which reuses every member), and
suite_spectra.csv the envelope of the members' spectra.csv. A single run
(no Suite) under `mpirun -np 2` runs once, on rank 0, with one warning.

Issue #24: under `mpirun -np 2` a suite whose folder cannot be created
(rank 0's step before the ranks meet) ends within 10 s with exit code 1
and one error line (rank 0's), a refused suite prints its line once, and
SIGTERM to mpirun stops the suite cleanly (suite.csv written; mpirun 4.1
itself exits with 1 when signalled)."""
import csv
import filecmp
import json
import os
import shutil
import signal
import subprocess
import time

from hati_test import Context

ctx = Context()
data = os.path.join(ctx.source, "data", "accelerograms")
elc = os.path.join(data, "RSN6_IMPVALL.I_I-ELC180.AT2")
r228 = os.path.join(data, "Rinaldi228.AT2")
rup = os.path.join(data, "RinaldiUP.AT2")
suite = ["Time integration/End time=0.4",
         "Output/Output interval=0",
         "Output/History interval=0.002",
         "Output/Spectra=A1, D1",
         "Suite/Records=elc: %s; rin: %s, , %s; rinx: %s" % (elc, r228, rup, r228)]
prm = ctx.prm("portal_frame_elcentro.prm")
members = ["elc_s1_0", "rin_s1_0", "rinx_s1_0"]


def run_suite(tag, sets, mpi=0):
    out = os.path.join(ctx.work, tag)
    cmd = [ctx.hati, prm, "--set", "Output/Output directory=" + out]
    for s in sets:
        cmd += ["--set", s]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    if mpi:
        cmd = ["mpirun", "-np", str(mpi), "--oversubscribe"] + cmd
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=300, env=env)
    print("$ " + " ".join(cmd[-6:]) + "\n" + p.stdout[-1500:] + p.stderr[-1500:])
    return out, p


def rows(out):
    with open(os.path.join(out, "suite.csv"), newline="") as f:
        return list(csv.DictReader(f))


for tag in ("serial", "mpi"):
    shutil.rmtree(os.path.join(ctx.work, tag), ignore_errors=True)
serial, p = run_suite("serial", suite)
ctx.check_true("serial suite: exit code 0", p.returncode == 0, str(p.returncode))
ctx.check_true("serial suite: progress line of the last member",
               "member 3/3 done" in p.stdout and "ETA" in p.stdout)
mpi, p = run_suite("mpi", suite, mpi=2)
ctx.check_true("mpirun -np 2 suite: exit code 0", p.returncode == 0, str(p.returncode))
ctx.check_true("mpirun -np 2: both ranks ran members",
               ", rank 0)" in p.stdout and ", rank 1)" in p.stdout)

a, b = rows(serial), rows(mpi)
ctx.check_true("suite.csv: 3 rows each", len(a) == 3 and len(b) == 3)
ctx.check_true("suite.csv: every member completed",
               all(r["status"] == "completed" for r in a + b))
for ra, rb in zip(a, b):
    ra.pop("wall_time"), rb.pop("wall_time")
    ctx.check_true("suite.csv row %s: serial == mpirun -np 2 (but the wall time)" % ra["member"],
                   ra == rb)
for m in members:
    for f in ("history.csv", "energy.csv", "section_forces.csv", "spectra.csv"):
        same = filecmp.cmp(os.path.join(serial, m, f), os.path.join(mpi, m, f), shallow=False)
        ctx.check_true("%s/%s: serial and MPI bitwise identical" % (m, f), same)
ctx.check_true("suite.csv has the key results",
               all(k in a[0] for k in ("A1.max_absolute_acceleration", "section_force.My")))


def hand_statistics(table):
    """max, mean and the governing member of every result column."""
    fixed = {"member", "record", "scale", "variation", "status", "error", "wall_time"}
    result = {}
    for q in (k for k in table[0] if k not in fixed):
        values = [(float(r[q]), r["member"]) for r in table if r[q] != ""]
        top = max(values)
        result[q] = (top[0], sum(v for v, _ in values) / len(values), top[1])
    return result


def check_statistic(out, name):
    with open(os.path.join(out, "suite_summary.json")) as f:
        summary = json.load(f)
    ctx.check_true("%s: suite_summary.json says statistic = %s" % (out, name),
                   summary["statistic"] == name)
    quantities = summary["groups"][0]["quantities"]
    hand = hand_statistics(rows(out))
    ctx.check_true("%s: a statistic for each of the %d quantities" % (name, len(hand)),
                   sorted(hand) == sorted(quantities))
    for q, (top, mean, governing) in hand.items():
        reference = top if name == "envelope" else mean
        ctx.check("%s of %s" % (name, q), quantities[q]["value"], reference, rel=1e-14)
        ctx.check_true("governing member of %s: %s" % (q, governing),
                       quantities[q]["governing_member"] == governing)


check_statistic(serial, "envelope")
# the envelope of the spectra: the largest of the members' spectra.csv
with open(os.path.join(serial, "suite_spectra.csv"), newline="") as f:
    spectra = list(csv.DictReader(f))
member_spectra = []
for m in members:
    with open(os.path.join(serial, m, "spectra.csv"), newline="") as f:
        member_spectra.append(list(csv.DictReader(f)))
worst = 0.0
for i, row in enumerate(spectra):
    for column in ("A1.x", "D1.z", "ground.x", "ground.z"):
        values = [float(t[i][column]) for t in member_spectra if column in t[i]]
        worst = max(worst, abs(float(row[column]) - max(values)))
ctx.check("suite_spectra.csv = envelope of the members' spectra (m/s^2)", worst, 0.0, abs_tol=0.0)
ctx.check_true("suite_spectra.csv: 2 damping ratios x 100 periods", len(spectra) == 200)

# a single run (no Suite) under mpirun -np 2: rank 0 runs it and warns once,
# the other rank stays idle (before, both ranks ran it and one found the
# output directory locked, exit code 1); its files equal the serial run's
single = ["Time integration/End time=0.2", "Output/Output interval=0", "Loading/Accelerogram X=" + elc]
for tag in ("single_serial", "single_mpi"):
    shutil.rmtree(os.path.join(ctx.work, tag), ignore_errors=True)
single_serial, p = run_suite("single_serial", single)
single_mpi, p = run_suite("single_mpi", single, mpi=2)
warning = ("2 MPI ranks for a single run: it runs on rank 0 and the other rank stays idle "
           "(a subsection Suite spreads the records of a suite over the ranks)")
ctx.check_true("mpirun -np 2, single run: exit code 0, one warning line on stderr",
               p.returncode == 0 and p.stderr.strip().splitlines() == ["hati: warning: " + warning],
               "(exit %d) %s" % (p.returncode, p.stderr[-500:]))
with open(os.path.join(single_mpi, "summary.json")) as f:
    summary = json.load(f)
ctx.check_true("mpirun -np 2, single run: summary.json completed, with the warning",
               summary.get("status") == "completed" and summary.get("warnings") == [warning],
               str(summary.get("warnings")))
ctx.check_true("mpirun -np 2, single run: history.csv and energy.csv equal the serial run's",
               all(filecmp.cmp(os.path.join(single_serial, f), os.path.join(single_mpi, f),
                               shallow=False) for f in ("history.csv", "energy.csv")))

# --- issue #24: no deadlock, one line, SIGTERM ---
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def mpirun_within(sets, seconds):
    """mpirun -np 2 hati with sets: (exit code or None if it hung, stderr)."""
    cmd = ["mpirun", "-np", "2", "--oversubscribe", ctx.hati, prm]
    for s in sets:
        cmd += ["--set", s]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            env=ENV, start_new_session=True, cwd=ctx.source)
    try:
        out, err = proc.communicate(timeout=seconds)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, err = proc.communicate()
        return None, err
    print(out[-500:] + err[-800:])
    return proc.returncode, err


afile = os.path.join(ctx.work, "afile")
with open(afile, "w") as f:
    f.write("a regular file\n")
short = ["Time integration/End time=0.2", "Output/Output interval=0",
         "Output/History interval=0.002"]
started = time.time()
code, err = mpirun_within(short + ["Output/Output directory=" + afile + "/sub",
                                   "Suite/Scale factors=1, 2"], 10)
errors = [l for l in err.splitlines() if l.startswith("hati: error:")]
ctx.check_true("mpirun -np 2, suite folder under a regular file: exit 1 within 10 s, "
               "one error line", code == 1 and len(errors) == 1 and "afile/sub" in errors[0],
               "(exit %s, %.1f s) %s" % (code, time.time() - started, errors))
code, err = mpirun_within(short + ["Output/Output directory=" + os.path.join(ctx.work, "dup"),
                                   "Suite/Scale factors=1, 1.0"], 20)
errors = [l for l in err.splitlines() if l.startswith("hati: error:")]
ctx.check_true("mpirun -np 2, a refused suite: exit 1, its line printed once (rank 0)",
               code == 1 and len(errors) == 1 and "given twice" in errors[0],
               "(exit %s) %s" % (code, errors))

term = os.path.join(ctx.work, "term")
shutil.rmtree(term, ignore_errors=True)
cmd = ["mpirun", "-np", "2", "--oversubscribe", ctx.hati, prm,
       "--set", "Output/Output directory=" + term, "--set", "Output/Output interval=0",
       "--set", "Time integration/End time=20",
       # members of about 3 s each (Newmark at 2e-4 s instead of 2e-3 s): at
       # the file's step a member took 0.3 s and the suite could finish
       # before the signal arrived (a fresh clone's run failed so)
       "--set", "Time integration/Time step=2e-4",
       "--set", "Suite/Records=a: %s; b: %s; c: %s" % (elc, r228, elc)]
proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=ENV)
deadline = time.time() + 60
while time.time() < deadline and not all(
        os.path.exists(os.path.join(term, m, "member.log")) for m in ("a_s1_0", "b_s1_0")):
    time.sleep(0.1)
proc.send_signal(signal.SIGTERM)
try:
    out, err = proc.communicate(timeout=60)
except subprocess.TimeoutExpired:
    proc.kill()
    out, err = proc.communicate()
print(out[-600:] + err[-600:])
# every rank stops as a serial suite does (exit code 143); Open MPI 4.1's
# mpirun itself exits with 1 when it is signalled, whatever its ranks return
ctx.check_true("mpirun -np 2, SIGTERM to mpirun: the suite stops cleanly, suite.csv written",
               proc.returncode in (1, 143) and "hati: suite interrupted by SIGTERM" in err and
               os.path.exists(os.path.join(term, "suite.csv")),
               "(exit %s)" % proc.returncode)

_, p = run_suite("serial", suite + ["Suite/Statistic=mean"])
ctx.check_true("Statistic = mean: every member reused",
               p.stdout.count(": reused,") == 3, p.stdout[-300:])
check_statistic(serial, "mean")
ctx.finish()
