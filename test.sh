#!/usr/bin/env bash
# ./test.sh [ctest options]: set up (Debian packages, Release build) and run
# the whole test suite with ctest.
set -euo pipefail
cd "$(dirname "$0")"
./scripts/setup.sh
cd build
ctest --output-on-failure -j2 "$@"
