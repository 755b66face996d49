#!/usr/bin/python3
"""Plots of a suite of records (doc/user_guide.md, "Qualifying a crane on a
suite of records"): suite.png, the key results of every member (suite.csv)
with the statistic of each group of scale factor and variation
(suite_summary.json), and spectra.png, the pseudo-acceleration spectra of
every member (its spectra.csv) with their statistic (suite_spectra.csv).
hati's rank 0 runs it at the end of a suite; exit code 3 without matplotlib.
A plot is drawn into a temporary file created exclusively in the folder and
renamed over its name: never written through a link there (a link at
suite.png or spectra.png is refused, exit code 1, its target untouched).

Usage: scripts/plot_suite.py SUITE_FOLDER"""
import csv
import json
import math
import os
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("plot_suite.py: matplotlib is not installed (python3-matplotlib)")
    sys.exit(3)

from plot_tools import save  # noqa: E402 (scripts/plot_tools.py)

# quantity suffix -> panel title (units)
CATEGORIES = [
    ("peak_mean_force", "peak mean wheel force (N)"),
    ("slip_distance", "wheel slip (m)"),
    ("uplift_time", "wheel uplift time (s)"),
    ("section_force", "section-force envelope (N, N m)"),
    ("max_absolute_acceleration", "peak absolute acceleration (m/s^2)"),
    ("max_tension", "peak rope tension (N)"),
]


def category(quantity):
    for key, _ in CATEGORIES:
        if quantity.startswith(key + ".") or quantity.endswith("." + key):
            return key
    return None


def number(text):
    try:
        return float(text)
    except ValueError:
        return math.nan


def group_key(row):
    return (number(row["scale"]), int(row["variation"]))


def plot_results(folder, rows, summary):
    fixed = {"member", "record", "scale", "variation", "status", "error", "wall_time"}
    quantities = [q for q in rows[0].keys() if q not in fixed and category(q)]
    panels = [(k, t) for k, t in CATEGORIES if any(category(q) == k for q in quantities)]
    if not panels:
        return
    groups = sorted({group_key(r) for r in rows})
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    fig, axes = plt.subplots(len(panels), 1, figsize=(11, 3.2 * len(panels)), squeeze=False)
    for ax, (key, title) in zip(axes[:, 0], panels):
        names = [q for q in quantities if category(q) == key]
        for g, group in enumerate(groups):
            members = [r for r in rows if group_key(r) == group and
                       r["status"] in ("completed", "reused")]
            shift = (g - (len(groups) - 1) / 2) * 0.8 / max(len(groups), 1)
            for r in members:
                ax.plot([i + shift for i in range(len(names))],
                        [number(r[q]) for q in names], "o", ms=4, alpha=0.6,
                        color=colours[g % len(colours)])
            stats = next((s for s in summary["groups"]
                          if (s["scale"], s["variation"]) == group), None)
            if stats:
                values = [stats["quantities"].get(q, {}).get("value", math.nan)
                          for q in names]
                ax.plot([i + shift for i in range(len(names))], values, "_", ms=18,
                        mew=2.5, color=colours[g % len(colours)],
                        label="scale %g, variation %d: %s" % (group[0], group[1],
                                                              summary["statistic"]))
        ax.set_xticks(range(len(names)))
        ax.set_xticklabels([q.replace("." + key, "").replace(key + ".", "")
                            for q in names], rotation=30, fontsize=8)
        ax.set_title(title, fontsize=10)
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=7)
    failed = [r["member"] for r in rows if r["status"] not in ("completed", "reused")]
    fig.suptitle("suite %s: %d members (dots), %s per group (bars)%s"
                 % (os.path.basename(os.path.normpath(folder)), len(rows),
                    summary["statistic"],
                    "; not usable: " + ", ".join(failed) if failed else ""), fontsize=10)
    # the suptitle above the first panel's title: tight_layout leaves it out
    # of its boxes, so keep 0.45 inch at the top for it
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.45 / fig.get_figheight()))
    save(fig, folder, "suite.png", "plot_suite.py")


def read_table(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def plot_spectra(folder, rows):
    path = os.path.join(folder, "suite_spectra.csv")
    if not os.path.exists(path):
        return
    statistic_rows = read_table(path)
    ratios = sorted({number(r["damping_ratio"]) for r in statistic_rows})
    ratio = min(ratios, key=lambda x: abs(x - 0.05))
    channels = [c for c in statistic_rows[0].keys()
                if c not in ("scale", "variation", "damping_ratio", "period")]
    n = len(channels)
    cols = min(n, 3)
    fig, axes = plt.subplots((n + cols - 1) // cols, cols, figsize=(4.2 * cols, 3.4 * ((n + cols - 1) // cols)),
                             squeeze=False)
    for ax, channel in zip(axes.flat, channels):
        for r in rows:
            member_file = os.path.join(folder, r["member"], "spectra.csv")
            if r["status"] not in ("completed", "reused") or not os.path.exists(member_file):
                continue
            table = [t for t in read_table(member_file)
                     if number(t["damping_ratio"]) == ratio and channel in t]
            ax.loglog([number(t["period"]) for t in table],
                      [number(t[channel]) for t in table], lw=0.7, alpha=0.5, color="grey")
        for group in sorted({group_key(r) for r in statistic_rows}):
            table = [t for t in statistic_rows if group_key(t) == group and
                     number(t["damping_ratio"]) == ratio]
            ax.loglog([number(t["period"]) for t in table],
                      [number(t[channel]) for t in table], lw=2,
                      label="scale %g, variation %d" % group)
        ax.set_title("%s, %g %% damping" % (channel, 100 * ratio), fontsize=9)
        ax.set_xlabel("period (s)")
        ax.set_ylabel("S_a (m/s^2)")
        ax.grid(alpha=0.3, which="both")
    for ax in list(axes.flat)[n:]:
        ax.set_visible(False)
    axes[0, 0].legend(fontsize=7)
    fig.suptitle("pseudo-acceleration spectra: members (grey) and the statistic", fontsize=10)
    fig.tight_layout()
    save(fig, folder, "spectra.png", "plot_suite.py")


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    folder = sys.argv[1]
    rows = read_table(os.path.join(folder, "suite.csv"))
    with open(os.path.join(folder, "suite_summary.json")) as f:
        summary = json.load(f)
    if rows:
        plot_results(folder, rows, summary)
        plot_spectra(folder, rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
