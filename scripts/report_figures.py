#!/usr/bin/python3
"""The pictures of report.html (scripts/report.py), each returned as the HTML
of an embedded PNG (report_html.image_tag) or a line saying why it is not
drawn: the frame from above and from the side (geometry.csv), the records'
spectra against the design spectrum, the response-spectrum comparison
(plot_rsa_comparison.py), the wheels' force, gap and slip over time
(contacts.csv) and the solids' stress envelope (render_girder_stresses.py
under pvpython). matplotlib and numpy (optional: without them the pictures
are left out with a line)."""
import csv
import io
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

from report_html import image_tag, missing, number, para, read_table

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:  # the report without its pictures
    plt = None

try:
    import numpy as np
except ImportError:
    np = None

SCRIPTS = os.path.dirname(os.path.abspath(__file__))
DPI = 100


def png(fig):
    """The figure as an embedded <img> (closed afterwards)."""
    buffer = io.BytesIO()
    try:
        fig.savefig(buffer, dpi=DPI, format="png")
    finally:
        plt.close(fig)
    return image_tag(buffer.getvalue(), "figure")


def no_matplotlib(what):
    return missing("%s: not drawn, matplotlib is not installed (python3-matplotlib)" % what)


def decimated(t, y, n=20000):
    """At most about 2 n points of (t, y) keeping each bin's extremes."""
    if np is None or len(t) <= 2 * n:
        return t, y
    t, y = np.asarray(t), np.asarray(y)
    k = int(math.ceil(len(t) / n))
    m = (len(t) // k) * k
    tb, yb = t[:m].reshape(-1, k), y[:m].reshape(-1, k)
    lo, hi = yb.argmin(axis=1), yb.argmax(axis=1)
    rows = np.arange(tb.shape[0])
    first, second = np.minimum(lo, hi), np.maximum(lo, hi)
    tt = np.column_stack((tb[rows, first], tb[rows, second])).ravel()
    yy = np.column_stack((yb[rows, first], yb[rows, second])).ravel()
    return np.concatenate((tt, t[m:])), np.concatenate((yy, y[m:]))


def frame_figure(path):
    rows = read_table(path)
    if not rows:
        return missing("geometry.csv has no element")
    absent = [c for c in ("member", "x1", "y1", "z1", "x2", "y2", "z2") if c not in rows[0]]
    if absent:
        return missing("geometry.csv has no column %s: the frame is not drawn" % ", ".join(absent))
    groups = {}
    for r in rows:
        prefix = re.sub(r"(_[0-9]+|_[a-z])+$", "", r["member"].strip()) or r["member"]
        groups.setdefault(prefix, []).append(
            [number(r[k]) for k in ("x1", "y1", "z1", "x2", "y2", "z2")])
    colours = plt.get_cmap("tab20" if len(groups) > 10 else "tab10").colors
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for g, (prefix, lines) in enumerate(sorted(groups.items())):
        colour = colours[g % len(colours)]
        for ax, (i, j) in zip(axes, ((0, 1), (0, 2))):
            for k, e in enumerate(lines):
                ax.plot([e[i], e[i + 3]], [e[j], e[j + 3]], "-", color=colour, lw=1.5,
                        label=prefix if (k == 0 and i == 0 and j == 1) else None)
    for ax, title, ylabel in zip(axes, ("from above (x-y)", "from the side (x-z)"),
                                 ("y (m)", "z (m)")):
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("x (m)")
        ax.set_ylabel(ylabel)
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(alpha=0.3)
    fig.legend(loc="center right", fontsize=7, frameon=False)
    fig.tight_layout(rect=(0, 0, 0.86, 1))
    return png(fig) + para("%d elements: %s" % (len(rows), ", ".join(
        "%s %d" % (prefix, len(lines)) for prefix, lines in sorted(groups.items()))), "small")


def spectra_figure(panels, title):
    """panels: [(title, [(periods, values, style dict)], shade range or None)]."""
    figures = []
    for start in range(0, len(panels), 3):
        chunk = panels[start:start + 3]
        fig, axes = plt.subplots(1, len(chunk), figsize=(min(10, 3.6 * len(chunk) + 0.6), 3.4),
                                 squeeze=False)
        for ax, (name, curves, shade) in zip(axes[0], chunk):
            for periods, values, style in curves:
                ax.loglog(periods, values, **style)
            if shade:
                ax.axvspan(shade[0], shade[1], color="tab:green", alpha=0.1,
                           label="EC8 check range")
            ax.set_title(name, fontsize=9)
            ax.set_xlabel("period (s)")
            ax.set_ylabel("S_a (m/s^2)")
            ax.grid(alpha=0.3, which="both")
            handles, labels = ax.get_legend_handles_labels()
            if labels:
                ax.legend(fontsize=6)
        fig.suptitle(title, fontsize=10)
        fig.tight_layout()
        figures.append(png(fig))
    return "".join(figures)


def closest_ratio(rows, wanted=0.05):
    ratios = sorted({number(r.get("damping_ratio")) for r in rows} - {math.nan})
    ratios = [x for x in ratios if not math.isnan(x)]
    return min(ratios, key=lambda x: abs(x - wanted)) if ratios else None


def series(rows, column, ratio):
    table_rows = [r for r in rows if number(r.get("damping_ratio")) == ratio]
    return ([number(r["period"]) for r in table_rows],
            [number(r.get(column)) for r in table_rows])


def rsa_picture(folder, path):
    """plot_rsa_comparison.py's picture, drawn in a temporary folder (the
    suite's own rsa_comparison.png if that fails)."""
    problem = "no rsa_comparison.csv"
    if path and plt is not None:
        try:
            sys.path.insert(0, SCRIPTS)
            sys.dont_write_bytecode = True  # no __pycache__ in the source tree
            import plot_rsa_comparison
            with tempfile.TemporaryDirectory(prefix="hati-report-") as tmp:
                shutil.copy(path, os.path.join(tmp, "rsa_comparison.csv"))
                argv = sys.argv
                sys.argv = ["plot_rsa_comparison.py", tmp]
                try:
                    plot_rsa_comparison.main()
                finally:
                    sys.argv = argv
                picture = os.path.join(tmp, "rsa_comparison.png")
                if os.path.isfile(picture):
                    with open(picture, "rb") as f:
                        return image_tag(f.read(), "rsa comparison")
                problem = "plot_rsa_comparison.py drew nothing (no quantity it knows)"
        except (Exception, SystemExit) as e:  # noqa: BLE001 (a picture is optional)
            problem = "plot_rsa_comparison.py failed (%s)" % e
    elif plt is None:
        problem = "matplotlib is not installed"
    own = os.path.join(folder.path, "rsa_comparison.png")
    if os.path.isfile(own) and not os.path.islink(own):
        with open(own, "rb") as f:
            data = f.read()
        if data.startswith(b"\x89PNG"):
            return para("(%s: the suite's rsa_comparison.png)" % problem, "small") + \
                image_tag(data, "rsa comparison")
    return missing("the comparison is not drawn: %s" % problem)


def read_contacts(path, names):
    """{name: {column: [values]}} of the rows of contacts.csv for @names."""
    data = {n: {} for n in names}
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader, None)
        if not header:
            return data, []
        index = {c: i for i, c in enumerate(header)}
        columns = [c for c in ("time", "gap", "force", "slip_velocity") if c in index]
        ci = index.get("contact")
        for row in reader:
            if ci is None or len(row) != len(header) or row[ci] not in data:
                continue
            d = data[row[ci]]
            for c in columns:
                d.setdefault(c, []).append(number(row[index[c]]))
    return data, header


