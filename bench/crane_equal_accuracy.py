#!/usr/bin/python3
"""HATI against fully explicit at equal accuracy on the default crane
(parameter_files/bridge_crane_hati.prm and bridge_crane_full_explicit.prm:
braked wheels with Coulomb friction, the load on its rope, true heights,
2 % frequency-range damping; Rinaldi 228 along X and UP along Z).

bench/crane_realtime.sh and crane_speedup.sh time each file at its own
steps (fully explicit dt = 2e-5 s, HATI dt = 4e-5 s with m = 5). Those
steps were chosen on the tied crane, where the wheels hammer the rails;
on this crane no wheel lifts off over the strong motion and both methods
may take larger steps. This bench asks which run is the cheapest one that
meets the accuracy of crane_friction_hati.py against a fine reference (the
fully explicit run at dt = 1e-5 s, a quarter of its critical step 4.42e-5
s): every wheel's slip distance within 2 % (wheels that slide more than 1
mm) and every peak friction force within 3 % (the tolerances of that
test), every peak mean wheel force within 3 % and the monitors'
translations within 3 % of their peaks (those above 1 mm; the history rows
interpolated to the reference's times), this bench's choice.

Candidates: fully explicit at dt = 2e-5 and 4e-5 s (0.45 and 0.9 of its
critical step); HATI at dt = 4e-5 s with m = 5 (the file), dt = 8e-5 s (0.9
of the explicit part's critical step 8.84e-5 s) with m = 1 and m = 2, and
dt = 2e-5 s with m = 10. m = 1 makes the macro step the micro step: the
stiff short members (end carriages, girder ends) go implicit and allow the
double step, and the wheels are out of the ramp's reach (no redone macro
step); from m = 2 on, the ramp reaches the wheels through their rigid
links, and a sliding wheel makes the macro step be redone.

Prints per run: stepping time (s, summary.json stepping_wall_time), redone
macro steps, the largest errors and whether the run meets the tolerances;
then the cheapest run of each method that meets them, and their ratio.
Usage: [REUSE=1] bench/crane_equal_accuracy.py [END_TIME [build directory]]
(REUSE=1: the outputs of an earlier run of the same END_TIME are read again)
(default 4 s: the strong motion is at 2.6-3.0 s).
"""
import csv
import json
import os
import subprocess
import sys

import numpy as np

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
end_time = sys.argv[1] if len(sys.argv) > 1 else "4"
build = sys.argv[2] if len(sys.argv) > 2 else os.path.join(root, "build")
out = os.path.join(root, "output", "bench_equal_accuracy")
# the tolerances of test_cases/crane_friction_hati.py (slip, friction) and
# of the wheels' forces and the monitors
tolerances = {"slip": 0.02, "friction": 0.03, "force": 0.03, "translation": 0.03}

runs = [  # name, file, dt (s), m (None: fully explicit)
    ("reference", "full_explicit", 1e-5, None),
    ("explicit_2e-5", "full_explicit", 2e-5, None),
    ("explicit_4e-5", "full_explicit", 4e-5, None),
    ("hati_4e-5_m5", "hati", 4e-5, 5),
    ("hati_8e-5_m1", "hati", 8e-5, 1),
    ("hati_8e-5_m2", "hati", 8e-5, 2),
    ("hati_2e-5_m10", "hati", 2e-5, 10),
]


def run(name, file, dt, m):
    directory = os.path.join(out, name)
    command = [os.path.join(build, "hati"),
               os.path.join(root, "parameter_files", "bridge_crane_%s.prm" % file),
               "--set", "Time integration/End time=" + end_time,
               "--set", "Time integration/Time step=%g" % dt,
               "--set", "Output/Output interval=0",
               "--set", "Output/Output directory=" + directory]
    if m is not None:
        command += ["--set", "Time integration/HATI/Time step ratio=%d" % m]
    if os.environ.get("REUSE") == "1" and os.path.exists(os.path.join(directory, "summary.json")):
        return directory
    subprocess.run(command, cwd=root, check=True, stdout=subprocess.DEVNULL)
    return directory


def read_history(directory):
    with open(os.path.join(directory, "history.csv")) as f:
        rows = list(csv.reader(f))
    data = np.array(rows[1:], dtype=float)
    return {key: data[:, i] for i, key in enumerate(rows[0])}


def errors(directory, reference):
    s, r = (json.load(open(os.path.join(d, "summary.json")))
            for d in (directory, reference))
    e = dict.fromkeys(tolerances, 0.)
    for wheel, c_ref in r["contacts"].items():
        c = s["contacts"][wheel]
        if c_ref["slip_distance"] > 1e-3:
            e["slip"] = max(e["slip"], abs(c["slip_distance"] / c_ref["slip_distance"] - 1))
        for key, kind in (("peak_friction_force", "friction"), ("peak_mean_force", "force")):
            if c_ref[key] > 0.:
                e[kind] = max(e[kind], abs(c[key] / c_ref[key] - 1))
    # the rows fall on whole macro steps: interpolated to the reference's
    h, h_ref = read_history(directory), read_history(reference)
    for key, values in h_ref.items():
        peak = np.max(np.abs(values))
        if key[-3:] in (".ux", ".uy", ".uz") and peak > 1e-3:
            at_reference = np.interp(h_ref["time"], h["time"], h[key])
            e["translation"] = max(e["translation"],
                                   np.max(np.abs(at_reference - values)) / peak)
    return e, s


directories = {name: run(name, file, dt, m) for name, file, dt, m in runs}
print("%g s of Rinaldi, the braked crane with its rope; reference: fully explicit, "
      "dt = 1e-5 s" % float(end_time))
print("%-15s %10s %8s %8s %8s %8s %8s  %s" % ("run", "stepping", "redone", "slip",
                                             "friction", "force", "transl.", "meets"))
cheapest = {}
for name, file, dt, m in runs[1:]:
    e, s = errors(directories[name], directories["reference"])
    meets = all(e[k] <= tolerances[k] for k in tolerances)
    stepping = s["stepping_wall_time"]
    print("%-15s %9.2fs %8s %7.2f%% %7.2f%% %7.2f%% %7.2f%%  %s" % (
        name, stepping, s.get("hati_redone_macro_steps", "-"), 100 * e["slip"],
        100 * e["friction"], 100 * e["force"], 100 * e["translation"],
        "yes" if meets else "no"))
    if meets and (file not in cheapest or stepping < cheapest[file][1]):
        cheapest[file] = (name, stepping)
for file, (name, stepping) in cheapest.items():
    print("cheapest %s run within the tolerances: %s, %.2f s of stepping "
          "(%.3f s per s of earthquake)" % (file.replace("_", " "), name, stepping,
                                            stepping / float(end_time)))
if len(cheapest) == 2:
    print("HATI's speed-up at equal accuracy: %.2f" % (
        cheapest["full_explicit"][1] / cheapest["hati"][1]))
