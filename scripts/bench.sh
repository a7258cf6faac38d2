#!/usr/bin/env bash
# Runs the peer benchmarks (issues 4, 13) and writes docs/BENCHMARKS.md, docs/bench.svg and the
# README's bench block: every family of the generator at 10^3..10^6 (10^7 for BENCH_LARGE), the
# floor, and the peers side by side in one run (CGAL, GLU, GEOS, native earcut.hpp in the C++ driver; earcut through
# its Python binding; earcut, libtess and poly2tri under Node.js); real coastlines from
# OpenStreetMap (bench/real_inputs.py, the family "coast"); then `flood triangulate` end to end at
# 10^6 and 10^7, and `flood check -j1` against `-j2` on the world's countries (bench/end_to_end.sh).
#   scripts/bench.sh                  everything: deps, build, inputs, earcut, peers, memory, report
#   scripts/bench.sh --report-only    rewrite the report from the last results in build-bench/bench
# Environment: BENCH_TIMEOUT (seconds per input and triangulator, default 30),
#              BENCH_MAX_SIZE (largest generated size, default 10000000), BENCH_SEED (default 1),
#              BENCH_LARGE (families also run at 10^7, comma-separated; default three cheap ones).
# About 70 minutes on 2 cores; run it with nothing else on the machine. Builds into build-bench
# with -DFLOOD_BENCH=ON; the npm peers are installed from bench/node/package-lock.json into
# build-bench/node by `npm ci`.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$root/build-bench"
data="$build/bench"
fixtures="$root/../shared/peers/earcut/fixtures"
timeout="${BENCH_TIMEOUT:-30}"
maxsize="${BENCH_MAX_SIZE:-10000000}"
large="${BENCH_LARGE:-spiral,circle-holes,comb-rect}"
seed="${BENCH_SEED:-1}"
py=/usr/bin/python3   # Debian's python: python3-numpy and python3-mapbox-earcut live there

if [ "${1:-}" != "--report-only" ]; then
  "$root/scripts/install-deps.sh"
  "$root/scripts/install-bench-deps.sh"
  # Native earcut.hpp from Debian's source package (no binary package ships the header).
  "$root/scripts/deb-source.sh" "$build/deps/src" python-mapbox-earcut
  earcut_hpp=$(ls -d "$build"/deps/src/python-mapbox-earcut-*/include | head -1)
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DFLOOD_BENCH=ON \
        -DFLOOD_VIEWER=OFF -DFLOOD_TESTS=OFF -DFLOOD_EARCUT_HPP="$earcut_hpp" >/dev/null
  cmake --build "$build" -j2 --target flood-bench flood
  rm -rf "$data" && mkdir -p "$data" "$build/node"
  cp "$root/bench/node/package.json" "$root/bench/node/package-lock.json" "$build/node/"
  (cd "$build/node" && npm ci --no-audit --no-fund --silent)
  [ -d "$fixtures" ] || echo "bench: $fixtures not found: running without earcut's fixtures"
  # Kept in build-bench/real between runs: making them valid (ogr2ogr -makevalid) takes a while.
  echo "== real coastlines"; "$py" "$root/bench/real_inputs.py" "$build/node/node_modules" "$build/real"
  echo "== inputs";  "$build/flood-bench" dump "$data" "$fixtures" --seed "$seed" --max-size "$maxsize" --large "$large" --real "$build/real"
  echo "== earcut (Python)";  "$py" "$root/bench/earcut_bench.py" "$data" --timeout "$timeout"
  for peer in earcut libtess poly2tri; do
    echo "== $peer (Node.js)"
    EARCUT_DIR="$build/node" node "$root/bench/node/peers_time.mjs" "$data" "$peer" --timeout "$timeout"
  done
  echo "== peers";   "$build/flood-bench" run "$data" --timeout "$timeout" --out "$data/results.tsv"
  echo "== small polygons"; "$root/scripts/small-bench.sh" "$build"  # its own kept section of BENCHMARKS.md
  echo "== memory"
  printf 'name\tmode\tstatus\tvertices\tmaxrss_loaded_kb\tmaxrss_peak_kb\ttriangles\tevents\n' > "$data/memory.tsv"
  tail -n +2 "$data/manifest.tsv" | while IFS=$'\t' read -r name family size vertices holes valid path verdict; do
    [ "$family" = fixture ] && continue
    for mode in plain record; do
      flag=""; [ $mode = record ] && flag=--record
      # One process per measurement, started from this small shell: ru_maxrss is its own peak.
      if out=$(timeout "$timeout" "$build/flood-bench" memory "$path" $flag); then
        printf '%s\t%s\tok\t%s\n' "$name" "$mode" "$out" >> "$data/memory.tsv"
      else
        printf '%s\t%s\tfailed\t%s\t0\t0\t0\t0\n' "$name" "$mode" "$vertices" >> "$data/memory.tsv"
      fi
    done
  done
  echo "== end to end"; "$root/bench/end_to_end.sh" "$data" "$build/flood" "$seed" "$((4 * timeout))" \
    "$build/node/node_modules/@geo-maps/countries-land-1m/map.geo.json"
  echo "== machine"
  { echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')";
    echo "cores: $(nproc)"; echo "kernel: $(uname -r)";
    echo "compiler: $(c++ --version | head -1)";
    echo "cgal: $(dpkg-query -W -f='${Version}' libcgal-dev)";
    echo "geos: $(dpkg-query -W -f='${Version}' libgeos-dev)";
    echo "glu: $(dpkg-query -W -f='${Version}' libglu1-mesa-dev)";
    echo "earcut: python3-mapbox-earcut $(dpkg-query -W -f='${Version}' python3-mapbox-earcut)";
    echo "node: $(node --version); npm: $(cd "$build/node" && npm ls --depth=0 2>/dev/null | tail -n +2 | sed 's/^[^a-z]*//' | tr '\n' ' ')";
    echo "date: $(date -u +%Y-%m-%d)";
    echo "timeout: $timeout s per input and triangulator";
    echo "load: $(cut -d' ' -f1-3 /proc/loadavg)"; } > "$data/machine.txt"
fi
echo "== report"
"$py" "$root/bench/report.py" "$data" "$root/docs/BENCHMARKS.md" "$root/docs/bench.svg" "$root/README.md"
