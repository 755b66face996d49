#!/usr/bin/python3
"""scripts/report.py, the self-contained qualification report (report.html),
against fixture folders written here in the formats hati writes (the
contacts.csv header and the parameters.prm layout of a run of
bridge_crane_hati.prm; summary.json with qualification, wheels,
beam_stresses and solids; qualification.csv; geometry.csv; runway_loads.csv;
a suite folder with suite.csv, suite_summary.json, suite_spectra.csv,
rsa_comparison.csv and two members):

1. a complete run: exit code 0, report.html parsed by html.parser with
   every tag closed in order (void elements aside), no <script>, <link>,
   <iframe>, <object>, <embed> or <base>; every <img> a
   data:image/png;base64 URI that decodes to a PNG; no attribute and no
   url(...) of a style referring to http:, https:, file: or any file (a
   src, href... must be a data: URI); the verdict table row by row the
   rows of qualification.csv (item, verdict, and the data-value of
   demand, capacity and ratio the exact CSV text; the row's class
   "verdict-row pass|fail" its verdict); the overall verdict FAIL with the
   count of failing rows; no temporary file left;
2. the same run without its optional files (geometry.csv, contacts.csv,
   runway_loads.csv, qualification.csv): a report all the same, one line
   for each missing file, the verdict table then from summary.json
   qualification.rows;
3. a suite: the same checks, the EC8 verdict line, the response-spectrum
   comparison drawn, the first completed member's wheels;
4. a folder without summary.json: exit code 1 and one line on stderr;
5. where a headless browser is on the PATH (chromium, chromium-browser,
   google-chrome), its screenshot of the report is a PNG of more than
   10 kB; otherwise "skipped: no headless browser".

check_report(folder) holds the checks of 1 (and 5) for any output folder
with a report.html.

Usage: test_cases/report.py HATI SOURCE_DIR WORK_DIR  (ctest; HATI unused)
       test_cases/report.py BUILD_DIR                 (work in BUILD_DIR/test_cases/report)
       test_cases/report.py OUTPUT_FOLDER             (a real run's or suite's folder:
                                                       report.py on it, then check_report)"""
import base64
import csv
import html.parser
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

VOID = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "param",
        "source", "track", "wbr"}
FORBIDDEN_TAGS = {"script", "link", "iframe", "object", "embed", "base", "frame", "applet"}
REFERENCE_ATTRIBUTES = {"src", "href", "action", "formaction", "poster", "background", "cite",
                        "data", "srcset", "longdesc", "manifest", "xlink:href", "ping",
                        "lowsrc", "dynsrc", "codebase"}
EXTERNAL = re.compile(r"\b(https?|file|ftp)\s*:", re.I)
URL = re.compile(r"url\(\s*(['\"]?)(.*?)\1\s*\)", re.I | re.S)
IMPORT = re.compile(r"@import", re.I)
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
BROWSERS = ("chromium", "chromium-browser", "google-chrome")


class Checker:
    """check(what, condition, detail) printing ok/FAIL and counting failures
    (or hati_test.Context.check_true)."""

    def __init__(self):
        self.failures = 0

    def __call__(self, what, condition, detail=""):
        self.failures += 0 if condition else 1
        print("%-4s %s %s" % ("ok" if condition else "FAIL", what, detail))


