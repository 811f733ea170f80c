#!/usr/bin/env bash
# Zero cost of the trace observers, measured: the same benchmark source compiled against the library headers of a
# base commit (before tracing) and against the current headers, with identical flags, run alternately in the same
# session; prints the median time of each and the ratio current / base per case.
#
#   bench/trace_overhead.sh <bench-source.cpp> [base-commit, default: the last commit before tracing, set below]
#   environment: ROUNDS (runs of each binary, default 7), CXX (default g++), CXXFLAGS_EXTRA (added to both builds),
#                BENCH_ARGS (passed to both binaries, e.g. --smoke), INSTRUCTIONS=1 (also count the instructions each
#                binary executes, once, under valgrind's callgrind: deterministic, immune to the machine's load)
#
# Contract for a benchmark source:
#   - it compiles as one translation unit with -std=c++17 -O3 -DNDEBUG -march=x86-64, the library's include/
#     directory (base or current) and Eigen (/usr/include/eigen3) on the include path, plus bench/ of the current
#     tree (so bench/bench_util.h may be used; it is not library code). So it uses only API that exists in both
#     trees: the untraced algorithms (`__has_include("rtl/seg/SegTrace.h")` tells the trees apart where the
#     API's meaning changed, e.g. CAR's step, so that both binaries do the same work);
#   - each run prints, on stdout, one line `time_ns <case> <nanoseconds>` per case it times (a case name has no
#     spaces; `time_ns <nanoseconds>` alone is case "all"), typically the median of a few repetitions after a
#     warm-up; other lines are ignored, except
#   - `check <case> <value...>` lines, which describe the result (cluster counts, a checksum): they must be the
#     same for both binaries, or the script stops (the two builds did not do the same work);
#   - it exits with status 0.
# Each of the ROUNDS rounds runs both binaries once, alternating which goes first; the reported time of a case is
# the median over the rounds. The base headers go to build/trace-base/<commit>/include (git archive), the
# binaries next to them.
set -euo pipefail

if [[ $# -lt 1 || $# -gt 2 ]]; then
  echo "usage: $0 <bench-source.cpp> [base-commit]" >&2
  exit 2
fi
source_file=$(realpath "$1")
base=${2:-01fd332}
rounds=${ROUNDS:-7}
cxx=${CXX:-g++}
root=$(cd "$(dirname "$0")/.." && pwd)
base_sha=$(git -C "$root" rev-parse --short "$base^{commit}")
work="$root/build/trace-base/$base_sha"
name=$(basename "$source_file" .cpp)

mkdir -p "$work"
if [[ ! -d "$work/include" ]]; then   # extracted aside, then moved: other runs may share the folder
  tmp=$(mktemp -d "$work/extract.XXXXXX")
  git -C "$root" archive "$base_sha" include | tar -x -C "$tmp"
  mv -T "$tmp/include" "$work/include" 2> /dev/null || true
  rm -rf "$tmp"
fi

flags=(-std=c++17 -O3 -DNDEBUG -march=x86-64 -I/usr/include/eigen3 -I"$root/bench")
# shellcheck disable=SC2206
extra=(${CXXFLAGS_EXTRA:-})
echo "compiling $name against $base_sha and the current headers: $cxx ${flags[*]} ${extra[*]}"
"$cxx" "${flags[@]}" "${extra[@]}" -I"$work/include" "$source_file" -o "$work/$name-base" &
pid=$!
"$cxx" "${flags[@]}" "${extra[@]}" -I"$root/include" "$source_file" -o "$work/$name-current"
wait "$pid"

results="$work/$name.results"
: > "$results"
checks_base="$work/$name.check-base"
checks_current="$work/$name.check-current"
for ((r = 0; r < rounds; ++r)); do
  if ((r % 2 == 0)); then order=(base current); else order=(current base); fi
  for which in "${order[@]}"; do
    # shellcheck disable=SC2086
    out=$("$work/$name-$which" ${BENCH_ARGS:-})
    awk -v w="$which" '$1 == "time_ns" { if (NF == 2) print w, "all", $2; else print w, $2, $3 }' <<< "$out" >> "$results"
    checks=$(grep '^check ' <<< "$out" || true)
    file="$work/$name.check-$which"
    if ((r == 0)); then printf '%s\n' "$checks" > "$file"
    elif [[ "$checks" != "$(cat "$file")" ]]; then echo "$which: check lines changed between runs" >&2; exit 1
    fi
  done
done
if ! diff "$checks_base" "$checks_current" > /dev/null; then
  echo "the base and current builds report different results (check lines):" >&2
  diff "$checks_base" "$checks_current" >&2 || true
  exit 1
fi

if [[ "${INSTRUCTIONS:-0}" == 1 ]]; then
  for which in base current; do
    # shellcheck disable=SC2086
    valgrind --tool=callgrind --callgrind-out-file="$work/$name-$which.callgrind" "$work/$name-$which" ${BENCH_ARGS:-} \
      2> "$work/$name-$which.valgrind" > /dev/null
  done
  ib=$(awk '/Collected :/ { print $NF }' "$work/$name-base.valgrind")
  ic=$(awk '/Collected :/ { print $NF }' "$work/$name-current.valgrind")
  awk -v b="$ib" -v k="$ic" 'BEGIN { printf "instructions executed (whole program, callgrind): base %.0f, current %.0f, ratio %.5f\n", b, k, k / b }'
  if command -v callgrind_annotate > /dev/null; then
    for which in base current; do
      echo "  top functions, $which:"
      callgrind_annotate "$work/$name-$which.callgrind" 2> /dev/null | grep -E '^ *[0-9,]+ \(' | sed -n '2,7p' | cut -c1-140
    done
  fi
fi

# median per (binary, case), then one row per case
printf '%-28s %14s %14s %10s\n' "case" "base ns" "current ns" "ratio"
for c in $(awk '{ print $2 }' "$results" | awk '!seen[$0]++'); do
  median() { awk -v w="$1" -v c="$c" '$1 == w && $2 == c { print $3 }' "$results" | sort -g |
             awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
  b=$(median base)
  k=$(median current)
  awk -v c="$c" -v b="$b" -v k="$k" 'BEGIN { printf "%-28s %14.0f %14.0f %10.3f\n", c, b, k, k / b }'
done
echo "($rounds rounds each, interleaved; base $base_sha; ratio = current / base, 1.000 = no cost)"
