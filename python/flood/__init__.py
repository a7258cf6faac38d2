"""Flood from Python: the Ronfard-Rossignac flooding triangulation of polygons with holes.

A *polygon* is any of:

- a ring list: a list of rings, each a sequence of (x, y) pairs, outer ring first, then its
  holes; a list of such ring lists is a multipolygon (one part per ring list);
- numpy arrays: one (n, 2) array (a polygon without holes) or a list of them (outer ring, then
  holes); any real or integer dtype (converted to float64: integers beyond 2**53 round);
- a shapely Polygon or MultiPolygon (z dropped), anything with ``__geo_interface__`` (fiona
  and geopandas features, shapely), or a GeoJSON-like mapping of a Polygon, a MultiPolygon or
  a Feature holding one;
- a str: WKT or GeoJSON text, read by the same readers as the ``flood`` command;
- bytes: WKB (ISO or PostGIS EWKB, either byte order, z/m dropped; hex WKB as a str too), or
  the text above encoded as UTF-8.

Rings may be open or closed; repeated consecutive points are dropped with a FloodWarning
(``warnings.warn``), as the command-line reader warns. Failures carry the command's exit-code
classes (docs/ERRORS.md).

- ``triangulate(polygon)`` returns ``Triangulation(vertices, triangles)``: vertices (m, 2)
  float64, triangles (n, 3) int64 indices into them, counter-clockwise, numbered in the order
  flooded. It validates first (``validate=False`` skips, like ``--no-validate``) and checks the
  result exactly, as the command does; any failure raises InvalidPolygon (InternalError for 6).
- ``validate(polygon)`` returns a Diagnostic (``.ok`` true when valid); it raises only for
  inputs that are not polygons at all (TypeError).
- ``trace(polygon)`` returns a Trace: ``.events``, a numpy structured array (EVENT_DTYPE, fields
  named as flood/machine/events.h names them), and ``.replay``, whose ``seek(step)`` gives the state
  after ``step`` events (fingers Left/Right/NextLeft/NextRight, the active chain, ...).
- ``check(features)`` triangulates many polygons on C++ threads and returns one Verdict each.
- ``triangulate_frame(gdf)`` returns a geopandas GeoDataFrame of every row's triangles, with
  the row's index (``source``) and the CRS kept; a failing row is warned about and skipped
  (``errors="raise"`` or ``"ignore"``, as in pandas): see flood.frame.
- ``generate(family, size, seed)`` returns a generated valid polygon as a list of parts.

The GIL is released while the core runs, so Python threads triangulate in parallel too.
"""

from __future__ import annotations

import re
import warnings as _warnings
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any, List, NamedTuple, Optional, Sequence

import numpy as np

from . import _flood
from ._version import __version__

__all__ = [
    "ACTIONS", "EVENT_DTYPE", "FORBIDDEN", "NONE", "TESTS", "__version__",
    "Diagnostic", "FloodWarning", "InternalError", "InvalidPolygon", "Replay", "Trace",
    "Triangulation",
    "Verdict", "check", "families", "generate", "trace", "triangulate", "triangulate_frame",
    "validate",
]

NONE = _flood.NONE                # "no vertex" in events and replay states (0xffffffff)
EVENT_DTYPE = _flood.EVENT_DTYPE  # one row per event; `action` indexes ACTIONS, `reason` FORBIDDEN
ACTIONS: List[str] = list(_flood.ACTIONS)
TESTS: List[str] = list(_flood.TESTS)          # bit i of `tested` / `passed`
FORBIDDEN: List[str] = list(_flood.FORBIDDEN)


@dataclass(frozen=True)
class Diagnostic:
    """The outcome of reading, validating or flooding one polygon.

    status: "ok", "malformed", "invalid", "forbidden" or "internal"; code: the exit code the
    ``flood`` command would end with (0, 3, 4, 5, 6); message: the command's one-line message;
    reason: the message without the input's name and the location; ring, vertex: where the
    problem is, from the diagnostic's culprits (its first vertex, else its first ring; rings
    numbered across all parts as the CLI numbers them, the vertex within its ring), None where
    the culprits name none.
    """

    status: str
    code: int
    message: str
    reason: str
    ring: Optional[int]
    vertex: Optional[int]
    warnings: List[str] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return self.code == 0

    @classmethod
    def _from(cls, found, warnings=(), **extra):
        """From the C++ side's (code, message, reason, ring, vertex): the location comes from
        the diagnostic's culprits there, never from the message's text."""
        code, message, reason, ring, vertex = found
        return cls(status=_flood.STATUS_NAMES[code], code=code, message=message, reason=reason,
                   ring=ring, vertex=vertex, warnings=list(warnings), **extra)


