#!/usr/bin/python3
"""Flood against earcut on earcut's valid fixtures, per call (issue 13): the small-polygon
section of docs/BENCHMARKS.md, written by scripts/small-bench.sh.

Usage: small_report.py EARCUT.tsv[,...] FLOOD.tsv[,...] CALLGRIND.txt MACHINE.txt BENCHMARKS.md

EARCUT.tsv comes from bench/node/earcut_time.mjs, FLOOD.tsv from `flood-small-bench time`; given
several of each (rounds run alternately), each figure is the least over the rounds, so a burst
of load from other jobs during one round does not decide a ratio.
FLOOD.tsv also carries Flood's fresh calls and native earcut.hpp's (fresh, warm).
CALLGRIND.txt holds "flood_triangulate N", "flood_validate_triangulate N" and "earcut_hpp N"
lines (instructions per call on `building`). The section is a kept block of BENCHMARKS.md (report.py
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


def geomean(xs):
    return math.exp(sum(math.log(x) for x in xs) / len(xs))


def section(earcut, flood, callgrind, machine):
    names = sorted(set(earcut) & set(flood), key=lambda n: (int(flood[n]["vertices"]), n))
    out = [TAG, "## Small polygons: Flood against earcut per call (issues 13, 31)", ""]
    out.append(
        "Each of earcut's valid fixtures is read and validated once; then one call is timed in a "
        "loop in the same process, without any call overhead: Flood natively and **native "
        "earcut.hpp** compiled into the same program at the same optimisation "
        "(`flood-small-bench time`; the header from Debian's source package python-mapbox-earcut), "
        "and earcut " + machine.get("earcut", "?") + " under Node.js " + machine.get("node", "?") +
        " (`bench/node/earcut_time.mjs`) as a second column, all on the same vertices (repeated "
        "and closing points dropped as Flood's reader drops them). *Fresh* is the free function "
        "(`flood::triangulate()`, `mapbox::earcut()`), allocating anew each call; *warm* reuses "
        "one `Triangulator` / one `Earcut` object. Flood + validation adds `validate()`, which the "
        "command line and the Python and C++ front doors always run; earcut validates nothing. "
        "A figure is the least of 15 batch means, batches of ~20 ms, and the least over " +
        machine.get("rounds", "?") + " rounds run alternately. Ratios are Flood / earcut.hpp "
        "(below 1: Flood is faster). Regenerate with `scripts/small-bench.sh` (machine: " +
        machine.get("cpu", "?") + ", load " + machine.get("load", "?") + ").")
    out += ["", "| fixture | vertices | earcut.hpp fresh ns | Flood fresh ns | ratio | earcut.hpp warm ns "
            "| Flood warm ns | ratio | Flood + validation, fresh ns | ratio | earcut (Node) ns |",
            "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    fresh, warm, valid = [], [], []
    for n in names:
        f = flood[n]
        ef, ew = float(f["earcut_hpp_fresh_ns"]), float(f["earcut_hpp_warm_ns"])
        ff, fw = float(f["fresh_triangulate_ns"]), float(f["triangulate_ns"])
        fv = float(f["fresh_validate_triangulate_ns"])
        node = float(earcut[n]["earcut_ns"])
        fresh.append(ff / ef), warm.append(fw / ew), valid.append(fv / ef)
        out.append(f"| {n} | {f['vertices']} | {ef:,.0f} | {ff:,.0f} | {ff / ef:.2f} | {ew:,.0f} | "
                   f"{fw:,.0f} | {fw / ew:.2f} | {fv:,.0f} | {fv / ef:.2f} | {node:,.0f} |")
    wins = lambda rs: sum(r < 1 for r in rs)
    k = len(names)
    out += ["", f"Against native earcut.hpp: Flood is faster on **{wins(warm)} of {k}** fixtures warm "
            f"(geometric-mean ratio **{geomean(warm):.2f}**), {wins(fresh)} of {k} fresh "
            f"({geomean(fresh):.2f}); validated, fresh, on {wins(valid)} of {k} "
            f"({geomean(valid):.2f}). Issue 31's goals: ≥ 28 wins and ≤ 0.8 core only, ≤ 1.2 "
            "validated."]
    if callgrind:
        out += ["", "Instructions per call on `building` (15 vertices), callgrind (deterministic): "
                f"Flood's warm `Triangulator::run()` **{callgrind.get('flood_triangulate', '?')}**, "
                f"`validate()` + `triangulate()` {callgrind.get('flood_validate_triangulate', '?')}, "
                f"native earcut.hpp's `mapbox::earcut()` **{callgrind.get('earcut_hpp', '?')}** (issue 31's goal: Flood ≤ "
                "4,889). Measured as the difference of a 1,100-call and a 100-call run of "
                "`flood-small-bench calls`, over 1,000."]
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
