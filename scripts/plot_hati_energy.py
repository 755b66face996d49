#!/usr/bin/python3
"""Energy terms of coupled (HATI) runs, one column of plots per run:
kinetic and internal energies of the explicit and implicit subdomains and
the external work (top), the interface work and the balance drift (bottom,
with their ratio to the external work in the legend).

Usage: scripts/plot_hati_energy.py OUTPUT.png RUN_DIRECTORY [RUN_DIRECTORY ...]
e.g. for the reference bar at m = 1 and m = 10:
  for m in 1 10; do build/hati parameter_files/bar_split_wave.prm \\
      --set "Time integration/HATI/Time step ratio=$m" \\
      --set "Output/Output directory=output/bar_split_wave_m$m"; done
  scripts/plot_hati_energy.py bar_split_wave_energy.png \\
      output/bar_split_wave_m1 output/bar_split_wave_m10"""
import json
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

if len(sys.argv) < 3:
    sys.exit(__doc__)
png, runs = sys.argv[1], sys.argv[2:]
fig, axes = plt.subplots(2, len(runs), figsize=(6 * len(runs), 7), squeeze=False, sharex="col")
for c, run in enumerate(runs):
    e = np.genfromtxt(os.path.join(run, "energy.csv"), delimiter=",", names=True)
    with open(os.path.join(run, "summary.json")) as f:
        s = json.load(f)
    t = e["time"]
    title = "%s: %s, m = %s" % (os.path.basename(run.rstrip("/")), s.get("method", "?"),
                                s.get("time_step_ratio", "-"))
    top = axes[0][c]
    for name, style in (("kinetic_explicit", "C0-"), ("internal_explicit", "C0--"),
                        ("kinetic_implicit", "C1-"), ("internal_implicit", "C1--"),
                        ("external_work", "k-")):
        top.plot(t, e[name], style, label=name.replace("_", " "))
    top.set_title(title)
    top.set_ylabel("energy (J)")
    top.legend(fontsize=8)
    top.grid(alpha=0.3)
    bottom = axes[1][c]
    w = e["external_work"][-1]
    bottom.plot(t, e["interface_work"], "C3-",
                label="interface work (end: %.2e of external work)" % (e["interface_work"][-1] / w))
    bottom.plot(t, e["balance_drift"], "C2-",
                label="balance drift (end: %.1e of external work)" % (e["balance_drift"][-1] / w))
    bottom.set_xlabel("time (s)")
    bottom.set_ylabel("energy (J)")
    bottom.legend(fontsize=8)
    bottom.grid(alpha=0.3)
fig.tight_layout()
fig.savefig(png, dpi=110)
print("wrote %s" % png)
