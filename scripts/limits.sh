#!/usr/bin/env bash
# Limits check (benchmark-style, not a unit test): a generated polygon of N vertices
# (default 10,000,000) must triangulate within memory proportional to n, or be refused with
# a clear message. Prints the peak RSS and wall time of `flood triangulate`, and bytes per
# vertex. Usage: scripts/limits.sh [N] [FAMILY]   (uses build/flood, builds it if missing)
set -euo pipefail
cd "$(dirname "$0")/.."
N="${1:-10000000}"
FAMILY="${2:-circle-jagged}"
FLOOD="${FLOOD:-build/flood}"
[ -x "$FLOOD" ] || { cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null && cmake --build build -j2 --target flood; }
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
"$FLOOD" generate "$FAMILY" "$N" -o "$TMP/in.json"
echo "input: $FAMILY, $N vertices, $(du -h "$TMP/in.json" | cut -f1)"
set +e
/usr/bin/time -v "$FLOOD" triangulate "$TMP/in.json" -o "$TMP/out.json" 2>"$TMP/time.txt"
rc=$?
set -e
grep -v "^\s*\(Command\|Average\|Major\|Minor\|Voluntary\|Involuntary\|Swaps\|File\|Socket\|Signals\|Page size\|Exit\|Percent\|System time\|User time\)" "$TMP/time.txt" || true
rss_kb=$(grep "Maximum resident" "$TMP/time.txt" | grep -o '[0-9]*$')
echo "exit $rc; peak RSS $((rss_kb / 1024)) MiB = $((rss_kb * 1024 / N)) bytes/vertex"
exit $rc
