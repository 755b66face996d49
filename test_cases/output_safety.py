#!/usr/bin/python3
"""Runs that never lose results (issue #7): fault tests of the output
directory.
- a run that fails before its first step leaves the previous results
  byte for byte;
- the next run deletes exactly the files of the previous run's manifest: a
  user's solution-00042.vtu and notes.txt survive, stale snapshots go;
- SIGTERM and SIGINT mid-run: exit 143 / 130, history.csv and energy.csv
  with the same number of complete rows, "status": "interrupted",
  time_reached and n_steps (the steps done) in summary.json;
- SIGKILL at four instants: every CSV ends on a complete line with the
  header's number of fields, solution.pvd parses and names complete VTU
  files; SIGKILL of the whole process group (os.killpg, the run in its own
  session, as a job scheduler kills) at 40 random instants of a run
  writing a row every step (1 MiB appends): every CSV ends on a complete
  line every time (the writer child, outside the group, finishes an append
  and holds .hati.lock until then);
- a symbolic link where an output file, a temporary file, the lock or the
  manifest would go (pointing at a victim file outside the folder, or at a
  missing one) is refused in one line naming the link; the victim stays
  byte for byte (the missing one is not created);
- a second concurrent run into the same directory is refused in one line;
- Output/Section force interval = 1e20 s gives the section force rows at
  the start and the end only; a link at a suite's plot_suite.log is named
  in the warning and its target untouched;
- a run failing mid-run writes "status": "failed" with the message;
- a closed standard output (SIGPIPE) does not stop the run;
- a folder deleted during the run and a full disk (a 1 MiB tmpfs, if this
  process may mount one; skipped with a message otherwise) end the run with
  a non-zero exit and one line naming the file and the system error; on
  the full disk every CSV ends on a whole line and summary.json says
  "status": "failed" with that line's message;
- issue #59: a records/ or modal/ folder that is a symbolic link is refused
  and its target stays empty."""
import hashlib
import itertools
import concurrent.futures
import fcntl
import json
import os
import random
import shutil
import signal
import subprocess
import time
import xml.etree.ElementTree as ET

from hati_test import Context

ctx = Context()
bar = ctx.prm("bar_impact_1d.prm")
# a run of minutes: 2e7 steps of 1 us, a history row every 10 steps
LONG = ["Time integration/End time=20", "Output/History interval=1e-5",
        "Output/Output interval=0"]


def command(out, sets=(), prm=bar):
    cmd = [ctx.hati, prm, "--set", "Output/Output directory=" + out]
    for s in sets:
        cmd += ["--set", s]
    return cmd


def environment():
    """An own TMPDIR for every run: Open MPI singletons starting at the same
    time race on creating their session directory in it (1 start in 80
    failed with 8 starts at a time in /tmp)."""
    tmp = os.path.join(ctx.work, "tmp", str(next(run_numbers)))
    os.makedirs(tmp, exist_ok=True)
    return dict(os.environ, TMPDIR=tmp)


run_numbers = itertools.count()  # (next() is atomic: runs start from threads too)
shutil.rmtree(os.path.join(ctx.work, "tmp"), ignore_errors=True)


def run(out, sets=(), prm=bar):
    return subprocess.run(command(out, sets, prm), capture_output=True, text=True,
                          timeout=600, env=environment())


def start(out, sets=(), prm=bar, new_session=False):
    return subprocess.Popen(command(out, sets, prm), stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, text=True, env=environment(),
                            start_new_session=new_session)


