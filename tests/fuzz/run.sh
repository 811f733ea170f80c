#!/usr/bin/env bash
# Fuzzes every reader of outside data: builds the libFuzzer harnesses (tests/fuzz/fuzz_*.cpp) with clang in
# build/fuzz and runs each for SECONDS (default 20) on its seeds plus the corpus of earlier runs. Exits non-zero on
# any crash, sanitizer report, broken invariant, leak or timeout; the reproducer is kept in build/fuzz/artifacts/.
# Needs clang with libFuzzer (Debian 12: apt-get install clang-14 libclang-rt-14-dev).
#   tests/fuzz/run.sh [SECONDS]        e.g. tests/fuzz/run.sh 600 for a longer session
#   replay a finding: build/fuzz/tests/fuzz/fuzz_carmen_log build/fuzz/artifacts/fuzz_carmen_log/crash-...
set -euo pipefail
seconds=${1:-20}
[[ $seconds =~ ^[1-9][0-9]*$ ]] || { echo "usage: $0 [seconds > 0]" >&2; exit 2; }
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$root/build/fuzz
cxx=${RTL_FUZZ_CXX:-$(command -v clang++-14 || command -v clang++ || true)}
[[ -n $cxx ]] || { echo "$0: clang++ not found (apt-get install clang-14 libclang-rt-14-dev)" >&2; exit 2; }

# A build folder configured for another source path (a moved or copied checkout) cannot be reused.
if [[ -f $build/CMakeCache.txt ]] && ! grep -qxF "CMAKE_HOME_DIRECTORY:INTERNAL=$root" "$build/CMakeCache.txt"; then
  rm -rf "$build"
fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER="$cxx" -DRTL_BUILD_FUZZERS=ON \
  -DRTL_BUILD_TESTS=OFF -DRTL_BUILD_EXAMPLES=OFF -DRTL_BUILD_BENCHMARKS=OFF -DRTL_BUILD_WASM=OFF -DRTL_INSTALL=OFF \
  > "$build.configure.log" 2>&1 || { cat "$build.configure.log" >&2; exit 1; }
cmake --build "$build" -j "${RTL_FUZZ_JOBS:-2}"

status=0
for harness in "$build"/tests/fuzz/fuzz_*; do
  [[ -x $harness && -f $harness ]] || continue
  name=$(basename "$harness")
  reader=${name#fuzz_}                       # fuzz_carmen_log: seeds/carmen_log, carmen_log.dict
  seeds=$root/tests/fuzz/seeds/$reader
  corpus=$build/corpus/$name
  artifacts=$build/artifacts/$name
  mkdir -p "$corpus" "$artifacts"
  dict=()
  [[ -f $root/tests/fuzz/$reader.dict ]] && dict=(-dict="$root/tests/fuzz/$reader.dict")
  echo "== $name: ${seconds}s on $(ls "$seeds" | wc -l) seeds + $(ls "$corpus" | wc -l) corpus inputs"
  if "$harness" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
       -artifact_prefix="$artifacts/" "${dict[@]}" "$corpus" "$seeds" > "$build/$name.log" 2>&1; then
    grep -E '^(Done|stat::number_of_executed_units|stat::peak_rss_mb)' "$build/$name.log" || true
  else
    status=1
    echo "$name FAILED; last lines of $build/$name.log:" >&2
    tail -n 40 "$build/$name.log" >&2
    ls "$artifacts" >&2
  fi
done
exit $status
