#!/usr/bin/python3
"""Plots of a bridge crane run (paper Fig. 8): the Z displacement of the four
trolley wheels (history.csv columns tw1.uz ... tw4.uz, relative to the
ground) and the vertical contact force of every wheel (contacts.csv), as one
PNG.

Usage: scripts/plot_crane.py RUN_DIRECTORY [--png FILE]
(default FILE: RUN_DIRECTORY/crane.png)"""
import argparse
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("run")
    p.add_argument("--png")
    a = p.parse_args()
    png = a.png or os.path.join(a.run, "crane.png")
    h = np.genfromtxt(os.path.join(a.run, "history.csv"), delimiter=",", names=True)
    c = np.genfromtxt(os.path.join(a.run, "contacts.csv"), delimiter=",", names=True,
                      dtype=None, encoding=None)
    fig, ax = plt.subplots(2, 1, figsize=(11, 7.5), sharex=True)
    for k in range(1, 5):
        column = "tw%duz" % k
        if column in h.dtype.names:
            ax[0].plot(h["time"], 1e3 * h[column], lw=0.8, label="trolley wheel %d" % k)
    ax[0].set_ylabel("Z displacement (mm)")
    ax[0].set_title("Trolley wheels: Z displacement relative to the ground (paper Fig. 8)")
    ax[0].grid(alpha=0.3)
    ax[0].legend(fontsize=8)
    for name in dict.fromkeys(c["contact"]):
        if name.endswith("_lateral") or name.endswith("_travel"):
            continue
        sel = c["contact"] == name
        ax[1].plot(c["time"][sel], 1e-3 * c["force"][sel], lw=0.7, label=name)
    ax[1].set_xlabel("time (s)")
    ax[1].set_ylabel("vertical wheel force (kN)")
    ax[1].set_title("Wheel contact forces at the output times")
    ax[1].grid(alpha=0.3)
    ax[1].legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print("plot: %s" % png)


if __name__ == "__main__":
    main()
