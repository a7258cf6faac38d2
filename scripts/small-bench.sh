#!/usr/bin/env bash
# Flood against earcut on small polygons (issue 13): earcut's 32 valid fixtures, one call timed
# in-process on each side (earcut under Node.js, Flood natively), and callgrind's instructions
# per call on `building`. Writes the small-polygon section of docs/BENCHMARKS.md.
#   scripts/small-bench.sh [BUILD_DIR]    default build/ (configured as the README says)
# Needs node with npm (the machine's nodejs package carries both) and valgrind
# (scripts/install-bench-deps.sh); earcut is installed from bench/node/package-lock.json into
# BUILD_DIR/earcut-node, never into the source tree.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
fixtures="$root/../shared/peers/earcut"
out="$build/small-bench"
[ -d "$fixtures/fixtures" ] || { echo "small-bench: $fixtures not found" >&2; exit 1; }
for tool in node npm valgrind; do
  command -v $tool >/dev/null || { echo "small-bench: $tool not found (see the comment above)" >&2; exit 1; }
done
# Native earcut.hpp, the peer a C++ program would pick: Debian's source package of
# python3-mapbox-earcut vendors it (no binary package ships the header).
"$root/scripts/deb-source.sh" "$build/deps/src" python-mapbox-earcut
earcut_hpp=$(ls -d "$build"/deps/src/python-mapbox-earcut-*/include | head -1)
cmake -S "$root" -B "$build" -DFLOOD_EARCUT_HPP="$earcut_hpp" >/dev/null
cmake --build "$build" -j2 --target flood-small-bench
mkdir -p "$out" "$build/earcut-node"
cp "$root/bench/node/package.json" "$root/bench/node/package-lock.json" "$build/earcut-node/"
(cd "$build/earcut-node" && npm ci --no-audit --no-fund --silent)
# The valid fixtures: GEOS's verdict in the fixtures' README.
mapfile -t files < <(grep '^|.*| Valid Geometry |' "$fixtures/README.md" | cut -d'|' -f2 | tr -d ' ' |
                     sed "s|.*|$fixtures/fixtures/&.json|")
rounds=3  # alternately, so that load from other jobs falls on both sides alike
earcut=() flood=()
for round in $(seq $rounds); do
  echo "== round $round: earcut (node), flood"
  EARCUT_DIR="$build/earcut-node" node "$root/bench/node/earcut_time.mjs" "${files[@]}" > "$out/earcut.$round.tsv"
  "$build/flood-small-bench" time "${files[@]}" > "$out/flood.$round.tsv"
  earcut+=("$out/earcut.$round.tsv") flood+=("$out/flood.$round.tsv")
done
echo "== callgrind"
: > "$out/callgrind.txt"
for mode in triangulate validate_triangulate earcut_hpp; do
  flag=""; [ $mode = validate_triangulate ] && flag=--validate; [ $mode = earcut_hpp ] && flag=--earcut
  count() {
    valgrind --tool=callgrind --callgrind-out-file=/dev/null "$build/flood-small-bench" calls \
      "$fixtures/fixtures/building.json" "$1" $flag 2>&1 | sed -n 's/.*refs: *//p' | tr -d ,
  }
  a=$(count 100); b=$(count 1100)
  echo "$([ $mode = earcut_hpp ] || echo flood_)$mode $(( (b - a) / 1000 ))" >> "$out/callgrind.txt"
done
{ echo "cpu $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')";
  echo "node $(node --version)";
  echo "earcut $(node -p "require('$build/earcut-node/node_modules/earcut/package.json').version")";
  echo "load $(cut -d' ' -f1-3 /proc/loadavg)"; echo "rounds $rounds"; } > "$out/machine.txt"
join() { local IFS=,; echo "$*"; }
/usr/bin/python3 "$root/bench/small_report.py" "$(join "${earcut[@]}")" "$(join "${flood[@]}")" "$out/callgrind.txt" \
  "$out/machine.txt" "$root/docs/BENCHMARKS.md"
cat "$out/callgrind.txt"
