#!/usr/bin/python3
"""report.html: one self-contained page for the reviewer of a crane's seismic
qualification, from the output folder of a transient run (summary.json) or
of a suite (suite_summary.json, suite.csv, one folder per member). hati runs
it at the end of every transient run and of every suite whose parameter file
has a subsection Qualification (as plot_suite.py: source/output/plot_script.cc).

Sections: the verdict in one line; Model (the parameters of parameters.prm,
the frame drawn from geometry.csv from above and from the side); Input (a
suite: the records' spectra against the design spectrum, suite_spectra.csv,
and the EC8 check, suite_summary.json design_spectrum_check; a run: its
spectra.csv); Verdicts (qualification.csv, one row per check, coloured by its
verdict; each number printed with 4 digits and its CSV text in the cell's
data-value attribute); the response-spectrum comparison (a suite's
rsa_comparison, drawn by plot_rsa_comparison.py); Wheels (contacts.csv:
force, uplift and slip over time; summary.json wheels; runway_loads.csv);
Stresses (summary.json beam_stresses and solids, the stress envelope rendered
by render_girder_stresses.py where pvpython is installed); Provenance (git
commit, the SHA-256 of parameters.prm, the date of the run, the machine,
the wall time). A suite's wheels and stresses are those of its first
completed member.

Every picture is embedded as a data: URI (no script, nothing fetched: the
page opens offline). A missing optional file leaves one line in its section
saying so. The page is written to .report.html.tmp in the folder and renamed
over report.html (a link at report.html is refused). Exit code 0 when the
report was written; 1 with one line on stderr otherwise (no summary.json nor
suite_summary.json in the folder, the folder not writable).

The HTML pieces are in report_html.py, the pictures in report_figures.py.

Usage: scripts/report.py OUTPUT_FOLDER"""
import csv
import datetime
import hashlib
import math
import os
import platform
import re
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree (its modules below)
from report_figures import (closest_ratio, frame_figure, no_matplotlib, plt, rsa_picture,
                            series, spectra_figure, stress_picture, wheel_figures)
from report_html import (cell, esc, fmt, image_tag, is_number, missing, number, para,
                         read_json, read_table, table, text_cell)

# the statuses of a suite's members whose results count
USABLE = ("completed", "reused")
# the subsections of parameters.prm whose every entry the report lists
PARAMETER_SECTIONS = ("Model", "Loading", "Time integration", "Qualification", "Suite",
                      "Design spectrum")
STYLE = """
body { font-family: sans-serif; font-size: 14px; margin: 1.5em auto; max-width: 1100px;
       color: #222; line-height: 1.35; }
h1 { font-size: 22px; margin-bottom: 0.2em; }
h2 { font-size: 18px; border-bottom: 1px solid #999; margin-top: 1.6em; }
h3 { font-size: 15px; margin-bottom: 0.3em; }
table { border-collapse: collapse; margin: 0.4em 0 1em 0; font-size: 13px; }
th, td { border: 1px solid #888; padding: 2px 6px; text-align: left; vertical-align: top; }
th { background: #e8e8e8; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
tr.pass td { background: #dff3df; }
tr.fail td { background: #f8d7d7; }
tr.changed td { font-weight: bold; }
.verdict { font-size: 17px; font-weight: bold; padding: 6px 10px; display: inline-block; }
.verdict.pass { background: #dff3df; border: 1px solid #3a3; }
.verdict.fail { background: #f8d7d7; border: 1px solid #c33; }
.verdict.none { background: #eee; border: 1px solid #999; }
.missing { color: #666; font-style: italic; }
img { max-width: 100%; border: 1px solid #ccc; margin: 0.3em 0; }
pre { background: #f4f4f4; padding: 6px; font-size: 12px; white-space: pre-wrap; }
.small { font-size: 12px; color: #555; }
"""


# ---------------------------------------------------------------- helpers


def find_digests(value, path=""):
    """(key path, value) of every entry of a summary whose key names a digest."""
    found = []
    if isinstance(value, dict):
        for k, v in value.items():
            p = path + "/" + k if path else k
            if re.search(r"digest|sha256|sha-256|fnv", k, re.I) and not isinstance(v, (dict, list)):
                found.append((p, v))
            else:
                found += find_digests(v, p)
    return found


def sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def mtime_iso(path):
    return datetime.datetime.fromtimestamp(os.path.getmtime(path)).astimezone().isoformat(
        timespec="seconds")


