"""flood.triangulate_frame: a GeoDataFrame in, a GeoDataFrame of its triangles out (geopandas:
Debian's python3-geopandas; imported only when called).

    tri = flood.triangulate_frame(parcels)           # one row per triangle, parcels' CRS
    tri = tri.join(parcels.drop(columns=parcels.geometry.name), on="source")  # the attributes

Each row's geometry (a Polygon or MultiPolygon) is triangulated as ``flood.triangulate`` does
(validated, flooded, checked exactly). A row that fails is handled as ``errors`` says, as in
pandas: "warn" (the default) skips it with a ``FloodWarning`` naming the row's index and the
reason, "raise" raises its ``InvalidPolygon`` (its message names the row), "ignore" skips it
silently; the other rows are triangulated all the same.
"""

from __future__ import annotations

import warnings

import numpy as np

from . import FloodWarning, InternalError, InvalidPolygon, triangulate

ERRORS = ("warn", "raise", "ignore")


def triangulate_frame(frame, *, errors: str = "warn", validate: bool = True, up: str = "+y"):
    """A GeoDataFrame of the triangles of every row of ``frame``: columns ``source`` (the row's
    index label), ``triangle`` (its number within the row, in flooding order) and the geometry
    (one counter-clockwise Polygon per triangle), in ``frame``'s CRS; rows in ``frame``'s order.
    A row without a geometry (None or empty) is a failure like an invalid one (see ``errors``).
    """
    import geopandas
    from shapely.geometry import Polygon

    if errors not in ERRORS:
        raise ValueError(f"errors must be one of {', '.join(ERRORS)}, not {errors!r}")
    sources, numbers, shapes = [], [], []
    for label, geometry in zip(frame.index, frame.geometry):
        name = f"row {label!r}"
        try:
            if geometry is None or geometry.is_empty:
                raise TypeError(f"{name}: no geometry")
            t = triangulate(geometry, validate=validate, up=up, name=name)
        except (InvalidPolygon, TypeError) as e:
            if errors == "raise":
                raise
            if errors == "warn":
                warnings.warn(f"{e}; row skipped", FloodWarning, stacklevel=2)
            continue
        except InternalError:
            raise  # a bug of Flood's, never a row's fault: not skipped
        corners = t.vertices[t.triangles]  # (n, 3, 2)
        shapes.extend(Polygon(c) for c in corners)
        sources.extend([label] * len(corners))
        numbers.append(np.arange(len(corners), dtype=np.int64))
    columns = {
        "source": sources,
        "triangle": np.concatenate(numbers) if numbers else np.zeros(0, dtype=np.int64),
    }
    return geopandas.GeoDataFrame(columns, geometry=geopandas.GeoSeries(shapes), crs=frame.crs)
