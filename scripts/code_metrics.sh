#!/usr/bin/env bash
# scripts/code_metrics.sh: the size limits of DEVELOPERS.md over source/ and
# include/: files over 700 lines and functions of 150 lines or more
# (function extents from Universal Ctags: apt-get install universal-ctags).
set -euo pipefail
cd "$(dirname "$0")/.."
echo "files over 700 lines:"
find source include -name '*.h' -o -name '*.cc' | xargs wc -l | grep -v ' total$' |
  awk '$1 > 700 {printf "  %5d %s\n", $1, $2}' | sort -rn
echo "functions of 150 lines or more:"
# fields separated by '|': names such as "operator ()" hold a space
ctags -R --languages=C++ --kinds-C++=f --fields=+ne -x --_xformat="%N|%F|%n|%e" source include |
  awk -F'|' '{n = $4 - $3 + 1; if (n >= 150) printf "  %5d %s (%s:%d)\n", n, $1, $2, $3}' | sort -rn
echo "largest files:"
find source include -name '*.h' -o -name '*.cc' | xargs wc -l | grep -v ' total$' | sort -rn | head -5 |
  awk '{printf "  %5d %s\n", $1, $2}'
