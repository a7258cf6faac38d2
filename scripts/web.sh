#!/usr/bin/env bash
# The web page: flood-viewer (and the flood CLI, for the tests) built for WebAssembly with
# Debian's emscripten into build-web/ (docs/WEB.md). The page is the static folder
# build-web/site/: index.html, index.js, index.wasm, index.data (polygons/ preloaded).
#   scripts/web.sh            install what is missing, build the page and the CLI
#   scripts/web.sh --serve    ... then serve build-web/site on http://127.0.0.1:PORT/
#                             (PORT: $FLOOD_WEB_PORT, default 8029)
#   scripts/web.sh --test     ... then tests/web/run.sh: the page in headless Chromium, and
#                             the CLI under Node against the native build/flood
#   scripts/web.sh --bench    ... then `flood bench` of a 10^5-vertex polygon (generated:
#                             circle-smooth, seed 1) by the wasm CLI under Node (the page's
#                             engine, V8) against the native build/flood: ns/vertex and ratio
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-build}
case "$mode" in build | --serve | --test | --bench) ;; *)
  echo "usage: scripts/web.sh [--serve | --test | --bench]" >&2
  exit 2
  ;;
esac
out=build-web
scripts/web-deps.sh "$out/deps/src"
# Header-only packages the native build uses too.
FLOOD_INSTALL_LABEL=web-deps scripts/install-deps.sh nlohmann-json3-dev libcli11-dev libstb-dev

# Emscripten's JavaScript tools need Debian's node modules (acorn) wherever node comes from.
export NODE_PATH=/usr/share/nodejs
# Configured every time (seconds; a failed configure is not kept), built incrementally.
{
  # Release at -O2 (not CMake's -O3: smaller, and the link is quicker). The cross-compiling
  # emulator emcmake sets (node --experimental-wasm-threads) is refused by Node 20: none.
  emcmake cmake -S . -B "$out" -DCMAKE_BUILD_TYPE=Release -DFLOOD_WERROR=ON \
    -DCMAKE_CXX_FLAGS_RELEASE="-O2 -DNDEBUG" -DCMAKE_C_FLAGS_RELEASE="-O2 -DNDEBUG" \
    -DCMAKE_CROSSCOMPILING_EMULATOR= >"$out/configure.log" 2>&1 ||
    { cat "$out/configure.log"; exit 1; }
}
cmake --build "$out" -j2 --target flood-viewer flood 2>&1 | tee "$out/build.log"
# A name of web/asyncify-only.txt that the page no longer has is only a warning of its link,
# and such a page stops after its first frame (cmake/web.cmake): an error here.
if grep -F "Asyncify onlylist contained a non-existing function name" "$out/build.log"; then
  echo "web: web/asyncify-only.txt names a function the page does not have (renamed?)" >&2
  exit 1
fi
echo "web: the page is $out/site/ ($(du -sh "$out/site" | cut -f1)); the CLI is node $out/flood.js"

case "$mode" in
--serve)
  port=${FLOOD_WEB_PORT:-8029}
  echo "web: serving http://127.0.0.1:$port/index.html (Ctrl+C stops)"
  exec python3 -m http.server --bind 127.0.0.1 --directory "$out/site" "$port"
  ;;
--test) exec tests/web/run.sh "$out" ;;
--bench)
  [ -x build/flood ] || { cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null &&
    cmake --build build -j2 --target flood; }
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  size=${FLOOD_WEB_BENCH_SIZE:-100000}
  build/flood generate circle-smooth "$size" --seed 1 -o "$tmp/in.json"
  echo "web bench: load before: $(cut -d' ' -f1-3 /proc/loadavg)"
  build/flood bench "$tmp/in.json" --repeat 5 >"$tmp/native.txt"
  # Node 20 cannot run Emscripten 3.1.6's output with its experimental fetch on.
  node --no-experimental-fetch "$out/flood.js" bench "$tmp/in.json" --repeat 5 >"$tmp/web.txt"
  echo "web bench: load after: $(cut -d' ' -f1-3 /proc/loadavg)"
  head -1 "$tmp/native.txt"
  # The in-process lines (LABEL: T ns  T/N ns/vertex) side by side, and wasm / native.
  perVertex() { sed -nE 's/^([^:]+): +[0-9]+ ns +([0-9.]+) ns\/vertex.*/\1|\2/p' "$1"; }
  paste -d'|' <(perVertex "$tmp/native.txt") <(perVertex "$tmp/web.txt") |
    awk -F'|' '{ printf "%-36s native %9.1f  wasm %9.1f ns/vertex  x%.2f\n", $1 ":", $2, $4, $4 / $2 }'
  ;;
esac