class InvalidPolygon(ValueError):
    """Raised by triangulate() and trace() for malformed, invalid or forbidden input; carries
    the Diagnostic (also as attributes: status, code, message, reason, ring, vertex)."""

    def __init__(self, diagnostic: Diagnostic):
        super().__init__(diagnostic.message)
        self.diagnostic = diagnostic

    def __getattr__(self, name):
        if name == "diagnostic":
            raise AttributeError(name)
        return getattr(self.diagnostic, name)


class FloodWarning(UserWarning):
    """What the reader repaired (a repeated point dropped), as the command warns on stderr."""


def _warn(messages) -> None:
    for message in messages:
        _warnings.warn(message, FloodWarning, stacklevel=3)


class InternalError(RuntimeError):
    """Exit code 6: the exact checker rejected Flood's own output (a bug: please report it)."""

    def __init__(self, diagnostic: Diagnostic):
        super().__init__(diagnostic.message)
        self.diagnostic = diagnostic


class Triangulation(NamedTuple):
    vertices: np.ndarray   # (m, 2) float64: the input's vertices, rings concatenated
    triangles: np.ndarray  # (n, 3) int64 indices into vertices


@dataclass(frozen=True)
class Verdict(Diagnostic):
    """check()'s record of one feature: its Diagnostic, its position and its triangle count."""

    index: Any = 0  # the feature's position, or the id given to check()
    triangles: int = 0


def _raise_for(d: Diagnostic):
    if d.code == 6:
        raise InternalError(d)
    if not d.ok:
        raise InvalidPolygon(d)


def _depth(x) -> int:
    """Nesting depth: 1 for a point, 2 for a ring, 3 for a ring list, 4 for a multipolygon.
    An empty list ends the descent and is read as part of a ring list, as the command line
    reads the same JSON (core/io/io_read.cpp, arrayDepth): [] is a polygon without rings
    (malformed), [[]] one with an empty ring (invalid), the same verdict through both doors."""
    d = 0
    while True:
        if isinstance(x, np.ndarray):
            return d + x.ndim
        if isinstance(x, (str, bytes)) or not isinstance(x, Sequence):
            return d
        if len(x) == 0:
            return max(d, 3)
        d += 1
        x = x[0]


def _ring(coords) -> np.ndarray:
    a = np.asarray(coords)
    if a.shape == (0,):
        a = np.zeros((0, 2))  # an empty ring: the validator says what is wrong with it
    if a.dtype.kind not in "fiu":
        raise TypeError(f"ring coordinates must be numbers, got dtype {a.dtype}")
    # Any shape goes on: the C++ side takes (n, 2), (n, 3) or (n, 4) rows of x, y[, z[, m]]
    # (z and m dropped, as shapely and GeoJSON may carry them) and refuses the rest, a
    # transposed [xs, ys, zs] among them, as malformed (code 3) rather than misreading it.
    return np.ascontiguousarray(a, dtype=np.float64)


def _name(name) -> str:
    """A name as messages carry it: a lone surrogate (no UTF-8 for it) as its escape, \\ud800."""
    return str(name).encode("utf-8", "backslashreplace").decode("utf-8")


_HEX_WKB = re.compile(r"0[01][0-9A-Fa-f]{8,}")


def _normalize(polygon) -> Any:
    """Any accepted polygon as what the C++ side reads: a str, or parts of float64 rings."""
    if isinstance(polygon, (bytes, bytearray, memoryview)):
        blob = bytes(polygon)
        if _flood.wkb_like(blob):
            return blob  # WKB: read by the core (core/io/io_wkb.cpp), on check()'s threads
        return blob.decode("utf-8")
    if isinstance(polygon, str):
        if len(polygon) % 2 == 0 and _HEX_WKB.fullmatch(polygon):
            return bytes.fromhex(polygon)
        return polygon
    if hasattr(polygon, "geom_type") and hasattr(polygon, "wkb"):
        if polygon.geom_type not in ("Polygon", "MultiPolygon"):
            raise TypeError("flood triangulates Polygon and MultiPolygon geometries, not "
                            f"{polygon.geom_type}")
        return polygon.wkb  # one GEOS call; no Python object per coordinate
    if not isinstance(polygon, Mapping) and hasattr(polygon, "__geo_interface__"):
        polygon = polygon.__geo_interface__
    if isinstance(polygon, Mapping):
        kind = polygon.get("type")
        if kind == "Feature":
            geometry = polygon.get("geometry")
            if geometry is None:
                raise TypeError("a GeoJSON Feature without a geometry")
            return _normalize(geometry)
        coords = polygon.get("coordinates")
        if kind == "Polygon":
            return [[_ring(r) for r in coords]]
        if kind == "MultiPolygon":
            return [[_ring(r) for r in p] for p in coords]
        if kind == "FeatureCollection":
            raise TypeError("a FeatureCollection holds many polygons: pass its features to "
                            "flood.check()")
        raise TypeError("a GeoJSON mapping of a Polygon, a MultiPolygon or a Feature, not "
                        f"{kind!r}")
    if isinstance(polygon, np.ndarray) or isinstance(polygon, Sequence):
        depth = _depth(polygon)
        if depth == 2:
            return [[_ring(polygon)]]
        if depth == 3:
            return [[_ring(r) for r in polygon]]
        if depth == 4:
            return [[_ring(r) for r in part] for part in polygon]
        raise TypeError("a polygon is a ring ((n, 2) coordinates), a list of rings or a list "
                        f"of such lists (nesting depth {depth} found)")
    raise TypeError(f"not a polygon: {type(polygon).__name__}")


