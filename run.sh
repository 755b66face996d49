#!/usr/bin/env bash
# ./run.sh [file.prm] [hati options]: set up (Debian packages, Release build)
# and run a parameter file, by default the main example: the bridge crane
# under the Northridge earthquake with HATI (parameter_files/bridge_crane_hati.prm,
# about 40 s on 2 cores). For a crane it then draws crane.png (trolley
# wheel Z displacements and wheel uplifts, paper Fig. 8, and the wheel
# forces); for the paper's case (bridge_crane_paper_case.prm) it also runs
# the fully explicit reference (CD-Lagrange, dt = 1.6e-6 s, about 20 s) and
# draws compare_runs.png (paper Fig. 9: the trolley wheel's displacement and
# uplift, fully explicit against HATI); for the bouncing ball
# bouncing_ball.png (numerical vs analytical solution).
set -euo pipefail
cd "$(dirname "$0")"
./scripts/setup.sh hati
prm="${1:-parameter_files/bridge_crane_hati.prm}"
[ $# -gt 0 ] && shift
./build/hati "$prm" "$@"
name=$(basename "$prm" .prm)
out="output/$name"
for a in "$@"; do
  case "$a" in Output/Output\ directory=*) out="${a#Output/Output directory=}" ;; esac
done
if [ "$name" = bouncing_ball ]; then
  /usr/bin/python3 scripts/plot_bouncing_ball.py "$out" bouncing_ball.png
elif grep -q "bridge crane" "$prm" && [ -f "$out/history.csv" ] && [ -f "$out/contacts.csv" ]; then
  /usr/bin/python3 scripts/plot_crane.py "$out"
  if [ "$name" = bridge_crane_paper_case ]; then
    ./build/hati "$prm" "$@" --set "Time integration/Method=CD-Lagrange" \
      --set "Time integration/Time step=1.6e-6" --set "Output/Output interval=0" \
      --set "Output/Output directory=${out}_explicit"
    /usr/bin/python3 scripts/compare_runs.py "${out}_explicit" "$out" --monitor tw1.uz \
      --gap trolley_wheel_1 --png "$out/compare_runs.png" | tail -n 3
    echo "paper Fig. 9: $out/compare_runs.png (fully explicit in ${out}_explicit/)"
  fi
  echo "outputs in $out/: solution.pvd (ParaView: displacement, contact_status,"
  echo "  subdomain), history.csv, contacts.csv, contact_episodes.csv,"
  echo "  section_forces.csv, energy.csv, summary.json, crane.png"
fi
