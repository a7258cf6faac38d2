#!/usr/bin/env bash
# Builds everything and opens the viewer on the default polygon. Without a display the viewer
# says so and prints what the flood did instead (the same as `flood transcript`).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
if [ -x build/flood-viewer ]; then
  exec build/flood-viewer "$@"
fi
echo "flood-viewer was not built; showing the flood of polygons/hole.json with the CLI:"
exec build/flood transcript polygons/hole.json
