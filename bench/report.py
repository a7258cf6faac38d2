#!/usr/bin/python3
"""Writes docs/BENCHMARKS.md and docs/bench.svg from the results of scripts/bench.sh.

Usage: report.py DATA_DIR BENCHMARKS.md PLOT.svg [README.md]

Standard library only. Everything in the output is computed from DATA_DIR (results.tsv,
memory.tsv, manifest.tsv, earcut-overhead.txt, machine.txt); nothing is typed in by hand. When
README.md holds the markers <!-- bench:begin --> and <!-- bench:end -->, the summary between
them is replaced too. Sections of BENCHMARKS.md between <!-- kept:begin --> and
<!-- kept:end --> (figures measured by other commands, which say so) are carried over as they are.
"""
import csv
import math
import os
import sys
from collections import defaultdict

TRIANGULATORS = ["flood", "flood-rec", "earcut-hpp", "earcut-js", "earcut", "libtess", "poly2tri", "glu", "cgal", "geos"]
PEERS = ["earcut-hpp", "earcut-js", "earcut", "libtess", "poly2tri", "glu", "cgal", "geos"]
LABEL = {"flood": "Flood", "flood-rec": "Flood + trace", "earcut-hpp": "earcut.hpp (C++)", "earcut-js": "earcut (Node)",
         "earcut": "earcut (Python)", "libtess": "libtess (Node)", "poly2tri": "poly2tri (Node)",
         "glu": "GLU", "cgal": "CGAL CDT", "geos": "GEOS CDT", "floor": "floor"}
COLOR = {"flood": "#d62728", "flood-rec": "#ff9896", "earcut-hpp": "#17becf", "earcut-js": "#1f77b4", "earcut": "#aec7e8",
         "libtess": "#98df8a", "poly2tri": "#e377c2", "glu": "#2ca02c", "cgal": "#9467bd",
         "geos": "#8c564b", "floor": "#000000"}
PLOTTED = TRIANGULATORS + ["floor"]
MILLION = 1000000  # the issue's goals are stated at N = 10^6
REAL = "coast"  # bench/real_inputs.py's family: real coastlines, apart from the generated ones
EVENT_BYTES = 112  # sizeof(flood::Event); main() reads the run's event_bytes.txt
TIMED = {"valid", "invalid", "count-differs", "adds-vertices", "refused", "ok"}  # ok: the floor
MARK = {"valid": "", "ok": "", "invalid": " ✗", "count-differs": " #", "adds-vertices": " +",
        "refused": " R", "error": "E", "timeout": "T", "crash": "C", "skipped": "S", "missing": "–"}


def read_tsv(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f, delimiter="\t", quoting=csv.QUOTE_NONE))


def fmt(x):
    if x is None:
        return "–"
    if x >= 100:
        return "{:,.0f}".format(x)
    if x >= 10:
        return "%.1f" % x
    return "%.2f" % x


