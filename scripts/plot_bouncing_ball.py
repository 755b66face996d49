#!/usr/bin/python3
"""Bouncing ball: numerical (hati) against analytical solution.

Usage: plot_bouncing_ball.py OUTPUT_DIR PNG_FILE

Reads OUTPUT_DIR/history.csv (columns time, ball.uz, ball.vz, ...),
OUTPUT_DIR/parameters.prm (the parameters hati used) and, if present,
OUTPUT_DIR/contacts.csv. Draws the height z(t) = z0 + uz and the vertical
velocity v(t) against the analytical solution (paper Fig. 2-3,
doc/theory.md) into PNG_FILE and prints the first five numerical and
analytical impact times.

Analytical solution (g = -gz > 0, v0 positive upwards, restitution e):
  free flight   z = z0 + v0 t - g t^2 / 2 until
  first impact  t1 = (v0 + sqrt(v0^2 + 2 g z0)) / g, impact speed v1 = g t1 - v0
  next impacts  t_{k+1} = t_k + 2 e^k v1 / g
  Zeno time     t_inf = t1 + 2 e v1 / (g (1 - e)); the ball rests at z = 0 after.

For CD-Lagrange the numerical velocity of row t_n is V_{n+1/2}, the constant
velocity of the step [t_n, t_{n+1}]; it is drawn as a staircase.
"""

import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

MAX_PLOT_ROWS = 20000


def read_prm(filename):
    """Parse a deal.II PRM file into {"Sub/Sub/Entry": "value"}."""
    values = {}
    path = []
    pending = ""
    with open(filename) as f:
        for raw in f:
            line = raw.split("#", 1)[0].rstrip()
            if line.endswith("\\"):  # continuation line
                pending += line[:-1] + " "
                continue
            line = (pending + line).strip()
            pending = ""
            if not line:
                continue
            words = line.split(None, 1)
            if words[0] == "subsection":
                path.append(words[1].strip())
            elif words[0] == "end":
                path.pop()
            elif words[0] == "set":
                name, _, value = words[1].partition("=")
                values["/".join(path + [name.strip()])] = value.strip()
    return values


def read_csv(filename):
    """Columns of a CSV file with a header line, as {name: array}."""
    with open(filename) as f:
        header = f.readline().strip().split(",")
    data = np.atleast_1d(np.genfromtxt(filename, delimiter=",", skip_header=1,
                                       dtype=None, encoding=None))
    if data.dtype.names is None:  # all columns numeric: a 2D array
        data = np.atleast_2d(data)
        return {name: data[:, i] for i, name in enumerate(header)}
    return {name: data[field] for name, field in zip(header, data.dtype.names)}


class BouncingBall:
    """The analytical solution of the bouncing ball."""

    def __init__(self, z0, v0, g, e):
        self.z0, self.v0, self.g, self.e = z0, v0, g, e
        self.t1 = (v0 + np.sqrt(v0 * v0 + 2. * g * z0)) / g
        self.v1 = g * self.t1 - v0  # impact speed (> 0)
        # impact times t_1, t_2, ... until the flights are negligible
        times = [self.t1]
        speeds = []  # take-off speed after impact k: e^k v1
        if e > 0. and self.v1 > 0.:
            k = 1
            while True:
                u = e ** k * self.v1
                flight = 2. * u / g
                speeds.append(u)
                times.append(times[-1] + flight)
                k += 1
                if e >= 1.:
                    if k > 10000:
                        break
                elif flight < 1e-14 * times[-1] or k > 100000:
                    break
        self.impacts = np.array(times)
        self.takeoff = np.array(speeds)
        if e < 1.:
            self.t_inf = self.t1 + 2. * e * self.v1 / (g * (1. - e))
        else:
            self.t_inf = np.inf

    def evaluate(self, t, side="right"):
        """Height z(t) and velocity v(t); at an impact time the velocity is
        the right limit (side="right") or the left limit (side="left")."""
        t = np.asarray(t, dtype=float)
        z = np.zeros_like(t)
        v = np.zeros_like(t)
        before = (t < self.t1) if side == "right" else (t <= self.t1)
        z[before] = self.z0 + self.v0 * t[before] - 0.5 * self.g * t[before] ** 2
        v[before] = self.v0 - self.g * t[before]
        # number of impacts passed
        k = np.searchsorted(self.impacts, t, side=side)
        flying = (~before) & (k >= 1) & (k <= len(self.takeoff)) & (t < self.t_inf)
        kk = k[flying]
        tau = t[flying] - self.impacts[kk - 1]
        u = self.takeoff[kk - 1]
        z[flying] = u * tau - 0.5 * self.g * tau ** 2
        v[flying] = u - self.g * tau
        return z, v


