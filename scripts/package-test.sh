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
for f in include/flood/flood.h include/flood/teach.h include/flood/flood_api.h bin/flood; do
    [ -e "$prefix/$f" ] || { echo "package-test: $f not installed" >&2; exit 1; }
done
# Only the public headers are installed (core/include/flood/, but for the GDAL module's
# interface), and each compiles alone on the prefix's include path: a public header that
# includes an internal one, or misses an include of its own, fails here.
[ ! -e "$prefix/include/flood/io/gdal" ] || { echo "package-test: io/gdal/ installed" >&2; exit 1; }
headers=$(cd "$prefix/include" && find flood -name '*.h' | sort)
expected=$(cd "$src/core/include" && find flood -name '*.h' -not -path '*/gdal/*' | sort)
[ "$headers" = "$expected" ] || { echo "package-test: installed headers differ from core/include" >&2; exit 1; }
for h in $headers; do
    printf '#include <%s>\n' "$h" | ${CXX:-c++} -std=c++17 -fsyntax-only -I"$prefix/include" -x c++ - ||
        { echo "package-test: <$h> does not compile alone" >&2; exit 1; }
done
echo "package-test: $(echo "$headers" | wc -l) installed headers, each compiles alone"

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

# docs/LIBRARY.md's example of the caller's own points (its second C++ block), as written.
echo "package-test: docs/LIBRARY.md's point view example"
awk '/^```cpp/ { n++; if (n == 2) { on = 1; next } } /^```$/ { on = 0 } on' \
    "$src/docs/LIBRARY.md" >"$tmp/view_example.cpp"
${CXX:-c++} -std=c++17 -O1 "$tmp/view_example.cpp" \
    $(PKG_CONFIG_PATH="$pcdir" pkg-config --cflags --libs flood) -o "$tmp/view_example"
[ "$("$tmp/view_example")" = "2 and 2 triangles" ] ||
    { echo "package-test: the point view example does not print '2 and 2 triangles'" >&2; exit 1; }

"$prefix/bin/flood" generate star 50 -o "$tmp/star.json" && "$prefix/bin/flood" verify "$tmp/star.json" >/dev/null
# The conventions of a command-line tool: its bash completion, and its man page where the
# build could make it (help2man).
[ -s "$prefix/share/bash-completion/completions/flood" ] ||
    { echo "package-test: the bash completion is not installed" >&2; exit 1; }
if [ -e "$build/man/flood.1" ] && [ ! -s "$prefix/share/man/man1/flood.1" ]; then
    echo "package-test: the man page is not installed" >&2; exit 1
fi

# The installed viewer opens the installed polygons (share/flood/polygons beside bin/), also
# once the prefix has moved, never the build's source tree; its desktop entry names its icon.
if [ -x "$prefix/bin/flood-viewer" ]; then
    echo "package-test: installed viewer"
    for f in share/flood/polygons/paper-figure-7.json share/flood/polygons/gallery.json \
             share/applications/flood-viewer.desktop \
             share/icons/hicolor/scalable/apps/flood-viewer.svg; do
        [ -s "$prefix/$f" ] || { echo "package-test: $f not installed" >&2; exit 1; }
    done
    grep -qx 'Exec=flood-viewer %f' "$prefix/share/applications/flood-viewer.desktop"
    grep -qx 'Icon=flood-viewer' "$prefix/share/applications/flood-viewer.desktop"
    if command -v desktop-file-validate >/dev/null; then
        desktop-file-validate "$prefix/share/applications/flood-viewer.desktop"
    fi
    mv "$prefix" "$tmp/moved"
    out=$(cd "$tmp" && env -u DISPLAY -u WAYLAND_DISPLAY -u FLOOD_POLYGONS_DIR \
          "$tmp/moved/bin/flood-viewer" 2>&1 || true)
    case $out in
      *"Summary of $tmp/moved/share/flood/polygons/paper-figure-7.json"*) ;;
      *) echo "package-test: the installed viewer did not open its own polygons:" >&2
         echo "$out" >&2; exit 1 ;;
    esac
fi
echo "package-test: ok"
