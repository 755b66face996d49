#!/usr/bin/env bash
# Scaling of a suite of records over MPI ranks (issue #18):
# parameter_files/bridge_crane_suite.prm (the default crane, fully explicit, under the
# 2 records of data/accelerograms at scale factors 0.5, 1, 1.5: 6 members),
# each member shortened to END_TIME seconds (default 0.5), run with 1 and
# with 2 ranks (mpirun -np 2; every rank runs members, assigned
# dynamically). Prints per run the wall time of the suite, the members per
# minute, the parallel efficiency (members per minute on N ranks / N times
# those on 1 rank) and the overhead of the suite over the sum of its
# members' wall times (suite_summary.json: N * wall_time / sum_member_wall_time - 1;
# goal under 5 %). On a cluster, the same with a hostfile:
#   mpirun -np 64 --hostfile hosts build/hati parameter_files/bridge_crane_suite.prm
# Usage: bench/suite_scaling.sh [END_TIME [build directory [ranks ...]]]
set -euo pipefail
cd "$(dirname "$0")/.."
end_time=${1:-0.5}
build=${2:-build}
shift $(( $# > 2 ? 2 : $# )) || true
ranks=("$@")
[ ${#ranks[@]} -gt 0 ] || ranks=(1 2)
[ -x "$build/hati" ] || ./scripts/setup.sh hati
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
out=output/bench_suite
rm -rf "$out"
mkdir -p "$out"
printf '%-6s %10s %12s %12s %12s %10s\n' ranks "wall (s)" "members/min" efficiency "member sum" overhead
base=""
for n in "${ranks[@]}"; do
  dir="$out/np$n"
  launcher=()
  [ "$n" -gt 1 ] && launcher=(mpirun -np "$n" --oversubscribe)
  "${launcher[@]}" "$build/hati" parameter_files/bridge_crane_suite.prm \
    --set "Time integration/End time=$end_time" \
    --set "Output/Output directory=$dir" > "$out/np$n.log" 2>&1 \
    || { echo "suite on $n ranks failed, see $out/np$n.log"; tail -3 "$out/np$n.log"; exit 1; }
  line=$(/usr/bin/python3 - "$dir" "$n" "$base" <<'PY'
import json, sys
s = json.load(open(sys.argv[1] + "/suite_summary.json"))
n = int(sys.argv[2])
rate = 60.0 * s["n_members"] / s["wall_time"]
base = float(sys.argv[3]) if sys.argv[3] else rate
print("%g %.3f %.3f %.3f %.3f %.1f" % (rate, s["wall_time"], rate, rate / (n * base),
      s["sum_member_wall_time"], 100.0 * (n * s["wall_time"] / s["sum_member_wall_time"] - 1.0)))
PY
)
  read -r rate wall r eff sum overhead <<< "$line"
  [ -n "$base" ] || base=$rate
  printf '%-6s %10s %12s %12s %12s %9s%%\n' "$n" "$wall" "$r" "$eff" "$sum" "$overhead"
done
echo "members: $(grep -c '^[^m]' "$out/np${ranks[0]}/suite.csv") per run, each $end_time s of the crane; logs in $out/np*.log"
