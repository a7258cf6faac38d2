#!/usr/bin/env bash
# Do two builds of `flood` write the same bytes? For changes meant not to change any output
# (speed, memory): compares triangulate, triangulate --no-validate, trace and transcript
# --narrate (stdout, stderr, exit code, output file) along +y, -y, +x and 30 degrees, on every
# polygons/*.json and on each generated family at 50 and 3,000 vertices (seed 1).
#   scripts/same-output.sh OLD_FLOOD NEW_FLOOD     prints "runs R differing D", lists the
#                                                  differing runs and exits 1 when D > 0
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
old="$1" new="$2"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

inputs=("$root"/polygons/*.json)
# The valid families, as the generator's own error message lists them.
families=$("$old" generate nonesuch 3 2>&1 | sed -n 's/.*; families: \([^;]*\);.*/\1/p' | tr -d , || true)
[ -n "$families" ] || { echo "same-output: no family list from $old generate" >&2; exit 2; }
for family in $families; do
  for size in 50 3000; do
    f="$tmp/$family-$size.json"
    # Every family must generate: a list misread (it once kept the commas, and compared two
    # families of twenty) would otherwise shrink the comparison without a word.
    "$old" generate "$family" "$size" --seed 1 -o "$f" ||
      { echo "same-output: $old cannot generate $family $size" >&2; exit 2; }
    inputs+=("$f")
  done
done

# run BIN SIDE CMD... -> SIDE.{stdout,stderr,rc,out} in $tmp, the binary's path masked
run() {
  local bin=$1 side=$2; shift 2
  rm -f "$tmp/$side.json"
  if [[ $1 == triangulate ]]; then
    timeout 120 "$bin" "$@" -o "$tmp/$side.json" >"$tmp/$side.stdout" 2>"$tmp/$side.stderr" && rc=0 || rc=$?
  else
    timeout 120 "$bin" "$@" >"$tmp/$side.stdout" 2>"$tmp/$side.stderr" && rc=0 || rc=$?
  fi
  echo "$rc" >"$tmp/$side.rc"
  sed -i "s#$bin#FLOOD#g" "$tmp/$side.stdout" "$tmp/$side.stderr"
}

runs=0 differing=0
for f in "${inputs[@]}"; do
  for up in +y -y +x 30; do
    for cmd in "triangulate" "triangulate --no-validate" "trace" "transcript --narrate"; do
      # shellcheck disable=SC2086  # cmd is a command and its flag
      run "$old" old $cmd "--up=$up" "$f"
      # shellcheck disable=SC2086
      run "$new" new $cmd "--up=$up" "$f"
      runs=$((runs + 1))
      # A usage error means the comparison, not the build, is wrong (it once compared two
      # refusals of an output name): stop rather than report the same bytes.
      if [ "$(cat "$tmp/old.rc")" = 2 ]; then
        echo "same-output: usage error from $old on $cmd $f: $(head -c 300 "$tmp/old.stderr")" >&2
        exit 2
      fi
      same=1
      for x in stdout stderr rc; do cmp -s "$tmp/old.$x" "$tmp/new.$x" || same=0; done
      if [ -e "$tmp/old.json" ] || [ -e "$tmp/new.json" ]; then cmp -s "$tmp/old.json" "$tmp/new.json" || same=0; fi
      if [ $same = 0 ]; then differing=$((differing + 1)); echo "differs: $(basename "$f") --up=$up $cmd"; fi
    done
  done
done
echo "runs $runs differing $differing"
[ "$differing" = 0 ]