# ---------------------------------------------------------------- the folder

class Folder:
    """What the report reads: a single run or a suite."""

    def __init__(self, path):
        self.path = path
        self.name = os.path.basename(os.path.normpath(os.path.abspath(path)))
        self.suite = os.path.isfile(os.path.join(path, "suite_summary.json"))
        self.summary_file = os.path.join(path, "suite_summary.json" if self.suite
                                         else "summary.json")
        self.summary, self.summary_problem = read_json(self.summary_file)
        if self.summary is not None and not isinstance(self.summary, dict):
            self.summary, self.summary_problem = None, "%s is not a JSON object" % (
                os.path.basename(self.summary_file))
        self.members = []  # (name, status) of a suite's members, suite.csv's order
        self.suite_problem = ""
        if self.suite:
            try:
                self.members = [(r.get("member", ""), r.get("status", ""))
                                for r in read_table(os.path.join(path, "suite.csv"))]
            except OSError as e:
                self.suite_problem = "suite.csv cannot be read (%s)" % e
        # a suite's member that stands for it (wheels, stresses, provenance)
        self.first = None
        for member, status in self.members:
            folder = os.path.join(path, member)
            if status in USABLE and os.path.isfile(os.path.join(folder, "summary.json")):
                self.first = member
                break
        self.run_summary = self.summary if not self.suite else None
        if self.suite and self.first:
            self.run_summary = read_json(os.path.join(path, self.first, "summary.json"))[0]
        if not isinstance(self.run_summary, dict):
            self.run_summary = None

    def summary_get(self, key, default=None):
        return self.summary.get(key, default) if self.summary else default

    def run_folder(self):
        """The folder of the run's own files (a suite: its first completed member)."""
        if not self.suite:
            return self.path
        return os.path.join(self.path, self.first) if self.first else None

    def run_label(self):
        return "" if not self.suite else " (member %s, the suite's first completed member)" % (
            self.first)

    def member_file(self, name, usable_only=True):
        """(path, member) of the first file @name of a member (a suite), or of
        the folder itself."""
        own = os.path.join(self.path, name)
        if os.path.isfile(own):
            return own, None
        for member, status in self.members:
            if usable_only and status not in USABLE:
                continue
            p = os.path.join(self.path, member, name)
            if os.path.isfile(p):
                return p, member
        return None, None


# ---------------------------------------------------------------- sections

def qualification_rows(folder):
    """(rows as dicts of CSV text, where they came from, a line if missing)."""
    path = os.path.join(folder.path, "qualification.csv")
    if os.path.isfile(path):
        try:
            return read_table(path), "qualification.csv", ""
        except (OSError, csv.Error) as e:
            return [], "", "qualification.csv cannot be read (%s)" % e
    q = folder.summary_get("qualification")
    if isinstance(q, dict) and isinstance(q.get("rows"), list):
        rows = [{k: ("" if v is None else str(v)) for k, v in r.items()}
                for r in q["rows"] if isinstance(r, dict)]
        return rows, "%s qualification.rows" % os.path.basename(folder.summary_file), ""
    return [], "", "no qualification.csv (the parameter file has no subsection Qualification)"