def summary(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def wait_running(out, rows=3, timeout=120):
    """Wait until the run writes into out and history.csv has rows."""
    t0 = time.time()
    while time.time() - t0 < timeout:
        try:
            if summary(out).get("status") == "running":
                with open(os.path.join(out, "history.csv")) as f:
                    if sum(1 for _ in f) > rows:
                        return True
        except (OSError, ValueError):
            pass
        time.sleep(0.05)
    return False


def wait_unlocked(out, timeout=30):
    """Wait until no process holds out/.hati.lock: after a SIGKILL the child
    finishing the last append of rows holds it until it is done."""
    t0 = time.time()
    with open(os.path.join(out, ".hati.lock"), "rb") as f:
        while time.time() - t0 < timeout:
            try:
                fcntl.flock(f, fcntl.LOCK_EX | fcntl.LOCK_NB)
                fcntl.flock(f, fcntl.LOCK_UN)
                return True
            except OSError:
                time.sleep(0.01)
    return False


def digest(out):
    r = {}
    for name in sorted(os.listdir(out)):
        path = os.path.join(out, name)
        if os.path.isfile(path):
            with open(path, "rb") as f:
                r[name] = hashlib.sha256(f.read()).hexdigest()
    return r


def csv_complete(path):
    """(rows, whether every line is complete with the header's field count)."""
    with open(path, "rb") as f:
        data = f.read()
    if not data.endswith(b"\n"):
        return 0, False
    lines = data.decode().splitlines()
    n = lines[0].count(",")
    return len(lines) - 1, all(l.count(",") == n for l in lines)


def one_line_error(p, *fragments):
    err = p.stderr.strip() if isinstance(p.stderr, str) else p.stderr.read().strip()
    lines = err.splitlines()
    return (p.returncode not in (0,) and p.returncode > 0 and len(lines) == 1
            and lines[0].startswith("hati: error:") and all(f in err for f in fragments)), err


# --- a failed run keeps the previous results ---
out = os.path.join(ctx.work, "keep")
shutil.rmtree(out, ignore_errors=True)
p = run(out, ["Output/Output interval=1e-4"])  # 21 snapshots, 00000 to 00020
ctx.check_true("a first run completes", p.returncode == 0, p.stderr)
before = digest(out)
ctx.check_true("it wrote snapshots and a manifest",
               "solution-00020.vtu" in before and ".hati-manifest" in before)
p = run(out, ["Time integration/Time step=3e-6"])
ok, err = one_line_error(p, "stability limit")
ctx.check_true("a run refused before its first step fails in one line", ok, err)
ctx.check_true("... and leaves every previous file as it was", digest(out) == before,
               "(%d files)" % len(before))

# --- only the files of the previous run are deleted ---
for name, text in (("solution-00042.vtu", "user's own file"), ("notes.txt", "notes")):
    with open(os.path.join(out, name), "w") as f:
        f.write(text)
p = run(out, ["Output/Output interval=0"])
ctx.check_true("a second run completes", p.returncode == 0, p.stderr)
with open(os.path.join(out, "solution-00042.vtu")) as f:
    ctx.check_true("a user's solution-00042.vtu survives", f.read() == "user's own file")
ctx.check_true("a user's notes.txt survives", os.path.exists(os.path.join(out, "notes.txt")))
left = [n for n in os.listdir(out) if n.startswith("solution")]
ctx.check_true("the previous run's snapshots and solution.pvd are deleted",
               left == ["solution-00042.vtu"], str(sorted(left)))
ctx.check_true("summary.json says completed", summary(out).get("status") == "completed")

# --- SIGTERM / SIGINT: complete, equal CSVs and "interrupted" ---
for sig, code in ((signal.SIGTERM, 143), (signal.SIGINT, 130)):
    name = signal.Signals(sig).name
    out = os.path.join(ctx.work, name.lower())
    shutil.rmtree(out, ignore_errors=True)
    proc = start(out, LONG)
    running = wait_running(out, rows=50)
    time.sleep(0.3)
    proc.send_signal(sig)
    try:
        proc.wait(timeout=30)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()
    err = proc.stderr.read().strip()
    ctx.check_true("%s: exit %d" % (name, code), running and proc.returncode == code,
                   "(exit %s) %s" % (proc.returncode, err))
    ctx.check_true("%s: one line on stderr saying interrupted" % name,
                   len(err.splitlines()) == 1 and "interrupted" in err, err)
    nh, okh = csv_complete(os.path.join(out, "history.csv"))
    ne, oke = csv_complete(os.path.join(out, "energy.csv"))
    ctx.check_true("%s: history.csv and energy.csv complete, %d and %d rows" % (name, nh, ne),
                   okh and oke and nh == ne and nh > 50)
    s = summary(out)
    ctx.check_true("%s: summary.json status interrupted" % name,
                   s.get("status") == "interrupted", str(s.get("status")))
    if "time_reached" in s:
        with open(os.path.join(out, "history.csv")) as f:
            last = float(f.read().splitlines()[-1].split(",")[0])
        # rows every 1e-5 s: the last row is at most one interval before
        ctx.check("%s: time_reached - last history time (s)" % name,
                  s["time_reached"] - last, 0.5e-5, abs_tol=0.5e-5 + 1e-12)
    else:
        ctx.check_true("%s: summary.json has time_reached" % name, False)
    # n_steps: the steps done (dt = 1e-6 s), not the 2e7 planned to t = 20 s
    done = round(s.get("time_reached", 0.0) / s.get("dt", 1.0))
    ctx.check_true("%s: n_steps %s = steps done to time_reached (%d), fewer than 2e7"
                   % (name, s.get("n_steps"), done),
                   s.get("n_steps") == done and 0 < done < 20000000)

# --- SIGKILL: complete lines and a valid PVD at any instant ---
out = os.path.join(ctx.work, "sigkill")
for attempt, delay in enumerate((0.0, 0.37, 0.81, 1.53)):
    shutil.rmtree(out, ignore_errors=True)
    proc = start(out, ["Time integration/End time=20", "Output/History interval=0",
                       "Output/Output interval=1e-5"])
    wait_running(out, rows=1)
    time.sleep(delay)
    proc.kill()
    proc.wait()
    bad = [] if wait_unlocked(out) else [".hati.lock still held"]
    for name in ("history.csv", "contacts.csv", "energy.csv"):
        n, ok = csv_complete(os.path.join(out, name))
        if not ok:
            bad.append(name)
    try:
        root = ET.parse(os.path.join(out, "solution.pvd")).getroot()
        files = [d.get("file") for d in root.iter("DataSet")]
        for f in files:
            ET.parse(os.path.join(out, f))  # complete XML
        pvd = "%d snapshots" % len(files)
    except (OSError, ET.ParseError) as e:
        bad.append("solution.pvd: %s" % e)
        pvd = ""
    ctx.check_true("SIGKILL %d (after %.2f s): CSVs on complete lines, valid PVD (%s)"
                   % (attempt + 1, delay, pvd), not bad, str(bad))

# --- SIGKILL of the process group at 40 random instants of a run appending
# 1 MiB blocks of rows ---
# (Linux cuts a large write() at a page boundary when the writer is killed:
# before the rows were appended by a child process, 1 kill in 5 to 10 left a
# cut line here; with a child in the run's process group, 2 group kills in
# 40, the child dying with the group). Each run in its own session, killed
# with os.killpg as a job scheduler does; four runs at a time (a start is
# mostly Open MPI waiting).


def tail_complete(path):
    """Whether the file ends on a whole line with the header's field count."""
    with open(path, "rb") as f:
        fields = f.readline().count(b",")
        f.seek(max(0, os.path.getsize(path) - 4096))
        tail = f.read()
    return tail.endswith(b"\n") and tail.splitlines()[-1].count(b",") == fields


def kill_at_random(attempt):
    out = os.path.join(ctx.work, "sigkill_random%02d" % attempt)
    shutil.rmtree(out, ignore_errors=True)
    proc = start(out, ["Time integration/End time=20", "Output/History interval=0",
                       "Output/Output interval=0"], new_session=True)
    started = wait_running(out, rows=1)
    time.sleep(delays[attempt])
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    if not started or not wait_unlocked(out):
        return ["%d: %s" % (attempt + 1, "no start" if not started else "lock held")]
    cut = ["%d: %s (%d bytes)" % (attempt + 1, name,
                                  os.path.getsize(os.path.join(out, name)))
           for name in ("history.csv", "contacts.csv", "energy.csv")
           if not tail_complete(os.path.join(out, name))]
    shutil.rmtree(out, ignore_errors=True)
    return cut


random.seed(19)
delays = [random.uniform(0.0, 0.5) for _ in range(40)]
t0 = time.time()
with concurrent.futures.ThreadPoolExecutor(4) as pool:
    cut = sum(pool.map(kill_at_random, range(40)), [])
ctx.check_true("SIGKILL of the process group at 40 random instants, a row every step: "
               "every CSV on whole lines (%.0f s)" % (time.time() - t0), not cut, str(cut))

# --- a symbolic link in the output folder is refused, its target untouched ---
# (all runs at once, each into its own folder, with its own victim file)
links = [(name, bar, ["Time integration/End time=1e-4", "Output/Output interval=5e-5"])
         for name in ("history.csv", "energy.csv", "contacts.csv", "summary.json",
                      ".summary.json.tmp", "parameters.prm", ".parameters.prm.tmp",
                      ".hati-manifest", ".hati.lock", "solution-00000.vtu",
                      "solution.pvd", ".solution.pvd.tmp", "contact_episodes.csv")]
links += [(name, ctx.prm("cantilever_modal.prm"), ["Analysis/Number of modes=2"])
          for name in ("modes.csv", "mode-002.vtu")]
VICTIM = b"a file outside the output folder\n"
runs = []
for k, (name, prm, sets) in enumerate(links):
    work = os.path.join(ctx.work, "link%02d" % k)
    shutil.rmtree(work, ignore_errors=True)
    out = os.path.join(work, "out")
    os.makedirs(out)
    # every third case: a link to a file that does not exist
    target = os.path.join(work, "missing.txt" if k % 3 == 2 else "victim.txt")
    with open(os.path.join(work, "victim.txt"), "wb") as f:
        f.write(VICTIM)
    os.symlink(target, os.path.join(out, name))
    runs.append((name, work, out, target, start(out, sets, prm)))
for name, work, out, target, proc in runs:
    try:
        proc.wait(timeout=120)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()
    ok, err = one_line_error(proc, os.path.join(out, name) + " is a symbolic link: refused")
    with open(os.path.join(work, "victim.txt"), "rb") as f:
        kept = f.read() == VICTIM and not os.path.exists(os.path.join(work, "missing.txt"))
    ctx.check_true("a link %s -> %s: refused in one line naming it, %s untouched"
                   % (name, os.path.basename(target), os.path.basename(target)),
                   ok and kept and os.path.islink(os.path.join(out, name)),
                   "(exit %s) %s" % (proc.returncode, err))

# --- Output/Section force interval far beyond the run (issue #24, 11) ---
# (std::lround overflowed: 1e20 s wrote a row at every history row)
frame = ctx.prm("portal_frame_elcentro.prm")
record = os.path.join(ctx.source, "data", "accelerograms", "RSN6_IMPVALL.I_I-ELC180.AT2")
quick = ["Time integration/End time=0.02", "Output/History interval=0.002",
         "Output/Output interval=0", "Loading/Accelerogram X=" + record]
for interval, expected in (("1e20", [0.0, 0.02]), ("0.01", [0.0, 0.01, 0.02])):
    out = os.path.join(ctx.work, "section_interval_" + interval)
    shutil.rmtree(out, ignore_errors=True)
    p = run(out, quick + ["Output/Section force interval=" + interval], prm=frame)
    times = []
    if p.returncode == 0:
        with open(os.path.join(out, "section_forces.csv")) as f:
            times = sorted({round(float(l.split(",")[0]), 9) for l in f.read().splitlines()[1:]})
    ctx.check_true("Section force interval = %s s: section_forces.csv rows at t = %s"
                   % (interval, expected), times == expected,
                   "(exit %d) times %s %s" % (p.returncode, times, p.stderr.strip()))

# --- a link at plot_suite.log is named as such (issue #24, 12) ---
# (posix_spawn fails to open it with O_NOFOLLOW: it said "python3 was not found")
work = os.path.join(ctx.work, "plot_log_link")
shutil.rmtree(work, ignore_errors=True)
out = os.path.join(work, "suite")
os.makedirs(out)
with open(os.path.join(work, "victim.txt"), "wb") as f:
    f.write(VICTIM)
os.symlink(os.path.join(work, "victim.txt"), os.path.join(out, "plot_suite.log"))
p = run(out, quick + ["Suite/Records=elc: " + record], prm=frame)
with open(os.path.join(work, "victim.txt"), "rb") as f:
    kept = f.read() == VICTIM
ctx.check_true("a link at plot_suite.log: the warning names the link, its target untouched",
               kept and os.path.join(out, "plot_suite.log") + " is a symbolic link" in p.stderr
               and "python3 was not found" not in p.stderr,
               "(exit %d) %s" % (p.returncode, p.stderr.strip()))

# --- a second concurrent run is refused ---
out = os.path.join(ctx.work, "concurrent")
shutil.rmtree(out, ignore_errors=True)
first = start(out, LONG)
wait_running(out)
p = run(out, LONG)
ok, err = one_line_error(p, "in use by another hati run", out)
ctx.check_true("a second run into the same directory is refused in one line", ok, err)
ctx.check_true("... and the first run's summary.json still says running",
               summary(out).get("status") == "running")
first.send_signal(signal.SIGTERM)
first.wait(timeout=30)
ctx.check_true("the first run then stops cleanly", first.returncode == 143,
               "(exit %s)" % first.returncode)

# --- a failure mid-run: "status": "failed" with the message ---
out = os.path.join(ctx.work, "failed")
shutil.rmtree(out, ignore_errors=True)
p = run(out, ["Time integration/Method=event-driven",
              "Time integration/Maximum number of events=5"], prm=ctx.prm("bouncing_ball.prm"))
ok, err = one_line_error(p, "Maximum number of events")
s = summary(out)
ctx.check_true("a run failing mid-run: one line", ok, err)
ctx.check_true("... summary.json says failed, with the message",
               s.get("status") == "failed" and "Maximum number of events" in s.get("message", ""),
               str(s))

# --- SIGPIPE: a closed standard output does not stop the run ---
out = os.path.join(ctx.work, "sigpipe")
shutil.rmtree(out, ignore_errors=True)
proc = subprocess.Popen(command(out, ["Output/Output interval=0"]), stdout=subprocess.PIPE,
                        stderr=subprocess.DEVNULL)
proc.stdout.readline()
proc.stdout.close()
proc.wait(timeout=600)
ctx.check_true("standard output closed after one line: the run completes",
               proc.returncode == 0 and summary(out).get("status") == "completed",
               "(exit %s)" % proc.returncode)

# --- the output folder vanishes during the run ---
out = os.path.join(ctx.work, "vanished")
shutil.rmtree(out, ignore_errors=True)
proc = start(out, LONG)
wait_running(out)
shutil.rmtree(out)
try:
    proc.wait(timeout=60)
except subprocess.TimeoutExpired:
    proc.kill()
    proc.wait()
ok, err = one_line_error(proc, "vanished", out)
ctx.check_true("a deleted output folder ends the run with one line", ok,
               "(exit %s) %s" % (proc.returncode, err))

# --- a full disk ---
disk = os.path.join(ctx.work, "tmpfs")
os.makedirs(disk, exist_ok=True)
subprocess.run(["umount", disk], capture_output=True)
mount = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=1m", "tmpfs", disk],
                       capture_output=True, text=True)
