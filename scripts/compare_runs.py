#!/usr/bin/python3
"""Compare two runs with contacts (e.g. fully explicit vs HATI, paper Fig. 9).

Prints, per contact name of contacts.csv:
- the contact-loss episodes of both runs: maximal intervals without contact
  impulse after the first contact (start = first step without impulse,
  end = first step with impulse again; an episode still open at the end of
  the run ends with "open"), matched by order, with their differences; from
  contact_episodes.csv (every step) when both runs wrote it, else from the
  rows of contacts.csv;
- the peak contact force of both runs (summary.json, every step, or
  contacts.csv) and its difference;
and the wall times of both runs (summary.json) and the speed-up of B over A.
With --monitor COLUMN (a history.csv column, e.g. tw1.uz) it also draws
COLUMN of both runs against time, full length and a zoom (--zoom t0,t1;
default: around the longest contact-loss episode of run A), as PNG; with
--gap CONTACT (a contacts.csv contact, e.g. trolley_wheel_1) also that
contact's gap in mm (the wheel's height above its rail: paper Fig. 9).

Usage: scripts/compare_runs.py RUN_A RUN_B [--monitor COLUMN] [--gap CONTACT]
                               [--zoom T0,T1] [--png FILE] [--min-duration S]
Episodes shorter than --min-duration (s, default 0) are ignored (chatter).
Exit code 0; the numbers are for the user (and tests) to judge."""
import argparse
import json
import os
import sys

import numpy as np


def read_csv(path):
    return np.atleast_1d(np.genfromtxt(path, delimiter=",", names=True, dtype=None,
                                       encoding=None))


def episodes(t, impulse, min_duration):
    """Contact-loss episodes (start, end or None) after the first contact."""
    on = impulse > 0
    if not on.any():
        return []
    first = np.argmax(on)
    result, start = [], None
    for i in range(first, len(t)):
        if not on[i] and start is None:
            start = t[i]
        elif on[i] and start is not None:
            if t[i] - start >= min_duration:
                result.append((start, t[i]))
            start = None
    if start is not None:
        result.append((start, None))
    return result


def contact_table(run):
    c = read_csv(os.path.join(run, "contacts.csv"))
    names = list(dict.fromkeys(c["contact"]))
    return {n: c[c["contact"] == n] for n in names}


def step_episodes(run, min_duration):
    """Contact-loss episodes at the step resolution (contact_episodes.csv),
    per contact name, or None if the run did not write the file."""
    path = os.path.join(run, "contact_episodes.csv")
    if not os.path.exists(path):
        return None
    result = {}
    with open(path) as f:
        next(f)
        for line in f:
            name, start, end, _ = line.rstrip("\n").split(",")
            start = float(start)
            end = float(end) if end else None
            if end is None or end - start >= min_duration:
                result.setdefault(name, []).append((start, end))
    return result


def summary(run):
    with open(os.path.join(run, "summary.json")) as f:
        return json.load(f)