def validate(polygon, *, name: str = "polygon") -> Diagnostic:
    """The validator's verdict (docs/ERRORS.md): ``.ok``, or the first problem found."""
    found, warnings = _flood.validate(_normalize(polygon), _name(name))
    _warn(warnings)
    return Diagnostic._from(found, warnings)


def triangulate(polygon, *, validate: bool = True, up: str = "+y",
                name: str = "polygon") -> Triangulation:
    """Triangulates like ``flood triangulate``: validate, flood, check exactly."""
    found, warnings, vertices, triangles, _ = _flood.triangulate(
        _normalize(polygon), validate, up, _name(name))
    _warn(warnings)
    _raise_for(Diagnostic._from(found, warnings))
    return Triangulation(vertices, triangles)


class Replay:
    """The machine's state at any step, rebuilt from the log (flood/log/replay.h)."""

    def __init__(self, handle):
        self._handle = handle

    def __len__(self) -> int:
        return len(self._handle)

    def seek(self, step: int):
        """State after the first ``step`` events (0: before anything happened): ``.fingers``
        (left, right, nextLeft, nextRight), ``.left``, ``.right``, ``.chain`` (Left to Right),
        ``.water``, ``.triangleCount``, ``.dormant``, ``.jumps``, ``.bridges``, ``.forbidden``.
        Vertex indices are global (rows of Trace.vertices); NONE where there is none."""
        return self._handle.seek(step)


class Trace:
    """A recorded run: ``events`` (structured array), ``replay``, ``vertices``, ``triangles``
    and ``diagnostic`` (not ok for a forbidden run, which is recorded all the same)."""

    def __init__(self, handle):
        self.events: np.ndarray = handle.events
        self.vertices: np.ndarray = handle.vertices
        self.triangles: np.ndarray = handle.triangles
        self.diagnostic = Diagnostic._from(handle.diagnostic, handle.warnings)
        self.replay = Replay(handle)
        _warn(handle.warnings)


def trace(polygon, *, validate: bool = True, up: str = "+y", name: str = "polygon") -> Trace:
    """Floods with a recorder, like ``flood trace``. Malformed or invalid input raises
    InvalidPolygon; a run stopped in a forbidden state is returned (see Trace.diagnostic)."""
    result = _flood.trace(_normalize(polygon), validate, up, _name(name))
    if isinstance(result, tuple):
        _raise_for(Diagnostic._from(result))
    return Trace(result)


def check(features, *, validate: bool = True, up: str = "+y", threads: int = 0,
          ids: Optional[Sequence] = None) -> List[Verdict]:
    """Triangulates every feature (any accepted polygon) on ``threads`` C++ threads (0: one
    per core) and returns one Verdict per feature, in order. Feature i is named "feature ID"
    in messages and its Verdict's ``index`` is ID, ``ids[i]`` (default: i).
    Nothing raises for a bad feature: its Verdict says what is wrong."""
    features = list(features)
    ids = list(range(len(features))) if ids is None else list(ids)
    if len(ids) != len(features):
        raise ValueError(f"{len(ids)} ids for {len(features)} features")
    names = [_name(f"feature {i}") for i in ids]
    inputs = [_normalize(f) for f in features]
    out = _flood.check(inputs, validate, up, threads, names)
    return [Verdict._from(found[:5], index=ids[k], triangles=found[5]) for k, found in enumerate(out)]


def generate(family: str, size: int, seed: int = 1) -> List[List[np.ndarray]]:
    """A valid polygon of a generator family (``flood generate``; see families()), as a list
    of parts, each [outer ring, holes...] of (n, 2) float64 arrays."""
    return _flood.generate(family, size, seed)


def families() -> List[str]:
    return list(_flood.families())


from .frame import triangulate_frame  # noqa: E402 (it uses what is defined above)