def section_title(folder, rows):
    s = folder.summary or {}
    model = s.get("model") or (folder.run_summary or {}).get("model") or ""
    title = ("suite %s" % folder.name) if folder.suite else folder.name
    out = ["<h1>Seismic qualification: %s</h1>\n" % esc(title)]
    if model:
        out.append(para(("model (member %s): " % folder.first if folder.suite else "model: ")
                        + model))
    out.append(para("report written %s; run of %s" % (
        datetime.datetime.now().astimezone().isoformat(timespec="seconds"),
        mtime_iso(folder.summary_file)), "small"))
    q = s.get("qualification") if isinstance(s.get("qualification"), dict) else {}
    passes = q.get("passes")
    n_fail = sum(1 for r in rows if r.get("verdict", "").strip() == "fail")
    n = len(rows)
    notes = []
    if folder.suite and s.get("n_failed"):
        notes.append("%d of %d members failed" % (s.get("n_failed"), s.get("n_members", 0)))
    status = s.get("status")
    if status and status != "completed":
        notes.append("run %s" % status)
    if passes is None and not rows:
        line, cls = "NO VERDICT: the run has no qualification (no qualification.csv, no " \
                    "qualification in %s)" % os.path.basename(folder.summary_file), "none"
    elif not rows:
        line, cls = "NO CHECK: the qualification has no row (no capacity given)", "none"
    elif passes is False or n_fail:
        line, cls = "FAIL: %d of %d checks fail" % (n_fail, n), "fail"
        if passes is True:
            notes.append("the summary says it passes, but %d rows fail" % n_fail)
        elif passes is None:
            notes.append("no qualification.passes in the summary")
    else:
        line, cls = "PASS: all %d checks pass" % n, "pass"
        if passes is None:
            notes.append("no qualification.passes in the summary")
    if notes:
        line += " (" + "; ".join(notes) + ")"
    out.append('<p class="verdict %s" id="overall-verdict">%s</p>\n' % (cls, esc(line)))
    # the failing checks at once, the largest ratio first (the table below has them all)
    failing = [r for r in rows if r.get("verdict", "").strip() == "fail"]

    def ratio(r):
        try:
            return float(r.get("ratio", "nan"))
        except ValueError:
            return float("nan")

    failing.sort(key=lambda r: -ratio(r) if ratio(r) == ratio(r) else 0.0)
    if failing:
        out.append('<ul class="failing">\n')
        for r in failing[:10]:
            out.append("<li>%s: %s ratio %.3g (%s %s against %s %s)%s</li>\n" % (
                esc(r.get("item", "")), esc(r.get("check", "")), ratio(r),
                esc(short(r.get("demand", ""))), esc(r.get("unit", "")),
                esc(short(r.get("capacity", ""))), esc(r.get("unit", "")),
                ", " + esc(r["where"]) if r.get("where") else ""))
        if len(failing) > 10:
            out.append("<li>... and %d more in the verdict table</li>\n" % (len(failing) - 10))
        out.append("</ul>\n")
    return "".join(out)


def short(text):
    """A number's text with 4 significant digits (other text as it is)."""
    try:
        return "%.4g" % float(text)
    except ValueError:
        return text


def parse_prm(path):
    """[(subsection path, entry, value, default or None)] of a parameters.prm."""
    entries, stack = [], []
    with open(path, errors="replace") as f:
        for line in f:
            text = line.strip()
            if text.startswith("subsection "):
                stack.append(text[len("subsection "):].strip())
            elif text == "end":
                if stack:
                    stack.pop()
            elif text.startswith("set "):
                body, _, comment = text[4:].partition("#")
                name, _, value = body.partition("=")
                default = None
                comment = comment.strip()
                if comment.startswith("default:"):
                    default = comment[len("default:"):].strip()
                entries.append(("/".join(stack), name.strip(), value.strip(), default))
    return entries


def section_model(folder):
    out = ["<h2>Model</h2>\n"]
    prm = os.path.join(folder.path, "parameters.prm")
    source = "parameters.prm"
    if not os.path.isfile(prm) and folder.suite:
        prm, member = folder.member_file("parameters.prm", usable_only=False)
        source = "%s/parameters.prm (the suite folder has none: its first member's)" % member
    if prm and os.path.isfile(prm):
        entries = parse_prm(prm)
        changed = [e for e in entries if e[3] is not None]
        out.append("<h3>Values differing from the defaults (%s)</h3>\n" % esc(source))
        out.append(table(["subsection", "entry", "value", "default"],
                         [[text_cell(x) for x in e] for e in changed], "parameters"))
        listed = [e for e in entries if e[0].split("/")[0] in PARAMETER_SECTIONS]
        out.append("<details><summary>every entry of %s (%d)</summary>\n" % (
            esc(", ".join(PARAMETER_SECTIONS)), len(listed)))
        out.append('<table class="parameters"><tr><th>subsection</th><th>entry</th>'
                   "<th>value</th></tr>\n")
        for e in listed:
            out.append('<tr%s><td>%s</td><td>%s</td><td>%s</td></tr>\n' % (
                ' class="changed"' if e[3] is not None else "", esc(e[0]), esc(e[1]),
                esc(e[2])))
        out.append("</table>\n</details>\n")
    else:
        out.append(missing("no parameters.prm: the parameters of the run are not listed"))
    out.append("<h3>The frame</h3>\n")
    geometry, member = folder.member_file("geometry.csv", usable_only=False)
    if geometry is None:
        out.append(missing("no geometry.csv%s: the frame is not drawn" % (
            " in the suite folder nor in any member's" if folder.suite else "")))
    elif plt is None:
        out.append(no_matplotlib("the frame"))
    else:
        if member:
            out.append(para("from %s/geometry.csv" % member, "small"))
        out.append(frame_figure(geometry))
    return "".join(out)


