#!/usr/bin/env python3
"""Writes the libFuzzer seed corpora from polygons/ and ../shared/peers/earcut/fixtures.

usage: scripts/fuzz-seeds.py OUTDIR [FLOOD_CLI]

OUTDIR/read   every polygon file as is (GeoJSON, ring arrays, WKT, the invalid ones), plus WKT
              renderings of the ring arrays
OUTDIR/flood  the same polygons in the byte encoding of fuzz/fuzz_poly.h
OUTDIR/trace  `flood trace` of each small polygon, JSON Lines and binary (needs FLOOD_CLI),
              including forbidden runs
"""
import json, os, struct, subprocess, sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOURCES = [os.path.join(ROOT, "polygons"), os.path.join(ROOT, "polygons", "invalid"),
           os.path.join(ROOT, "polygons", "regress"),
           os.path.join(ROOT, "..", "shared", "peers", "earcut", "fixtures")]
MAX_SEED = 16 * 1024


def files():
    for d in SOURCES:
        if not os.path.isdir(d):
            continue
        for f in sorted(os.listdir(d)):
            p = os.path.join(d, f)
            if os.path.isfile(p) and f.rsplit(".", 1)[-1] in ("json", "wkt", "geojson"):
                yield p


def parts_of(doc):
    """List of parts (each a list of rings of [x, y]) from GeoJSON or a ring array."""
    if isinstance(doc, dict):
        t = doc.get("type")
        if t == "Polygon":
            return [doc["coordinates"]]
        if t == "MultiPolygon":
            return list(doc["coordinates"])
        if t == "Feature":
            return parts_of(doc.get("geometry") or {})
        if t == "FeatureCollection":
            return [p for f in doc.get("features", []) for p in parts_of(f)]
        return []
    if isinstance(doc, list) and doc and isinstance(doc[0], list) and doc[0] and \
            isinstance(doc[0][0], list):
        return [doc]
    return []


def encode(parts):
    out = bytearray([0])
    for pi, rings in enumerate(parts):
        for ri, ring in enumerate(rings):
            pts = [(float(p[0]), float(p[1])) for p in ring
                   if isinstance(p, list) and len(p) >= 2 and all(isinstance(c, (int, float)) for c in p[:2])]
            small = all(c.is_integer() and -128 <= c <= 127 for pt in pts for c in pt)
            n = min(len(pts), 65535)
            h = (64 if ri == 0 and pi > 0 else 0) | (0 if small else 128)
            if n >= 63:
                out += bytes([h | 63]) + struct.pack("<H", n)
            else:
                out.append(h | n)
            for x, y in pts[:n]:
                out += struct.pack("<bb", int(x), int(y)) if small else struct.pack("<dd", x, y)
    return bytes(out)


def wkt(parts):
    def ring(r):
        return "(" + ", ".join("%r %r" % (float(p[0]), float(p[1])) for p in r) + ")"
    return "MULTIPOLYGON(" + ", ".join("(" + ", ".join(ring(r) for r in rings) + ")" for rings in parts) + ")"


def main():
    out = sys.argv[1]
    cli = sys.argv[2] if len(sys.argv) > 2 else None
    for sub in ("read", "flood", "trace"):
        os.makedirs(os.path.join(out, sub), exist_ok=True)
    count = {"read": 0, "flood": 0, "trace": 0}
    for path in files():
        name = os.path.basename(os.path.dirname(path)) + "-" + os.path.basename(path)
        data = open(path, "rb").read()
        if len(data) > MAX_SEED:
            continue
        open(os.path.join(out, "read", name), "wb").write(data)
        count["read"] += 1
        try:
            parts = parts_of(json.loads(data))
            text, binary = wkt(parts), encode(parts)
        except (ValueError, TypeError, KeyError, IndexError, struct.error):
            parts = []  # malformed on purpose (polygons/invalid): only the read seed
        if parts:
            open(os.path.join(out, "read", name + ".wkt"), "w").write(text)
            open(os.path.join(out, "flood", name + ".bin"), "wb").write(binary)
            count["read"] += 1
            count["flood"] += 1
        if cli and len(data) < 4096:
            # Both forms of the trace: JSON Lines and the compact binary one.
            for form, ext in (("jsonl", ".jsonl"), ("bin", ".ftb")):
                r = subprocess.run([cli, "trace", path, "--format", form], capture_output=True)
                if r.stdout:
                    open(os.path.join(out, "trace", name + ext), "wb").write(r.stdout)
                    count["trace"] += 1
    print("seeds: " + ", ".join("%s %d" % kv for kv in count.items()))


if __name__ == "__main__":
    main()
