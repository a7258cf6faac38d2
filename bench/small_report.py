#!/usr/bin/python3
"""Flood against earcut on earcut's valid fixtures, per call (issue 13): the small-polygon
section of docs/BENCHMARKS.md, written by scripts/small-bench.sh.

Usage: small_report.py EARCUT.tsv[,...] FLOOD.tsv[,...] CALLGRIND.txt MACHINE.txt BENCHMARKS.md

EARCUT.tsv comes from bench/node/earcut_time.mjs, FLOOD.tsv from `flood-small-bench time`; given
several of each (rounds run alternately), each figure is the least over the rounds, so a burst
of load from other jobs during one round does not decide a ratio.
CALLGRIND.txt holds "flood_triangulate N" and "flood_validate_triangulate N" lines
(instructions per call on `building`). The section is a kept block of BENCHMARKS.md (report.py
carries it over), recognised by its tag and replaced, or appended when absent.
"""
import csv
import math
import os
import sys

TAG = "<!-- small-polygons -->"


def rows(paths):
    best = {}
    for path in paths.split(","):
        with open(path, newline="") as f:
            for r in csv.DictReader(f, delimiter="\t"):
                name = os.path.basename(r["file"]).removesuffix(".json")
                if name in best:
                    r = {k: (str(min(float(v), float(best[name][k]))) if k.endswith("_ns") else v) for k, v in r.items()}
                best[name] = r
    return best


def section(earcut, flood, callgrind, machine):
    names = sorted(set(earcut) & set(flood), key=lambda n: (int(flood[n]["vertices"]), n))
    out = [TAG, "## Small polygons: Flood against earcut per call (issue 13)", ""]
    out.append(
        "Each of earcut's valid fixtures is read and validated once; then one call is timed in a "
        "loop in the same process, without any call overhead: Flood's `Triangulator::run()` "
        "natively (`flood-small-bench time`), earcut " + machine.get("earcut", "?") +
        " under Node.js " + machine.get("node", "?") + " (`bench/node/earcut_time.mjs`), both "
        "on the same vertices (repeated and closing points dropped as Flood's reader drops "
        "them). A figure is the least of 15 batch means, batches of ~20 ms, and the least over " + machine.get("rounds", "?") + " rounds run alternately. Ratio = Flood / earcut "
        "(below 1: Flood is faster). Flood + validation adds `validate()`, which the command line "
        "always runs; earcut validates nothing. Regenerate with `scripts/small-bench.sh` "
        "(machine: " + machine.get("cpu", "?") + ", load " + machine.get("load", "?") + ").")
    out += ["", "| fixture | vertices | earcut ns | Flood ns | ratio | Flood + validation ns | ratio |",
            "|---|---:|---:|---:|---:|---:|---:|"]
    logs, logs_v, faster, faster_v = [], [], 0, 0
    for n in names:
        e = float(earcut[n]["earcut_ns"])
        f = float(flood[n]["triangulate_ns"])
        v = float(flood[n]["validate_triangulate_ns"])
        logs.append(math.log(f / e))
        logs_v.append(math.log(v / e))
        faster += f < e
        faster_v += v < e
        out.append(f"| {n} | {flood[n]['vertices']} | {e:,.0f} | {f:,.0f} | {f / e:.2f} | {v:,.0f} | {v / e:.2f} |")
    g = math.exp(sum(logs) / len(logs))
    gv = math.exp(sum(logs_v) / len(logs_v))
    out += ["", f"Flood is faster on **{faster} of {len(names)}** fixtures (goal ≥ 28), geometric-mean "
            f"ratio **{g:.2f}** (goal ≤ 0.8); with validation faster on {faster_v} of {len(names)}, "
            f"geometric-mean ratio {gv:.2f} (goal ≤ 1.5)."]
    if callgrind:
        out += ["", "Instructions per call on `building` (15 vertices), callgrind (deterministic): "
                f"`triangulate()` **{callgrind.get('flood_triangulate', '?')}**, `validate()` + "
                f"`triangulate()` {callgrind.get('flood_validate_triangulate', '?')}; the issue's "
                "reference for the C++ earcut.hpp is 5,024. Measured as the difference of a 1,100-call "
                "and a 100-call run of `flood-small-bench calls`, over 1,000."]
    return "\n".join(out) + "\n"


def main():
    if len(sys.argv) != 6:
        sys.exit("usage: small_report.py EARCUT.tsv FLOOD.tsv CALLGRIND.txt MACHINE.txt BENCHMARKS.md")
    kv = lambda p: dict(l.split(" ", 1) for l in open(p).read().splitlines() if " " in l) if os.path.exists(p) else {}
    text = section(rows(sys.argv[1]), rows(sys.argv[2]), kv(sys.argv[3]), kv(sys.argv[4]))
    md = sys.argv[5]
    old = open(md).read() if os.path.exists(md) else ""
    kb, ke = "<!-- kept:begin -->", "<!-- kept:end -->"
    block = kb + "\n" + text + ke
    start = old.find(kb + "\n" + TAG)
    if start >= 0:
        end = old.index(ke, start) + len(ke)
        new = old[:start] + block + old[end:]
    else:
        new = old.rstrip("\n") + "\n\n" + block + "\n"
    with open(md, "w") as f:
        f.write(new)


if __name__ == "__main__":
    main()
