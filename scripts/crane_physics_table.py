#!/usr/bin/python3
"""What wheel friction and the load's pendulum change in the seismic response
of the default crane (issue #17): four runs of
parameter_files/bridge_crane_full_explicit.prm (CD-Lagrange, Rinaldi 228
along X and Rinaldi UP along Z, static start) with Travel = tied | braked and
Hoist = rigid | rope, one table (printed, Markdown) and one PNG.

Usage: scripts/crane_physics_table.py [END_TIME] [--hati build/hati]
         [--out output/crane_physics] [--jobs 1] [--reuse] [--png FILE]
         [--set "Subsection/Entry=value" ...]
END_TIME: s of the record (default 8). --reuse keeps a run whose
summary.json says "completed" for the same END_TIME.

Figures per run (summary.json and history.csv of each run):
- peak vertical wheel force: the largest `peak_mean_force` (mean over the
  1 ms contact force window) among the crane wheels and the trolley wheels;
- peak friction force: the largest `peak_friction_force` (idem, the
  tangential force of the wheel on its rail) and the largest
  `slip_distance` among the crane and the trolley wheels (tied: no
  friction, the crane is held along X by supports and the trolley along Y
  by a bilateral tie);
- uplift: the largest `uplift_time` (time out of contact) of a crane wheel
  and of a trolley wheel;
- girder moments: `section_force_envelope` My and Mz (largest |M| of the
  girders, local axes; My bends the girder vertically, Mz horizontally);
- absolute accelerations of the trolley's centre (node `hoist`) and of the
  load (node `load` with the rope, `hoist` with the rigid hoist): from the
  translations of history.csv (velocities differenced between rows plus the
  ground acceleration of the record, linear between its samples), because
  `max_absolute_acceleration` of summary.json also sums the rotations of a
  frame node into its norm; the norm and its horizontal (X) part;
- rope: the largest tension, the least, and the time slack.
"""
import argparse
import json
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PRM = os.path.join(ROOT, "parameter_files", "bridge_crane_full_explicit.prm")
RECORD_X = os.path.join(ROOT, "data", "accelerograms", "Rinaldi228.AT2")
RECORD_Z = os.path.join(ROOT, "data", "accelerograms", "RinaldiUP.AT2")
G_UNITS = 9.80665  # the records' unit g (hati's standard gravity)
RUNS = [("tied", "rigid"), ("braked", "rigid"), ("tied", "rope"), ("braked", "rope")]
CRANE_WHEELS = ["crane_wheel_%d" % k for k in range(1, 5)]
TROLLEY_WHEELS = ["trolley_wheel_%d" % k for k in range(1, 5)]


def read_at2(path):
    """(dt, acceleration in m/s^2) of a PEER AT2 record."""
    with open(path) as f:
        lines = f.readlines()
    header = lines[3].upper().replace(",", " ").split()
    npts = int(header[header.index("NPTS=") + 1])
    dt = float(header[header.index("DT=") + 1])
    values = np.array([float(x) for line in lines[4:] for x in line.split()])[:npts]
    return dt, values * G_UNITS


def ground(record, t):
    """The record at the times t, linear between its samples, 0 after it."""
    dt, a = record
    return np.interp(t, np.arange(len(a)) * dt, a, right=0.0)


def read_history(path):
    with open(path) as f:
        names = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    return {n: data[:, i] for i, n in enumerate(names)}


def absolute_acceleration(h, node, records):
    """Largest norm of the translational absolute acceleration of node and
    largest |a_x| (m/s^2), between history rows."""
    t = h["time"]
    tm = 0.5 * (t[1:] + t[:-1])
    comps = []
    for c, rec in zip("xyz", records):
        a = np.diff(h["%s.v%s" % (node, c)]) / np.diff(t)
        if rec is not None:
            a = a + ground(rec, tm)
        comps.append(a)
    norm = np.sqrt(sum(a * a for a in comps))
    return float(norm.max()), float(np.abs(comps[0]).max())


def run(args, travel, hoist):
    tag = "%s_%s" % (travel, hoist)
    out = os.path.join(args.out, tag)
    summary = os.path.join(out, "summary.json")
    if args.reuse and os.path.exists(summary):
        with open(summary) as f:
            s = json.load(f)
        if s.get("status") == "completed" and abs(s.get("end_time", -1) - args.end_time) < 1e-9:
            return tag, out
    cmd = [args.hati, PRM,
           "--set", "Model/Bridge crane/Travel=" + travel,
           "--set", "Model/Bridge crane/Hoist=" + hoist,
           "--set", "Time integration/End time=%g" % args.end_time,
           "--set", "Output/Output interval=0",
           "--set", "Output/Output directory=" + out]
    for extra in args.set:
        cmd += ["--set", extra]
    print("run: %s" % " ".join("'%s'" % c if " " in c else c for c in cmd), flush=True)
    with open(os.path.join(args.out, tag + ".log"), "w") as log:
        r = subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT, cwd=ROOT)
    if r.returncode != 0:
        sys.exit("crane_physics_table: the run %s failed (%s.log)" % (tag, os.path.join(args.out, tag)))
    return tag, out


