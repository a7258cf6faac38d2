#!/bin/sh
# `pip install` of python/ as a user does it, offline: a throwaway venv that sees Debian's
# packages (numpy, pybind11's headers, setuptools), `pip install --no-build-isolation
# --no-index` of a copy of python/ and core/ (pip builds in the tree: the checkout stays
# clean), then `import flood` from that venv triangulates a square. Registered with ctest as
# `python.pip-install`. Exit 77 (skipped) when Debian's pip or venv is missing.
#   scripts/pip-install-test.sh [PYTHON]   (default /usr/bin/python3)
set -eu
src=$(cd "$(dirname "$0")/.." && pwd)
python=${1:-/usr/bin/python3}
if ! "$python" -m pip --version >/dev/null 2>&1; then
    echo "pip-install-test: SKIP: $python has no pip (apt-get install python3-pip)"
    exit 77
fi
tmp=$(mktemp -d "${TMPDIR:-/tmp}/flood-pip.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
# --without-pip: the venv uses Debian's pip through the system site-packages, so nothing is
# fetched or unpacked for it.
if ! "$python" -m venv --system-site-packages --without-pip "$tmp/venv" >"$tmp/venv.log" 2>&1; then
    cat "$tmp/venv.log"
    echo "pip-install-test: SKIP: $python cannot make a venv (apt-get install python3-venv)"
    exit 77
fi
mkdir "$tmp/src"
cp -r "$src/python" "$src/core" "$src/cli" "$tmp/src/"
rm -rf "$tmp/src/python/build" "$tmp/src/python/"*.egg-info
echo "pip-install-test: pip install --no-build-isolation --no-index $tmp/src/python"
PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_NO_CACHE_DIR=1 "$tmp/venv/bin/python" -m pip install -q --no-build-isolation \
    --no-index "$tmp/src/python"
# Run from elsewhere so the import finds the installed package, not a source folder.
cd "$tmp"
"$tmp/venv/bin/python" - <<'PY'
import os, sys
import flood
where = os.path.dirname(flood.__file__)
assert where.startswith(sys.prefix), f"flood imported from {where}, not the venv {sys.prefix}"
vertices, triangles = flood.triangulate([[(0, 0), (1, 0), (1, 1), (0, 1)]])
assert triangles.shape == (2, 3), triangles
assert sorted(set(triangles.ravel().tolist())) == [0, 1, 2, 3], triangles
print(f"pip-install-test: ok: flood from {where} triangulates a square into {len(triangles)} triangles")
PY
# The console script pip put on the venv's PATH is the flood command: its version, an output
# equal to the one `python -m flood` writes, and the exit code of invalid input.
"$tmp/venv/bin/flood" --version | grep -qx "flood $("$tmp/venv/bin/python" -c 'import flood; print(flood.__version__)')"
printf '[[[0,0],[4,0],[4,4],[0,4]]]' >"$tmp/square.json"
"$tmp/venv/bin/flood" triangulate "$tmp/square.json" -o "$tmp/a.json"
"$tmp/venv/bin/python" -m flood triangulate "$tmp/square.json" -o "$tmp/b.json"
cmp "$tmp/a.json" "$tmp/b.json"
printf '[[[0,0],[4,4],[4,0],[0,4]]]' >"$tmp/bowtie.json"
rc=0; "$tmp/venv/bin/flood" triangulate "$tmp/bowtie.json" -o "$tmp/c.json" 2>/dev/null || rc=$?
[ "$rc" = 4 ] || { echo "pip-install-test: flood on a bow-tie exited $rc, not 4" >&2; exit 1; }
echo "pip-install-test: ok: the flood console script and python -m flood are the command"
