#!/usr/bin/python3
"""Data-driven bad-input test: every case of test_cases/bad_inputs/cases.ini
(a parameter file, --set overrides, further arguments) must end with the
expected exit code and exactly one line on stderr, "hati: error: ...",
containing every expected fragment; and, validate-then-write, a case that
fails before its first step must not create its output directory."""
import configparser
import os
import shutil
import subprocess
import time

from hati_test import Context

ctx = Context()
cases = configparser.ConfigParser(interpolation=None, delimiters=("=",),
                                  comment_prefixes=("#",), empty_lines_in_values=False)
cases.optionxform = str
table = os.path.join(ctx.source, "test_cases", "bad_inputs", "cases.ini")
with open(table) as f:
    cases.read_file(f)


def available_gb():
    with open("/proc/meminfo") as f:
        for line in f:
            if line.startswith("MemAvailable:"):
                return float(line.split()[1]) * 1024 / 1e9
    return 0.0


def lines(case, key):
    return [l.strip() for l in case.get(key, "").splitlines() if l.strip()]


ctx.check_true("the table holds cases", len(cases.sections()) >= 30,
               "(%d cases in %s)" % (len(cases.sections()), table))
for index, name in enumerate(cases.sections()):
    case = cases[name]
    if "skip above GB" in case and available_gb() > float(case["skip above GB"]):
        print("skip %s: %.0f GB available, more than %s" % (name, available_gb(),
                                                          case["skip above GB"]))
        continue
    work = os.path.join(ctx.work, "case%02d" % index)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    out = os.path.join(work, "out")
    cmd = [ctx.hati]
    if "file" in case:
        cmd.append(case["file"])
    cmd += ["--set", "Output/Output directory=" + out]
    for s in lines(case, "set"):
        cmd += ["--set", s.replace("{work}", work)]
    cmd += [a.replace("{work}", work) for a in lines(case, "args")]
    start = time.monotonic()
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=300, cwd=ctx.source)
    seconds = time.monotonic() - start
    err = p.stderr.strip()
    expected_exit = int(case.get("exit", "1"))
    missing = [f for f in lines(case, "contains") if f not in err]
    one_line = len(err.splitlines()) == 1 and err.startswith("hati: error:")
    untouched = case.get("touches output", "no") == "yes" or not os.path.exists(out)
    quick = "at most seconds" not in case or seconds <= float(case["at most seconds"])
    ok = p.returncode == expected_exit and one_line and not missing and untouched and quick
    detail = "(exit %d, expected %d)" % (p.returncode, expected_exit)
    if not quick:
        detail += " slower than %s s" % case["at most seconds"]
    if missing:
        detail += " missing %s" % missing
    if not untouched:
        detail += " created the output directory"
    ctx.check_true(name, ok, "%s %s (%.2f s)" % (detail, err, seconds))
ctx.finish()