def ec8_check(check):
    out = ["<h3>EC8 check of the records (EN 1998-1 3.2.3.1.2)</h3>\n"]
    if not isinstance(check, dict):
        return out[0] + missing("no design_spectrum_check in suite_summary.json (the suite "
                                "has no subsection Design spectrum)")
    first_last = check.get("period_range_checked") or [math.nan, math.nan]
    out.append(para("%s of the records against the target over [0.2 T1, 2 T1] = [%s, %s] s, "
                    "T1 = %s s (%s), %s %% damping, scale %s" % (
                        check.get("statistic", "mean"), fmt(first_last[0]),
                        fmt(first_last[-1]), fmt(check.get("fundamental_period")),
                        check.get("fundamental_period_source", ""),
                        fmt(100 * check.get("damping_ratio", math.nan)),
                        fmt(check.get("scale")))))
    rows = []
    targets = check.get("target", {})
    for axis, c in sorted((check.get("components") or {}).items()):
        ok = (c.get("enough_records") and c.get("passes_ec8_90_percent")
              and c.get("pga_not_below_target"))
        rows.append("<tr class=\"%s\">" % ("pass" if ok else "fail") + "".join(
            cell(x) for x in (axis, targets.get(axis, ""), c.get("n_records"),
                              c.get("min_ratio"), c.get("period_of_min_ratio"),
                              "yes" if c.get("passes_ec8_90_percent") else "NO",
                              c.get("mean_pga"), c.get("target_pga"),
                              "pass" if ok else "fail")) + "</tr>\n")
    out.append("<table><tr>" + "".join("<th>%s</th>" % esc(h) for h in (
        "axis", "target", "records", "min ratio", "at T (s)", ">= 90 %", "mean PGA (m/s^2)",
        "target PGA (m/s^2)", "verdict")) + "</tr>\n" + "".join(rows) + "</table>\n")
    passes = check.get("passes_ec8")
    line = "the suite %s the EC8 check" % ("passes" if passes else "does NOT pass")
    reasons = check.get("reasons") or []
    if reasons:
        line += ": " + "; ".join(str(r) for r in reasons)
    out.append('<p class="verdict %s">%s</p>\n' % ("pass" if passes else "fail", esc(line)))
    return "".join(out)


def records_table(folder):
    """The records: a suite's members (suite.csv: record, scale, status) and
    the picture of its artificial records (records/records.png); a run's
    ground motion entries of parameters.prm (Loading)."""
    out = []
    if folder.suite:
        try:
            rows = read_table(os.path.join(folder.path, "suite.csv"))
        except OSError:
            rows = []
        if rows:
            out.append("<h3>The records</h3>\n")
            out.append(table(["member", "record", "scale", "status"],
                             [[text_cell(r.get("member", "")), text_cell(r.get("record", "")),
                               r.get("scale", ""), text_cell(r.get("status", ""))]
                              for r in rows]))
        picture = os.path.join(folder.path, "records", "records.png")
        if os.path.isfile(picture) and not os.path.islink(picture):
            with open(picture, "rb") as f:
                data = f.read()
            if data.startswith(b"\x89PNG"):
                out.append(para("the artificial records and their spectra against the target "
                                "(records/records.png)"))
                out.append(image_tag(data, "the records"))
        return "".join(out)
    prm = os.path.join(folder.path, "parameters.prm")
    if not os.path.isfile(prm):
        return missing("no parameters.prm: the run's ground motion is not listed")
    # the records and the base acceleration step, where set (parameters.prm
    # gives a "# default:" comment to the entries away from their default)
    entries = [(e, v) for sub, e, v, default in parse_prm(prm)
               if sub == "Loading" and default is not None and
               (e.startswith("Accelerogram") or e.startswith("Base acceleration"))]
    if not entries:
        return ""
    return "<h3>The ground motion</h3>\n" + table(
        ["entry (Loading)", "value"], [[text_cell(e), text_cell(v)] for e, v in entries])


