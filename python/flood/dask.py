"""flood.check over datasets larger than one machine, with Dask (Debian's python3-dask and
python3-distributed).

Each Dask partition is checked by one ``flood.check`` call (C++ threads, the GIL released), and
only the failing features travel back, with their diagnostics:

    import dask.bag as db, distributed, flood.dask
    client = distributed.Client()                      # or Client("tcp://scheduler:8786")
    bag = db.from_sequence(enumerate(wkt_strings), npartitions=64)   # (id, geometry) pairs
    for failure in flood.dask.failures(bag):
        print(failure["id"], failure["message"])

A geometry is anything flood accepts (a shapely Polygon or MultiPolygon, WKT or GeoJSON text,
rings). Records are plain dicts: id, status, code, message, reason, ring, vertex (see
flood.Diagnostic). With a dataframe (needs python3-pandas), ``check_dataframe`` keeps the
failing rows, index and columns as they were, with the diagnostic's columns added.
"""

from __future__ import annotations

from typing import Any, Dict, List

import flood

# The diagnostic's fields that a failure record carries (flood.Diagnostic).
FIELDS = ("status", "code", "message", "reason", "ring", "vertex")


def _records(ids, geometries, options) -> List[Dict[str, Any]]:
    verdicts = flood.check(geometries, ids=ids, **options)
    return [dict({"id": v.index}, **{f: getattr(v, f) for f in FIELDS}) for v in verdicts if not v.ok]


def _check_pairs(pairs, options):
    pairs = list(pairs)
    return _records([p[0] for p in pairs], [p[1] for p in pairs], options)


def check_bag(bag, *, validate: bool = True, up: str = "+y", threads: int = 1):
    """A lazy bag of failure records, one per failing (id, geometry) item of ``bag``.
    ``threads`` is flood.check's per partition: 1 suits one Dask worker thread per core."""
    options = dict(validate=validate, up=up, threads=threads)
    return bag.map_partitions(_check_pairs, options)


def failures(bag, **options) -> List[Dict[str, Any]]:
    """check_bag computed: the failing features' records, sorted by id."""
    return sorted(check_bag(bag, **options).compute(), key=lambda r: r["id"])


def _check_frame(frame, geometry, options):
    records = _records(list(frame.index), list(frame[geometry]), options)
    failing = frame.loc[[r["id"] for r in records]].copy()
    for f in FIELDS:
        failing[f] = [r[f] for r in records]
    return failing


def check_dataframe(df, geometry: str = "geometry", *, validate: bool = True, up: str = "+y",
                    threads: int = 1):
    """The failing rows of a Dask dataframe whose column ``geometry`` holds the features
    (shapely objects or WKT strings), with the diagnostic's columns added (lazy)."""
    import pandas as pd

    options = dict(validate=validate, up=up, threads=threads)
    meta = df._meta.copy()
    for f, kind in zip(FIELDS, ("object", "int64", "object", "object", "object", "object")):
        meta[f] = pd.Series(dtype=kind)
    return df.map_partitions(_check_frame, geometry, options, meta=meta)