def fmt(x):
    return "open" if x is None else "%.6f" % x


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("run_a")
    p.add_argument("run_b")
    p.add_argument("--monitor", help="history.csv column to plot (e.g. NODE.uz)")
    p.add_argument("--gap", help="contacts.csv contact whose gap to plot (e.g. trolley_wheel_1)")
    p.add_argument("--zoom", help="t0,t1 of the zoomed plot (s)")
    p.add_argument("--png", default="compare_runs.png", help="output picture")
    p.add_argument("--min-duration", type=float, default=0.0,
                   help="ignore contact-loss episodes shorter than this (s)")
    a = p.parse_args()
    ca, cb = contact_table(a.run_a), contact_table(a.run_b)
    sa, sb = summary(a.run_a), summary(a.run_b)
    xa, xb = step_episodes(a.run_a, a.min_duration), step_episodes(a.run_b, a.min_duration)
    if (xa is None) != (xb is None):
        xa = xb = None  # compare like with like: both from contacts.csv
    print("A: %s (%s)\nB: %s (%s)" % (a.run_a, sa.get("method"), a.run_b, sb.get("method")))
    worst_time, worst_force = 0.0, 0.0
    # the crane's wheels (summary.json "wheels") apart from the lateral and
    # travel contacts, whose flanges chatter
    wheels = set(sa.get("wheels", {}))
    wheel_time, wheel_force = 0.0, 0.0
    longest_episode = None
    for name in ca:
        if name not in cb:
            print("contact %s: only in A" % name)
            continue
        ea = (xa.get(name, []) if xa is not None else
              episodes(ca[name]["time"], ca[name]["impulse"], a.min_duration))
        eb = (xb.get(name, []) if xb is not None else
              episodes(cb[name]["time"], cb[name]["impulse"], a.min_duration))
        # peak force at the step resolution when summary.json has it
        fa = sa.get("contacts", {}).get(name, {}).get("peak_impact_force",
                                                      np.max(ca[name]["force"]))
        fb = sb.get("contacts", {}).get(name, {}).get("peak_impact_force",
                                                      np.max(cb[name]["force"]))
        print("\ncontact %s: %d contact-loss episodes in A, %d in B; peak force A %.6g N, "
              "B %.6g N (%+.2f %%)" % (name, len(ea), len(eb), fa, fb,
                                       100 * (fb - fa) / fa if fa else 0.0))
        # the mean force over the force window compares runs with different
        # steps (the force of one step grows as dt falls)
        ma = sa.get("contacts", {}).get(name, {}).get("peak_mean_force")
        mb = sb.get("contacts", {}).get(name, {}).get("peak_mean_force")
        if ma and mb:
            print("  peak mean force over %g s: A %.6g N, B %.6g N (%+.2f %%)"
                  % (sa.get("contact_force_window", 0.0), ma, mb, 100 * (mb - ma) / ma))
            fa, fb = ma, mb
        worst_force = max(worst_force, abs(fb - fa) / fa if fa else 0.0)
        if name in wheels:
            wheel_force = max(wheel_force, abs(fb - fa) / fa if fa else 0.0)
        print("  %3s %12s %12s %12s %12s %11s %11s" % ("#", "start A", "end A", "start B",
                                                    "end B", "d start", "d end"))
        for k in range(max(len(ea), len(eb))):
            sa_, ea_ = ea[k] if k < len(ea) else (None, None)
            sb_, eb_ = eb[k] if k < len(eb) else (None, None)
            ds = sb_ - sa_ if sa_ is not None and sb_ is not None else None
            de = eb_ - ea_ if ea_ is not None and eb_ is not None else None
            for d in (ds, de):
                if d is not None:
                    worst_time = max(worst_time, abs(d))
                    if name in wheels:
                        wheel_time = max(wheel_time, abs(d))
            print("  %3d %12s %12s %12s %12s %11s %11s" % (
                k + 1, fmt(sa_), fmt(ea_), fmt(sb_), fmt(eb_),
                "-" if ds is None else "%+.2e" % ds, "-" if de is None else "%+.2e" % de))
            if sa_ is not None:
                span = (sa_, ea_ if ea_ is not None else sa_ + 0.05)
                if longest_episode is None or (span[1] - span[0] >
                                               longest_episode[1] - longest_episode[0]):
                    longest_episode = span
    wa, wb = sa.get("stepping_wall_time", sa["wall_time"]), sb.get("stepping_wall_time",
                                                                   sb["wall_time"])
    print("\nlargest difference of episode start/end times: %.3e s; of peak forces: %.2f %%"
          % (worst_time, 100 * worst_force))
    if wheels:
        print("wheels only (summary.json \"wheels\"): largest difference of episode start/end "
              "times %.3e s; of peak forces %.2f %%" % (wheel_time, 100 * wheel_force))
    print("wall time of the time stepping: A %.3f s, B %.3f s, speed-up of B over A %.2f"
          % (wa, wb, wa / wb if wb > 0 else float("nan")))
    if a.monitor or a.gap:
        plot(a, sa, sb, ca, cb, longest_episode)


def plot(a, sa, sb, ca, cb, longest_episode):
    """The monitor column and/or the contact gap of both runs, whole run and
    zoom, one row each."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = []  # (title, ylabel, [(t, y) of A, (t, y) of B])
    if a.monitor:
        ha = read_csv(os.path.join(a.run_a, "history.csv"))
        hb = read_csv(os.path.join(a.run_b, "history.csv"))
        column = a.monitor.replace(".", "")  # numpy drops the dot of NODE.uz
        if column not in ha.dtype.names or column not in hb.dtype.names:
            sys.exit("compare_runs.py: no column %s in history.csv" % a.monitor)
        rows.append((a.monitor, a.monitor + " (m)",
                     [(h["time"], h[column]) for h in (ha, hb)]))
    if a.gap:
        if a.gap not in ca or a.gap not in cb:
            sys.exit("compare_runs.py: no contact %s in contacts.csv" % a.gap)
        rows.append(("%s gap" % a.gap, "%s gap (mm)" % a.gap,
                     [(c[a.gap]["time"], 1e3 * c[a.gap]["gap"]) for c in (ca, cb)]))
    t_all = np.concatenate([t for _, _, runs in rows for t, _ in runs])
    if a.zoom:
        z0, z1 = (float(x) for x in a.zoom.split(","))
    elif longest_episode:
        z0, z1 = longest_episode[0] - 0.02, longest_episode[1] + 0.02
    else:
        z0, z1 = t_all.min(), t_all.max()
    fig, ax = plt.subplots(len(rows), 2, figsize=(13, 4.5 * len(rows)), squeeze=False)
    for (title, ylabel, runs), axes in zip(rows, ax):
        for axis, (lo, hi) in zip(axes, ((t_all.min(), t_all.max()), (z0, z1))):
            for (t, y), label, style in zip(runs, ("A: " + str(sa.get("method")),
                                                   "B: " + str(sb.get("method"))),
                                            ("k-", "C3--")):
                sel = (t >= lo) & (t <= hi)
                axis.plot(t[sel], y[sel], style, label=label)
            axis.set_xlabel("time (s)")
            axis.set_ylabel(ylabel)
            axis.grid(alpha=0.3)
            axis.legend()
        axes[0].set_title("%s: whole run" % title)
        axes[1].set_title("%s: zoom %.3f-%.3f s" % (title, z0, z1))
    fig.tight_layout()
    fig.savefig(a.png, dpi=110)
    print("wrote %s" % a.png)

if __name__ == "__main__":
    main()
