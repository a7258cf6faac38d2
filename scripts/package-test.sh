#!/bin/sh
# The C++ package as a user gets it: `cmake --install` into a temporary prefix, then two
# consumers (tests/package/) built against that prefix alone, one with find_package(Flood),
# one with pkg-config, and run. Registered with ctest as `package`.
#   scripts/package-test.sh [BUILD_DIR]
# With BUILD_DIR (ctest passes its own), installs that build; without, configures and builds
# a fresh one first (build-package/, core and CLI only).
set -eu
src=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/flood-package.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

build=${1:-}
if [ -z "$build" ]; then
    build=$src/build-package
    cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DFLOOD_VIEWER=OFF -DFLOOD_TESTS=OFF >/dev/null
    cmake --build "$build" -j2 >/dev/null
fi
prefix=$tmp/prefix
cmake --install "$build" --prefix "$prefix" >/dev/null
for f in include/flood/flood_api.h bin/flood; do
    [ -e "$prefix/$f" ] || { echo "package-test: $f not installed" >&2; exit 1; }
done

echo "package-test: find_package(Flood) consumer"
cmake -S "$src/tests/package" -B "$tmp/consumer" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$tmp/consumer" >/dev/null
"$tmp/consumer/consumer"

echo "package-test: pkg-config consumer"
pcdir=$(dirname "$(find "$prefix" -name flood.pc | head -n 1)")
# The library is static: its requirements (GMP, simdjson) come with or without --static.
for static in "" --static; do
  flags=$(PKG_CONFIG_PATH="$pcdir" pkg-config --cflags --libs $static flood)
  ${CXX:-c++} -std=c++17 -O1 "$src/tests/package/consumer.cpp" $flags -o "$tmp/consumer-pc"
  "$tmp/consumer-pc"
done

"$prefix/bin/flood" generate star 50 -o "$tmp/star.json" && "$prefix/bin/flood" verify "$tmp/star.json" >/dev/null
echo "package-test: ok"
