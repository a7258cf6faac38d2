#!/usr/bin/python3
"""earcut (earcut.hpp as compiled in Debian's python3-mapbox-earcut) on the benchmark inputs.

Usage: earcut_bench.py DIR [--timeout S]

Reads DIR/manifest.tsv and the .poly files written by `flood-bench dump`, times
mapbox_earcut.triangulate_float64(vertices, ring_end_indices) per part, writes the triangles
to DIR/<name>.earcut.tri (uint32 triples) and the timings to DIR/earcut.tsv; `flood-bench run`
then checks the triangles exactly. Each input runs in a forked child with a time limit.

The measured time includes the Python call into the binding (argument conversion, result
array). That overhead is measured on a 3-vertex triangle and written to DIR/earcut-overhead.txt;
it is reported, not subtracted (it is well under a microsecond per call).
"""
import multiprocessing as mp
import os
import statistics
import struct
import sys
import time

import numpy as np
import mapbox_earcut


def read_poly(path):
    """Returns (xy float64 array (n, 2), list of (count, outer) per ring)."""
    with open(path, "rb") as f:
        if f.read(8) != b"FLPOLY2\n":
            raise ValueError("not a .poly file: " + path)
        (rings,) = struct.unpack("<Q", f.read(8))
        shape = np.frombuffer(f.read(16 * rings), dtype="<u8").reshape(rings, 2)
        total = int(shape[:, 0].sum()) if rings else 0
        xy = np.frombuffer(f.read(16 * total), dtype="<f8").reshape(-1, 2)
        # the T-junction list follows; earcut does not use it
    return xy, [(int(c), bool(o)) for c, o in shape]


def parts_of(xy, shape):
    """Per part: (vertex array, ring end indices, offset of its first vertex)."""
    parts, start = [], 0
    for count, outer in shape:
        if outer:
            parts.append([start, []])
        parts[-1][1].append(start + count - parts[-1][0])
        start += count
    out = []
    for i, (first, ends) in enumerate(parts):
        last = first + ends[-1]
        out.append((np.ascontiguousarray(xy[first:last]), np.array(ends, dtype=np.uint32), first))
    return out


def triangulate(parts):
    res = []
    for verts, ends, first in parts:
        res.append(mapbox_earcut.triangulate_float64(verts, ends).astype(np.uint32) + np.uint32(first))
    return res


def time_runs(fn):
    """Same policy as the C++ driver: >= 3 runs until ~0.5 s (<= 21); one run if over 10 s."""
    times, total, result = [], 0.0, None
    while True:
        t0 = time.perf_counter_ns()
        result = fn()
        ns = time.perf_counter_ns() - t0
        times.append(ns)
        total += ns
        if times[0] > 10e9:
            break
        if len(times) >= 3 and (total > 0.5e9 or len(times) >= 21):
            break
    return statistics.median_low(times), len(times), result


def child(path, tri_path, conn):
    try:
        xy, shape = read_poly(path)
        parts = parts_of(xy, shape)
        ns, runs, result = time_runs(lambda: triangulate(parts))
        tris = np.concatenate(result) if result else np.zeros(0, dtype=np.uint32)
        tris.astype("<u4").tofile(tri_path)
        conn.send(("ok", ns, runs, len(tris) // 3, ""))
    except Exception as e:  # reported as a row, like a peer failure
        conn.send(("error", 0, 0, 0, repr(e)[:150]))
    conn.close()


def overhead_ns():
    tri = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    ends = np.array([3], dtype=np.uint32)
    samples = []
    for _ in range(50):
        t0 = time.perf_counter_ns()
        for _ in range(1000):
            mapbox_earcut.triangulate_float64(tri, ends)
        samples.append((time.perf_counter_ns() - t0) / 1000)
    return statistics.median(samples)


def main():
    if len(sys.argv) < 2:
        sys.exit("usage: earcut_bench.py DIR [--timeout S]")
    d = sys.argv[1]
    timeout = float(sys.argv[sys.argv.index("--timeout") + 1]) if "--timeout" in sys.argv else 60.0
    ctx = mp.get_context("fork")
    with open(os.path.join(d, "earcut-overhead.txt"), "w") as f:
        f.write("%.1f\n" % overhead_ns())
    rows = []
    with open(os.path.join(d, "manifest.tsv")) as f:
        next(f)
        manifest = [line.rstrip("\n").split("\t") for line in f]
    history, given_up = {}, set()
    for name, family, size, vertices, holes, valid, path, *_ in manifest:
        tri_path = os.path.join(d, name.replace("/", "_") + ".earcut.tri")
        h = history.setdefault(family, [])
        if int(size) > 1000000:  # 10^7 (a few cheap families): Flood and the floor only
            rows.append((name, "skipped", 0, 0, 0, "above 10^6 only Flood and the floor run"))
            continue
        if family != "fixture" and family in given_up:
            rows.append((name, "skipped", 0, 0, 0, "timed out or predicted over the limit at a smaller size"))
            continue
        if family != "fixture" and len(h) >= 2:
            predicted = h[-1] * max(10.0, h[-1] / h[-2]) * 1e-9
            if predicted > 0.75 * timeout:
                given_up.add(family)
                rows.append((name, "skipped", 0, 0, 0, "predicted %d s per run from the smaller sizes" % predicted))
                continue
        a, b = ctx.Pipe(duplex=False)
        p = ctx.Process(target=child, args=(path, tri_path, b))
        p.start()
        b.close()
        row = None
        if a.poll(timeout):
            try:
                row = a.recv()
            except EOFError:
                row = None
        p.join(1 if row is not None else 0)
        if p.is_alive():
            p.kill()
            p.join()
            row = ("timeout", 0, 0, 0, "over %d s" % timeout)
            given_up.add(family)
        elif row is None:
            row = ("crash", 0, 0, 0, "exit code %s" % p.exitcode)
            given_up.add(family)
        else:
            h.append(row[1])
        rows.append((name,) + tuple(row))
        print("%-30s earcut     %-8s %12.1f ns/vertex %s" % (name, row[0], row[1] / max(1, int(vertices)), row[4]),
              file=sys.stderr, flush=True)
    with open(os.path.join(d, "earcut.tsv"), "w") as f:
        f.write("name\tstatus\tns\truns\ttriangles\tdetail\n")
        for r in rows:
            f.write("\t".join(str(x) for x in r) + "\n")


if __name__ == "__main__":
    main()
