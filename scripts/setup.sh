#!/usr/bin/env bash
# Shared set-up of run.sh and test.sh: install the missing Debian packages,
# configure and build the Release build in build/. Idempotent and quick when
# nothing changed. Usage: scripts/setup.sh [cmake build target, default all]
set -euo pipefail
cd "$(dirname "$0")/.."

# libopenblas0-serial: an optimised BLAS/LAPACK for the direct solvers'
# dense kernels (MUMPS's fronts, the Lanczos runs of the modal analyses and
# of the Craig-Bampton reduction: 30 % of the 3D crane's set-up with
# Debian's reference BLAS), single-threaded so that the MPI suites keep one
# process per core. Results differ from the reference BLAS's at round-off.
packages=(libdeal.ii-dev libmumps-dev numdiff libboost-program-options-dev cmake make g++
          python3-numpy python3-matplotlib nlohmann-json3-dev libopenblas0-serial)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "== installing Debian packages: ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

if [ ! -f build/CMakeCache.txt ]; then
  echo "== configuring build/ (Release)"
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
fi
echo "== building ${1:-all}"
cmake --build build -j2 --target "${1:-all}"
