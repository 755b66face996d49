#!/usr/bin/python3
"""The qualification of a run end to end (issue #54): the crane of
bridge_crane_hati.prm for 0.3 s of its record with a Qualification
subsection whose rope capacity lies below the rope's static tension
(200 kN against 199.6 kN static and more under the record) and generous
other capacities:
- the run exits with 0 (a failed check is a result) and ends with the
  verdict table and the closing line "hati: qualification: 1 of N checks
  fail (hoist_rope rope ratio ...)";
- qualification.csv has the columns of the contract and one row per
  checked item: a stress row per beam member of summary.json beam_stresses
  (the rigid posts have none), an uplift row per one-sided contact, a
  lateral-offset row per wheel, the rope; each row's demand, capacity and
  ratio equal summary.json's qualification rows and the summary's own
  results (beam_stresses ... max_von_mises, contacts ... max_uplift, wheels
  ... max_lateral_offset, rope_tension ... max) to 1e-9;
- report.html passes the checks of test_cases/report.py (well-formed, every
  picture embedded, the verdict table equal to qualification.csv, nothing
  fetched from elsewhere), with the frame drawn from geometry.csv;
- a suite of three scale factors (bridge_crane_suite.prm for 0.05 s):
  each group's statistic checked, the demand equal to suite_summary.json's
  value, where its governing member and its group;
- a static analysis with the same Qualification is not checked: it runs,
  writes no qualification.csv and warns "Qualification is ignored".
"""
import csv
import json
import os
import sys

from hati_test import Context, read_summary

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import report  # noqa: E402  (test_cases/report.py: check_report)

ctx = Context()
capacities = ["Qualification/Yield strength=235e6", "Qualification/Maximum uplift=0.025",
              "Qualification/Maximum lateral play=0.03", "Qualification/Rope capacity=2e5"]
records = os.path.join(ctx.source, "data", "accelerograms")
out, p = ctx.run(ctx.prm("bridge_crane_hati.prm"), "run",
                 capacities + ["Time integration/End time=0.3",
                               "Output/Output interval=0",
                               "Loading/Accelerogram X=" + os.path.join(records, "Rinaldi228.AT2"),
                               "Loading/Accelerogram Z=" + os.path.join(records, "RinaldiUP.AT2")])
ctx.check_true("exit code 0 with a failing check", p.returncode == 0)
last = p.stdout.strip().splitlines()[-1]
ctx.check_true("the closing line is the last line",
               last.startswith("hati: qualification: 1 of ") and
               "checks fail (hoist_rope rope ratio 1.0" in last, last)
ctx.check_true("the verdict table is printed", "qualification (qualification.csv):" in p.stdout)

s = read_summary(out)
rows = list(csv.DictReader(open(out + "/qualification.csv")))
ctx.check_true("qualification.csv columns",
               list(rows[0].keys()) == ["check", "item", "demand", "capacity", "unit", "ratio",
                                        "verdict", "where"], str(list(rows[0].keys())))
q = s["qualification"]
ctx.check_true("summary.json qualification: passes false, 1 failing row",
               q["passes"] is False and q["n_fail"] == 1 and q["n_checks"] == len(rows))
expected = {("stress", m): e["max_von_mises"]["value"] for m, e in s["beam_stresses"].items()}
expected.update({("uplift", c): e["max_uplift"] for c, e in s["contacts"].items()
                 if "max_uplift" in e})
expected.update({("lateral offset", w): e["max_lateral_offset"]
                 for w, e in s["wheels"].items()})
expected.update({("rope", r): e["max"] for r, e in s["rope_tension"].items()})
ctx.check_true("one row per checked item (stress per member, uplift per one-sided contact, "
               "lateral offset per wheel, rope)",
               sorted((r["check"], r["item"]) for r in rows) == sorted(expected),
               "%d rows, %d expected" % (len(rows), len(expected)))
