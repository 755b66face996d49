#!/usr/bin/env bash
# Fuzz the input readers of hati with libFuzzer, AddressSanitizer and
# UndefinedBehaviorSanitizer (doc/user_guide.md, "Fuzzing"): the .prm front
# end (fuzz_prm: parse, parameter structs, model build, accelerograms,
# decomposition), the command-line overrides (fuzz_set: --set
# "Subsection/Entry=value" lines, then the same front end), the Gmsh frame
# reader (fuzz_gmsh: read_gmsh_frame and the frame built from the mesh) and
# the accelerogram reader (fuzz_accelerogram: PEER .AT2 and two-column
# files).
#
# Usage: bench/fuzz.sh [seconds per harness, default 600] [harness ...]
#   harness: prm, set, gmsh, accelerogram (default: all four, one after the
#   other)
# Environment: FUZZ_TIMEOUT (s per input before it counts as a hang,
#   default 10), FUZZ_RSS_MB (memory limit, default 2048), FUZZ_JOBS (harnesses
#   run at the same time, default 1).
#
# Installs clang and libclang-rt-dev (libFuzzer, sanitizer runtimes) if
# missing, configures build-fuzz/ (clang++, HATI_FUZZ=ON, Release deal.II;
# only hati's own sources are instrumented), builds the harnesses and runs
# each under nice -n 19 from the repository root (the seeds name mesh and
# accelerogram files relative to it). The corpus grows in
# build-fuzz/corpus/<harness>/ from one run to the next; crashes, hangs
# (timeout-*), out-of-memory inputs and sanitizer reports are written to
# build-fuzz/findings/<harness>/ and the log to build-fuzz/logs/<harness>.log.
# Prints the executions and findings per harness; exits 1 if there is a
# finding. Reproduce one with build-fuzz/fuzz_<harness> <file>; turn it into
# a regression case in test_cases/fuzz_regressions/.
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-600}
shift || true
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=(prm set gmsh accelerogram)
timeout_s=${FUZZ_TIMEOUT:-10}
rss_mb=${FUZZ_RSS_MB:-2048}
jobs=${FUZZ_JOBS:-1}
case "$seconds" in
  '' | *[!0-9]*)
    echo "bench/fuzz.sh: error: seconds per harness must be a positive integer, got '$seconds'" >&2
    exit 2
    ;;
esac
for h in "${harnesses[@]}"; do
  case "$h" in
    prm | set | gmsh | accelerogram) ;;
    *)
      echo "bench/fuzz.sh: error: unknown harness '$h' (prm, set, gmsh or accelerogram)" >&2
      exit 2
      ;;
  esac
done

packages=(clang libclang-rt-dev libdeal.ii-dev libboost-program-options-dev cmake make)
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

if [ ! -f build-fuzz/CMakeCache.txt ]; then
  echo "== configuring build-fuzz/ (clang, libFuzzer, ASan + UBSan)"
  cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_C_COMPILER=clang -DHATI_FUZZ=ON -DHATI_DEBUG_EXECUTABLE=OFF
fi
targets=()
for h in "${harnesses[@]}"; do targets+=("fuzz_$h"); done
echo "== building ${targets[*]}"
nice -n 19 cmake --build build-fuzz -j2 --target "${targets[@]}"

# seed corpora: the repository's inputs and the small hand-written seeds
for h in "${harnesses[@]}"; do
  rm -rf "build-fuzz/seeds/$h"
  mkdir -p "build-fuzz/seeds/$h" "build-fuzz/corpus/$h" "build-fuzz/findings/$h" build-fuzz/logs
  cp bench/fuzz/seeds/"$h"/* "build-fuzz/seeds/$h/"
done
for h in "${harnesses[@]}"; do
  case "$h" in
    prm) cp parameter_files/*.prm build-fuzz/seeds/prm/ ;;
    set) /usr/bin/python3 bench/fuzz/prm_to_set.py build-fuzz/seeds/set parameter_files/*.prm \
      bench/fuzz/seeds/prm/*.prm ;;
    gmsh) cp parameter_files/*.msh build-fuzz/seeds/gmsh/ ;;
    accelerogram) cp data/accelerograms/*.AT2 build-fuzz/seeds/accelerogram/ ;;
  esac
done

# ASan: no allocation stack traces and a small quarantine (the .prm harness
# allocates a lot: 3x faster); reproduce a finding with the defaults for the
# full report. Every UBSan report stops the run (-fno-sanitize-recover=all).
export ASAN_OPTIONS=${ASAN_OPTIONS:-malloc_context_size=0:quarantine_size_mb=16:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

run_one() {
  local h=$1 dict=() max_len
  case "$h" in
    prm) max_len=8192 dict=(-dict=bench/fuzz/prm.dict) ;;
    set) max_len=8192 dict=(-dict=bench/fuzz/set.dict) ;;
    gmsh) max_len=8192 dict=(-dict=bench/fuzz/gmsh.dict) ;;
    accelerogram) max_len=4096 dict=(-dict=bench/fuzz/accelerogram.dict) ;;
  esac
  echo "== fuzz_$h: ${seconds} s (timeout ${timeout_s} s per input, ${rss_mb} MB)"
  # libFuzzer stops at the first finding: start again (keeping the corpus)
  # until the time is used, so that one run reports every finding
  local end executed=0 log="build-fuzz/logs/$h.log" marker="build-fuzz/logs/$h.start"
  : >"$log"
  touch "$marker"
  end=$(($(date +%s) + seconds))
  while :; do
    local left=$((end - $(date +%s))) rc=0 n first
    [ "$left" -gt 0 ] || break
    first=$(($(wc -l <"$log") + 1))
    nice -n 19 "build-fuzz/fuzz_$h" "build-fuzz/corpus/$h" "build-fuzz/seeds/$h" \
      "${dict[@]}" -max_len="$max_len" -max_total_time="$left" -timeout="$timeout_s" \
      -rss_limit_mb="$rss_mb" -malloc_limit_mb="$rss_mb" -print_final_stats=1 \
      -artifact_prefix="build-fuzz/findings/$h/" >>"$log" 2>&1 || rc=$?
    n=$(tail -n +"$first" "$log" | grep -a 'stat::number_of_executed_units' | awk '{print $2}')
    executed=$((executed + ${n:-0}))
    # libFuzzer stops at a finding (non-zero exit): start again with the
    # grown corpus until the time is used, so that one run reports them all
    [ "$rc" -ne 0 ] || break
    echo "   fuzz_$h: finding (exit $rc), continuing; see $log"
    echo "== restart after exit $rc" >>"$log"
  done
  local findings
  findings=$(find "build-fuzz/findings/$h" -type f -newer "$marker" | wc -l)
  echo "$h $executed $findings" >>build-fuzz/logs/summary.txt
}

rm -f build-fuzz/logs/summary.txt
running=0
for h in "${harnesses[@]}"; do
  run_one "$h" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then
    wait -n || true
    running=$((running - 1))
  fi
done
wait || true

echo "== results (${seconds} s per harness)"
printf '%-14s %14s %10s\n' harness executions findings
status=0
while read -r h executed findings; do
  printf '%-14s %14s %10s\n' "fuzz_$h" "$executed" "$findings"
  [ "$findings" -eq 0 ] || status=1
done <build-fuzz/logs/summary.txt
if [ "$status" -ne 0 ]; then
  echo "findings of this run (crash-*, timeout-*, oom-*, leak-*; reports in build-fuzz/logs/):"
  for h in "${harnesses[@]}"; do
    find "build-fuzz/findings/$h" -type f -newer "build-fuzz/logs/$h.start"
  done
fi
exit "$status"