def section_input(folder):
    out = ["<h2>Input</h2>\n", records_table(folder)]
    if not folder.suite:
        path = os.path.join(folder.path, "spectra.csv")
        if not os.path.isfile(path):
            return "".join(out) + missing("no spectra.csv (Output/Spectra is empty): no "
                                          "response spectra of the run")
        if plt is None:
            return "".join(out) + no_matplotlib("the response spectra")
        rows = read_table(path)
        ratio = closest_ratio(rows)
        if ratio is None or not rows:
            return "".join(out) + missing("spectra.csv has no row")
        points = {}
        for c in rows[0].keys():
            if c not in ("damping_ratio", "period"):
                points.setdefault(c.rsplit(".", 1)[0], []).append(c)
        panels = [("%s, %g %% damping" % (p, 100 * ratio),
                   [(series(rows, c, ratio) + ({"lw": 1.2, "label": c.rsplit(".", 1)[-1]},))
                    for c in cs], None) for p, cs in points.items()]
        out.append(para("pseudo-acceleration spectra of the monitor points and of the "
                        "ground (spectra.csv)"))
        out.append(spectra_figure(panels, "response spectra of the run"))
        return "".join(out)
    check = folder.summary_get("design_spectrum_check")
    path = os.path.join(folder.path, "suite_spectra.csv")
    if not os.path.isfile(path):
        out.append(missing("no suite_spectra.csv (Output/Spectra is empty): the records' "
                           "spectra are not drawn"))
    elif plt is None:
        out.append(no_matplotlib("the records' spectra"))
    else:
        statistic = read_table(path)
        ratio = (check or {}).get("damping_ratio") or closest_ratio(statistic)
        if statistic and ratio not in {number(r["damping_ratio"]) for r in statistic}:
            ratio = closest_ratio(statistic, ratio)
        channels = [c for c in (statistic[0].keys() if statistic else [])
                    if c.startswith("ground.")]
        target_file = os.path.join(folder.path, "records", "records_spectra.csv")
        target = read_table(target_file) if os.path.isfile(target_file) else []
        check_file = os.path.join(folder.path, "design_spectrum_check.csv")
        checked = read_table(check_file) if os.path.isfile(check_file) else []
        shade = (check or {}).get("period_range_checked")
        panels = []
        member_spectra = {}
        for member, status in folder.members:
            p = os.path.join(folder.path, member, "spectra.csv")
            if status in USABLE and os.path.isfile(p):
                member_spectra[member] = read_table(p)
        for channel in channels:
            axis = channel.split(".", 1)[1]
            curves = []
            for k, (member, rows) in enumerate(member_spectra.items()):
                t, v = series(rows, channel, ratio)
                curves.append((t, v, {"lw": 0.6, "color": "grey", "alpha": 0.6,
                                      "label": "members" if k == 0 else None}))
            for group in sorted({(number(r["scale"]), r["variation"]) for r in statistic}):
                rows = [r for r in statistic
                        if (number(r["scale"]), r["variation"]) == group]
                t, v = series(rows, channel, ratio)
                curves.append((t, v, {"lw": 2, "label": "%s, scale %g, variation %s" % (
                    folder.summary_get("statistic", "statistic"), group[0], group[1])}))
            if target and "target." + axis in target[0]:
                curves.append(([number(r["period"]) for r in target],
                               [number(r["target." + axis]) for r in target],
                               {"lw": 1.5, "color": "k", "ls": "--", "label": "design spectrum"}))
            elif checked and "target." + axis in checked[0]:
                curves.append(([number(r["period"]) for r in checked],
                               [number(r["target." + axis]) for r in checked],
                               {"lw": 1.5, "color": "k", "ls": "--", "label": "design spectrum"}))
            if checked and "mean." + axis in checked[0]:
                curves.append(([number(r["period"]) for r in checked],
                               [0.9 * number(r["target." + axis]) for r in checked],
                               {"lw": 1, "color": "tab:red", "ls": ":", "label": "90 % of it"}))
            panels.append(("%s, %g %% damping" % (channel, 100 * ratio), curves, shade))
        if panels:
            out.append(para("pseudo-acceleration spectra of the ground motion of every "
                            "member (grey), their statistic (suite_spectra.csv) and the "
                            "design spectrum%s" % (
                                " (records/records_spectra.csv)" if target else
                                " over the check range (design_spectrum_check.csv)" if checked
                                else ": none (no records/records_spectra.csv nor "
                                     "design_spectrum_check.csv)")))
            out.append(spectra_figure(panels, "the records against the design spectrum"))
        else:
            out.append(missing("suite_spectra.csv has no ground spectrum"))
    out.append(ec8_check(check))
    return "".join(out)


