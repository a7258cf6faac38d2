#!/bin/sh
# Writes the man pages flood.1 and flood-viewer.1 into OUTDIR from the programs' own --help
# and --version (help2man, Debian's help2man), so they never drift from the options: flood.1
# also gets a COMMANDS section, each command's own --help. Run by the build (target `man`,
# when help2man is installed) and installed into share/man/man1.
#   scripts/man-pages.sh FLOOD FLOOD_VIEWER OUTDIR     (FLOOD_VIEWER "-": flood.1 alone)
set -eu
flood=$1 viewer=$2 out=$3
mkdir -p "$out"
include="$out/flood.h2m"
{
    echo "[COMMANDS]"
    for cmd in triangulate trace transcript verify bench generate shrink check; do
        echo ".SS $cmd"
        echo ".nf"
        # Lines starting with a dot or a quote would be read as roff requests.
        "$flood" "$cmd" --help | sed -e 's|^Usage: [^ ]*flood |Usage: flood |' \
            -e 's/\\/\\e/g' -e 's/^[.'"'"']/\\\&&/'
        echo ".fi"
    done
    echo "[SEE ALSO]"
    echo "flood-viewer(1); docs/CLI.md and docs/ERRORS.md (exit codes) in the source tree."
} >"$include"
help2man -N --no-discard-stderr -n "triangulate polygons with holes by flooding" \
    --include "$include" -o "$out/flood.1.tmp" "$flood"
mv "$out/flood.1.tmp" "$out/flood.1"
[ "$viewer" = - ] && exit 0
printf '[SEE ALSO]\nflood(1); docs/VIEWER.md in the source tree.\n' >"$out/flood-viewer.h2m"
help2man -N --no-discard-stderr -n "step through the flooding triangulation of a polygon" \
    --include "$out/flood-viewer.h2m" -o "$out/flood-viewer.1.tmp" "$viewer"
mv "$out/flood-viewer.1.tmp" "$out/flood-viewer.1"
