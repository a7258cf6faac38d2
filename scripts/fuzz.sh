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
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_EACH="${1:-60}"
B=build-fuzz
cmake -S . -B "$B" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang -DFLOOD_FUZZ=ON \
  -DFLOOD_TESTS=OFF -DFLOOD_VIEWER=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$B" -j2 --target flood fuzz_read fuzz_flood fuzz_trace
python3 scripts/fuzz-seeds.py "$B/seeds" "$B/flood"
mkdir -p "$B/artifacts"
status=0
for h in ${FUZZ_ONLY:-read flood trace}; do
  mkdir -p "$B/corpus/$h"
  log="$B/fuzz_$h.log"
  if ASAN_OPTIONS=detect_leaks=1 "$B/fuzz/fuzz_$h" "$B/corpus/$h" "$B/seeds/$h" \
      -max_total_time="$SECONDS_EACH" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
      -print_final_stats=1 -artifact_prefix="$B/artifacts/$h-" ${FUZZ_SEED:+-seed=$FUZZ_SEED} \
      ${FUZZ_FLAGS:-} >"$log" 2>&1; then
    result=ok
  else
    result=FAILED
    status=1
    tail -40 "$log"
  fi
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
  [ -n "$execs" ] || execs=$(grep -o '^#[0-9]*' "$log" | tail -1 | tr -d '#' || true)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 || true)
  echo "fuzz_$h: $result, $execs executions in ${SECONDS_EACH} s, $cov, corpus $(ls "$B/corpus/$h" | wc -l) files"
done
exit $status
