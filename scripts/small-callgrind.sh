#!/usr/bin/env bash
# Instructions per call on earcut's 32 valid fixtures (issue 31 goal 2), counted by callgrind:
# Flood's triangulate() alone (a kept Triangulator), validate() + triangulate(), and native
# earcut.hpp (fresh). Instruction counts are deterministic, so a loaded machine gives the same
# table; nothing is timed. A few minutes (192 valgrind runs).
#   scripts/small-callgrind.sh [BUILD_DIR]     default build/; prints a Markdown table
# Per call: (count of N calls − count of M calls) / (N − M), so that reading the file, the
# first call's allocations and the process around them cancel out; N, M = 1100, 100 up to 20
# vertices, 110, 10 up to 200, 11, 1 above. Needs valgrind and earcut.hpp, fetched as
# scripts/small-bench.sh does (Debian's source package of python-mapbox-earcut).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
fixtures="$root/../shared/peers/earcut"
[ -d "$fixtures/fixtures" ] || { echo "small-callgrind: $fixtures not found" >&2; exit 1; }
command -v valgrind >/dev/null || { echo "small-callgrind: valgrind not found" >&2; exit 1; }
"$root/scripts/deb-source.sh" "$build/deps/src" python-mapbox-earcut >&2
earcut_hpp=$(ls -d "$build"/deps/src/python-mapbox-earcut-*/include | head -1)
cmake -S "$root" -B "$build" -DFLOOD_EARCUT_HPP="$earcut_hpp" >/dev/null
cmake --build "$build" -j2 --target flood-small-bench >&2
bench="$build/flood-small-bench"
# The valid fixtures: GEOS's verdict in the fixtures' README.
mapfile -t names < <(grep '^|.*| Valid Geometry |' "$fixtures/README.md" | cut -d'|' -f2 | tr -d ' ')
refs() {  # FILE CALLS [FLAG]: the instructions of one run
  valgrind --tool=callgrind --callgrind-out-file=/dev/null "$bench" calls "$@" 2>&1 |
    sed -n 's/.*refs: *//p' | tr -d ,
}
for name in "${names[@]}"; do
  file="$fixtures/fixtures/$name.json"
  n=$("$bench" vertices "$file")
  if [ "$n" -le 20 ]; then hi=1100 lo=100; elif [ "$n" -le 200 ]; then hi=110 lo=10; else hi=11 lo=1; fi
  row="$name $n"
  for flag in "" --validate --earcut; do
    b=$(refs "$file" $hi $flag) a=$(refs "$file" $lo $flag)
    row+=" $(( (b - a) / (hi - lo) ))"
  done
  echo "$row"
done | sort -k2,2n -k1,1 | awk '
  function c(x,  s, r) {  # 12345 -> 12,345
    s = sprintf("%.0f", x); r = ""
    while (length(s) > 3) { r = "," substr(s, length(s) - 2) r; s = substr(s, 1, length(s) - 3) }
    return s r }
  BEGIN { print "| fixture | vertices | Flood core | Flood validated | earcut.hpp | core / earcut | validated / earcut |";
          print "|---|---:|---:|---:|---:|---:|---:|" }
  { rc = $3 / $5; rv = $4 / $5; lc += log(rc); lv += log(rv); k++; wc += rc < 1; wv += rv < 1
    printf "| %s | %d | %s | %s | %s | %.2f | %.2f |\n", $1, $2, c($3), c($4), c($5), rc, rv }
  END { printf "\nFixtures: %d. Core only: wins %d, geomean %.3f. Validated: wins %d, geomean %.3f.\n",
               k, wc, exp(lc / k), wv, exp(lv / k) }'