class Page(html.parser.HTMLParser):
    """The structure of a page: its tag errors, images, references, the verdict rows."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.stack, self.errors, self.images, self.references = [], [], [], []
        self.forbidden, self.styles = [], []
        self.rows = []  # verdict rows: {"class": ..., "cells": {column: (text, data-value)}}
        self.in_verdicts = 0  # depth of the open table id="verdicts" (0: outside)
        self.cell = None
        self.text = []

    def handle_starttag(self, tag, attrs):
        self.check_attributes(tag, attrs)
        a = dict(attrs)
        if tag not in VOID:
            self.stack.append(tag)
        if tag == "table" and a.get("id") == "verdicts":
            self.in_verdicts = len(self.stack)
        if self.in_verdicts and tag == "tr" and "verdict-row" in (a.get("class") or "").split():
            self.rows.append({"class": a.get("class"), "cells": {}})
        if self.in_verdicts and tag == "td" and self.rows:
            column = next((c[4:] for c in (a.get("class") or "").split()
                           if c.startswith("col-")), None)
            self.cell = (column, a.get("data-value"), [])

    def handle_startendtag(self, tag, attrs):
        self.check_attributes(tag, attrs)
        if tag not in VOID:  # <div/> is not a closed div in HTML
            self.errors.append("self-closing <%s/>" % tag)

    def handle_endtag(self, tag):
        if tag in VOID:
            self.errors.append("end tag </%s> of a void element" % tag)
            return
        if not self.stack or self.stack[-1] != tag:
            self.errors.append("</%s> closes <%s> (line %d)" % (
                tag, self.stack[-1] if self.stack else "nothing", self.getpos()[0]))
            if tag in self.stack:
                while self.stack and self.stack.pop() != tag:
                    pass
            return
        self.stack.pop()
        if tag == "td" and self.cell is not None:
            column, value, text = self.cell
            if column:
                self.rows[-1]["cells"][column] = ("".join(text).strip(), value)
            self.cell = None
        if tag == "table" and self.in_verdicts and len(self.stack) < self.in_verdicts:
            self.in_verdicts = 0

    def handle_data(self, data):
        self.text.append(data)
        if self.cell is not None:
            self.cell[2].append(data)
        if self.stack and self.stack[-1] == "style":
            self.styles.append(data)

    def check_attributes(self, tag, attrs):
        if tag in FORBIDDEN_TAGS:
            self.forbidden.append(tag)
        for name, value in attrs:
            value = value or ""
            if name.startswith("on"):
                self.forbidden.append("%s attribute %s" % (tag, name))
            if tag == "img" and name == "src":
                self.images.append(value)
            if name in REFERENCE_ATTRIBUTES and not value.startswith("data:"):
                self.references.append("%s %s=%r" % (tag, name, value[:80]))
            elif EXTERNAL.search(value) and not value.startswith("data:"):
                self.references.append("%s %s=%r" % (tag, name, value[:80]))
            if name == "style":
                self.styles.append(value)


def style_references(styles):
    found = []
    for s in styles:
        found += ["url(%s)" % u[:60] for _, u in URL.findall(s) if not u.startswith("data:")]
        if IMPORT.search(s):
            found.append("@import")
        if EXTERNAL.search(URL.sub("", s)):
            found.append("an external reference in a style")
    return found


def parse_report(path):
    page = Page()
    with open(path, encoding="utf-8") as f:
        page.feed(f.read())
    page.close()
    return page


def expected_rows(folder):
    """The rows the verdict table must show: qualification.csv's, else the
    summary's qualification.rows (each value as JSON text); None if neither."""
    path = os.path.join(folder, "qualification.csv")
    if os.path.isfile(path):
        with open(path, newline="") as f:
            return list(csv.DictReader(f))
    for name in ("summary.json", "suite_summary.json"):
        p = os.path.join(folder, name)
        if os.path.isfile(p):
            with open(p) as f:
                q = json.load(f).get("qualification")
            if isinstance(q, dict) and isinstance(q.get("rows"), list):
                return [{k: "" if v is None else str(v) for k, v in r.items()} for r in q["rows"]]
    return None