def wheel_figures(path, wheels):
    names = wheels or []
    if not names:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            seen = []
            for r in reader:
                n = r.get("contact", "")
                if n in seen:
                    break
                seen.append(n)
        names = [n for n in seen if not n.endswith("_lateral")]
    data, header = read_contacts(path, names)
    data = {n: d for n, d in data.items() if d.get("time")}
    if not header:
        return missing("contacts.csv is empty")
    if not data:
        return missing("contacts.csv has no row of the wheels (%s)" % ", ".join(names))
    out = []
    panels = [("force", "contact force (kN)", 1e-3, False),
              ("gap", "uplift = gap (mm)", 1e3, False)]
    if "slip_velocity" in header:
        panels.append(("slip_velocity", "slip (mm, the slip velocity integrated over the "
                                        "rows)", 1e3, True))
    else:
        out.append(missing("contacts.csv has no slip_velocity column (no friction): no slip"))
    for column, title, scale, integrate in panels:
        fig, ax = plt.subplots(figsize=(10, 3))
        for name, d in data.items():
            t, y = d["time"], [scale * v for v in d[column]]
            if integrate:
                total, acc = 0.0, []
                for i in range(len(t)):
                    if i:
                        total += 0.5 * (y[i] + y[i - 1]) * (t[i] - t[i - 1])
                    acc.append(total)
                y = acc
            t, y = decimated(t, y)
            ax.plot(t, y, lw=0.8, label=name)
        if column == "gap":
            largest = max(max(d["gap"]) for d in data.values())
            title += ": largest %.4g mm%s" % (1e3 * largest, ", no wheel lifts off" if
                                               largest < 1e-6 else "")
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("time (s)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=6, ncol=2, loc="center left", bbox_to_anchor=(1.0, 0.5))
        fig.tight_layout()
        out.append(png(fig))
    return "".join(out)


def stress_picture(folder):
    envelope, member = folder.member_file("stress_envelope.vtu")
    if envelope is None:
        return missing("no stress_envelope.vtu (a transient run with Model/Frame/Solids "
                       "writes it): no stress envelope picture")
    pvpython = shutil.which("pvpython")
    if pvpython is None:
        return missing("pvpython is not installed (python3-paraview): the stress envelope "
                       "(%s) is not rendered" % os.path.relpath(envelope, folder.path))
    script = os.path.join(SCRIPTS, "render_girder_stresses.py")
    with tempfile.TemporaryDirectory(prefix="hati-report-") as tmp:
        picture = os.path.join(tmp, "stresses.png")
        try:
            p = subprocess.run([pvpython, "--force-offscreen-rendering", script,
                                os.path.dirname(envelope), picture],
                               capture_output=True, text=True, timeout=180)
        except (OSError, subprocess.TimeoutExpired) as e:
            return missing("render_girder_stresses.py did not finish (%s)" % e)
        if p.returncode != 0 or not os.path.isfile(picture):
            last = (p.stderr or p.stdout).strip().splitlines()
            return missing("render_girder_stresses.py failed (%s)" % (
                last[-1] if last else "exit code %d" % p.returncode))
        if plt is not None:  # smaller: 1000 pixels wide
            import matplotlib.image
            pixels = matplotlib.image.imread(picture)
            h, w = pixels.shape[:2]
            fig = plt.figure(figsize=(10, 10 * h / w))
            fig.add_axes((0, 0, 1, 1)).imshow(pixels)
            fig.axes[0].set_axis_off()
            tag = png(fig)
        else:
            with open(picture, "rb") as f:
                tag = image_tag(f.read(), "stress envelope")
    label = "the largest von Mises stress of each cell over the run (stress_envelope.vtu%s)" % (
        " of member %s" % member if member else "")
    return para(label) + tag
