#!/usr/bin/env bash
# The web build's tests (scripts/web.sh --test; CI's web phase). BUILD_WEB is build-web/.
#  1. the flood CLI built for wasm, under Node, against the native build/flood on every
#     polygons/**/*.json: triangulate (triangles, messages, exit code) and transcript
#     --narrate give the same bytes; its output files are readable (mode 644, not 000);
#  2. the page in headless Chromium (page_test.mjs): no console error, the URL's polygon and
#     step, the canvas against the native viewer's screenshot, arrow keys, Save PNG as a
#     download, Copy into the browser's clipboard (against the native flood transcript), a
#     dropped file, the file picker, recent files kept over a reload, presenter=1,
#     theme=light, a second gallery polygon clicked in the Open panel, the Export panel's SVG
#     and PNG sequence downloaded and read back against the native CLI and viewer, the Shrink
#     panel's shrink in a Web Worker (its repro downloaded and read back by the native CLI), a
#     crash of that worker forced by the test-only URL parameter test-shrink-crash=N, and its
#     Cancel (the worker ends, a shrink started next finishes).
# The native build/flood and build/flood-viewer are built if missing (CI's test phase made them).
set -euo pipefail
cd "$(dirname "$0")/../.."
web=${1:-build-web}
native=build
if [ ! -x "$native/flood" ] || [ ! -x "$native/flood-viewer" ]; then
  cmake -S . -B "$native" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$native" -j2 --target flood flood-viewer
fi
tmp=$(mktemp -d)
server=""
trap '[ -z "$server" ] || kill "$server"; rm -rf "$tmp"' EXIT
failed=0

# ---- 1. the CLI: same bytes as the native one ------------------------------------------------
# Node 20 cannot run Emscripten 3.1.6's output with its experimental fetch on.
webflood() { node --no-experimental-fetch "$web/flood.js" "$@"; }
runs=0 differ=0
while IFS= read -r f; do
  for cmd in triangulate transcript; do
    for side in native web; do
      # The same output path for both: messages name it.
      args=("$cmd" "$f")
      [ "$cmd" = triangulate ] && args+=(-o "$tmp/out.json")
      [ "$cmd" = transcript ] && args+=(--narrate)
      rm -f "$tmp/out.json" "$tmp/$side.out"
      if [ "$side" = native ]; then "$native/flood" "${args[@]}"; else webflood "${args[@]}"; fi \
        >"$tmp/$side.stdout" 2>"$tmp/$side.stderr" && rc=0 || rc=$?
      echo "$rc" >"$tmp/$side.rc"
      [ ! -e "$tmp/out.json" ] || mv "$tmp/out.json" "$tmp/$side.out"
    done
    runs=$((runs + 1))
    for part in stdout stderr rc out; do
      if ! cmp -s "$tmp/native.$part" "$tmp/web.$part" 2>/dev/null &&
        { [ -e "$tmp/native.$part" ] || [ -e "$tmp/web.$part" ]; }; then
        differ=$((differ + 1))
        echo "web: flood $cmd $f: $part differs from the native build's"
        diff "$tmp/native.$part" "$tmp/web.$part" | head -5 || true
        break
      fi
    done
  done
done < <(find polygons -name '*.json' | sort)
echo "web: CLI: $runs runs, $differ differing from the native build"
[ "$differ" -eq 0 ] || failed=1
webflood triangulate polygons/paper-figure-7.json -o "$tmp/mode.json"
mode=$(stat -c %a "$tmp/mode.json")
if [ "$mode" = 644 ]; then echo "web: CLI: an output file is mode 644"
else echo "web: CLI: an output file is mode $mode, not 644 (Emscripten's umask)"; failed=1; fi

# ---- 2. the page ---------------------------------------------------------------------------
shot="$tmp/native-step-23.png"
layout=$(xvfb-run -a -s "-screen 0 1280x800x24" "$native/flood-viewer" polygons/paper-figure-7.json \
  --step 23 --size 1280x800 --scale 1 --screenshot "$shot" --print-layout)
canvas=$(echo "$layout" | awk '$2 == "layout" && $3 == "canvas" {print $4 "," $5 "," $6 "," $7}')
[ -n "$canvas" ] || { echo "web: no canvas in the native viewer's layout:"; echo "$layout"; exit 1; }
printf '[[[0,0],[4,0],[4,3],[2,5],[0,3]]]\n' >"$tmp/dropped-house.json"
printf 'POLYGON ((0 0, 6 0, 3 4, 0 0))\n' >"$tmp/picked-triangle.wkt"
# A face whose invariant scan takes many frames' slices in the page (FLOOD_WEB_BIG vertices:
# docs/BENCHMARKS.md measures the page's stalls with 10^6).
"$native/flood" generate spiral "${FLOOD_WEB_BIG:-100000}" -o "$tmp/big-spiral.json"
# The Export panel's downloads against the native viewer's exports: Fig. 7's last step as SVG,
# monotone.json's flood as a PNG sequence (the panel's default size, 1280x800, both).
xvfb-run -a -s "-screen 0 1280x800x24" "$native/flood-viewer" polygons/paper-figure-7.json \
  --step 99999 --screenshot "$tmp/native-last.svg" >/dev/null
xvfb-run -a -s "-screen 0 1280x800x24" "$native/flood-viewer" polygons/monotone.json \
  --export-png-dir "$tmp/native-frames" >/dev/null
port=${FLOOD_WEB_PORT:-8029}
python3 -m http.server --bind 127.0.0.1 --directory "$web/site" "$port" >"$tmp/server.log" 2>&1 &
server=$!
for _ in $(seq 50); do
  curl -sf -o /dev/null "http://127.0.0.1:$port/index.html" && break
  sleep 0.1
done
shots=${FLOOD_WEB_SHOTS:-$web/test-shots}
mkdir -p "$shots"
cp "$shot" "$shots/"
node --experimental-websocket tests/web/page_test.mjs "http://127.0.0.1:$port/index.html" \
  "$shot" "$canvas" "$tmp/dropped-house.json" "$tmp/picked-triangle.wkt" "$shots" \
  "$tmp/big-spiral.json" "$tmp/native-last.svg" "$tmp/native-frames" || failed=1
echo "web: screenshots in $shots"
exit $failed