def check_report(folder, check=None, browser=True):
    """The checks of report.html in @folder; returns the number of failures
    (each printed by @check: a Checker by default)."""
    check = check or Checker()
    before = getattr(check, "failures", 0)
    path = os.path.join(folder, "report.html")
    check("report.html written", os.path.isfile(path), path)
    if not os.path.isfile(path):
        return getattr(check, "failures", 1) - before
    check("no temporary file left", not os.path.exists(os.path.join(folder, ".report.html.tmp")))
    page = parse_report(path)
    check("html.parser: every tag closed in order", not page.errors and not page.stack,
          "; ".join(page.errors[:5] + (["open at the end: %s" % page.stack] if page.stack
                                       else [])))
    check("no script, link, iframe, object, embed, base nor on... handler", not page.forbidden,
          ", ".join(page.forbidden[:5]))
    bad = []
    for src in page.images:
        prefix = "data:image/png;base64,"
        try:
            data = base64.b64decode(src[len(prefix):], validate=True)
        except ValueError as e:
            data = b""
            bad.append("%s... does not decode (%s)" % (src[:40], e))
            continue
        if not src.startswith(prefix) or not data.startswith(PNG_MAGIC):
            bad.append("%s..." % src[:40])
    check("every <img> an embedded PNG (data:image/png;base64, magic bytes)", not bad,
          "%d images; %s" % (len(page.images), "; ".join(bad[:3])))
    references = page.references + style_references(page.styles)
    check("no reference to http:, https:, file: or a file (src, href, url(...))",
          not references, "; ".join(references[:5]))
    text = " ".join("".join(page.text).split())
    for heading in ("Model", "Input", "Verdicts", "Response-spectrum comparison", "Wheels",
                    "Stresses", "Provenance"):
        check("section %s" % heading, heading in text)
    rows = expected_rows(folder)
    if rows is None:
        check("no qualification: the report says so", "no qualification.csv" in text)
        check("no qualification: no verdict row", not page.rows)
    else:
        check("the verdict table has a row per qualification row", len(page.rows) == len(rows),
              "%d rows, %d expected" % (len(page.rows), len(rows)))
        mismatches = []
        for i, (shown, row) in enumerate(zip(page.rows, rows)):
            cells = shown["cells"]
            verdict = row.get("verdict", "").strip()
            if cells.get("item", ("",))[0] != " ".join(row.get("item", "").split()):
                mismatches.append("row %d item %r != %r" % (i, cells.get("item"), row["item"]))
            if cells.get("verdict", ("",))[0] != verdict:
                mismatches.append("row %d verdict %r != %r" % (i, cells.get("verdict"), verdict))
            for column in ("demand", "capacity", "ratio"):
                if cells.get(column, (None, None))[1] != row.get(column, ""):
                    mismatches.append("row %d %s data-value %r != %r" % (
                        i, column, cells.get(column, (None, None))[1], row.get(column)))
            if shown["class"].split() != ["verdict-row", verdict]:
                mismatches.append("row %d class %r, verdict %r" % (i, shown["class"], verdict))
        check("the verdict rows are the qualification rows (item, verdict, data-value of "
              "demand, capacity, ratio, class)", not mismatches, "; ".join(mismatches[:4]))
        n_fail = sum(1 for r in rows if r.get("verdict", "").strip() == "fail")
        overall = ("FAIL: %d of %d checks fail" % (n_fail, len(rows)) if n_fail
                   else "PASS: all %d checks pass" % len(rows) if rows
                   else "NO CHECK: the qualification has no row")
        check("the overall verdict line: %s" % overall, overall in text)
    if browser:
        screenshot(path, check)
    return getattr(check, "failures", 0) - before


def screenshot(path, check):
    browser = next((b for b in BROWSERS if shutil.which(b)), None)
    if browser is None:
        print("skipped: no headless browser (%s)" % ", ".join(BROWSERS))
        return
    with tempfile.TemporaryDirectory(prefix="hati-report-shot-") as tmp:
        shot = os.path.join(tmp, "shot.png")
        try:
            p = subprocess.run([browser, "--headless", "--disable-gpu", "--no-sandbox",
                                "--user-data-dir=" + os.path.join(tmp, "profile"),
                                "--screenshot=" + shot, "--window-size=1200,900",
                                "file://" + os.path.abspath(path)],
                               capture_output=True, text=True, timeout=60)
            detail = "exit code %d" % p.returncode
        except subprocess.TimeoutExpired:
            detail = "timed out after 60 s"
        size = os.path.getsize(shot) if os.path.isfile(shot) else 0
        with open(shot, "rb") if size else open(os.devnull, "rb") as f:
            magic = f.read(8)
        check("%s --headless screenshot of the report: a PNG of more than 10 kB" % browser,
              size > 10000 and magic == PNG_MAGIC, "(%d bytes, %s)" % (size, detail))