def section_verdicts(folder, rows, source, problem):
    out = ["<h2>Verdicts</h2>\n"]
    if problem:
        return out[0] + missing(problem)
    out.append(para("%d checks from %s; the ratio is demand / capacity" % (len(rows), source),
                    "small"))
    columns = ["check", "item", "demand", "capacity", "unit", "ratio", "verdict", "where"]
    out.append('<table id="verdicts"><tr>' + "".join("<th>%s</th>" % c for c in columns)
               + "</tr>\n")
    for r in rows:
        verdict = r.get("verdict", "").strip()
        cls = verdict if verdict in ("pass", "fail") else "unknown"
        cells = []
        for c in columns:
            text = r.get(c, "") or ""
            if c in ("demand", "capacity", "ratio"):
                numeric = not math.isnan(number(text))
                cells.append('<td class="col-%s%s" data-value="%s">%s</td>' % (
                    c, " num" if numeric else "", esc(text),
                    esc(fmt(text) if numeric else text)))
            else:
                cells.append('<td class="col-%s">%s</td>' % (c, esc(text)))
        out.append('<tr class="verdict-row %s">%s</tr>\n' % (cls, "".join(cells)))
    out.append("</table>\n")
    return "".join(out)


def section_rsa(folder):
    out = ["<h2>Response-spectrum comparison</h2>\n"]
    if not folder.suite:
        return out[0] + missing("a single run: the response-spectrum comparison is a suite's "
                                "(Suite/Response spectrum comparison with a Design spectrum)")
    comparison = folder.summary_get("rsa_comparison")
    path = os.path.join(folder.path, "rsa_comparison.csv")
    rows = []
    if os.path.isfile(path):
        rows = read_table(path)
    elif isinstance(comparison, dict):
        rows = [dict(quantity=q, **v) for q, v in (comparison.get("quantities") or {}).items()]
    if not rows:
        return out[0] + missing("no rsa_comparison.csv nor rsa_comparison in "
                                "suite_summary.json (the suite ran no response-spectrum "
                                "analysis)")
    if isinstance(comparison, dict):
        out.append(para("ratio = response spectrum / time history (%s of the records); the "
                        "response-spectrum analysis in %s" % (
                            comparison.get("time_history_statistic", ""),
                            comparison.get("response_spectrum_folder", ""))))
    out.append(rsa_picture(folder, path if os.path.isfile(path) else None))
    out.append(table(["quantity", "unit", "time history", "response spectrum", "ratio"],
                     [[r.get("quantity", ""), r.get("unit", ""), r.get("time_history", ""),
                       r.get("response_spectrum", ""), r.get("ratio", "")] for r in rows]))
    return "".join(out)


WHEEL_KEYS = [("n_impacts", "impacts"), ("peak_mean_force", "peak mean force (N)"),
              ("uplift_time", "uplift time (s)"), ("max_uplift", "max uplift (m)"),
              ("max_lateral_offset", "max lateral offset (m)"),
              ("slip_distance", "slip distance (m)")]


def section_wheels(folder):
    out = ["<h2>Wheels</h2>\n"]
    run = folder.run_folder()
    if run is None:
        return out[0] + missing("no completed member in the suite: no wheel results")
    summary = folder.run_summary or {}
    wheels = summary.get("wheels") if isinstance(summary.get("wheels"), dict) else {}
    if folder.suite:
        out.append(para("member %s, the suite's first completed member" % folder.first))
    contacts = os.path.join(run, "contacts.csv")
    if not os.path.isfile(contacts):
        out.append(missing("no contacts.csv%s: the wheels are not drawn" % folder.run_label()))
    elif plt is None:
        out.append(no_matplotlib("the wheels"))
    else:
        out.append(wheel_figures(contacts, list(wheels)))
    if wheels:
        keys = [(k, t) for k, t in WHEEL_KEYS
                if any(isinstance(w, dict) and k in w for w in wheels.values())]
        out.append("<h3>Wheels of summary.json</h3>\n")
        out.append(table(["wheel"] + [t for _, t in keys],
                         [[name] + [w.get(k, "") for k, _ in keys]
                          for name, w in wheels.items() if isinstance(w, dict)]))
    else:
        out.append(missing("no wheels in summary.json%s" % folder.run_label()))
    loads = os.path.join(run, "runway_loads.csv")
    if os.path.isfile(loads):
        rows = read_table(loads)
        out.append("<h3>Runway loads (runway_loads.csv; N, s)</h3>\n")
        header = list(rows[0].keys()) if rows else []
        out.append(table(header, [[r[h] for h in header] for r in rows]))
    else:
        out.append(missing("no runway_loads.csv%s" % folder.run_label()))
    # Runway = springs: the forces of the runway springs (summary.json runway_reaction)
    reactions = summary.get("runway_reaction")
    if isinstance(reactions, dict) and reactions:
        rows = []
        for wheel, directions in reactions.items():
            for direction, r in (directions or {}).items():
                if isinstance(r, dict):
                    rows.append([wheel, direction, r.get("max", ""), r.get("max_time", ""),
                                 r.get("min", ""), r.get("min_time", "")])
        out.append("<h3>Runway reactions (summary.json runway_reaction: the runway "
                   "springs' forces; N, s)</h3>\n")
        out.append(table(["wheel", "direction", "max", "at t", "min", "at t"], rows))
    return "".join(out)


