#!/usr/bin/env bash
# Builds the libFuzzer harnesses (fuzz/, clang++) into build-fuzz and runs each for a bounded
# time: scripts/fuzz.sh [SECONDS]  (default 60 s per harness).
# The corpus grows in build-fuzz/corpus/<harness> across runs; seeds come from polygons/ and
# ../shared/peers/earcut/fixtures (scripts/fuzz-seeds.py). A crash, hang (> 10 s on one
# input), leak or UB stops the run, leaves the input in build-fuzz/artifacts/ and fails.
# FUZZ_FLAGS adds libFuzzer flags, e.g. FUZZ_FLAGS="-fork=1 -ignore_crashes=1
# -ignore_timeouts=1" keeps going past findings; FUZZ_ONLY="read trace" picks harnesses.
# FUZZ_SEED=N fixes libFuzzer's random seed: with a fresh corpus the run is then a prefix of
# any longer run with the same seed, which is how CI keeps its pass reproducible.
# FUZZ_JOBS=N runs N harnesses at once (default 1; each libFuzzer process uses one core).
# FUZZ_CLI=path/to/flood writes the trace seeds with a CLI already built (CI passes build/'s:
# every build writes the same traces), instead of building one in build-fuzz.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_EACH="${1:-60}"
B=build-fuzz
cmake -S . -B "$B" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang -DFLOOD_FUZZ=ON \
  -DFLOOD_TESTS=OFF -DFLOOD_VIEWER=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cli="${FUZZ_CLI:-$B/flood}"
[ -n "${FUZZ_CLI:-}" ] || cmake --build "$B" -j2 --target flood
cmake --build "$B" -j2 --target fuzz_read fuzz_flood fuzz_trace
python3 scripts/fuzz-seeds.py "$B/seeds" "$cli"
mkdir -p "$B/artifacts"

# One harness for SECONDS_EACH; its one-line summary goes to $B/fuzz_<h>.result.
fuzz_one() {
  local h=$1 log="$B/fuzz_$1.log" result execs cov
  mkdir -p "$B/corpus/$h"
  if ASAN_OPTIONS=detect_leaks=1 "$B/fuzz/fuzz_$h" "$B/corpus/$h" "$B/seeds/$h" \
      -max_total_time="$SECONDS_EACH" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
      -print_final_stats=1 -artifact_prefix="$B/artifacts/$h-" ${FUZZ_SEED:+-seed=$FUZZ_SEED} \
      ${FUZZ_FLAGS:-} >"$log" 2>&1; then
    result=ok
  else
    result=FAILED
  fi
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
  [ -n "$execs" ] || execs=$(grep -o '^#[0-9]*' "$log" | tail -1 | tr -d '#' || true)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 || true)
  echo "fuzz_$h: $result, $execs executions in ${SECONDS_EACH} s, $cov, corpus $(ls "$B/corpus/$h" | wc -l) files" >"$B/fuzz_$h.result"
}

harnesses=(${FUZZ_ONLY:-read flood trace})
running=0
for h in "${harnesses[@]}"; do
  if [ "$running" -ge "${FUZZ_JOBS:-1}" ]; then
    wait -n
    running=$((running - 1))
  fi
  rm -f "$B/fuzz_$h.result"
  fuzz_one "$h" &
  running=$((running + 1))
done
wait
status=0
for h in "${harnesses[@]}"; do
  cat "$B/fuzz_$h.result"
  if ! grep -q '^fuzz_[a-z]*: ok,' "$B/fuzz_$h.result"; then
    status=1
    tail -40 "$B/fuzz_$h.log"
  fi
done
exit $status
