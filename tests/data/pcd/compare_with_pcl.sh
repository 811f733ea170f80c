#!/usr/bin/env bash
# Differential check of rtl's PCD reader against PCL's own PCDReader (not run by CI; needs g++, Eigen and Debian's
# pcl-tools). For every file given (e.g. the fuzzing corpus, build/fuzz/corpus/fuzz_pcd/*), PCL reads it and writes
# it as ascii with 9 significant digits (pcl_convert_pcd_ascii_binary ... 0 9); rtl reads the file and PCL's copy, and
# the x, y, z bits of both are compared. Prints one line per file (rtl's result, then PCL's) and a summary:
#   OK/OK same   both read the same points          OK/OK DIFF   both read it, differently: a bug on one side
#   ERR/ERR      rtl rejects it, PCL fails to read  ERR/OK       rtl rejects what PCL accepts (PCL is lenient: it
#                it (or crashes: PCL's reader is    warns and reads on after a wrong value count, skips unknown
#                not hardened against bad input)    keys, parses the start of a bad number)
#   OK/ERR       rtl reads what PCL rejects
#   tests/data/pcd/compare_with_pcl.sh build/fuzz/corpus/fuzz_pcd/*  > compare.tsv
set -uo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
g++ -std=c++17 -O1 -I"$here/../../../include" -I/usr/include/eigen3 "$here/pcd_points_digest.cpp" -o "$tmp/digest"
summary=$tmp/summary
for f in "$@"; do
  rtl=$("$tmp/digest" "$f" | head -c 200 | tr '\t\n' '  ')
  rm -f "$tmp/pcl.pcd"
  if timeout 20 pcl_convert_pcd_ascii_binary "$f" "$tmp/pcl.pcd" 0 9 > /dev/null 2>&1 && [[ -s $tmp/pcl.pcd ]]; then
    pcl=$("$tmp/digest" "$tmp/pcl.pcd" | head -c 200 | tr '\t\n' '  ')
  else
    pcl="ERR PCL could not read it"
  fi
  kind="${rtl%% *}/${pcl%% *}"
  [[ $kind == OK/OK ]] && { [[ $rtl == "$pcl" ]] && kind="OK/OK same" || kind="OK/OK DIFF"; }
  printf '%s\t%s\t%s\t%s\n' "$kind" "$f" "$rtl" "$pcl"
  echo "$kind" >> "$summary"
done
sort "$summary" | uniq -c >&2