def stress_rows(entries, unit_scale=1e-6):
    """[[name, quantity, value (MPa), where, time]] of a beam_stresses / solids entry."""
    rows = []
    for name, quantities in (entries or {}).items():
        if not isinstance(quantities, dict):
            continue
        for quantity, v in quantities.items():
            if not isinstance(v, dict):
                continue
            value = v.get("value")
            where = v.get("x", v.get("point", ""))
            if isinstance(where, list):
                where = "(" + ", ".join(fmt(x) for x in where) + ")"
            rows.append([name, quantity, value * unit_scale if is_number(value) else value,
                         where, v.get("time", "")])
    return rows


def section_stresses(folder):
    out = ["<h2>Stresses</h2>\n"]
    summary = folder.run_summary
    if summary is None:
        return out[0] + missing("no summary.json of a run%s: no stresses" % (
            " (no completed member)" if folder.suite else ""))
    if folder.suite:
        out.append(para("member %s, the suite's first completed member" % folder.first))
    beams = summary.get("beam_stresses")
    if isinstance(beams, dict) and beams:
        out.append("<h3>Beam members (summary.json beam_stresses)</h3>\n")
        out.append(table(["member", "quantity", "value (MPa)", "x (m)", "time (s)"],
                         stress_rows(beams)))
    else:
        out.append(missing("no beam_stresses in summary.json%s" % folder.run_label()))
    envelope = summary.get("section_force_envelope")
    if isinstance(envelope, dict) and envelope:
        out.append("<h3>Section-force envelope (summary.json section_force_envelope; N, N m)"
                   "</h3>\n")
        out.append(table(["force", "max |value|", "member", "x (m)", "time (s)"],
                         [[k, v.get("max_abs", ""), v.get("member", ""), v.get("x", ""),
                           v.get("time", "")] for k, v in envelope.items()
                          if isinstance(v, dict)]))
    solids = summary.get("solids")
    if isinstance(solids, dict) and solids:
        out.append("<h3>Solids (summary.json solids)</h3>\n")
        out.append(table(["solid", "quantity", "value (MPa)", "point (m)", "time (s)"],
                         stress_rows(solids)))
    else:
        out.append(missing("no solids in summary.json%s (a frame without Model/Frame/Solids)"
                           % folder.run_label()))
    out.append(stress_picture(folder))
    return "".join(out)


