#!/usr/bin/env bash
# ./run.sh [file.prm] [hati options]: set up (Debian packages, Release build)
# and run a parameter file, by default the main example. For the bouncing
# ball it also draws bouncing_ball.png (numerical vs analytical solution).
set -euo pipefail
cd "$(dirname "$0")"
./scripts/setup.sh hati
prm="${1:-parameter_files/bouncing_ball.prm}"
[ $# -gt 0 ] && shift
./build/hati "$prm" "$@"
name=$(basename "$prm" .prm)
if [ "$name" = bouncing_ball ]; then
  /usr/bin/python3 scripts/plot_bouncing_ball.py "output/$name" bouncing_ball.png
fi
