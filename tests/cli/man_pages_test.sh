#!/bin/sh
# The man pages the build wrote (scripts/man-pages.sh): flood.1 has every command's section
# and usage, flood-viewer.1 (when the viewer is built) its options; each renders, where man is
# installed.
#   tests/cli/man_pages_test.sh MAN_DIR
set -eu
dir=$1
fail() { echo "man-pages-test: $*" >&2; exit 1; }
grep -q '^\.SH COMMANDS' "$dir/flood.1" || fail "flood.1 has no COMMANDS section"
for cmd in triangulate trace transcript verify bench generate shrink check; do
    grep -q "^Usage: flood $cmd " "$dir/flood.1" || fail "flood.1 has no usage of $cmd"
done
if [ -e "$dir/flood-viewer.1" ]; then
    grep -q 'presenter' "$dir/flood-viewer.1" || fail "flood-viewer.1 lists no --presenter"
fi
if command -v man >/dev/null; then
    for page in "$dir"/*.1; do
        MANWIDTH=100 man -l "$page" 2>&1 >/dev/null | grep . && fail "$page: man warns"
        MANWIDTH=100 man -l "$page" | grep -q '^NAME' || fail "$page does not render"
    done
fi
echo "man-pages-test: ok"
