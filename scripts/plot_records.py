#!/usr/bin/python3
"""Plot of spectrum-compatible artificial records (doc/user_guide.md,
"Qualifying against a design spectrum"): records.png, the acceleration
history of every record (its AT2 file, listed in records.csv) per component,
and the 5 % pseudo-acceleration spectra of the records (records_spectra.csv)
against their target with the matching tolerance band and their mean.
hati runs it after generating the records; exit code 3 without matplotlib.
The plot is drawn into a temporary file created exclusively in the folder
and renamed over records.png: never written through a link.

Usage: scripts/plot_records.py RECORDS_FOLDER"""
import csv
import os
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("plot_records.py: matplotlib is not installed (python3-matplotlib)")
    sys.exit(3)

from plot_tools import save  # noqa: E402 (scripts/plot_tools.py)

G = 9.80665


def read_table(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def read_at2(path):
    with open(path) as f:
        lines = f.read().splitlines()
    header = lines[3].replace(",", " ").split()
    n = int(header[header.index("NPTS=") + 1])
    dt = float(header[header.index("DT=") + 1])
    values = [float(x) * G for line in lines[4:] for x in line.split()][:n]
    return [i * dt for i in range(n)], values


def main(folder):
    records = read_table(os.path.join(folder, "records.csv"))
    spectra = read_table(os.path.join(folder, "records_spectra.csv"))
    components = sorted({r["component"] for r in records})
    fig, axes = plt.subplots(2, len(components), figsize=(6.5 * len(components), 8.5),
                             squeeze=False)
    periods = [float(row["period"]) for row in spectra]
    for c, axis in enumerate(components):
        mine = [r for r in records if r["component"] == axis]
        top = axes[0][c]
        for k, r in enumerate(mine):
            t, a = read_at2(os.path.join(folder, r["file"]))
            offset = 2.5 * float(r["target_peak_acceleration"]) * k
            top.plot(t, [x - offset for x in a], lw=0.5, label=r["record"])
        top.set_title("records along %s (offset by record)" % axis)
        top.set_xlabel("time (s)")
        top.set_ylabel("ground acceleration (m/s^2)")
        top.set_yticks([])
        bottom = axes[1][c]
        key = axis.lower()
        target = [float(row["target." + key]) for row in spectra]
        columns = ["%s.%s" % (r["record"], key) for r in mine]
        for name in columns:
            bottom.plot(periods, [float(row[name]) for row in spectra], lw=0.6, alpha=0.7)
        mean = [sum(float(row[n]) for n in columns) / len(columns) for row in spectra]
        bottom.plot(periods, mean, "b", lw=1.5, label="mean of %d records" % len(columns))
        bottom.plot(periods, target, "k", lw=2, label="target")
        tol = max(float(r["max_deviation"]) for r in mine)
        bottom.fill_between(periods, [x * (1 - tol) for x in target],
                            [x * (1 + tol) for x in target], color="0.85",
                            label="largest deviation %.3f" % tol)
        bottom.plot(periods, [0.9 * x for x in target], "k--", lw=0.8, label="90 % of target")
        bottom.set_xscale("log")
        bottom.set_xlabel("period (s)")
        bottom.set_ylabel("pseudo-acceleration (m/s^2)")
        bottom.set_title("spectra along %s" % axis)
        bottom.legend(fontsize=8)
    fig.tight_layout()
    save(fig, folder, "records.png", "plot_records.py")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    main(sys.argv[1])
