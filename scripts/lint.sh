#!/usr/bin/env bash
# Static checks, any finding fails: the layers of core/ (scripts/check-layers.py: no #include
# climbs the stack of core/LAYERS, none reaches past the public headers), clang-tidy
# (.clang-tidy) over core/ (every layer's folder) and cli/, cppcheck over the same, and
# clang-format (.clang-format) on the C++ files given as
# arguments, or else on every tracked C++ file.
# Needs only a configured build tree (compile_commands.json), never a built one.
set -euo pipefail
cd "$(dirname "$0")/.."
B=build-lint
cmake -S . -B "$B" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DFLOOD_VIEWER=OFF -DFLOOD_TESTS=OFF \
  -DFLOOD_PYTHON=OFF >/dev/null

echo "lint: layers"
scripts/check-layers.py

echo "lint: clang-tidy"
run-clang-tidy-14 -p "$B" -j2 -quiet "$PWD/(core|cli)/.*\.cpp$" >"$B/clang-tidy.log" 2>&1 || {
  grep -E 'error:|warning:' "$B/clang-tidy.log" || cat "$B/clang-tidy.log"
  exit 1
}

echo "lint: cppcheck"
cppcheck --quiet --std=c++17 --language=c++ --enable=warning,performance,portability \
  --error-exitcode=1 --inline-suppr -j2 -I core/include -I core -I cli core cli

# The whole tree was formatted once, in a commit of its own; from then on every file stays so.
files=("$@")
[ ${#files[@]} -gt 0 ] || mapfile -t files < <(git ls-files '*.cpp' '*.h')
echo "lint: clang-format (${#files[@]} files)"
clang-format-14 --dry-run --Werror "${files[@]}"
echo "lint: clean"