def figures(out, hoist, records):
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    w = s["wheels"]
    h = read_history(os.path.join(out, "history.csv"))
    env = s["section_force_envelope"]
    load = "load" if hoist == "rope" else "hoist"
    a_trolley, ax_trolley = absolute_acceleration(h, "hoist", records)
    a_load, ax_load = absolute_acceleration(h, load, records)
    rope = s.get("rope_tension", {}).get("hoist_rope")

    def peak(names, key):
        values = [w[n][key] for n in names if key in w[n]]
        return max(values) if values else None

    return {
        "F_v crane (kN)": peak(CRANE_WHEELS, "peak_mean_force") / 1e3,
        "F_v trolley (kN)": peak(TROLLEY_WHEELS, "peak_mean_force") / 1e3,
        "F_h crane (kN)": (lambda v: None if v is None else v / 1e3)(peak(CRANE_WHEELS, "peak_friction_force")),
        "F_h trolley (kN)": (lambda v: None if v is None else v / 1e3)(peak(TROLLEY_WHEELS, "peak_friction_force")),
        "slip crane (mm)": (lambda v: None if v is None else v * 1e3)(peak(CRANE_WHEELS, "slip_distance")),
        "slip trolley (mm)": (lambda v: None if v is None else v * 1e3)(peak(TROLLEY_WHEELS, "slip_distance")),
        "uplift crane (s)": peak(CRANE_WHEELS, "uplift_time"),
        "uplift trolley (s)": peak(TROLLEY_WHEELS, "uplift_time"),
        "girder My (kN m)": env["My"]["max_abs"] / 1e3,
        "girder Mz (kN m)": env["Mz"]["max_abs"] / 1e3,
        "a trolley (m/s2)": a_trolley,
        "a_x trolley (m/s2)": ax_trolley,
        "a load (m/s2)": a_load,
        "a_x load (m/s2)": ax_load,
        "rope T max (kN)": rope["max"] / 1e3 if rope else None,
        "rope T min (kN)": rope["min"] / 1e3 if rope else None,
        "rope slack (s)": rope["slack_time"] if rope else None,
        "warnings (count)": len(s.get("warnings", [])),
    }


def cell(v):
    if v is None:
        return "-"
    if isinstance(v, int):
        return str(v)
    return "%.4g" % v if abs(v) < 1e5 else "%.0f" % v


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("end_time", nargs="?", type=float, default=8.0)
    p.add_argument("--hati", default=os.path.join(ROOT, "build", "hati"))
    p.add_argument("--out", default=os.path.join(ROOT, "output", "crane_physics"))
    p.add_argument("--jobs", type=int, default=1)
    p.add_argument("--reuse", action="store_true")
    p.add_argument("--png")
    p.add_argument("--set", action="append", default=[],
                   help="one more --set for every run, e.g. "
                        "'Model/Bridge crane/Eccentricities=false' (repeatable)")
    args = p.parse_args()
    if not os.access(args.hati, os.X_OK):
        sys.exit("crane_physics_table: %s is not an executable: build hati first "
                 "(scripts/setup.sh hati) or give --hati" % args.hati)
    args.out = os.path.abspath(args.out)
    os.makedirs(args.out, exist_ok=True)
    png = args.png or os.path.join(args.out, "crane_physics.png")
    records = [read_at2(RECORD_X), None, read_at2(RECORD_Z)]

    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        done = list(pool.map(lambda r: run(args, *r), RUNS))
    results = {tag: figures(out, tag.split("_")[1], records) for tag, out in done}
    tags = [tag for tag, _ in done]

    keys = list(results[tags[0]].keys())
    pga = [float(np.abs(records[i][1]).max()) for i in (0, 2)]
    print("\nThe default crane, Rinaldi 228 (X, PGA %.2f m/s2) + UP (Z, PGA %.2f m/s2), "
          "%g s, CD-Lagrange dt = 2e-5 s\n" % (pga[0], pga[1], args.end_time))
    print("| | " + " | ".join("Travel = %s, Hoist = %s" % tuple(t.split("_")) for t in tags) + " |")
    print("|---|" + "---:|" * len(tags))
    for k in keys:
        print("| %s | " % k + " | ".join(cell(results[t][k]) for t in tags) + " |")

    panels = [("F_v crane (kN)", "F_v trolley (kN)", "peak vertical wheel force (kN)"),
              ("F_h crane (kN)", "F_h trolley (kN)", "peak friction force (kN)"),
              ("slip crane (mm)", "slip trolley (mm)", "largest slip distance (mm)"),
              ("uplift crane (s)", "uplift trolley (s)", "largest time out of contact (s)"),
              ("girder My (kN m)", "girder Mz (kN m)", "girder moment envelope (kN m)"),
              ("a_x trolley (m/s2)", "a_x load (m/s2)", "peak absolute acceleration along X (m/s^2)")]
    fig, axes = plt.subplots(2, 3, figsize=(14, 7.5))
    x = np.arange(len(tags))
    labels = ["%s\n%s" % tuple(t.split("_")) for t in tags]
    for ax, (k1, k2, title) in zip(axes.flat, panels):
        for off, k, colour in ((-0.2, k1, "C0"), (0.2, k2, "C1")):
            v = [results[t][k] or 0.0 for t in tags]
            ax.bar(x + off, v, 0.4, color=colour, label=k.split(" (")[0])
        ax.set_xticks(x)
        ax.set_xticklabels(labels, fontsize=8)
        ax.set_title(title, fontsize=10)
        ax.grid(axis="y", alpha=0.3)
        if k1.startswith("a_x"):
            ax.axhline(pga[0], color="k", ls="--", lw=0.8, label="PGA X")
            ax.set_yscale("log")
        ax.legend(fontsize=7)
    fig.suptitle("Default crane under Rinaldi 228 + UP (%g s): Travel tied/braked, "
                 "Hoist rigid/rope" % args.end_time)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print("\nplot: %s" % png)


if __name__ == "__main__":
    main()
