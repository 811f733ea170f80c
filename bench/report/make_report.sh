#!/usr/bin/env bash
# The speed report of ./run bench (bench/report/README.md): times the vectorizers and segmenters
# natively (speed_native) and through the package (speed_wasm.mjs, dist/), size by size so that both sides of one
# size are measured seconds apart, draws the figures (speed_figure: TikZ and SVG), compiles the TikZ with pdflatex
# and writes report.md with the tables and the machine.
#
#   bench/report/make_report.sh --build BUILD_DIR [--out OUT_DIR] [--smoke] [--rounds=R]
#
# BUILD_DIR: a native CMake build with the targets speed_native and speed_figure built (Release for real figures).
# OUT_DIR: default build/bench/report. --smoke: 10, 100 and 1000 points, one round (for the test of this script).
# Without node or dist/ the wasm side is left out (and said so in the report).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd -P)
BUILD="" OUT="$ROOT/build/bench/report" SMOKE="" ROUNDS=""
while [ $# -gt 0 ]; do
  case "$1" in
    --build) BUILD=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --smoke) SMOKE=--smoke; shift ;;
    --rounds=*) ROUNDS=$1; shift ;;
    *) echo "make_report.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
[ -n "$BUILD" ] || { echo "make_report.sh: --build BUILD_DIR is required" >&2; exit 2; }
NATIVE="$BUILD/bench/report/speed_native" FIGURE="$BUILD/bench/report/speed_figure"
for p in "$NATIVE" "$FIGURE"; do
  [ -x "$p" ] || { echo "make_report.sh: $p is not built (cmake --build $BUILD --target speed_native speed_figure)" >&2; exit 1; }
done
if [ -n "$SMOKE" ]; then SIZES=(10 100 1000) ROUND_COUNT=1 BATCH=1,000; else SIZES=(10 30 100 300 1000 3000 10000 30000 100000 300000 1000000) ROUND_COUNT=11 BATCH=200,000; fi
[ -z "$ROUNDS" ] || ROUND_COUNT=${ROUNDS#--rounds=}

mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd -P)
POINTS="$OUT/points"
rm -rf "$POINTS" && mkdir -p "$POINTS"
trap 'rm -rf "$POINTS"' EXIT
rm -f "$OUT"/native.tsv "$OUT"/wasm.tsv "$OUT"/report.md "$OUT"/speed_{vectorizers,segmenters}.{tex,svg,pdf,log}

