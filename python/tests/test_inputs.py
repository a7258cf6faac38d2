"""Every accepted kind of input reads as the same polygon: shapely (with holes, multipolygons),
numpy arrays of any dtype, nested lists, open or closed rings."""
import numpy as np
import pytest
import shapely.geometry as sg

import flood

OUTER = [(0, 0), (10, 0), (10, 10), (0, 10)]
HOLES = [[(2, 2), (2, 4), (4, 4), (4, 2)], [(6, 6), (6, 8), (8, 8), (8, 6)]]


def expected_count(n, h):  # n + 2h - 2 triangles (§1)
    return n + 2 * h - 2


def test_shapely_polygon_with_holes_equals_the_ring_list():
    rings = flood.triangulate([OUTER] + HOLES)
    shapely_result = flood.triangulate(sg.Polygon(OUTER, HOLES))  # closed rings, as shapely keeps
    assert shapely_result.vertices.tolist() == rings.vertices.tolist()
    assert shapely_result.triangles.tolist() == rings.triangles.tolist()
    assert len(rings.triangles) == expected_count(12, 2)


def test_shapely_multipolygon_floods_every_part():
    square = [(20, 0), (30, 0), (30, 10), (20, 10)]
    multi = sg.MultiPolygon([sg.Polygon(OUTER, HOLES), sg.Polygon(square)])
    result = flood.triangulate(multi)
    assert len(result.vertices) == 16
    assert len(result.triangles) == expected_count(12, 2) + expected_count(4, 0)
    assert result.triangles.tolist() == flood.triangulate([[OUTER] + HOLES, [square]]).triangles.tolist()
    # The triangles cover the multipolygon's area exactly.
    v = result.vertices[result.triangles]
    areas = 0.5 * np.cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0])
    assert (areas > 0).all() and areas.sum() == multi.area


@pytest.mark.parametrize("dtype", [np.float32, np.float64, np.int32, np.int64])
def test_numpy_dtypes_give_the_same_result(dtype):
    reference = flood.triangulate([OUTER] + HOLES)
    arrays = [np.array(r, dtype=dtype) for r in [OUTER] + HOLES]
    result = flood.triangulate(arrays)
    assert result.vertices.dtype == np.float64
    assert result.triangles.tolist() == reference.triangles.tolist()
    one_ring = flood.triangulate(np.array(OUTER, dtype=dtype))
    assert one_ring.triangles.tolist() == flood.triangulate([OUTER]).triangles.tolist()


def test_wkt_and_geojson_mapping():
    poly = sg.Polygon(OUTER, HOLES)
    reference = flood.triangulate(poly).triangles.tolist()
    assert flood.triangulate(poly.wkt).triangles.tolist() == reference
    assert flood.triangulate(sg.mapping(poly)).triangles.tolist() == reference


def test_repeated_points_are_dropped_with_a_warning():
    with pytest.warns(flood.FloodWarning):
        d = flood.validate([(0, 0), (10, 0), (10, 0), (10, 10), (0, 10)])
    assert d.ok and len(d.warnings) == 1 and "repeated point dropped" in d.warnings[0]


def test_what_is_not_a_polygon_is_refused():
    with pytest.raises(TypeError):
        flood.triangulate(sg.Point(0, 0))
    with pytest.raises(TypeError):
        flood.triangulate(42)
    with pytest.raises(flood.InvalidPolygon) as caught:
        flood.triangulate(np.zeros((4, 3, 1)))  # depth 3, but points of one coordinate
    assert caught.value.status == "malformed" and caught.value.code == 3


# --- the doors of the Python ecosystem (issue 30 §2) ------------------------------------------

class _Feature:
    """A fiona/geopandas-style object: only __geo_interface__, a GeoJSON Feature mapping."""

    def __init__(self, geometry):
        self.__geo_interface__ = {"type": "Feature", "properties": {"name": "x"},
                                  "geometry": geometry}


def test_geo_interface_and_feature_mappings_read_as_the_geometry():
    poly = sg.Polygon(OUTER, HOLES)
    reference = flood.triangulate(poly).triangles.tolist()
    feature = {"type": "Feature", "properties": {}, "geometry": sg.mapping(poly)}
    assert flood.triangulate(feature).triangles.tolist() == reference
    assert flood.triangulate(_Feature(sg.mapping(poly))).triangles.tolist() == reference
    with pytest.raises(TypeError, match="Feature without a geometry"):
        flood.triangulate({"type": "Feature", "geometry": None})
    with pytest.raises(TypeError, match="flood.check"):
        flood.triangulate({"type": "FeatureCollection", "features": [feature]})


@pytest.mark.parametrize("geometry", [
    sg.Polygon(OUTER, HOLES),
    sg.MultiPolygon([sg.Polygon(OUTER, HOLES), sg.Polygon([(20, 0), (30, 0), (30, 10)])]),
])
def test_wkb_in_both_byte_orders_with_z_and_as_hex(geometry):
    import shapely.wkb
    reference = flood.triangulate(sg.mapping(geometry))
    for big_endian in (False, True):
        blob = shapely.wkb.dumps(geometry, big_endian=big_endian)
        result = flood.triangulate(blob)
        assert result.vertices.tolist() == reference.vertices.tolist()
        assert result.triangles.tolist() == reference.triangles.tolist()
    hexed = shapely.wkb.dumps(geometry, hex=True)
    assert flood.triangulate(hexed).triangles.tolist() == reference.triangles.tolist()
    # With z (EWKB's flag; shapely writes it so), the z is dropped.
    lifted = shapely.wkb.loads(shapely.wkb.dumps(geometry))
    from shapely.ops import transform
    with_z = transform(lambda x, y, z=None: (x, y, np.full_like(np.asarray(x), 7.0)), lifted)
    assert with_z.has_z
    assert flood.triangulate(shapely.wkb.dumps(with_z)).triangles.tolist() == \
        reference.triangles.tolist()