# ---------------------------------------------------------------- fixtures

PARAMETERS = """# Listing of Parameters
# ---------------------
subsection Analysis
  # transient: start from the model's initial displacement and velocity
  # (given) or at rest from the static equilibrium under the constant loads
  set Initial state      = static    # default: given

  set Type               = transient
end


subsection Loading
  # PEER AT2 file of the ground acceleration along X (m/s^2 or g).
  set Accelerogram X            = data/accelerograms/Rinaldi228.AT2 # default: 
  set Gravity                   = 0, 0, -9.81
end


subsection Model
  set Type = bridge crane # default: point mass

  subsection Bridge crane
    set Span                       = 20
    set Trolley position           = 0.3                                                # default: 0.5
  end

end


subsection Qualification
  set Rail head capacity = 2.5e5 # default: 0
end


subsection Time integration
  set End time                 = 0.05  # default: 1
  set Method                   = HATI  # default: CD-Lagrange
  set Time step                = 8e-5  # default: 1e-3

  subsection HATI
    set Time step ratio = 1            # default: 10
  end

end


"""

# a small crane: two girders along X, two end carriages along Y, the trolley
# and its rope (metres)
GEOMETRY = [("girder_1", 0, 0, 10, 5, 0, 10), ("girder_1", 5, 0, 10, 10, 0, 10),
            ("girder_2", 0, 2, 10, 5, 2, 10), ("girder_2", 5, 2, 10, 10, 2, 10),
            ("end_carriage_1", 0, -0.5, 10, 0, 2.5, 10),
            ("end_carriage_2", 10, -0.5, 10, 10, 2.5, 10),
            ("trolley_1", 3, 0, 10.4, 3, 2, 10.4), ("trolley_2", 4, 0, 10.4, 4, 2, 10.4),
            ("hoist_rope", 3.5, 1, 10.4, 3.5, 1, 4)]

QUALIFICATION = [
    # check, item, demand, capacity, unit, ratio, verdict, where
    ("wheel load", "crane_wheel_1", "107538.14014711413", "250000", "N",
     "0.43015256058845652", "pass", "t = 0.00112 s"),
    ("girder stress", "girder_1, midspan", "2.3456789012e+08", "2.35e8", "Pa",
     "0.99816123455319149", "pass", "x = 6.9 m & t = 0.05 s"),
    ("uplift", "trolley_wheel_3", "0.0123", "0.01", "m", "1.23", "fail",
     "trolley_wheel_3 <flange>"),
]

WHEELS = ["crane_wheel_1", "crane_wheel_2", "trolley_wheel_1", "trolley_wheel_2"]


def write(path, text):
    with open(path, "w") as f:
        f.write(text)


def contacts_csv(t_end=0.05, dt=0.00048):
    """The rows of contacts.csv (the header of a run with friction): every
    wheel and its lateral contact per output time; trolley_wheel_1 lifts off
    between 0.02 and 0.03 s and crane_wheel_1 slips."""
    lines = ["time,contact,gap,normal_velocity,impulse,force,active,tangential_impulse,"
             "slip_velocity,state"]
    n = int(round(t_end / dt))
    for i in range(1, n + 1):
        t = i * dt
        for k, w in enumerate(WHEELS):
            lifted = w == "trolley_wheel_1" and 0.02 < t < 0.03
            gap = 1e-3 * (t - 0.02) * (0.03 - t) / 2.5e-5 if lifted else 2.75e-13
            force = 0.0 if lifted else (1.0754e5 if k < 2 else 5.916e4) * (1 + 0.01 * k * t)
            slip = 0.002 if w == "crane_wheel_1" and t > 0.01 else 0.0
            lines.append("%r,%s,%r,0,%r,%r,%d,%r,%r,%s" % (
                t, w, gap, force * 8e-5, force, 0 if lifted else 1, 1e-4 * force * 8e-5, slip,
                "open" if lifted else ("slip" if slip else "stick")))
            lines.append("%r,%s_lateral,0.0069551650075503095,0,0,0,0,0,0,open" % (t, w))
    return "\n".join(lines) + "\n"


