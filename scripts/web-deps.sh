#!/usr/bin/env bash
# The web build's dependencies, all from Debian (docs/WEB.md): the toolchain (emscripten), the
# browser the tests drive (chromium) and, as source packages, what must be compiled for wasm
# (Dear ImGui with its backends, simdjson, double-conversion, GMP's mini-gmp). Sources are
# unpacked once into DIR (default build-web/deps/src); nothing is downloaded when they are there.
# Run as root (or with sudo available), like scripts/install-deps.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
src=${1:-build-web/deps/src}
# python3 serves the page for the tests; nodejs runs them (and emscripten itself).
FLOOD_INSTALL_LABEL=web-deps scripts/install-deps.sh emscripten chromium nodejs python3 dpkg-dev

# The versions are bookworm's (imgui 1.86, simdjson 3.0.1, double-conversion 3.2.1, gmp 6.2.1).
scripts/deb-source.sh "$src" imgui simdjson double-conversion gmp
ls -d "$src"/*/