def section_provenance(folder):
    out = ["<h2>Provenance</h2>\n"]
    rows = []
    if folder.suite:
        commits = {}
        for member, _ in folder.members:
            s = read_json(os.path.join(folder.path, member, "summary.json"))[0]
            if isinstance(s, dict):
                commits.setdefault(s.get("git_commit", "(none)"), []).append(member)
        if commits:
            for commit, members in commits.items():
                rows.append(["hati git commit", "%s (%d of %d members)" % (
                    commit, len(members), len(folder.members))])
        else:
            rows.append(["hati git commit", "unknown: no member's summary.json"])
    else:
        rows.append(["hati git commit", folder.summary_get("git_commit",
                                                           "unknown: no git_commit in "
                                                           "summary.json")])
    prm = os.path.join(folder.path, "parameters.prm")
    if os.path.isfile(prm):
        rows.append(["SHA-256 of parameters.prm", sha256(prm)])
    elif folder.suite:
        prm, member = folder.member_file("parameters.prm", usable_only=False)
        rows.append(["SHA-256 of parameters.prm", "%s (member %s: the suite folder has none)"
                     % (sha256(prm), member) if prm else "no parameters.prm"])
    else:
        rows.append(["SHA-256 of parameters.prm", "no parameters.prm"])
    for key, value in find_digests(folder.summary or {}):
        rows.append(["%s %s" % (os.path.basename(folder.summary_file), key), value])
    rows.append(["date of the run (%s written)" % os.path.basename(folder.summary_file),
                 mtime_iso(folder.summary_file)])
    rows.append(["machine (of the report)", "%s, %s" % (platform.node(), platform.platform())])
    wall = folder.summary_get("wall_time")
    rows.append(["wall time (s)", fmt(wall) if wall is not None else "no wall_time"])
    if folder.suite:
        rows.append(["members", "%s of %s usable" % (folder.summary_get("n_usable", "?"),
                                                     folder.summary_get("n_members", "?"))])
    out.append('<table class="provenance">' + "".join(
        "<tr><th>%s</th><td>%s</td></tr>\n" % (esc(k), esc(v)) for k, v in rows) + "</table>\n")
    digests = []
    for member in ([None] + [m for m, _ in folder.members]):
        p = os.path.join(folder.path, member or "", "input_digests.txt")
        if os.path.isfile(p):
            with open(p, errors="replace") as f:
                digests += [("%s: " % member if member else "") + line.rstrip("\n")
                            for line in f if line.strip()]
    if digests:
        out.append("<h3>Input files (input_digests.txt)</h3>\n<pre>%s</pre>\n" % esc(
            "\n".join(digests[:200]) + ("\n..." if len(digests) > 200 else "")))
    return "".join(out)


def guarded(name, function, *args):
    """A section; an error in it (a malformed file) leaves one line."""
    try:
        return function(*args)
    except Exception as e:  # noqa: BLE001 (the report is written whatever happens)
        if plt is not None:
            plt.close("all")
        return "<h2>%s</h2>\n" % esc(name) + missing(
            "this section could not be made: %s: %s" % (type(e).__name__, e))


def report(folder):
    rows, source, problem = qualification_rows(folder)
    title = folder.name if not folder.suite else "suite " + folder.name
    body = [guarded("Seismic qualification", section_title, folder, rows)]
    if folder.summary is None:
        body.append(missing(folder.summary_problem))
    if folder.suite_problem:
        body.append(missing(folder.suite_problem))
    body.append(guarded("Model", section_model, folder))
    body.append(guarded("Input", section_input, folder))
    body.append(guarded("Verdicts", section_verdicts, folder, rows, source, problem))
    body.append(guarded("Response-spectrum comparison", section_rsa, folder))
    body.append(guarded("Wheels", section_wheels, folder))
    body.append(guarded("Stresses", section_stresses, folder))
    body.append(guarded("Provenance", section_provenance, folder))
    return ("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            "<title>%s</title>\n<style>%s</style>\n</head>\n<body>\n%s</body>\n</html>\n"
            % (esc("qualification report: " + title), STYLE, "".join(body)))


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    path = sys.argv[1]
    if not os.path.isdir(path):
        sys.stderr.write("report.py: %s is not a folder\n" % path)
        return 1
    if not (os.path.isfile(os.path.join(path, "summary.json"))
            or os.path.isfile(os.path.join(path, "suite_summary.json"))):
        sys.stderr.write("report.py: %s has no summary.json nor suite_summary.json: not the "
                         "output folder of a run or a suite\n" % path)
        return 1
    target = os.path.join(path, "report.html")
    if os.path.islink(target):
        sys.stderr.write("report.py: %s is a symbolic link: refused (the report is never "
                         "written through a link; remove the link)\n" % target)
        return 1
    text = report(Folder(path))
    temporary = os.path.join(path, ".report.html.tmp")
    try:
        if os.path.lexists(temporary):
            os.unlink(temporary)  # a stale one (or a link: removed, never followed)
        fd = os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW, 0o644)
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(temporary, target)
    except OSError as e:
        if os.path.lexists(temporary):
            os.unlink(temporary)
        sys.stderr.write("report.py: cannot write %s (%s)\n" % (target, e))
        return 1
    print("wrote %s (%d kB)" % (target, (len(text) + 1023) // 1024))
    return 0


if __name__ == "__main__":
    sys.exit(main())