def fit(points):
    """Least-squares slope and constant of log T = log c + A log N."""
    if len(points) < 2:
        return None, None
    xs = [math.log(n) for n, _ in points]
    ys = [math.log(t) for _, t in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    a = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx
    return a, math.exp(my - a * mx)


class Data:
    def __init__(self, d):
        self.rows = read_tsv(os.path.join(d, "results.tsv"))
        self.memory = read_tsv(os.path.join(d, "memory.tsv"))
        self.e2e = {r["name"]: r for r in read_tsv(os.path.join(d, "e2e.tsv"))}  # bench/end_to_end.sh
        self.inputs = []  # in manifest order
        self.info = {}
        for r in read_tsv(os.path.join(d, "manifest.tsv")):
            self.inputs.append(r["name"])
            self.info[r["name"]] = r
        self.cell = {}
        for r in self.rows:
            self.cell[(r["name"], r["triangulator"])] = r
        p = os.path.join(d, "earcut-overhead.txt")
        self.overhead = float(open(p).read()) if os.path.exists(p) else None
        p = os.path.join(d, "machine.txt")
        self.machine = open(p).read().strip().splitlines() if os.path.exists(p) else []
        self.small_section = False  # S13's small-polygon section is kept in BENCHMARKS.md (main())
        p = os.path.join(d, "check_jobs.tsv")  # bench/end_to_end.sh: flood check -j1, -j2
        self.check_jobs = read_tsv(p) if os.path.exists(p) else []
        self.families = []  # the generator's families (not earcut's fixtures, not the coastlines)
        for n in self.inputs:
            fam = self.info[n]["family"]
            if fam not in ("fixture", REAL) and fam not in self.families:
                self.families.append(fam)

    def get(self, name, who):
        return self.cell.get((name, who))

    def nsv(self, name, who):
        """ns per vertex, or None when not timed."""
        r = self.get(name, who)
        if not r or r["status"] not in TIMED:
            return None
        return float(r["ns"]) / max(1, int(r["vertices"]))

    def rec_extra(self, name):
        rr = self.get(name, "flood-rec")
        return dict(kv.split("=", 1) for kv in rr["extra"].split(";") if "=" in kv) if rr else {}

    def rec_base(self, name):
        """Flood without a listener, ns per vertex, as timed in turn with the recorded runs
        (same child, same load); the separate Flood row when the pair is missing."""
        e = self.rec_extra(name)
        if "paired_plain_ns" in e:
            return float(e["paired_plain_ns"]) / max(1, int(self.info[name]["vertices"]))
        return self.nsv(name, "flood")

    def cell_text(self, name, who):
        r = self.get(name, who)
        if not r:
            return "–"
        v = self.nsv(name, who)
        if v is None:
            return MARK.get(r["status"], r["status"])
        return fmt(v) + MARK.get(r["status"], " ?")

    def extra(self, name, who):
        r = self.get(name, who)
        return dict(kv.split("=", 1) for kv in r["extra"].split(";") if "=" in kv) if r else {}

    def at_million(self, fam):
        """The family's input at N = 10^6 (the goals' size), else its largest up to 10^6."""
        ns = [n for n in self.by_family(fam) if int(self.info[n]["size"]) <= MILLION]
        exact = [n for n in ns if int(self.info[n]["size"]) == MILLION]
        return exact[0] if exact else (ns[-1] if ns else None)

    def sag_share(self, name):
        """The sag search's share of the machine's counted work (flood/geometry/work.h), or None."""
        e = self.extra(name, "flood")
        if "machine_work" not in e or int(e["machine_work"]) == 0:
            return None
        return int(e["sag_work"]) / int(e["machine_work"])

    def by_family(self, fam):
        return [n for n in self.inputs if self.info[n]["family"] == fam]

    def validated(self, name):
        """validate() + a fresh triangulate(), ns per vertex, as a caller pays it; or None."""
        v, e = self.nsv(name, "flood"), self.extra(name, "flood")
        if v is None or "validate_ns" not in e:
            return None
        return v + float(e["validate_ns"]) / max(1, int(self.info[name]["vertices"]))

    def exponent(self, fam, who, smallest=0):
        pts, clean = [], True
        for n in self.by_family(fam):
            if int(self.info[n]["size"]) < smallest:
                continue
            r = self.get(n, who)
            v = self.nsv(n, who)
            if v is not None:
                pts.append((int(r["vertices"]), float(r["ns"])))
                clean = clean and r["status"] == "valid"
        a, _ = fit(pts)
        return a, len(pts), clean


def status_legend():
    return ("Cells are ns per vertex (median time / input vertices). Marks: ✗ output fails the exact "
            "checker, # triangle count differs from n + 2h − 2 (e.g. dropped collinear or duplicate "
            "vertices), + output has points that are not input vertices, R Flood refused the input "
            "(forbidden transition), T timeout, S skipped (timed out at a smaller size, or its time "
            "predicted from the two smaller sizes is over the limit), C crash, E the peer reported an "
            "error. Unmarked: valid by the exact checker.")


def size_note(D, n):
    return "" if int(D.info[n]["size"]) == MILLION else " (N = %s: 10⁶ not run)" % D.info[n]["vertices"]


def caveat(D):
    """A warning computed from the run itself: stopped below 10^6, or a machine busier than its cores."""
    out = []
    largest = max((int(D.info[n]["size"]) for n in D.inputs if D.info[n]["family"] != "fixture"), default=0)
    if largest < MILLION:
        out.append("this run stopped at N = %s (BENCH_MAX_SIZE): it checks the pipeline, and the goals "
                   "stated at 10⁶ are not measured by it" % "{:,}".format(largest))
    load = next((l.split(": ", 1)[1] for l in D.machine if l.startswith("load")), None)
    cores = next((l.split(": ", 1)[1] for l in D.machine if l.startswith("cores")), None)
    if load and cores and float(load.split()[0]) > int(cores):
        out.append("the load average at the end was %s on %s cores: other jobs ran beside it, so every time "
                   "is inflated (by several times where the load is several times the cores)" % (load.split()[0], cores))
    return ("**Caveat**: " + "; ".join(out) + ".\n\n") if out else ""


def goals(D):
    """Issue 13's goals, at N = 10^6 on every family."""
    out = []
    # A <= 1.05 on every family.
    lines, ok = [], True
    for fam in D.families:
        a, k, _ = D.exponent(fam, "flood")
        last = D.get(D.by_family(fam)[-1], "flood")
        complete = last is not None and last["status"] in TIMED
        ok = ok and a is not None and a <= 1.05 and complete
        lines.append("%s %s%s" % (fam, "–" if a is None else "%.2f" % a, "" if complete else " (largest size not timed)"))
    out.append(("Flood's fitted exponent A ≤ 1.05 on every family", "; ".join(lines), ok))
    # <= 300 ns/vertex at 10^6 on every family, the median family <= 150.
    lines, ok, per = [], True, []
    for fam in D.families:
        n = D.at_million(fam)
        v = D.nsv(n, "flood") if n else None
        ok = ok and v is not None and v <= 300 and int(D.info[n]["size"]) == MILLION
        if v is not None:
            per.append((v, fam))
        lines.append("%s %s%s" % (fam, fmt(v), size_note(D, n) if n else ""))
    out.append(("Flood ≤ 300 ns/vertex at 10⁶ on every family", "; ".join(lines), ok))
    per.sort()
    if per:
        med = per[len(per) // 2] if len(per) % 2 else per[len(per) // 2 - 1]  # the lower median: a family
        out.append(("The median family ≤ 150 ns/vertex at 10⁶",
                    "%s: %s ns/v (of %d families; the lower median)" % (med[1], fmt(med[0]), len(per)),
                    med[0] <= 150 and all(int(D.info[D.at_million(f)]["size"]) == MILLION for f in D.families)))
    # The sag search costs no more than the rest of the machine.
    lines, ok = [], True
    for fam in D.families:
        n = D.at_million(fam)
        sh = D.sag_share(n) if n else None
        ok = ok and sh is not None and sh <= 0.5
        lines.append("%s %s" % (fam, "–" if sh is None else "%.0f%%" % (100 * sh)))
    out.append(("The sag search ≤ the rest of the machine on every family (its share of the counted work, flood/geometry/work.h)",
                "; ".join(lines), ok))
    # Flood within 6x of the floor.
    lines, ok = [], True
    for fam in D.families:
        n = D.at_million(fam)
        f, fl = (D.nsv(n, "flood"), D.nsv(n, "floor")) if n else (None, None)
        ok = ok and f is not None and fl is not None and f <= 6 * fl
        lines.append("%s %s" % (fam, "%.1f×" % (f / fl) if f and fl else "–"))
    out.append(("Flood ≤ 6× the floor on every family (at 10⁶)", "; ".join(lines), ok))
    out += end_to_end_goals(D)
    # Small polygons: triangulation alone against earcut under Node.js, on the valid fixtures.
    pairs = []
    for n in D.inputs:
        if D.info[n]["family"] != "fixture" or D.info[n]["valid"] != "1":
            continue
        f, e = D.nsv(n, "flood"), D.nsv(n, "earcut-js")
        fr, er = D.get(n, "flood"), D.get(n, "earcut-js")
        if f and e and fr["status"] == "valid" and er["status"] in ("valid", "count-differs"):
            pairs.append(f / e)
    if pairs:
        wins = sum(r <= 1 for r in pairs)
        gm = math.exp(sum(math.log(r) for r in pairs) / len(pairs))
        out.append(("Small polygons: Flood ahead of earcut (Node) on ≥ 28 of 32 valid fixtures, geometric mean ratio ≤ 0.8",
                    "ahead on %d of %d (valid by Flood's validate(), both timed); geometric mean Flood / earcut %.2f%s" %
                    (wins, len(pairs), gm, "; per-call figures and instruction counts: the small-polygon section below"
                     if D.small_section else ""),
                    wins >= 28 and gm <= 0.8))
    return out


STEPS = ["read", "validate", "flood", "check", "write"]  # `flood bench`'s steps of the command
ISSUE_CIRCLE_HOLES_S = 3.5  # issue 13: `flood triangulate` on circle-holes 10^6 took 3.5 s end to end


def e2e_figures(D, n):
    """(command ns/vertex, command / triangulate(), peak B/vertex above the base) or None."""
    r = D.e2e.get(n)
    if not r or r["status"] != "ok":
        return None
    v = int(r["vertices"])
    ns = float(r["wall_s"]) * 1e9 / v
    f = D.nsv(n, "flood")
    return ns, (ns / f if f else None), (int(r["peak_kb"]) - int(r["base_kb"])) * 1024 / v


def trace_bytes_per_event(D, n):
    """The peak of record() above that of triangulate() on the same input, per event."""
    m = {x["mode"]: x for x in D.memory if x["name"] == n and x["status"] == "ok"}
    if "plain" not in m or "record" not in m or int(m["record"]["events"]) == 0:
        return None
    return (int(m["record"]["maxrss_peak_kb"]) - int(m["plain"]["maxrss_peak_kb"])) * 1024 / int(m["record"]["events"])


def end_to_end_goals(D):
    """The command line's goals: time against triangulate() alone, and its peak memory."""
    if not D.e2e:
        return []
    out = []
    lines, ok = [], True
    for fam in D.families:
        n = D.at_million(fam)
        e = e2e_figures(D, n) if n else None
        ok = ok and e is not None and e[1] is not None and e[1] <= 2
        lines.append("%s %s" % (fam, "%.1f×" % e[1] if e and e[1] else "–"))
    out.append(("`flood triangulate FILE -o OUT` within 2× of a fresh `triangulate()` at 10⁶ on every family",
                "; ".join(lines), ok))
    n = D.at_million("circle-holes")
    e = e2e_figures(D, n) if n else None
    if e:
        wall = float(D.e2e[n]["wall_s"])
        out.append(("`flood triangulate` ≥ 5× faster than the issue's 3.5 s on circle-holes 10⁶",
                    "%.2f s: %.1f× faster" % (wall, ISSUE_CIRCLE_HOLES_S / wall), ISSUE_CIRCLE_HOLES_S / wall >= 5))
    lines, ok = [], True
    for n in D.inputs:
        if n not in D.e2e:
            continue
        e = e2e_figures(D, n)
        ok = ok and e is not None and e[2] <= 120
        lines.append("%s %s" % (n, fmt(e[2]) if e else D.e2e[n]["status"]))
    out.append(("`flood triangulate` peak ≤ 120 bytes/vertex above the program at 10⁶ and 10⁷",
                "; ".join(lines), ok))
    per = [(trace_bytes_per_event(D, D.at_million(f)), f) for f in D.families]
    per = sorted((b, f) for b, f in per if b is not None)
    out.append(("The trace ≤ 100 bytes/event",
                "the log holds %d B an event (sizeof(Event), sized exactly by record()); record()'s peak "
                "above triangulate()'s at 10⁶, which adds the trace's polygon and triangles and the "
                "machine's working memory alive beside the log: %s–%s B/event (%s–%s)" %
                (EVENT_BYTES, fmt(per[0][0]) if per else "–", fmt(per[-1][0]) if per else "–",
                 per[0][1] if per else "", per[-1][1] if per else ""), EVENT_BYTES <= 100))
    return out


OVER = "over"  # a ratio whose peer did not finish within the limit while Flood did: a win


def ratio(D, name, flood_nsv, peer):
    """Flood / peer on one input: a number, OVER, or None when not both measured."""
    p = D.nsv(name, peer)
    if flood_nsv and p:
        return flood_nsv / p
    r = D.get(name, peer)
    if flood_nsv and r and r["status"] in ("timeout", "skipped"):
        return OVER
    return None


def ratio_line(pairs, peer):
    """'name ×r' for (name, ratio()) pairs, and whether Flood is ahead on every one."""
    text = "; ".join("%s %s" % (n, "×%.2f" % r if isinstance(r, float) else
                                "%s over the limit" % LABEL[peer] if r == OVER else "–") for n, r in pairs)
    return text, bool(pairs) and all(r == OVER or (r is not None and r < 1) for _, r in pairs)


def issue31_goals(D):
    """Issue 31's goals that the run measures: what a user pays, against the peer they would pick."""
    out = []
    coasts = [n for n in D.inputs if D.info[n]["family"] == REAL]
    if coasts:
        pairs = [("%s (%s v)" % (n.split("/")[1], D.info[n]["vertices"]), ratio(D, n, D.validated(n), "earcut-hpp"))
                 for n in coasts]
        text, ok = ratio_line(pairs, "earcut-hpp")
        out.append(("Validated (validate() + a fresh `triangulate()`) ahead of native earcut.hpp on every real "
                    "coastline (Flood / earcut.hpp)", text, ok))
    pairs = [(n, ratio(D, n, D.validated(n), "earcut-hpp")) for fam in D.families for n in D.by_family(fam)
             if int(D.info[n]["size"]) in (100000, MILLION)]
    text, ok = ratio_line(pairs, "earcut-hpp")
    out.append(("Validated ahead of native earcut.hpp on every family at 10⁵ and 10⁶ (Flood / earcut.hpp)",
                text, ok))
    pairs = [(n, ratio(D, n, D.nsv(n, "flood"), "earcut-hpp")) for n in D.by_family("islands")]
    text, ok = ratio_line(pairs, "earcut-hpp")
    out.append(("islands: a fresh `triangulate()` ahead of native earcut.hpp at every size", text, ok))
    lines, ok = [], True
    for fam in D.families:
        a, k, _ = D.exponent(fam, "flood", smallest=10000)
        ok = ok and a is not None and a <= 1.05 and k >= 3
        lines.append("%s %s" % (fam, "–" if a is None else "%.2f" % a))
    out.append(("Fitted exponent A ≤ 1.05 from 10⁴ up (10⁷ where run) on every family", "; ".join(lines), ok))
    pairs = [(n, ratio(D, n, D.nsv(n, "flood"), "glu")) for fam in ("comb", "equal-heights")
             for n in D.by_family(fam)]
    text, ok = ratio_line(pairs, "glu")
    out.append(("Ahead of GLU on comb and equal-heights at every size (Flood / GLU)", text, ok))
    jobs = {r["jobs"]: r for r in D.check_jobs if r["wall_s"] != "failed"}
    if "1" in jobs and "2" in jobs:
        one, two = float(jobs["1"]["wall_s"]), float(jobs["2"]["wall_s"])
        out.append(("`flood check -j2` ≥ 1.7× faster than `-j1` on a real dataset",
                    "%s (%.0f MB): -j1 %.2f s, -j2 %.2f s: ×%.2f" %
                    (jobs["1"]["dataset"], int(jobs["1"]["bytes"]) / 1e6, one, two, one / two), one / two >= 1.7))
    return out


def targets(D):
    out = goals(D) + issue31_goals(D)
    # 1. Flood <= earcut on the fixtures of >= 1000 vertices.
    big = [n for n in D.inputs if D.info[n]["family"] == "fixture" and int(D.info[n]["vertices"]) >= 1000]
    lines, wins, total = [], 0, 0
    for n in big:
        f, e = D.nsv(n, "flood"), D.nsv(n, "earcut-js")
        valid = D.info[n]["valid"] == "1"
        fr = D.get(n, "flood")
        if not valid:
            lines.append("%s (invalid input: Flood %s)" % (n.split("/")[1], fr["status"] if fr else "–"))
            continue
        if f is None or e is None:
            lines.append("%s: not timed" % n.split("/")[1])
            continue
        total += 1
        wins += f <= e
        lines.append("%s %s vs %s ns/v (×%.2f)" % (n.split("/")[1], fmt(f), fmt(e), f / e))
    out.append(("Flood ≤ earcut (Node) on the valid fixtures of ≥ 1,000 vertices",
                "%d of %d: " % (wins, total) + "; ".join(lines), total > 0 and wins == total))
    # 2. Faster than every peer at 10^6 (the peers do not run at 10^7) on every family.
    lines, ok = [], True
    for fam in D.families:
        n = D.at_million(fam)
        f = D.nsv(n, "flood")
        peers = [(D.nsv(n, p), p) for p in PEERS if D.nsv(n, p) is not None]
        if f is None:
            ok = False
            r = D.get(n, "flood")
            lines.append("%s: Flood %s" % (n, r["status"] if r else "–"))
            continue
        best = min(peers) if peers else None
        if best and best[0] < f:
            ok = False
            lines.append("%s: Flood %s vs %s %s ns/v (×%.2f)" % (n, fmt(f), LABEL[best[1]], fmt(best[0]), f / best[0]))
        else:
            lines.append("%s: Flood %s, best peer %s" % (n, fmt(f), (LABEL[best[1]] + " " + fmt(best[0])) if best else "none finished"))
    out.append(("Faster than every peer at 10⁶, every family", "; ".join(lines), ok))
    # 4. Recording overhead <= 1.5x.
    ratios = []
    for n in D.inputs:
        if D.info[n]["family"] == "fixture" or int(D.info[n]["vertices"]) < 10000:
            continue
        f, r = D.rec_base(n), D.nsv(n, "flood-rec")
        if f and r:
            ratios.append((r / f, n))
    reused = []
    for n in D.inputs:
        rr = D.get(n, "flood-rec")
        f = D.rec_base(n)
        extra = D.rec_extra(n)
        if rr and f and D.info[n]["family"] != "fixture" and int(D.info[n]["vertices"]) >= 10000 and "reused_ns" in extra:
            reused.append(float(extra["reused_ns"]) / int(rr["vertices"]) / f)
    reused.sort()
    if ratios:
        ratios.sort()
        med = ratios[len(ratios) // 2][0]
        out.append(("Trace recording ≤ 1.5× the time without a listener (generated inputs, N ≥ 10⁴)",
                    "record(): median ×%.2f, worst ×%.2f (%s)" % (med, ratios[-1][0], ratios[-1][1]) +
                    ("; log reused: median ×%.2f, worst ×%.2f" % (reused[len(reused) // 2], reused[-1]) if reused else ""),
                    ratios[-1][0] <= 1.5))
    return out


def table(header, rows):
    s = "| " + " | ".join(header) + " |\n|" + "|".join("---" for _ in header) + "|\n"
    for r in rows:
        s += "| " + " | ".join(str(x) for x in r) + " |\n"
    return s


def summary_table(D):
    rows = []
    for fam in D.families:
        n = D.at_million(fam)
        f = D.nsv(n, "flood")
        fl = D.nsv(n, "floor")
        peers = [(D.nsv(n, p), p) for p in PEERS if D.nsv(n, p) is not None]
        best = min(peers) if peers else None
        a, _, _ = D.exponent(fam, "flood")
        rows.append([fam, D.info[n]["vertices"]] + [D.cell_text(n, w) for w in TRIANGULATORS] +
                    [D.cell_text(n, "floor"), "%.1f" % (f / fl) if f and fl else "–",
                     "%.2f" % (f / best[0]) if f and best else "–", "–" if a is None else "%.2f" % a])
    return table(["family", "N"] + [LABEL[w] for w in TRIANGULATORS] +
                 ["floor", "Flood / floor", "Flood / best peer", "A (Flood)"], rows)


def floor_table(D):
    """Per family at 10^6 (and 10^7 where run): Flood against the floor's parts, the sag search's share."""
    rows = []
    for fam in D.families:
        for n in D.by_family(fam):
            if int(D.info[n]["size"]) < MILLION and n != D.at_million(fam):
                continue
            f, fl = D.nsv(n, "flood"), D.nsv(n, "floor")
            e = D.extra(n, "floor")
            v = max(1, int(D.info[n]["vertices"]))
            part = lambda k: fmt(float(e[k]) / v) if k in e else "–"
            sh = D.sag_share(n)
            rows.append([n, D.info[n]["vertices"], fmt(f), part("io_ns"), part("orient_ns"), part("sags_ns"),
                         fmt(fl), "%.1f" % (f / fl) if f and fl else "–", "–" if sh is None else "%.0f%%" % (100 * sh)])
    return table(["input", "n", "Flood ns/v", "floor: io", "floor: orient", "floor: sort sags", "floor ns/v",
                  "Flood / floor", "sag search share"], rows)


def markdown(D, svg_name):
    s = ["# Benchmarks: Flood against the peer triangulators\n",
         "Generated by `scripts/bench.sh` (bench/report.py) from the measurements of one run; do not "
         "edit by hand, rerun the command. Machine: " + "; ".join(D.machine) + ".\n\n"]
    s.append("\n## Method\n\n")
    s.append(
        "- One driver process (`flood-bench run`) reads every input once and measures each "
        "(input, triangulator) in a forked child with a time limit, so a crash or a hang costs one "
        "row (Flood and the floor get 4× the time limit: their figures are what the goals are about). "
        "Time is the **median** of ≥ 3 runs (until ~0.5 s are spent, at most 21; one run when a "
        "run takes over 10 s). The machine has 2 cores and other jobs ran beside the benchmark: "
        "treat differences under ~1.5× on small inputs as noise.\n"
        "- **Flood**: `triangulate(polygon)` without a listener; validation is not included (its "
        "cost is listed separately). **Flood + trace**: `record(polygon)`, full trace recording "
        "into a fresh `Trace` each run, timed alternately with plain runs in the same child (≥ 5 pairs) "
        "(the recording ratio uses those paired plain runs).\n"
        "- **GLU** (libglu1-mesa): `gluTess*`, `GLU_TESS_WINDING_ODD`, normal +z, edge-flag callback "
        "installed so only triangles come out; timed from building the coordinate array to "
        "`gluDeleteTess`.\n"
        "- **CGAL CDT** (libcgal-dev): `Constrained_Delaunay_triangulation_2` (Epick, "
        "`Exact_predicates_tag`), points with their index inserted in bulk (spatially sorted), every "
        "ring edge inserted as a constraint, faces marked inside by nesting level; timed whole, "
        "including collecting the inside triangles.\n"
        "- **GEOS CDT** (libgeos 3.11 C API): `GEOSConstrainedDelaunayTriangulation_r` on the polygon "
        "built with `GEOSCoordSeq_copyFromBuffer_r`; timed from building the geometry to destroying "
        "the result. Its output coordinates are mapped back to input indices by exact lookup in an "
        "untimed extra run.\n"
        "- **earcut (Node)**, **libtess (Node)**, **poly2tri (Node)**: the npm packages `earcut`, "
        "`libtess` (the GLU tessellator ported to JavaScript) and `poly2tri` at the versions of "
        "`bench/node/package-lock.json` (installed by `npm ci`), timed in-process under Node.js by "
        "`bench/node/peers_time.mjs` on the same vertex files, one Node process per input with the "
        "time limit. After a ~0.2 s JIT warm-up, runs shorter than 1 ms are timed in batches of "
        "~1 ms (the clock would otherwise dominate). earcut and poly2tri are called per part, libtess "
        "once (odd winding, like GLU); poly2tri gets fresh point objects each run (it keeps its sweep "
        "state on them). earcut (Node) is earcut itself without any binding's call overhead: the "
        "anchor.\n"
        "- **earcut.hpp (C++)**: native earcut.hpp from Debian's source package python-mapbox-earcut, "
        "compiled into the C++ driver at the same optimisation as Flood, `mapbox::earcut()` called "
        "afresh per part, its triangles judged like every peer's.\n"
        "- **earcut (Python)**: earcut.hpp as compiled in Debian's `python3-mapbox-earcut`, called through "
        "its numpy API `triangulate_float64(vertices, ring_end_indices)` from `bench/earcut_bench.py` "
        "on the same vertex files. The measured Python call overhead (a 3-vertex triangle) is "
        "**%s ns per call**; it is included in its times, not subtracted.\n" % (fmt(D.overhead) if D.overhead is not None else "–") +
        "- **floor** (`flood-bench floor`, bench/floor.h): what any triangulator must at least do, on the "
        "same input: *io*, a copy of the n points into fresh memory and n + 2h − 2 index triples "
        "written out (memory bandwidth); *orient*, one exact orientation test per vertex with its ring "
        "neighbours; *sort sags*, finding the sags (vertices below both neighbours) and sorting them. "
        "Each part is the median of ≥ 7 runs; the floor is their sum.\n"
        "- **Sag search share**: one extra untimed Flood run counted with flood/geometry/work.h: the sag search's "
        "node visits, sag tests and orientation tests (`sagSearch`) over all the machine's "
        "(`nodeVisits + sagTests + orientCalls`). Above 50%% the sag search costs more than the rest.\n"
        "- **Validity**: every output goes through Flood's exact checker (`flood/check/checker.h`). Peer "
        "triangles are mapped to input vertices by exact coordinates (the Node and Python peers "
        "return indices) and oriented counter-clockwise first (orientation is a convention); a "
        "triangle count different from n + 2h − 2 − 2d is reported as such (earcut drops collinear "
        "and duplicate vertices); a libtess triangle on a point it made (combine callback) counts as "
        "added.\n"
        "- **Inputs**: earcut's 59 fixtures (`../shared/peers/earcut`, consecutive duplicate points "
        "removed by Flood's reader; validity by Flood's `validate()`), and every family of the core "
        "generator (`flood generate --help`, %d families) seeded (seed 1) at N = 10³…%s; "
        "%s also at 10⁷, where only Flood and the floor run (the peers would take minutes and their "
        "growth is plain from 10³…10⁶).\n" % (len(D.families), "10⁶" if any(int(D.info[n]["size"]) >= MILLION for n in D.inputs) else "10⁵",
                                           ", ".join("`%s`" % f for f in D.families if any(int(D.info[n]["size"]) > MILLION for n in D.by_family(f))) or "no family"))
    s.append("\n## Targets\n\n")
    s.append(caveat(D))
    rows = [[t, ("**met**" if ok else "**not met**"), detail] for t, detail, ok in targets(D)]
    s.append(table(["target", "", "measured"], rows))
    s.append("\nReading the targets: the load average above was measured at the end of the run; when other "
             "jobs shared the 2 cores absolute times are inflated and ratios near 1 are within noise. "
             "Where a goal is not met, the per-family rows below say by how much; the sag search "
             "share and the floor's parts say where Flood's time goes beyond the floor.\n")
    s.append("\n## At 10⁶ per family (ns per vertex)\n\n")
    s.append(status_legend() + " *floor*: see the method; *Flood / floor*: the goal is ≤ 6.\n\n")
    s.append(summary_table(D))
    s.append("\n## Flood against the floor, and the sag search's share\n\n")
    s.append(floor_table(D))
    s.append("\n![log-log plot of time against N per family](%s)\n" % svg_name)
    s.append("\n## Fitted exponent A (T = c·N^A, least squares on log T vs log N)\n\n")
    s.append("Over the sizes that finished (number of points in brackets); * = some points are not "
             "valid triangulations. The paper reports A between 0.9 and 1.4.\n\n")
    rows = []
    for fam in D.families:
        r = [fam]
        for w in TRIANGULATORS:
            a, k, clean = D.exponent(fam, w)
            r.append("–" if a is None else "%.2f (%d)%s" % (a, k, "" if clean else "*"))
        rows.append(r)
    s.append(table(["family"] + [LABEL[w] for w in TRIANGULATORS], rows))
    s.append("\n## Generated families (ns per vertex; Flood / peer in brackets)\n\n")
    rows = []
    for fam in D.families:
        for n in D.by_family(fam):
            f = D.nsv(n, "flood")
            r = [n, D.info[n]["vertices"], D.info[n]["holes"]]
            for w in TRIANGULATORS:
                t = D.cell_text(n, w)
                v = D.nsv(n, w)
                if w in PEERS and f and v:
                    t += " (%.2f)" % (f / v)
                r.append(t)
            rows.append(r)
    s.append(table(["input", "n", "holes"] + [LABEL[w] for w in TRIANGULATORS], rows))
    coasts = [n for n in D.inputs if D.info[n]["family"] == REAL]
    if coasts:
        s.append("\n## Real coastlines (ns per vertex)\n\n")
        s.append("The outer rings of the largest land masses of OpenStreetMap's world land (npm "
                 "`@geo-maps/earth-lands-1m`, data ODbL), made valid by `ogr2ogr -makevalid` (a ring "
                 "touching itself becomes a ring and holes touching it), each the largest polygon that "
                 "gives (bench/real_inputs.py). *Validated* is what a caller pays: `validate()` plus a "
                 "fresh `triangulate()`; native earcut.hpp validates nothing.\n\n")
        others = [w for w in TRIANGULATORS if w not in ("flood", "flood-rec", "earcut-hpp")]
        rows = []
        for n in coasts:
            f, v = D.nsv(n, "flood"), D.validated(n)
            e = D.nsv(n, "earcut-hpp")
            rows.append([n, D.info[n]["vertices"], D.info[n]["holes"], D.cell_text(n, "flood"), fmt(v),
                         D.cell_text(n, "earcut-hpp"), "%.2f" % (f / e) if f and e else "–",
                         "%.2f" % (v / e) if v and e else "–"] +
                        [D.cell_text(n, w) for w in others])
        s.append(table(["input", "n", "holes", "Flood", "Flood validated", "earcut.hpp (C++)", "Flood / earcut.hpp",
                        "validated / earcut.hpp"] +
                       [LABEL[w] for w in others], rows))
    s.append("\n## earcut's fixtures (ns per vertex)\n\n")
    s.append("Input validity is Flood's `validate()`; invalid inputs are run anyway, and every "
             "triangulator's output is judged. Flood / earcut (Node) is given where both are valid.\n\n")
    rows = []
    for n in D.inputs:
        if D.info[n]["family"] != "fixture":
            continue
        f, e = D.nsv(n, "flood"), D.nsv(n, "earcut-js")
        fv = D.get(n, "flood")
        ev = D.get(n, "earcut-js")
        ratio = "%.2f" % (f / e) if f and e and fv["status"] == "valid" and ev["status"] == "valid" else "–"
        rows.append([n.split("/")[1], D.info[n]["vertices"], D.info[n]["holes"],
                     "yes" if D.info[n]["valid"] == "1" else "**no**"] +
                    [D.cell_text(n, w) for w in TRIANGULATORS] + [ratio])
    s.append(table(["fixture", "n", "holes", "valid input"] + [LABEL[w] for w in TRIANGULATORS] +
                   ["Flood / earcut"], rows))
    s.append("\n## Trace recording overhead and validation cost\n\n")
    s.append("*record()*: full trace recording as `flood trace` and the viewer get it, a fresh "
             "`Trace` per run (the polygon copied, the event log reserved once and advised onto 2 MB "
             "pages, ~%d B per event, ~1.1–1.5 events per vertex). It is timed in turn with plain "
             "runs in one child process; *Flood ns/v (paired)* is the median of those plain runs, "
             "so the ratio compares runs under the same load. *Log reused*: one listener vector "
             "cleared between runs, keeping its capacity: the gap to *record()* is first-touch "
             "memory; the rest is the listener itself.\n\n" % EVENT_BYTES)
    rows = []
    for n in D.inputs:
        if D.info[n]["family"] == "fixture":
            continue
        f, r = D.rec_base(n), D.nsv(n, "flood-rec")
        fr = D.get(n, "flood")
        rr = D.get(n, "flood-rec")
        extra = D.rec_extra(n)
        ev = extra.get("events")
        reused = float(extra["reused_ns"]) / max(1, int(rr["vertices"])) if "reused_ns" in extra else None
        val = None
        if "validate_ns" in D.extra(n, "flood"):
            val = float(D.extra(n, "flood")["validate_ns"]) / max(1, int(fr["vertices"]))
        rows.append([n, fmt(f), fmt(r), "%.2f" % (r / f) if f and r else "–", fmt(reused),
                     "%.2f" % (reused / f) if f and reused else "–",
                     "%.2f" % (int(ev) / int(D.info[n]["vertices"])) if ev else "–", fmt(val)])
    s.append(table(["input", "Flood ns/v (paired)", "+ trace ns/v (record())", "ratio", "+ trace ns/v (log reused)", "ratio", "events / vertex", "validate() ns/v"], rows))
    s.append("\n## Peak memory of Flood\n\n")
    s.append("One process per measurement (`flood-bench memory`, started from the shell): the input "
             "is read from its binary file, then triangulated once. *Extra* is the growth of "
             "`ru_maxrss` during `triangulate()` (working memory plus the output triangles, 12 B "
             "each); *total* is the process peak, including the input (16 B per vertex) and the "
             "program itself. Sizes under 10⁵ are dominated by page granularity.\n\n")
    rows = []
    mem = defaultdict(dict)
    for m in D.memory:
        mem[m["name"]][m["mode"]] = m
    for n in D.inputs:
        if n not in mem:
            continue
        r = [n]
        for mode in ("plain", "record"):
            m = mem[n].get(mode)
            if not m or m["status"] != "ok":
                r += ["–", "–"]
                continue
            v = int(m["vertices"])
            extra = (int(m["maxrss_peak_kb"]) - int(m["maxrss_loaded_kb"])) * 1024 / v
            total = int(m["maxrss_peak_kb"]) * 1024 / v
            r += [fmt(extra), fmt(total)]
        rows.append(r)
    s.append(table(["input", "extra B/vertex", "total B/vertex", "extra B/vertex (trace)",
                    "total B/vertex (trace)"], rows))
    if D.e2e:
        s.append("\n## The command line end to end (bench/end_to_end.sh)\n\n")
        s.append("`flood triangulate FILE -o OUT` as a user runs it: read the JSON (`flood generate FAMILY N "
                 "--seed 1`, the same polygon as above), validate, flood, the exact check, write. The faster "
                 "of two runs (wall clock) beside `triangulate()` alone from the table above; *peak* is "
                 "GNU time's maximum resident size less that of the same command on an 8-vertex polygon "
                 "(the program and its libraries), as `tests/cli/cli_memory_test.cpp` measures it. The check "
                 "and the writing run on two threads, so user time can exceed wall time. Where the time "
                 "goes, at 10⁶: `flood bench FILE --repeat 1`, the CPU time of each step of the same "
                 "command in one process (*flood* is the step's own run, not the table's median); *one core* "
                 "is the same command's faster of two runs under `taskset -c 0`.\n\n")
        rows = []
        for n in D.inputs:
            r = D.e2e.get(n)
            if not r:
                continue
            e = e2e_figures(D, n)
            if not e:
                rows.append([n, r["vertices"], r["status"], "–", fmt(D.nsv(n, "flood")), "–", "–", "–", "–"])
                continue
            st = dict(kv.split("=", 1) for kv in r.get("steps", "").split(";") if "=" in kv)
            one = float(r["wall_1core_s"]) if r.get("wall_1core_s") else None
            rows.append([n, r["vertices"], fmt(e[0]), fmt(float(r["user_s"]) * 1e9 / int(r["vertices"])),
                         fmt(D.nsv(n, "flood")), "%.1f" % e[1] if e[1] else "–", fmt(e[2]),
                         fmt(one * 1e9 / int(r["vertices"])) if one else "–",
                         "%.2f" % (one / float(r["wall_s"])) if one else "–"] +
                        [fmt(float(st[k])) if k in st else "–" for k in STEPS])
        s.append(table(["input", "n", "command ns/v (wall)", "command ns/v (user)", "triangulate() ns/v",
                        "command / triangulate()", "peak B/vertex", "one core ns/v (wall)",
                        "one core / two"] + ["%s ns/v" % k for k in STEPS], rows))
    s.append("\n## Every result that is not a valid triangulation\n\n")
    rows = []
    for r in D.rows:
        if r["status"] in ("valid", "ok") or r["detail"].startswith("above 10^6"):
            continue
        rows.append([r["name"], LABEL[r["triangulator"]], r["status"],
                     "%s / %s" % (r["triangles"], r["expected"]), r["detail"].replace("|", "\\|")])
    s.append(table(["input", "triangulator", "status", "triangles / expected", "detail"], rows))
    return "".join(s)


def svg(D):
    fams = D.families
    cols, pw, ph, m = 4, 300, 230, 50
    rows_ = (len(fams) + 1 + cols - 1) // cols
    W, H = cols * pw, rows_ * ph + 30
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="11">' % (W, H),
           '<rect width="100%" height="100%" fill="white"/>',
           '<text x="%d" y="18" font-size="14" text-anchor="middle">Time T (s) against input size N, log-log, per family (hollow = output not valid)</text>' % (W / 2)]
    ts = [float(r["ns"]) * 1e-9 for r in D.rows if r["status"] in TIMED and r["family"] not in ("fixture", REAL)]
    ns = [int(r["vertices"]) for r in D.rows if r["family"] not in ("fixture", REAL)]
    if not ts:
        return "\n".join(out + ["</svg>"])
    lt0, lt1 = math.floor(math.log10(min(ts))), math.ceil(math.log10(max(ts)))
    ln0, ln1 = math.floor(math.log10(min(ns))), math.ceil(math.log10(max(ns)))
    for i, fam in enumerate(fams + ["legend"]):
        ox, oy = (i % cols) * pw, 30 + (i // cols) * ph
        x0, x1, y0, y1 = ox + m, ox + pw - 12, oy + ph - 35, oy + 18
        if fam == "legend":
            for j, w in enumerate(PLOTTED):
                y = oy + 30 + j * 18
                out.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="%s" stroke-width="2"/>' % (ox + 30, y, ox + 60, y, COLOR[w]))
                out.append('<text x="%d" y="%d">%s</text>' % (ox + 68, y + 4, LABEL[w]))
            out.append('<text x="%d" y="%d" fill="#555">dashed grey: slope 1 (T ∝ N)</text>' % (ox + 30, oy + 30 + len(PLOTTED) * 18))
            continue
        X = lambda n: x0 + (math.log10(n) - ln0) / (ln1 - ln0) * (x1 - x0)
        Y = lambda t: y0 - (math.log10(t) - lt0) / (lt1 - lt0) * (y0 - y1)
        out.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="#999"/>' % (x0, y1, x1 - x0, y0 - y1))
        out.append('<text x="%d" y="%d" font-weight="bold" text-anchor="middle">%s</text>' % ((x0 + x1) / 2, y1 - 4, fam))
        for e in range(ln0, ln1 + 1):
            out.append('<text x="%.1f" y="%d" text-anchor="middle">10^%d</text>' % (X(10 ** e), y0 + 13, e))
            out.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#eee"/>' % (X(10 ** e), y0, X(10 ** e), y1))
        for e in range(lt0, lt1 + 1, 2 if lt1 - lt0 > 6 else 1):
            out.append('<text x="%d" y="%.1f" text-anchor="end">1e%d</text>' % (x0 - 3, Y(10 ** e) + 4, e))
            out.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#eee"/>' % (x0, Y(10 ** e), x1, Y(10 ** e)))
        out.append('<text x="%d" y="%d" text-anchor="middle" fill="#555">N</text>' % ((x0 + x1) / 2, y0 + 26))
        # slope-1 reference through Flood's first point
        first = D.by_family(fam)[0]
        f = D.get(first, "flood")
        if f and f["status"] in TIMED:
            n1, t1 = int(f["vertices"]), float(f["ns"]) * 1e-9
            n2 = 10 ** ln1
            out.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#888" stroke-dasharray="4,3"/>' % (X(n1), Y(t1), X(n2), Y(t1 * n2 / n1)))
        for w in PLOTTED:
            pts = []
            for n in D.by_family(fam):
                r = D.get(n, w)
                if r and r["status"] in TIMED:
                    pts.append((X(int(r["vertices"])), Y(float(r["ns"]) * 1e-9), r["status"] == "valid"))
            if len(pts) > 1:
                out.append('<polyline fill="none" stroke="%s" stroke-width="1.6" points="%s"/>' % (COLOR[w], " ".join("%.1f,%.1f" % (x, y) for x, y, _ in pts)))
            for x, y, ok in pts:
                out.append('<circle cx="%.1f" cy="%.1f" r="3" fill="%s" stroke="%s"/>' % (x, y, COLOR[w] if ok else "white", COLOR[w]))
    out.append("</svg>")
    return "\n".join(out)


def readme_summary(D, svg_rel):
    s = ["Measured by `scripts/bench.sh` (" + next((l for l in D.machine if l.startswith("date")), "") +
         "); the full tables, the method and every failure are in [docs/BENCHMARKS.md](docs/BENCHMARKS.md). " +
         caveat(D) + "ns per vertex at 10⁶ on each family (S skipped: predicted or timed out over the limit (%s) at a smaller N; T timeout; ✗ invalid output; %s):\n\n" %
         (next((l.split(": ", 1)[1] for l in D.machine if l.startswith("timeout")), "–"),
          next((l for l in D.machine if l.startswith("load")), "load –")), summary_table(D), "\n"]
    for t, detail, ok in targets(D):
        s.append("- %s: **%s**.\n" % (t, "met" if ok else "not met"))
    s.append("\nBy how much each goal is missed, and where the time goes: the Targets table of "
             "[docs/BENCHMARKS.md](docs/BENCHMARKS.md), its end-to-end section, and its kept section on "
             "how the time grows with N.\n")
    s.append("\n![benchmark plot](%s)\n" % svg_rel)
    return "".join(s)


def main():
    if len(sys.argv) < 4:
        sys.exit("usage: report.py DATA_DIR BENCHMARKS.md PLOT.svg [README.md]")
    global EVENT_BYTES
    D = Data(sys.argv[1])
    eb = os.path.join(sys.argv[1], "event_bytes.txt")
    if os.path.exists(eb):
        EVENT_BYTES = int(open(eb).read().strip() or EVENT_BYTES)
    md_path, svg_path = sys.argv[2], sys.argv[3]
    kept = ""
    if os.path.exists(md_path):
        old, kb, ke = open(md_path).read(), "<!-- kept:begin -->", "<!-- kept:end -->"
        while kb in old and ke in old.split(kb, 1)[1]:
            block, old = old.split(kb, 1)[1].split(ke, 1)
            kept += "\n" + kb + block + ke + "\n"
        D.small_section = "<!-- small-polygons -->" in kept
    with open(svg_path, "w") as f:
        f.write(svg(D))
    with open(md_path, "w") as f:
        f.write(markdown(D, os.path.relpath(svg_path, os.path.dirname(md_path))) + kept)
    if len(sys.argv) > 4 and os.path.exists(sys.argv[4]):
        readme = open(sys.argv[4]).read()
        b, e = "<!-- bench:begin -->", "<!-- bench:end -->"
        if b in readme and e in readme:
            head, rest = readme.split(b, 1)
            _, tail = rest.split(e, 1)
            rel = os.path.relpath(svg_path, os.path.dirname(os.path.abspath(sys.argv[4])))
            with open(sys.argv[4], "w") as f:
                f.write(head + b + "\n" + readme_summary(D, rel) + e + tail)
    print("report: wrote %s and %s" % (md_path, svg_path))


if __name__ == "__main__":
    main()