if mount.returncode != 0:
    print("skip the full-disk test: cannot mount a tmpfs here (%s)" % mount.stderr.strip())
else:
    try:
        out = os.path.join(disk, "out")
        p = run(out, ["Time integration/End time=0.2", "Output/History interval=0",
                      "Output/Output interval=0"])
        ok, err = one_line_error(p, "No space left on device", out)
        ctx.check_true("a full disk: non-zero exit, one line naming the file and the error",
                       ok, "(exit %d) %s" % (p.returncode, err))
        whole = {name: csv_complete(os.path.join(out, name))
                 for name in ("history.csv", "contacts.csv", "energy.csv")}
        ctx.check_true("a full disk: every CSV ends on a whole line (%s rows)"
                       % ", ".join("%s %d" % (n, r) for n, (r, _) in whole.items()),
                       all(ok for _, ok in whole.values()))
        s = summary(out)
        ctx.check_true("a full disk: summary.json says failed with the message",
                       s.get("status") == "failed" and
                       err == "hati: error: " + s.get("message", ""), str(s))
        # a suite on the full disk (issue #24, item 13): its failure is reported
        p = subprocess.run([ctx.hati, ctx.prm("portal_frame_elcentro.prm"),
                            "--set", "Output/Output directory=" + os.path.join(disk, "suite"),
                            "--set", "Time integration/End time=0.05",
                            "--set", "Output/Output interval=0",
                            "--set", "Suite/Scale factors=1, 2"],
                           capture_output=True, text=True, timeout=120, cwd=ctx.source)
        errors = [l for l in p.stderr.splitlines() if l.startswith("hati: error:")]
        ctx.check_true("a full disk, a suite: exit 1, one line with the system error",
                       p.returncode == 1 and len(errors) == 1 and
                       "No space left on device" in errors[0], "(exit %d) %s" % (p.returncode, errors))
    finally:
        subprocess.run(["umount", disk], capture_output=True)

