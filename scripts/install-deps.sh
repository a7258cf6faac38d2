#!/usr/bin/env bash
# Installs every Debian package the build, tests and viewer need — or, given package names as
# arguments, those instead (scripts/install-bench-deps.sh does that). Idempotent: installs only
# what is missing, with apt-get only. Run as root (or with sudo available).
set -euo pipefail
packages=(
  build-essential cmake pkg-config ninja-build
  help2man                                            # man pages from --help, at build time
  nlohmann-json3-dev libcli11-dev libgmp-dev          # core + CLI
  libsimdjson-dev                                     #   the fast JSON reader
  libgtest-dev libbenchmark-dev                       # tests, benchmarks
  libgeos-dev                                         # GEOS, the validity oracle of tests/check/geos_diff_test.cpp
  libgdal-dev gdal-bin                                # GIS formats through GDAL (core/io/gdal/, optional)
  libglfw3-dev libglm-dev libimgui-dev libstb-dev     # viewer
  libgif-dev                                          #   its animated GIF exports
  python3-glad python3-jinja2                         # GL loader generated at build time
  xvfb xauth                                          # headless GUI tests
  clang libclang-rt-14-dev python3                    # fuzzing pass and sanitizers in CI
  clang-tidy-14 clang-format-14 cppcheck              # scripts/lint.sh
  pybind11-dev python3-dev python3-numpy              # Python module (python/)
  python3-shapely python3-pytest                      #   its inputs and tests
  python3-dask python3-distributed python3-pandas     #   flood.dask (bags, dataframes)
  python3-geopandas                                   #   flood.triangulate_frame (its test skips without it)
  python3-pip python3-venv python3-setuptools         #   `pip install ./python` (ctest python.pip-install)
)
label=install-deps
if [ $# -gt 0 ]; then packages=("$@"); label="${FLOOD_INSTALL_LABEL:-install-deps}"; fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "$label: all ${#packages[@]} packages present"
  exit 0
fi
echo "$label: installing ${missing[*]}"
SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
