#!/usr/bin/python3
"""Plots of a bridge crane run (paper Fig. 8): the Z displacement of the four
trolley wheels (history.csv columns tw1.uz ... tw4.uz, relative to the
ground), every wheel's height above its rail (contacts.csv gap: above zero
the wheel has lifted off, paper Figs. 8-9), the vertical contact force of
every wheel (contacts.csv), and, when
the run has them, the slip velocity of the wheels with friction (contacts.csv
slip_velocity; their slip distances from summary.json in the legend) and the
rope tension (history.csv hoist_rope.tension), as one PNG.

Usage: scripts/plot_crane.py RUN_DIRECTORY [--png FILE]
(default FILE: RUN_DIRECTORY/crane.png)"""
import argparse
import json
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
    contact_names = [n for n in dict.fromkeys(c["contact"])
                     if not (n.endswith("_lateral") or n.endswith("_travel"))]
    friction = "slip_velocity" in c.dtype.names
    ropes = [n[:-len("tension")] for n in h.dtype.names if n.endswith("tension")]
    summary = {}
    if os.path.exists(os.path.join(a.run, "summary.json")):
        with open(os.path.join(a.run, "summary.json")) as f:
            summary = json.load(f)
    panels = 3 + friction + bool(ropes)
    fig, ax = plt.subplots(panels, 1, figsize=(11, 3.75 * panels), sharex=True)
    for k in range(1, 5):
        column = "tw%duz" % k
        if column in h.dtype.names:
            ax[0].plot(h["time"], 1e3 * h[column], lw=0.8, label="trolley wheel %d" % k)
    ax[0].set_ylabel("Z displacement (mm)")
    ax[0].set_title("Trolley wheels: Z displacement relative to the ground (paper Fig. 8)")
    ax[0].grid(alpha=0.3)
    ax[0].legend(fontsize=8)
    for name in contact_names:
        sel = c["contact"] == name
        ax[1].plot(c["time"][sel], 1e3 * np.maximum(c["gap"][sel], 0.), lw=0.8, label=name)
    ax[1].set_ylabel("height above the rail (mm)")
    ax[1].set_title("Wheel uplift: the vertical contacts' gaps (0: on the rail)")
    ax[1].grid(alpha=0.3)
    ax[1].legend(fontsize=7, ncol=2)
    for name in contact_names:
        sel = c["contact"] == name
        ax[2].plot(c["time"][sel], 1e-3 * c["force"][sel], lw=0.7, label=name)
    ax[2].set_ylabel("vertical wheel force (kN)")
    ax[2].set_title("Wheel contact forces at the output times")
    ax[2].grid(alpha=0.3)
    ax[2].legend(fontsize=7, ncol=2)
    panel = 3
    if friction:
        wheels = summary.get("wheels", {})
        for name in contact_names:
            sel = c["contact"] == name
            if not np.any(c["slip_velocity"][sel] != 0.):
                continue
            distance = wheels.get(name, {}).get("slip_distance")
            label = name if distance is None else "%s (slip %.3f m)" % (name, distance)
            ax[panel].plot(c["time"][sel], c["slip_velocity"][sel], lw=0.7, label=label)
        ax[panel].set_ylabel("slip velocity (m/s)")
        ax[panel].set_title("Wheel slips (Coulomb friction) at the output times")
        ax[panel].grid(alpha=0.3)
        if ax[panel].get_legend_handles_labels()[0]:
            ax[panel].legend(fontsize=7, ncol=2)
        panel += 1
    if ropes:
        for rope in ropes:
            ax[panel].plot(h["time"], 1e-3 * h[rope + "tension"], lw=0.7,
                           label=rope.rstrip("."))
        ax[panel].set_ylabel("rope tension (kN)")
        ax[panel].set_title("Hoist rope tension (0: slack)")
        ax[panel].grid(alpha=0.3)
        ax[panel].legend(fontsize=8)
    ax[-1].set_xlabel("time (s)")
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print("plot: %s" % png)


if __name__ == "__main__":
    main()