WASM=yes
if ! command -v node >/dev/null 2>&1 || [ ! -f "$ROOT/dist/rtl.wasm" ]; then WASM=""; fi
LOAD_BEFORE=$(uptime)
header=""
for n in "${SIZES[@]}"; do
  "$NATIVE" $SMOKE $ROUNDS --sizes="$n" --points="$POINTS" --out="$OUT/native.tsv" $header
  if [ -n "$WASM" ]; then
    (cd "$ROOT" && node bench/report/speed_wasm.mjs $SMOKE $ROUNDS --sizes="$n" --points="$POINTS" --out="$OUT/wasm.tsv" $header)
  fi
  rm -f "$POINTS"/*
  header=--no-header
done
LOAD_AFTER=$(uptime)

"$FIGURE" --out="$OUT" "$OUT/native.tsv" ${WASM:+"$OUT/wasm.tsv"}
PDF=""
if command -v pdflatex >/dev/null 2>&1; then
  for f in speed_vectorizers speed_segmenters; do
    (cd "$OUT" && pdflatex -interaction=nonstopmode -halt-on-error "$f.tex" >/dev/null) ||
      { echo "make_report.sh: pdflatex failed on $OUT/$f.tex (log: $OUT/$f.log)" >&2; exit 1; }
    rm -f "$OUT/$f.aux" "$OUT/$f.log"
  done
  PDF=yes
fi

cache="$BUILD/CMakeCache.txt"
cxx=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$cache" 2>/dev/null)
build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$cache" 2>/dev/null)
flags=$(sed -n "s/^CMAKE_CXX_FLAGS_${build_type^^}:[A-Z]*=//p" "$cache" 2>/dev/null)
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo 2>/dev/null | head -1)
figure_links() {
  local f=$1
  echo "![$2]($f.svg)"
  echo
  echo "Files: [$f.svg]($f.svg), [$f.tex]($f.tex)${PDF:+, [$f.pdf]($f.pdf)} (drawn by rtl::Drawing2D, written by rtl::writeSvg and rtl::writeTikz)."
}
{
  echo "# Speed of the vectorizers and segmenters${SMOKE:+ (smoke run: tiny sizes, one round, not figures)}"
  echo
  echo "Written by \`./run bench\` (bench/report/make_report.sh) on $(date -u '+%Y-%m-%d %H:%M UTC')."
  echo "The RTL paper's figure \"Speed benchmark of vectorization algorithms\": time per point against the number"
  echo "of points, log-log, for FTLS, incremental TLS (ITLS), Douglas-Peucker (DP) and Reumann-Witkam (RW) on the"
  echo "paper's semicircle (radius 8, Gaussian noise 0.01 per axis; sigma 0.03, delta 3 for the TLS methods, epsilon"
  echo "0.09 for DP and RW), and the same for the segmenters CAR (step 10, bounds 0.01-0.1, RTL's parameters) and IA"
  echo "(step 9 with CAR step 10's threshold: the same 9 predecessors, the same clusters) on a closed scan of 10 walls"
  echo "(the semicircle's noise equals the lower bound, which would cut it into more clusters the more points it has)."
  echo
  echo "Solid: the C++ library (double points, one reused vectorizer or CAR segmenter per size, a new IA segmenter per"
  echo "call). Dashed: the same calls through the rtl-wasm package in Node on the same points (the whole call: argument"
  echo "checks, copy into wasm memory, the library, the result objects). Grey: the floor, measured in the same rounds:"
  echo "one pass computing every point's squared distance to one chord and their maximum (C++, and the same loop in"
  echo "JavaScript over the Float64Array). Every size is measured in interleaved rounds (floor, FTLS, ITLS, ..., floor, FTLS, ...: $ROUND_COUNT of them); a"
  echo "case's time in one round is a batch of calls (as many as cover $BATCH points, but no more than take about"
  echo "5 ms) divided by the calls; shown is the median over the rounds of the CPU time (the thread's natively, the process's in Node), which"
  echo "does not count the time the process waits for a core on a shared machine. The TSVs also hold wall times."
  echo
  echo "How to read it: at 10-300 points the fixed cost of a call dominates (natively the allocation of a segmenter's"
  echo "or vectorizer's outputs; in wasm the JavaScript around the call), so time per point falls like 1/n; from about"
  echo "1000 points it is flat where the algorithm is linear. The floor's ratio in the tables says how far each case"
  echo "is from the least work any of them must do: reading every point once."
  echo
  echo "## Figures"
  echo
  figure_links speed_vectorizers "time per point of FTLS, ITLS, DP and RW on the semicircle, native and wasm"
  echo
  figure_links speed_segmenters "time per point of CAR and IA on a 10-wall scan, native and wasm"
  echo
  echo "## Tables"
  [ -n "$WASM" ] || { echo; echo "(wasm not measured: node or dist/rtl.wasm missing; run \`npm run build\`)"; }
  cat "$OUT/tables.md"
  echo
  echo "## Machine"
  echo
  echo "- CPU: ${cpu:-unknown}; nproc $(nproc)"
  echo "- load before: \`${LOAD_BEFORE# }\`"
  echo "- load after: \`${LOAD_AFTER# }\`"
  echo "- compiler: \`$("${cxx:-c++}" --version 2>/dev/null | head -1)\`, CMAKE_BUILD_TYPE ${build_type:-none} (\`${flags}\`)"
  [ -z "$WASM" ] || echo "- Node $(node --version), rtl-wasm $(node -p "require('$ROOT/package.json').version")"
  echo "- raw data: [native.tsv](native.tsv)${WASM:+, [wasm.tsv](wasm.tsv)}"
} > "$OUT/report.md"
rm -f "$OUT/tables.md"
echo "speed report: $OUT/report.md"
