#!/usr/bin/python3
"""The version stamp (include/hati/base/version.h): `hati --version` and
summary.json `git_commit` name the commit of the source tree the build was
configured from, against `git rev-parse --short=12 HEAD` of the source
directory run here (an independent reading of the checkout; "-dirty" when
the tree had changes at configure time, which the comparison leaves out),
or "unknown" where the source is not a git checkout."""
import os
import shutil
import subprocess

from hati_test import Context, read_summary

ctx = Context()
expected = "unknown"
if shutil.which("git"):
    p = subprocess.run(["git", "-C", ctx.source, "rev-parse", "--short=12", "HEAD"],
                       capture_output=True, text=True)
    if p.returncode == 0 and p.stdout.strip():
        expected = p.stdout.strip()
print("source tree commit:", expected)

p = subprocess.run([ctx.hati, "--version"], capture_output=True, text=True, timeout=60)
ctx.check_true("hati --version exits with 0", p.returncode == 0, p.stderr.strip())
line = p.stdout.strip()
prefix = "hati, git commit "
ctx.check_true("hati --version prints 'hati, git commit <commit>'",
               line.startswith(prefix), "(%s)" % line)
stamp = line[len(prefix):]
ctx.check_true("the stamp is the source tree's commit", stamp.split("-dirty")[0] == expected,
               "(stamp %s, tree %s)" % (stamp, expected))

out, _ = ctx.run(ctx.prm("cantilever_static.prm"), "static")
ctx.check_true("summary.json git_commit = hati --version's",
               read_summary(out).get("git_commit") == stamp,
               "(%s)" % read_summary(out).get("git_commit"))
ctx.finish()
