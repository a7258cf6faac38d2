#!/usr/bin/env bash
# Builds everything, warnings as errors, and runs the whole test suite (GUI tests under one
# Xvfb server).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DFLOOD_WERROR=ON
cmake --build build -j"$(nproc)"
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null; then
  xvfb-run -a -s "-screen 0 1280x800x24" ctest --test-dir build --output-on-failure -j"$(nproc)"
else
  ctest --test-dir build --output-on-failure -j"$(nproc)"
fi