def numerical_impacts(time, vz, contacts):
    """Times of the numerical impacts: the first row of each run of rows with
    a positive impulse in contacts.csv, else (contacts is None) the rows where
    the velocity jumps from negative to positive."""
    if contacts is not None and len(contacts["time"]) > 1:
        names = contacts["contact"]
        rows = names == names[0]
        t = contacts["time"][rows]
        on = contacts["impulse"][rows] > 0.
        start = on & ~np.r_[False, on[:-1]]
        return t[start], "contacts.csv"
    scale = max(np.abs(vz).max(), 1e-300)
    jump = (vz[:-1] < 0.) & (vz[1:] > 0.) & (vz[1:] - vz[:-1] > 1e-9 * scale)
    return time[1:][jump], "history.csv"


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: plot_bouncing_ball.py OUTPUT_DIR PNG_FILE")
    directory, png = sys.argv[1], sys.argv[2]

    prm = read_prm(os.path.join(directory, "parameters.prm"))
    if prm.get("Model/Type", "point mass") != "point mass":
        sys.exit("plot_bouncing_ball.py: %s is not a point mass run (Model/Type = %s)"
                 % (directory, prm["Model/Type"]))
    z0 = float(prm["Model/Point mass/Initial height"])
    v0 = float(prm["Model/Point mass/Initial velocity"])
    e = float(prm["Contact/Restitution coefficient"])
    gravity = [float(x) for x in prm["Loading/Gravity"].split(",")]
    g = -gravity[2]
    method = prm.get("Time integration/Method", "")
    if g <= 0.:
        sys.exit("plot_bouncing_ball.py: the gravity must point downwards (gz < 0), "
                 "got gz = %g" % gravity[2])

    history = read_csv(os.path.join(directory, "history.csv"))
    time = np.asarray(history["time"], dtype=float)
    z = z0 + np.asarray(history["ball.uz"], dtype=float)
    vz = np.asarray(history["ball.vz"], dtype=float)
    dt = time[1] - time[0] if len(time) > 1 else 0.
    contacts_file = os.path.join(directory, "contacts.csv")
    contacts = read_csv(contacts_file) if os.path.exists(contacts_file) else None

    ball = BouncingBall(z0, v0, g, e)

    # impact times; contacts.csv holds the impulse of the sampled steps only,
    # so a CD-Lagrange history sampled more coarsely than dt uses the velocity
    sampled = (method == "CD-Lagrange" and
               float(prm.get("Output/History interval", "0")) >
               float(prm.get("Time integration/Time step", "0")))
    t_num, source = numerical_impacts(time, vz, None if sampled else contacts)
    if sampled:
        source += ", sampled every %g s" % float(prm["Output/History interval"])
    print("Bouncing ball, %s: e = %g, z0 = %g m, v0 = %g m/s, g = %g m/s^2, dt = %g s"
          % (method, e, z0, v0, g, dt))
    print("impact  numerical (s)  analytical (s)  difference (s)   [numerical from %s]"
          % source)
    for k in range(min(5, len(ball.impacts))):
        if k < len(t_num):
            print("%6d  %13.6f  %14.6f  %14.3e"
                  % (k + 1, t_num[k], ball.impacts[k], t_num[k] - ball.impacts[k]))
        else:
            print("%6d  %13s  %14.6f" % (k + 1, "-", ball.impacts[k]))
    if np.isfinite(ball.t_inf):
        print("analytical Zeno time t_inf = %.6f s" % ball.t_inf)

    # decimate: every stride-th row plus the rows around each impact
    n = len(time)
    keep = np.arange(n)
    if n > MAX_PLOT_ROWS:
        stride = int(np.ceil(n / MAX_PLOT_ROWS))
        around = np.searchsorted(time, t_num)
        keep = np.unique(np.concatenate([
            np.arange(0, n, stride), around, around - 1, [n - 1]]))
        keep = keep[(keep >= 0) & (keep < n)]

    # analytical curves on a fine grid with both limits at each impact
    t_end = time[-1]
    grid = np.linspace(0., t_end, 20001)
    hits = ball.impacts[ball.impacts <= t_end]
    t_a = np.concatenate([grid, hits, hits])
    sides = np.concatenate([np.zeros(len(grid)), np.zeros(len(hits)),
                            np.ones(len(hits))])  # 0 left, 1 right limit
    order = np.lexsort((sides, t_a))
    t_a, sides = t_a[order], sides[order]
    z_a, v_a = ball.evaluate(t_a, side="right")
    _, v_left = ball.evaluate(t_a, side="left")
    v_a = np.where(sides == 0, v_left, v_a)

    fig, (ax_z, ax_v) = plt.subplots(2, 1, figsize=(9, 7.5), sharex=True)
    label = "numerical (%s)" % method if method else "numerical"
    ax_z.plot(t_a, z_a, "k-", lw=1.0, label="analytical")
    ax_z.plot(time[keep], z[keep], "C3--", lw=1.0, label=label)
    ax_z.set_ylabel("height z (m)")
    ax_z.grid(True, alpha=0.3)
    ax_z.legend(loc="upper right")
    title = ("Bouncing ball: e = %g, z0 = %g m, v0 = %g m/s, dt = %g s"
             % (e, z0, v0, dt))
    if sampled:
        title += " (rows; time step %g s)" % float(prm["Time integration/Time step"])
    ax_z.set_title(title)

    ax_v.plot(t_a, v_a, "k-", lw=1.0, label="analytical")
    if method == "CD-Lagrange":  # V_{n+1/2} is constant on [t_n, t_{n+1}]
        ax_v.plot(time[keep], vz[keep], "C0--", lw=1.0, drawstyle="steps-post",
                  label=label + r", $V_{n+1/2}$ on $[t_n, t_{n+1}]$")
    else:
        ax_v.plot(time[keep], vz[keep], "C0--", lw=1.0, label=label)
    ax_v.set_xlabel("time t (s)")
    ax_v.set_ylabel("velocity v (m/s)")
    ax_v.grid(True, alpha=0.3)
    ax_v.legend(loc="best")
    if np.isfinite(ball.t_inf) and ball.t_inf <= t_end:
        for ax in (ax_z, ax_v):
            ax.axvline(ball.t_inf, color="0.5", lw=0.8, ls=":")
        ax_z.annotate(r"$t_\infty$ = %.4f s" % ball.t_inf,
                      (ball.t_inf, 0.5 * max(z.max(), z0)), xytext=(-4, 0),
                      textcoords="offset points", ha="right", fontsize=8,
                      color="0.3")

    fig.tight_layout()
    fig.savefig(png, dpi=150)
    print("wrote %s" % png)


if __name__ == "__main__":
    main()
