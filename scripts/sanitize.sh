#!/usr/bin/env bash
# Builds the whole test suite with AddressSanitizer + UndefinedBehaviorSanitizer (Debug, no
# viewer) into build-asan and runs ctest with leak detection. Any sanitizer report fails.
# -O1, as the sanitizers' manuals advise: assertions stay on, and the library runs several times
# faster than at -O0.
set -euo pipefail
cd "$(dirname "$0")/.."
B=build-asan
cmake -S . -B "$B" -DFLOOD_SANITIZE=address,undefined -DCMAKE_BUILD_TYPE=Debug \
  -DFLOOD_VIEWER=OFF -DCMAKE_CXX_FLAGS="-O1 -fno-sanitize-recover=undefined" >/dev/null
cmake --build "$B" -j2
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Tests at 10^6 vertices (names ending in AtScale) take minutes under Debug+ASan; the rest run,
# the growth tests (tests/machine/growth_test.cpp) up to 10^4 vertices.
export FLOOD_GROWTH_MAX_N=10000
ctest --test-dir "$B" --output-on-failure -j2 -E 'AtScale$'
