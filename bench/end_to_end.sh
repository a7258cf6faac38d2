#!/usr/bin/env bash
# The command line end to end (issue 13): `flood triangulate FILE -o OUT` on each generated
# family at 10^6 and above, as a user runs it (read JSON, validate, flood, exact check, write),
# beside Flood's triangulate() alone timed by `flood-bench run`. Writes DATA/e2e.tsv:
# wall and user seconds (the best of two runs) and the peak resident size, less that of the same
# command on an 8-vertex polygon (the program and its libraries), as tests/cli/cli_memory_test.cpp
# measures it. At 10^6 also where the command's time goes: `flood bench`'s CPU time per step (read,
# validate, flood, exact check, write; one run each, ns per vertex), and the wall time on one core
# (taskset -c 0) beside the two cores' (issue 31 goal 5).
# With DATASET (a large GeoJSON FeatureCollection: bench.sh gives the world's countries), also
# `flood check -j1` against `-j2` on it: DATA/check_jobs.tsv, the best wall time of two runs each.
#   bench/end_to_end.sh DATA FLOOD SEED TIMEOUT [DATASET]
set -euo pipefail
data="$1" flood="$2" seed="$3" timeout="$4" dataset="${5:-}"
tmp="$data/e2e"
mkdir -p "$tmp"

# smaller A [B] -> the smaller of two times (A when B is empty): a best of runs.
smaller() { echo "$1 ${2:-$1}" | awk '{ print $1 < $2 ? $1 : $2 }'; }

# peak_run FILE [PREFIX...] -> "wall user peak_kb" of one run, or "failed"
peak_run() {
  local file="$1"; shift
  if /usr/bin/time -f '%e %U %M' -o "$tmp/time.txt" timeout "$timeout" \
      "$@" "$flood" triangulate "$file" -o "$tmp/out.json" >/dev/null 2>"$tmp/stderr.txt"; then
    tail -1 "$tmp/time.txt"
  else
    echo failed
  fi
}

"$flood" generate circle-smooth 8 -o "$tmp/tiny.json"
base=$(peak_run "$tmp/tiny.json" | cut -d' ' -f3)
printf 'name\tvertices\tstatus\twall_s\tuser_s\tpeak_kb\tbase_kb\tsteps\twall_1core_s\n' > "$data/e2e.tsv"
tail -n +2 "$data/manifest.tsv" | while IFS=$'\t' read -r name family size vertices holes valid path verdict; do
  [ "$family" = fixture ] || [ "$size" -lt 1000000 ] && continue
  "$flood" generate "$family" "$size" --seed "$seed" -o "$tmp/in.json"
  best=""
  runs="1 2"; [ "$size" -gt 1000000 ] && runs=1  # 10^7: one run
  for run in $runs; do
    r=$(peak_run "$tmp/in.json")
    [ "$r" = failed ] && { best=failed; break; }
    # The faster run's wall time and its own user time; the larger peak of the two.
    if [ -z "$best" ]; then best="$r"; else
      best=$(echo "$best $r" | awk '{ w = $1 < $4 ? $1 " " $2 : $4 " " $5; m = $3 > $6 ? $3 : $6; print w, m }')
    fi
  done
  if [ "$best" = failed ]; then
    printf '%s\t%s\tfailed\t0\t0\t0\t%s\t\t\n' "$name" "$vertices" "$base" >> "$data/e2e.tsv"
  else
    read -r wall user peak <<< "$best"
    steps="" one=""
    if [ "$size" -eq 1000000 ]; then
      # The same command held to one core: the best of two runs.
      for run in 1 2; do
        r=$(peak_run "$tmp/in.json" taskset -c 0)
        [ "$r" = failed ] && { one=""; break; }
        w=${r%% *}
        one=$(smaller "$w" "$one")
      done
      # "end to end, CPU time per step ...: read R validate V flood F check C write W ns/vertex; ..."
      steps=$(timeout "$timeout" "$flood" bench "$tmp/in.json" --repeat 1 | grep '^end to end' |
              sed -E 's/.*: (read [^;]*) ns\/vertex;.*/\1/' | awk '{ printf "%s=%s;%s=%s;%s=%s;%s=%s;%s=%s", $1, $2, $3, $4, $5, $6, $7, $8, $9, $10 }') || steps=""
    fi
    printf '%s\t%s\tok\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$vertices" "$wall" "$user" "$peak" "$base" "$steps" "$one" >> "$data/e2e.tsv"
  fi
  rm -f "$tmp/in.json" "$tmp/out.json"
done

# flood check on a real dataset, one thread against two.
if [ -n "$dataset" ] && [ -f "$dataset" ]; then
  printf 'dataset\tbytes\tjobs\twall_s\tpeak_kb\n' > "$data/check_jobs.tsv"
  for jobs in 1 2; do
    best="" peak=""
    for run in 1 2; do
      # Exit 4: the dataset holds invalid features; anything above 6 is a failure of the run.
      /usr/bin/time -f '%e %M' -o "$tmp/time.txt" timeout "$timeout" \
        "$flood" check -q -j"$jobs" "$dataset" >/dev/null 2>"$tmp/stderr.txt" || [ $? -le 6 ] || continue
      read -r w peak < <(tail -1 "$tmp/time.txt")
      best=$(smaller "$w" "$best")
    done
    printf '%s\t%s\t%s\t%s\t%s\n' "$(basename "$(dirname "$dataset")")" "$(stat -c %s "$dataset")" \
      "$jobs" "${best:-failed}" "${peak:-0}" >> "$data/check_jobs.tsv"
  done
fi
