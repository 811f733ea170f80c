#!/usr/bin/env bash
# Builds the libFuzzer harnesses (tests/fuzz/fuzz_*.cpp, clang, ASan + UBSan) in build/fuzz and runs each one on
# its seeds (tests/fuzz/seeds/<name>/, dictionary tests/fuzz/<name>.dict if present) plus the corpus that earlier
# runs grew in build/fuzz/corpus/. Exits non-zero on any crash, sanitizer report, broken invariant, leak or
# timeout; the reproducer is kept in build/fuzz/artifacts/<harness>/.
#   tests/fuzz/run.sh --brief        the test command's pass: the seeds plus a fixed number of new inputs per
#                                    harness (RTL_FUZZ_BRIEF_RUNS, default 3000; at most 15 s each), seed 1
#   tests/fuzz/run.sh [SECONDS]      a fuzzing session: SECONDS per harness (default 60); `./run fuzz SECONDS`
#   RTL_FUZZ_ONLY=<regex>            build and run only the harnesses whose name matches (e.g. 'carmen|lidar')
#   RTL_FUZZ_BUILD=<dir>             another build folder (default build/fuzz), e.g. one per engineer
# Every run appends one line per harness to build/fuzz/stats.tsv (date, harness, seconds, executions, coverage,
# features, corpus size), so the executions of several sessions can be added up.
# Needs clang with libFuzzer (Debian 12: apt-get install clang-14 libclang-rt-14-dev).
#   replay a finding: build/fuzz/tests/fuzz/fuzz_carmen_log build/fuzz/artifacts/fuzz_carmen_log/crash-...
set -euo pipefail
mode=session seconds=60
if [[ ${1:-} == --brief ]]; then
  mode=brief seconds=15
elif [[ -n ${1:-} ]]; then
  [[ $1 =~ ^[1-9][0-9]*$ ]] || { echo "usage: $0 --brief | [seconds > 0]" >&2; exit 2; }
  seconds=$1
fi
brief_runs=${RTL_FUZZ_BRIEF_RUNS:-3000}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=${RTL_FUZZ_BUILD:-$root/build/fuzz}
cxx=${RTL_FUZZ_CXX:-$(command -v clang++-14 || command -v clang++ || true)}
[[ -n $cxx ]] || { echo "$0: clang++ not found (apt-get install clang-14 libclang-rt-14-dev)" >&2; exit 2; }

# A build folder configured for another source path (a moved or copied checkout) cannot be reused.
if [[ -f $build/CMakeCache.txt ]] && ! grep -qxF "CMAKE_HOME_DIRECTORY:INTERNAL=$root" "$build/CMakeCache.txt"; then
  rm -rf "$build"
fi
# -O1 -gline-tables-only: the harnesses instantiate Eigen-heavy templates; at -O1 they compile about 3x faster than
# at -O2 and still give symbolised stack traces. The build is part of every test run, the fuzzing time is not.
mkdir -p "$(dirname "$build")"   # the configure log sits next to the build folder
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O1 -gline-tables-only" \
  -DCMAKE_CXX_COMPILER="$cxx" -DRTL_BUILD_FUZZERS=ON -DRTL_BUILD_TESTS=OFF -DRTL_BUILD_EXAMPLES=OFF \
  -DRTL_BUILD_BENCHMARKS=OFF -DRTL_BUILD_WASM=OFF -DRTL_INSTALL=OFF \
  > "$build.configure.log" 2>&1 || { cat "$build.configure.log" >&2; exit 1; }
targets=()
for source in "$root"/tests/fuzz/fuzz_*.cpp; do
  name=$(basename "$source" .cpp)
  [[ -z ${RTL_FUZZ_ONLY:-} || $name =~ $RTL_FUZZ_ONLY ]] && targets+=(--target "$name")
done
[[ ${#targets[@]} -gt 0 ]] || { echo "$0: no harness matches RTL_FUZZ_ONLY='${RTL_FUZZ_ONLY:-}'" >&2; exit 2; }
cmake --build "$build" -j "${RTL_FUZZ_JOBS:-2}" "${targets[@]}"

stat() { sed -n "s/^stat::$1: *//p" "$2" | tail -1; }
status=0
for harness in "$build"/tests/fuzz/fuzz_*; do
  [[ -x $harness && -f $harness ]] || continue
  name=$(basename "$harness")
  [[ -z ${RTL_FUZZ_ONLY:-} || $name =~ $RTL_FUZZ_ONLY ]] || continue
  reader=${name#fuzz_}                       # fuzz_carmen_log: seeds/carmen_log, carmen_log.dict
  seeds=$root/tests/fuzz/seeds/$reader
  corpus=$build/corpus/$name
  artifacts=$build/artifacts/$name
  mkdir -p "$corpus" "$artifacts" "$seeds"
  dict=()
  [[ -f $root/tests/fuzz/$reader.dict ]] && dict=(-dict="$root/tests/fuzz/$reader.dict")
  nseeds=$(find "$seeds" -type f | wc -l)
  limits=(-max_total_time="$seconds")
  # Brief: the seeds, then a fixed number of mutations with a fixed seed, so that a test run does the same work.
  # A harness with an open finding (tests/fuzz/<name>.open says which) only replays its seeds in the brief pass.
  runs=$brief_runs
  [[ -f $root/tests/fuzz/$reader.open ]] && runs=0 && echo "   open finding, seeds only: $(head -1 "$root/tests/fuzz/$reader.open")"
  [[ $mode == brief ]] && limits+=(-runs=$((nseeds + runs)) -seed=1)
  echo "== $name: $mode, ${seconds}s at most, $nseeds seeds + $(find "$corpus" -type f | wc -l) corpus inputs"
  log=$build/$name.log
  if "$harness" "${limits[@]}" -timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
       -artifact_prefix="$artifacts/" "${dict[@]}" "$corpus" "$seeds" > "$log" 2>&1; then
    execs=$(stat number_of_executed_units "$log")
    last=$(grep -E '^#[0-9]+' "$log" | tail -1)
    cov=$(sed -nE 's/.* cov: ([0-9]+).*/\1/p' <<<"$last")
    ft=$(sed -nE 's/.* ft: ([0-9]+).*/\1/p' <<<"$last")
    echo "   executions ${execs:-0}, coverage ${cov:-?} edges, ${ft:-?} features, peak rss $(stat peak_rss_mb "$log") MB"
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$(date -u +%FT%TZ)" "$name" "$seconds" "${execs:-0}" "${cov:-}" "${ft:-}" \
      "$(find "$corpus" -type f | wc -l)" >> "$build/stats.tsv"
  else
    status=1
    echo "$name FAILED; last lines of $log:" >&2
    tail -n 40 "$log" >&2
    ls "$artifacts" >&2
  fi
done
exit $status
