#!/usr/bin/env bash
# Static checks, any finding fails: clang-tidy (.clang-tidy) over core/ and cli/, cppcheck over
# the same, and clang-format (.clang-format) on the C++ files given as arguments, or else on the
# lines changed since the merge-base with main (the tree as a whole is not format-checked until
# it has been formatted once, in a commit of its own).
# Needs only a configured build tree (compile_commands.json), never a built one.
set -euo pipefail
cd "$(dirname "$0")/.."
B=build-lint
cmake -S . -B "$B" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DFLOOD_VIEWER=OFF -DFLOOD_TESTS=OFF \
  -DFLOOD_PYTHON=OFF >/dev/null

echo "lint: clang-tidy"
run-clang-tidy-14 -p "$B" -j2 -quiet "$PWD/(core|cli)/[^/]*\.cpp$" >"$B/clang-tidy.log" 2>&1 || {
  grep -E 'error:|warning:' "$B/clang-tidy.log" || cat "$B/clang-tidy.log"
  exit 1
}

echo "lint: cppcheck"
cppcheck --quiet --std=c++17 --language=c++ --enable=warning,performance,portability \
  --error-exitcode=1 --inline-suppr -j2 -I core -I cli core cli

if [ $# -gt 0 ]; then
  echo "lint: clang-format ($*)"
  clang-format-14 --dry-run --Werror "$@"
elif base=$(git merge-base HEAD main 2>/dev/null); then
  # Only the lines changed since the merge-base: untouched code keeps its layout until the
  # tree is formatted as a whole.
  echo "lint: clang-format (lines changed since ${base:0:12})"
  out=$(git clang-format-14 --binary clang-format-14 --diff --extensions cpp,h "$base" -- . || true)
  case "$out" in
    ""|"no modified files to format"|"clang-format did not modify any files") ;;
    *) echo "$out"; echo "lint: clang-format would change the lines above"; exit 1 ;;
  esac
fi
echo "lint: clean"