ctx.check_true("no stress row of a rigid post", not any("post" in r["item"] for r in rows))
capacity = {"stress": 0.9 * 235e6, "uplift": 0.025, "lateral offset": 0.03, "rope": 2e5}
for r, j in zip(rows, q["rows"]):
    key = (r["check"], r["item"])
    if key not in expected:
        continue
    demand = expected[key]
    ctx.check("%s %s demand = summary.json result" % key, float(r["demand"]), demand,
              rel=1e-9, abs_tol=1e-300)
    ctx.check("%s %s capacity" % key, float(r["capacity"]), capacity[r["check"]], rel=1e-12)
    ctx.check("%s %s ratio = demand / capacity" % key, float(r["ratio"]),
              demand / capacity[r["check"]], rel=1e-9, abs_tol=1e-300)
    ctx.check_true("%s %s verdict (csv = json = ratio <= 1)" % key,
                   r["verdict"] == j["verdict"] ==
                   ("pass" if demand <= capacity[r["check"]] else "fail"))
ctx.check_true("geometry.csv drawn from the model",
               os.path.isfile(out + "/geometry.csv") and
               open(out + "/geometry.csv").readline().strip() == "member,x1,y1,z1,x2,y2,z2")


class Checks:
    def __init__(self):
        self.failures = 0

    def __call__(self, what, ok, detail=""):
        ctx.check_true("report: " + what, ok, detail)
        self.failures += 0 if ok else 1


report.check_report(out, Checks())

# a suite of three scale factors (bridge_crane_suite.prm, 0.05 s of each
# record): each group's statistic (the envelope) checked, where its
# governing member and its group; demand = suite_summary.json's value
out, p = ctx.run(ctx.prm("bridge_crane_suite.prm"), "suite",
                 ["Qualification/Rope capacity=2.0e5", "Qualification/Maximum uplift=0.025",
                  "Time integration/End time=0.05",
                  "Suite/Records=elcentro: %s, , ; rinaldi: %s, , %s"
                  % (os.path.join(records, "RSN6_IMPVALL.I_I-ELC180.AT2"),
                     os.path.join(records, "Rinaldi228.AT2"),
                     os.path.join(records, "RinaldiUP.AT2"))])
s = json.load(open(out + "/suite_summary.json"))
rows = list(csv.DictReader(open(out + "/qualification.csv")))
groups = s["groups"]
per_group = [q for q in groups[0]["quantities"]
             if q.endswith(".max_uplift") or q.endswith(".max_tension")]
ctx.check_true("suite: a row per group and checked quantity",
               len(rows) == len(groups) * len(per_group) and len(groups) == 3,
               "%d rows, %d groups x %d quantities" % (len(rows), len(groups), len(per_group)))
for k, g in enumerate(groups):
    for j, quantity in enumerate(per_group):
        r = rows[k * len(per_group) + j]
        q = g["quantities"][quantity]
        ctx.check("suite %s scale %g: demand = the group's statistic" % (quantity, g["scale"]),
                  float(r["demand"]), q["value"], rel=1e-9, abs_tol=1e-300)
        ctx.check_true("suite %s scale %g: where names the governing member and the group"
                       % (quantity, g["scale"]),
                       r["where"] == "governing member %s (scale %g)"
                       % (q["governing_member"], g["scale"]), r["where"])
ctx.check_true("suite: report.html written", os.path.isfile(out + "/report.html"))

# a static analysis: the checks are ignored with a warning
out, p = ctx.run(ctx.prm("bridge_crane_static.prm"), "static", capacities)
s = read_summary(out)
ctx.check_true("static: no qualification.csv", not os.path.exists(out + "/qualification.csv"))
ctx.check_true("static: warning 'Qualification is ignored'",
               any(w.startswith("Qualification is ignored: a static analysis")
                   for w in s.get("warnings", [])), str(s.get("warnings")))
ctx.finish()
