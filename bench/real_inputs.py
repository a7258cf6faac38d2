#!/usr/bin/env python3
"""Real coastlines for the benchmark (issue 31 goal 2): the outer rings of the largest land
masses of OpenStreetMap's world land (npm package @geo-maps/earth-lands-1m, data ODbL,
installed into the bench's node_modules by scripts/bench.sh), made valid the way a GIS user
would (`ogr2ogr -makevalid`: a ring that touches itself becomes a ring and holes touching it),
each kept as the largest polygon it gives. Written as DIR/coast-KK.json (01 for the largest),
GeoJSON Polygons that `flood-bench dump --real DIR` adds to the inputs as the family "coast".

    real_inputs.py NODE_MODULES DIR [--count N]

Files already in DIR are kept (making them valid takes a while), so the inputs stay the same
from one run to the next.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile


def largest_outer_rings(path, count):
    with open(path) as f:
        doc = json.load(f)
    geometries = doc["geometries"] if doc.get("type") == "GeometryCollection" else [
        f["geometry"] for f in doc["features"]]
    rings = []
    for g in geometries:
        polygons = g["coordinates"] if g["type"] == "MultiPolygon" else [g["coordinates"]]
        rings += [p[0] for p in polygons]
    rings.sort(key=len, reverse=True)
    return rings[:count]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("node_modules")
    ap.add_argument("dir")
    ap.add_argument("--count", type=int, default=12)
    a = ap.parse_args()
    os.makedirs(a.dir, exist_ok=True)
    wanted = [os.path.join(a.dir, "coast-%02d.json" % (k + 1)) for k in range(a.count)]
    if all(os.path.exists(w) for w in wanted):
        print("real_inputs: %d coastlines already in %s" % (a.count, a.dir))
        return 0
    source = os.path.join(a.node_modules, "@geo-maps", "earth-lands-1m", "map.geo.json")
    if not os.path.exists(source):
        print("real_inputs: %s not found: no real coastlines" % source, file=sys.stderr)
        return 1
    rings = largest_outer_rings(source, a.count)
    with tempfile.TemporaryDirectory() as tmp:
        raw, valid = os.path.join(tmp, "rings.geojson"), os.path.join(tmp, "valid.geojson")
        with open(raw, "w") as f:
            json.dump({"type": "FeatureCollection", "features": [
                {"type": "Feature", "properties": {"rank": k + 1},
                 "geometry": {"type": "Polygon", "coordinates": [r]}} for k, r in enumerate(rings)]}, f)
        subprocess.run(["ogr2ogr", "--config", "OGR_GEOJSON_MAX_OBJ_SIZE", "0", "-f", "GeoJSON",
                        "-makevalid", "-explodecollections", "-nlt", "POLYGON", valid, raw], check=True)
        with open(valid) as f:
            parts = json.load(f)["features"]
    for k in range(len(rings)):
        mine = [p["geometry"]["coordinates"] for p in parts if p["properties"]["rank"] == k + 1]
        best = max(mine, key=lambda rs: sum(len(r) for r in rs))
        tmp_path = wanted[k] + ".tmp"
        with open(tmp_path, "w") as f:
            json.dump({"type": "Polygon", "coordinates": best}, f)
        os.replace(tmp_path, wanted[k])
        print("real_inputs: %s: %d vertices, %d rings (from a ring of %d)" %
              (wanted[k], sum(len(r) - 1 for r in best), len(best), len(rings[k]) - 1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