def summary_json(rows, passes, extra=None):
    wheels = {}
    for k, w in enumerate(WHEELS):
        wheels[w] = {"n_impacts": 1 if w == "trolley_wheel_1" else 0,
                     "peak_mean_force": 107538.14 + k, "uplift_time": 0.01 if k == 2 else 0.0,
                     "max_uplift": 1e-3 if k == 2 else 2.75e-13,
                     "slip_distance": 8e-5 if k == 0 else 0.0,
                     "max_lateral_offset": 0.003 + 1e-4 * k}
    summary = {"method": "HATI",
               "model": "bridge crane: span 10 m (report test fixture), trolley at 0.3 of the "
                        "span; 3D frame: 9 elements",
               "wall_time": 12.345678, "git_commit": "835d971af637",
               "wheels": wheels,
               "beam_stresses": {"girder_1": {
                   "max_normal_stress": {"value": 2.3456789012e8, "x": 6.9, "time": 0.05},
                   "max_von_mises": {"value": 2.41e8, "x": 6.9, "time": 0.05}},
                   "girder_2": {
                       "max_normal_stress": {"value": 1.2e8, "x": 3.0, "time": 0.04},
                       "max_von_mises": {"value": 1.3e8, "x": 3.0, "time": 0.04}}},
               "solids": {"girder_box_1": {"max_von_mises": {
                   "value": 1.9e8, "time": 0.031, "point": [6.9, 0.1, 10.2]}}},
               "qualification": {"rows": [dict(zip(
                   ("check", "item", "demand", "capacity", "unit", "ratio", "verdict", "where"),
                   (r[0], r[1], float(r[2]), float(r[3]), r[4], float(r[5]), r[6], r[7])))
                   for r in rows], "passes": passes},
               "warnings": [], "status": "completed"}
    summary.update(extra or {})
    return json.dumps(summary, indent=2)


