#!/usr/bin/env bash
# A longer run of the GEOS-differential test (tests/check/geos_diff_test.cpp): the same generator of
# polygons and MultiPolygons, the same assertions (validate() agrees with GEOS 3.11's isValid;
# every accepted case triangulates and passes the exact checker), with a seed and a count:
#   scripts/geos-diff.sh [--seed S] [--cases N] [--dump DIR]
# --dump DIR writes every case GEOS calls invalid into DIR as GeoJSON (a corpus for other
# tools). Defaults: seed 1, 100000 cases. Needs libgeos-dev (scripts/install-deps.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
seed=1 cases=100000 dump=""
while [ $# -gt 0 ]; do
  case "$1" in
    --seed) seed="$2"; shift 2 ;;
    --cases) cases="$2"; shift 2 ;;
    --dump) dump="$2"; shift 2 ;;
    *) echo "usage: scripts/geos-diff.sh [--seed S] [--cases N] [--dump DIR]" >&2; exit 2 ;;
  esac
done
[ -z "$dump" ] || dump="$(mkdir -p "$dump" && cd "$dump" && pwd)"
B=build
[ -f "$B/CMakeCache.txt" ] || cmake -S . -B "$B" -DCMAKE_BUILD_TYPE=Release -DFLOOD_VIEWER=OFF >/dev/null
cmake --build "$B" -j2 --target flood_tests >/dev/null
FLOOD_GEOS_SEED="$seed" FLOOD_GEOS_CASES="$cases" FLOOD_GEOS_DUMP="$dump" \
  "$B/tests/flood_tests" --gtest_filter='GeosDiff.*' --gtest_brief=1 | grep -v '^Running main'
