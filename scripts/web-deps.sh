#!/usr/bin/env bash
# The web build's dependencies, all from Debian (docs/WEB.md): the toolchain (emscripten), the
# browser the tests drive (chromium) and, as source packages, what must be compiled for wasm
# (Dear ImGui with its backends, simdjson, double-conversion, GMP's mini-gmp). Sources are
# unpacked once into DIR (default build-web/deps/src); nothing is downloaded when they are there.
# Run as root (or with sudo available), like scripts/install-deps.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
src=${1:-build-web/deps/src}
SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
# python3 serves the page for the tests; nodejs runs them (and emscripten itself).
FLOOD_INSTALL_LABEL=web-deps scripts/install-deps.sh emscripten chromium nodejs python3 dpkg-dev

# apt-get source needs a deb-src entry: the same archive as the binary packages.
sources=/etc/apt/sources.list.d/flood-deb-src.sources
if [ ! -e "$sources" ]; then
  from=/etc/apt/sources.list.d/debian.sources
  [ -e "$from" ] || { echo "web-deps: no $from to copy a deb-src entry from" >&2; exit 1; }
  sed 's/^Types: deb$/Types: deb-src/' "$from" | $SUDO tee "$sources" >/dev/null
  $SUDO apt-get update -qq
fi

mkdir -p "$src"
cd "$src"
# The versions are bookworm's (imgui 1.86, simdjson 3.0.1, double-conversion 3.2.1, gmp 6.2.1).
for name in imgui simdjson double-conversion gmp; do
  if ! ls -d "$name"-*/ >/dev/null 2>&1; then
    echo "web-deps: apt-get source $name"
    apt-get source -qq --only-source "$name" >/dev/null 2>&1 || apt-get source -qq --only-source "$name"
  fi
done
ls -d */