def test_bad_wkb_is_malformed_and_says_what_is_wrong():
    import shapely.wkb
    blob = shapely.wkb.dumps(sg.Polygon(OUTER))
    for bad, what in [(blob[:-5], "truncated"), (blob + b"\0", "left over"),
                      (shapely.wkb.dumps(sg.LineString([(0, 0), (1, 1)])), "not LineString")]:
        with pytest.raises(flood.InvalidPolygon, match=what) as e:
            flood.triangulate(bad)
        assert e.value.code == 3  # malformed, as the CLI says of a file it cannot read
    # check() reads WKB on its threads, with the same verdicts.
    verdicts = flood.check([blob, blob[:-5], shapely.wkb.dumps(sg.Polygon(OUTER, HOLES))])
    assert [v.code for v in verdicts] == [0, 3, 0]


def test_check_converts_shapely_in_one_pass():
    polys = [sg.Polygon([(i, 0), (i + 1, 0), (i, 1)]) for i in range(300)]
    assert all(v.ok and v.triangles == 1 for v in flood.check(polys))


def test_repeated_points_warn_through_the_warnings_module():
    with pytest.warns(flood.FloodWarning, match="repeated point dropped"):
        flood.triangulate([(0, 0), (10, 0), (10, 0), (10, 10), (0, 10)])
    with pytest.warns(flood.FloodWarning):
        flood.validate([(0, 0), (10, 0), (10, 0), (10, 10), (0, 10)])


def test_version_is_the_projects_and_the_package_is_typed():
    import os
    import re
    root = os.environ.get("FLOOD_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
    cmake = open(os.path.join(root, "CMakeLists.txt")).read()
    pyproject = open(os.path.join(root, "python", "pyproject.toml")).read()
    assert re.search(r"project\(flood VERSION ([0-9.]+)", cmake).group(1) == flood.__version__
    assert re.search(r'^version = "([0-9.]+)"', pyproject, re.M).group(1) == flood.__version__
    assert os.path.exists(os.path.join(os.path.dirname(flood.__file__), "py.typed"))


def test_a_transposed_or_misshapen_ring_is_refused_not_misread():
    # [xs, ys, zs] of four points, a (3, 4) array, was read as three points of (x, y).
    xs, ys, zs = [0, 10, 10, 0], [0, 0, 10, 10], [5, 5, 5, 5]
    for bad, shape in [(np.array([xs, ys, zs]), "(3, 4)"), (np.array([xs, ys]), "(2, 4)"),
                       (np.zeros((10, 5)), "(10, 5)"), (np.zeros((10, 1)), "(10, 1)"),
                       ([np.zeros(8)], "(1, 8)")]:
        d = flood.validate([bad])
        assert not d.ok and d.status == "malformed" and d.code == 3, (shape, d)
        assert "a ring is an (n, 2), (n, 3) or (n, 4) array" in d.message, d.message
        assert shape in d.message, d.message
        with pytest.raises(flood.InvalidPolygon) as caught:
            flood.triangulate(bad)
        assert caught.value.code == 3
    assert "transposed?" in flood.validate(np.array([xs, ys, zs])).message
    # Its transpose, and rows carrying z or z and m, are rings.
    square = flood.triangulate([(0, 0), (10, 0), (10, 10), (0, 10)]).triangles.tolist()
    assert flood.triangulate(np.array([xs, ys, zs]).T).triangles.tolist() == square
    assert flood.triangulate(np.array([xs, ys, zs, zs]).T).triangles.tolist() == square
    # One point with z, a Steiner hole, is no transposed ring.
    assert flood.validate([[(0, 0), (10, 0), (10, 10), (0, 10)], [(5, 5, 1)]]).ok


# A str with a lone surrogate (no UTF-8 for it) raised RuntimeError "Unable to cast Python
# instance to C++ type": it is malformed text, as the command line calls "\ud800" in a file.
def test_a_lone_surrogate_is_malformed_text_named():
    bad = "POLYGON((0 0, 10 0, 0 10, 0 0))\udc80"
    d = flood.validate(bad, name="t.wkt")
    assert d.code == 3 and d.status == "malformed", d
    assert d.message == ("t.wkt: the text holds a lone surrogate U+DC80 at character 31: it is "
                         "not Unicode, and UTF-8 cannot encode it"), d.message
    with pytest.raises(flood.InvalidPolygon) as caught:  # a ValueError
        flood.triangulate(bad)
    assert isinstance(caught.value, ValueError) and "U+DC80" in str(caught.value)
    with pytest.raises(flood.InvalidPolygon):
        flood.trace("\ud800")
    good = "POLYGON((0 0, 10 0, 0 10, 0 0))"
    verdicts = flood.check([good, bad, good], ids=["a", "b\ud800", "c"])
    assert [v.code for v in verdicts] == [0, 3, 0]
    assert verdicts[1].message.startswith("feature b\\ud800: the text holds a lone surrogate")
    # A name with one is shown escaped, not refused.
    assert flood.validate(good, name="x\ud800").ok
    assert flood.validate("[]", name="x\ud800").message.startswith("x\\ud800: ")
