#!/usr/bin/python3
"""rsa_comparison.png: what the nonlinear time histories of a suite give
against the linear response-spectrum analysis of the same model at the same
target (doc/user_guide.md, "Response-spectrum analysis and what the time
history saves"), from the suite folder's rsa_comparison.csv. Left: both
values of every quantity, grouped by kind (wheel forces, girder section
forces, accelerations, stresses); right: their ratio response spectrum /
time history (above 1: the linear method overestimates). hati's rank 0
runs it at the end of a suite with a Design spectrum; exit code 3 without
matplotlib; a link at rsa_comparison.png is refused (exit code 1).

Usage: scripts/plot_rsa_comparison.py SUITE_FOLDER"""
import csv
import os
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("plot_rsa_comparison.py: matplotlib is not installed (python3-matplotlib)")
    sys.exit(3)

from plot_tools import save  # noqa: E402 (scripts/plot_tools.py)

KINDS = [(".peak_mean_force", "wheel forces (kN)", 1e-3),
         ("section_force.", "girder section forces (kN, kN m)", 1e-3),
         (".max_absolute_acceleration", "absolute accelerations (m/s^2)", 1.0),
         (".max_von_mises", "von Mises stress (MPa)", 1e-6)]


def kind_of(quantity):
    for k, (key, _, _) in enumerate(KINDS):
        if key in quantity:
            return k
    return None


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    folder = sys.argv[1]
    with open(os.path.join(folder, "rsa_comparison.csv")) as f:
        rows = list(csv.DictReader(f))
    groups = {}
    for r in rows:
        k = kind_of(r["quantity"])
        if k is not None:
            groups.setdefault(k, []).append(r)
    if not groups:
        return 0
    kinds = sorted(groups)
    height = max(3.0, 0.28 * len(rows) + 1.2 * len(kinds))
    fig, axes = plt.subplots(len(kinds), 2, figsize=(11, height), squeeze=False,
                             gridspec_kw={"height_ratios": [len(groups[k]) + 1 for k in kinds]})
    for (ax, ax_ratio), k in zip(axes, kinds):
        _, title, scale = KINDS[k]
        names = [r["quantity"].replace(KINDS[k][0], "").replace(".", " ") or r["quantity"]
                 for r in groups[k]]
        y = range(len(names))
        th = [float(r["time_history"]) * scale for r in groups[k]]
        rs = [float(r["response_spectrum"]) * scale for r in groups[k]]
        ax.barh([i + 0.2 for i in y], th, 0.4, label="time history", color="tab:blue")
        ax.barh([i - 0.2 for i in y], rs, 0.4, label="response spectrum", color="tab:orange")
        ax.set_yticks(list(y))
        ax.set_yticklabels(names, fontsize=7)
        ax.invert_yaxis()
        ax.set_title(title, fontsize=9)
        ax.grid(alpha=0.3, axis="x")
        ratio = [float(r["ratio"]) for r in groups[k]]
        ax_ratio.barh(list(y), ratio, 0.6,
                      color=["tab:red" if q < 1 else "tab:green" for q in ratio])
        ax_ratio.axvline(1.0, color="k", lw=1)
        ax_ratio.set_yticks(list(y))
        ax_ratio.set_yticklabels([])
        ax_ratio.invert_yaxis()
        ax_ratio.set_title("ratio response spectrum / time history", fontsize=9)
        ax_ratio.grid(alpha=0.3, axis="x")
    axes[0, 0].legend(fontsize=7)
    fig.suptitle("linear response spectrum against the nonlinear time histories "
                 "(green: the linear method gives more)", fontsize=10)
    fig.tight_layout()
    save(fig, folder, "rsa_comparison.png", "plot_rsa_comparison.py")
    return 0


if __name__ == "__main__":
    sys.exit(main())