# issue #59, finding 4: a records/ (artificial records) or modal/ (a suite's
# T1) that is a symbolic link is refused, its target untouched
for sub, sets in (("records", ["Artificial records/Number=1", "Artificial records/Duration=6",
                               "Artificial records/Strong motion=4",
                               "Artificial records/Time step=0.01",
                               "Artificial records/Components=X",
                               "Suite/Records=artificial"]),
                  ("modal", ["Suite/Scale factors=1, 2"])):
    out = os.path.join(ctx.work, "linked_" + sub)
    shutil.rmtree(out, ignore_errors=True)
    victim = os.path.join(ctx.work, "victim_" + sub)
    shutil.rmtree(victim, ignore_errors=True)
    os.makedirs(out)
    os.makedirs(victim)
    os.symlink(victim, os.path.join(out, sub))
    p = subprocess.run(command(out, ["Time integration/End time=0.05", "Output/Output interval=0",
                                     "Design spectrum/Type=EC8 type 1",
                                     "Design spectrum/Peak ground acceleration=3",
                                     "Design spectrum/Period range=0.05, 1"] + sets,
                               prm=ctx.prm("portal_frame_elcentro.prm")),
                       capture_output=True, text=True, timeout=300, cwd=ctx.source,
                       env=environment())
    ctx.check_true("a linked %s/ refused naming it, its target empty" % sub,
                   p.returncode != 0 and os.path.join(out, sub) + " is a symbolic link" in p.stderr
                   and os.listdir(victim) == [], "(exit %d) %s" % (p.returncode, p.stderr.strip()[-300:]))
ctx.finish()