def run_fixture(folder):
    os.makedirs(folder)
    write(os.path.join(folder, "parameters.prm"), PARAMETERS)
    write(os.path.join(folder, "summary.json"), summary_json(QUALIFICATION, False))
    with open(os.path.join(folder, "qualification.csv"), "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["check", "item", "demand", "capacity", "unit", "ratio", "verdict", "where"])
        w.writerows(QUALIFICATION)
    write(os.path.join(folder, "geometry.csv"), "member,x1,y1,z1,x2,y2,z2\n" + "".join(
        "%s,%s\n" % (g[0], ",".join(repr(float(x)) for x in g[1:])) for g in GEOMETRY))
    write(os.path.join(folder, "contacts.csv"), contacts_csv())
    write(os.path.join(folder, "runway_loads.csv"),
          "wheel,vertical_max,vertical_max_time,vertical_min,vertical_min_time,lateral_max,"
          "lateral_max_time,longitudinal_max,longitudinal_max_time\n"
          "crane_wheel_1,107538.1401,0.00112,107499.3778,0.03504,0,0,272.6180441,0.05\n"
          "crane_wheel_2,107651.5176,0.05,107539.612,0.00272,0,0,214.238528,0.05\n")


def spectra_rows(columns, scale=1.0):
    rows = []
    for xi in (0.02, 0.05):
        for i in range(20):
            period = 0.02 * (200 ** (i / 19))
            rows.append([xi, period] + [scale * (1 + j) * 3.0 / (1 + period) for j in
                                        range(len(columns))])
    return rows


def write_csv(path, header, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(header)
        w.writerows(rows)


def suite_fixture(folder, run):
    """A suite of two members (copies of the run @run), the second failed."""
    os.makedirs(folder)
    members = [("rec01_s1_0", "completed"), ("rec02_s1_0", "failed")]
    write_csv(os.path.join(folder, "suite.csv"),
              ["member", "record", "scale", "variation", "status", "error", "wall_time",
               "crane_wheel_1.peak_mean_force"],
              [[m, m[:5], 1, 0, s, "" if s == "completed" else "diverged", 1.5, 107538.14]
               for m, s in members])
    channels = ["hoist.x", "hoist.z", "ground.x", "ground.z"]
    for m, s in members:
        member = os.path.join(folder, m)
        shutil.copytree(run, member)
        os.unlink(os.path.join(member, "qualification.csv"))
        write_csv(os.path.join(member, "spectra.csv"), ["damping_ratio", "period"] + channels,
                  spectra_rows(channels))
        write(os.path.join(member, "input_digests.txt"),
              "Loading/Accelerogram X = %s/records/%s_X.AT2: fnv1a64 5aed81a67064a2b2, "
              "69057 bytes\n" % (folder, m[:5]))
    os.unlink(os.path.join(folder, members[0][0], "geometry.csv"))  # the first with one: 2nd
    write_csv(os.path.join(folder, "suite_spectra.csv"),
              ["scale", "variation", "damping_ratio", "period"] + channels,
              [[1, 0] + r for r in spectra_rows(channels, 1.1)])
    periods = [0.1 * (10 ** (i / 9)) for i in range(10)]
    write_csv(os.path.join(folder, "design_spectrum_check.csv"),
              ["period", "target.x", "mean.x", "ratio.x"],
              [[t, 7.5, 7.0, 7.0 / 7.5] for t in periods])
    write_csv(os.path.join(folder, "rsa_comparison.csv"),
              ["quantity", "unit", "time_history", "response_spectrum", "ratio"],
              [["crane_wheel_1.peak_mean_force", "N", 107789, 146652, 1.3605],
               ["section_force.My", "N m", 566760, 752980, 1.3286],
               ["hoist.max_absolute_acceleration", "m/s^2", 0.299, 9.2, 30.77]])
    check = {"target": {"X": "EC8 type 1, ground type C, a_g = 3 m/s^2, 5 % damping, "
                             "horizontal"},
             "damping_ratio": 0.05, "statistic": "mean", "scale": 1.0,
             "fundamental_period": 0.5, "fundamental_period_source": "Suite/Fundamental period",
             "period_range_checked": [0.1, 1.0], "periods": periods,
             "components": {"X": {"records": ["rec01"], "n_records": 1,
                                  "enough_records": False, "min_ratio": 0.9333,
                                  "period_of_min_ratio": 0.1, "passes_ec8_90_percent": True,
                                  "mean_pga": 3.5, "target_pga": 3.45,
                                  "pga_not_below_target": True}},
             "passes_ec8": False,
             "reasons": ["X: 1 record, EN 1998-1 3.2.3.1.2 asks for at least 3"]}
    rows = [QUALIFICATION[0], QUALIFICATION[1]]
    write(os.path.join(folder, "suite_summary.json"), json.dumps({
        "wall_time": 3.2, "design_spectrum_check": check,
        "rsa_comparison": {"time_history_statistic": "mean",
                           "response_spectrum_folder": folder + "/response_spectrum",
                           "quantities": {}},
        "statistic": "mean", "n_members": 2, "n_usable": 1, "n_failed": 1,
        "failed": ["rec02_s1_0"], "groups": [],
        "qualification": {"rows": [], "passes": True}}, indent=2))
    write_csv(os.path.join(folder, "qualification.csv"),
              ["check", "item", "demand", "capacity", "unit", "ratio", "verdict", "where"], rows)


def run_report(source, folder):
    start = time.monotonic()
    p = subprocess.run(["/usr/bin/python3" if os.path.exists("/usr/bin/python3") else "python3",
                        os.path.join(source, "scripts", "report.py"), folder],
                       capture_output=True, text=True, timeout=300)
    print("report.py %s: %.1f s, exit code %d%s" % (
        folder, time.monotonic() - start, p.returncode,
        (": " + p.stderr.strip()) if p.stderr.strip() else ""))
    return p


def report_text(folder):
    with open(os.path.join(folder, "report.html"), encoding="utf-8") as f:
        return " ".join(f.read().split())


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    if len(sys.argv) == 2 and any(os.path.isfile(os.path.join(sys.argv[1], n))
                                  for n in ("summary.json", "suite_summary.json")):
        # a real output folder: the report of it and its checks
        check = Checker()
        p = run_report(os.path.dirname(here), sys.argv[1])
        check("report.py exits with 0", p.returncode == 0, p.stderr.strip())
        check_report(sys.argv[1], check)
        if check.failures:
            raise SystemExit("%d check(s) failed" % check.failures)
        print("all checks passed")
        return
    if len(sys.argv) == 2:
        source, work = os.path.dirname(here), os.path.join(sys.argv[1], "test_cases", "report")
        check = Checker()
    else:
        from hati_test import Context
        ctx = Context()
        source, work = ctx.source, ctx.work
        check = ctx.check_true
    start = time.monotonic()
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)

    # 1. a complete run
    run = os.path.join(work, "run")
    run_fixture(run)
    p = run_report(source, run)
    check("1. report.py exits with 0 on a run", p.returncode == 0, p.stderr.strip())
    check_report(run, check)
    text = report_text(run)
    for line in ("frame", "girder_1", "end_carriage", "hoist_rope", "stress"):
        check("1. the report names %r" % line, line in text)
    check("1. the frame drawn (an image after 'The frame')",
          re.search(r"The frame</h3>\s*<img", text) is not None)
    check("1. the overall verdict FAIL (passes false)", 'class="verdict fail"' in text)
    check("1. no spectra.csv: said so", "no spectra.csv" in text)
    check("1. the model's parameters listed", "Trolley position" in text and "0.3" in text)
    check("1. the girder stress in MPa (234.6)", "234.6" in text)
    check("1. the runway loads (107651.5176 as 1.077e+05)", "1.077e+05" in text)
    check("1. the wall time and the git commit", "12.35" in text and "835d971af637" in text)

    # 2. the same run without its optional files
    bare = os.path.join(work, "bare")
    shutil.copytree(run, bare)
    for name in ("geometry.csv", "contacts.csv", "runway_loads.csv", "qualification.csv",
                 "report.html"):
        os.unlink(os.path.join(bare, name))
    p = run_report(source, bare)
    check("2. report.py exits with 0 without the optional files", p.returncode == 0,
          p.stderr.strip())
    check_report(bare, check, browser=False)
    text = report_text(bare)
    for line in ("no geometry.csv: the frame is not drawn", "no contacts.csv",
                 "no runway_loads.csv"):
        check("2. the missing line %r" % line, line in text)
    check("2. the verdicts then from summary.json qualification.rows",
          "summary.json qualification.rows" in text)

    # 3. a suite
    suite = os.path.join(work, "suite")
    suite_fixture(suite, run)
    p = run_report(source, suite)
    check("3. report.py exits with 0 on a suite", p.returncode == 0, p.stderr.strip())
    check_report(suite, check, browser=False)
    text = report_text(suite)
    check("3. the EC8 verdict line", "the suite does NOT pass the EC8 check: X: 1 record" in text)
    check("3. the failed member counted", "1 of 2 members failed" in text)
    check("3. the first member's wheels", "member rec01_s1_0, the suite" in text)
    check("3. the frame of the first member with geometry.csv",
          "from rec02_s1_0/geometry.csv" in text)
    check("3. the suite's parameters from its first member",
          "rec01_s1_0/parameters.prm (the suite folder has none" in text)
    check("3. spectra, frame, rsa comparison and wheel images",
          text.count("data:image/png;base64,") >= 6, "(%d images)"
          % text.count("data:image/png;base64,"))
    check("3. the members' input digests", "fnv1a64 5aed81a67064a2b2" in text)

    # 4. not an output folder
    empty = os.path.join(work, "empty")
    os.makedirs(empty)
    p = run_report(source, empty)
    check("4. no summary.json: exit code 1, one line on stderr",
          p.returncode == 1 and len(p.stderr.strip().splitlines()) == 1, p.stderr.strip())
    check("4. no report written", not os.listdir(empty))

    elapsed = time.monotonic() - start
    print("the test took %.1f s" % elapsed)
    if len(sys.argv) == 2:
        if check.failures:
            raise SystemExit("%d check(s) failed" % check.failures)
        print("all checks passed")
    else:
        ctx.finish()


if __name__ == "__main__":
    main()
