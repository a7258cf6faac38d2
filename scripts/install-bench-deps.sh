#!/usr/bin/env bash
# Installs the Debian packages the peer benchmarks need (bench/, -DFLOOD_BENCH=ON): the peer
# triangulators CGAL, GEOS, the GLU tessellator and earcut (as compiled in python3-mapbox-earcut,
# driven through numpy), and Node.js for the JavaScript peers (earcut, libtess, poly2tri from
# bench/node/package-lock.json, installed by `npm ci` into the build tree by scripts/bench.sh).
# Idempotent: installs only what is missing, with apt-get only.
# The plot is written by bench/report.py with the Python standard library: no matplotlib.
set -euo pipefail
packages=(
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev     # CGAL constrained Delaunay (header-only)
  libgeos-dev                                         # GEOS 3.11 C API
  libglu1-mesa-dev                                    # GLU tessellator (gluTess*)
  python3 python3-numpy python3-mapbox-earcut         # earcut.hpp via its numpy binding
  valgrind                                            # callgrind for scripts/small-bench.sh
  nodejs                                              # the npm peers, timed in-process
)
# Debian packages npm apart from nodejs; a nodejs from elsewhere may carry its own.
command -v npm >/dev/null || packages+=(npm)
FLOOD_INSTALL_LABEL=install-bench-deps exec "$(dirname "$0")/install-deps.sh" "${packages[@]}"
