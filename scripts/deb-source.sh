#!/usr/bin/env bash
# Unpacks Debian source packages into DIR with `apt-get source`, adding the deb-src entry it
# needs (the same archive as the binary packages) on first use. A package already unpacked
# there (a NAME-*/ folder) is not fetched again. Used where no binary package fits: the web
# build's sources (scripts/web-deps.sh) and earcut.hpp for the benchmarks (scripts/small-bench.sh).
#   scripts/deb-source.sh DIR SOURCE_PACKAGE...
# Run as root (or with sudo available), like scripts/install-deps.sh.
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: scripts/deb-source.sh DIR SOURCE_PACKAGE..." >&2; exit 2; }
dir=$1; shift
SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
command -v dpkg-source >/dev/null ||
  FLOOD_INSTALL_LABEL=deb-source "$(dirname "$0")/install-deps.sh" dpkg-dev
sources=/etc/apt/sources.list.d/flood-deb-src.sources
if [ ! -e "$sources" ]; then
  from=/etc/apt/sources.list.d/debian.sources
  [ -e "$from" ] || { echo "deb-source: no $from to copy a deb-src entry from" >&2; exit 1; }
  sed 's/^Types: deb$/Types: deb-src/' "$from" | $SUDO tee "$sources" >/dev/null
  $SUDO apt-get update -qq
fi
mkdir -p "$dir"
cd "$dir"
for name in "$@"; do
  if ! ls -d "$name"-*/ >/dev/null 2>&1; then
    echo "deb-source: apt-get source $name"
    apt-get source -qq --only-source "$name" >/dev/null 2>&1 || apt-get source -qq --only-source "$name"
  fi
done
