"""flood.triangulate_frame (python/flood/frame.py): a GeoDataFrame in, its triangles out, each
with its source row's index and the CRS kept; a bad row reported by errors= as pandas does,
the others triangulated all the same. Needs geopandas (Debian's python3-geopandas)."""
import warnings

import pytest

geopandas = pytest.importorskip(
    "geopandas", reason="geopandas is not installed (apt-get install python3-geopandas)")
shapely_geometry = pytest.importorskip("shapely.geometry")

import flood  # noqa: E402

Polygon = shapely_geometry.Polygon
MultiPolygon = shapely_geometry.MultiPolygon

HOLED = Polygon([(0, 0), (10, 0), (10, 10), (0, 10)], [[(3, 3), (3, 7), (7, 7), (7, 3)]])
TWO = MultiPolygon([Polygon([(20, 0), (21, 0), (21, 1)]), Polygon([(30, 0), (31, 0), (31, 1), (30, 1)])])
BOWTIE = Polygon([(0, 0), (4, 2), (4, 0), (0, 3)])


def frame(rows, index):
    return geopandas.GeoDataFrame({"name": [f"parcel {i}" for i in index]}, geometry=rows,
                                  index=index, crs="EPSG:2263")


def test_triangles_keep_the_source_index_and_crs():
    gdf = frame([HOLED, TWO], index=["a", "b"])
    tri = flood.triangulate_frame(gdf)
    assert isinstance(tri, geopandas.GeoDataFrame)
    assert tri.crs == gdf.crs and tri.crs.to_epsg() == 2263
    assert list(tri.columns) == ["source", "triangle", "geometry"]
    # n + 2h - 2 per part: 8 for the holed square, 1 + 2 for the two parts.
    assert list(tri["source"]) == ["a"] * 8 + ["b"] * 3
    assert list(tri["triangle"]) == list(range(8)) + list(range(3))
    assert all(g.geom_type == "Polygon" and len(g.exterior.coords) == 4 for g in tri.geometry)
    # The triangles tile each row's geometry: the same area, nothing outside it.
    for label, geometry in zip(gdf.index, gdf.geometry):
        mine = tri[tri["source"] == label]
        assert mine.area.sum() == pytest.approx(geometry.area)
        assert all(geometry.buffer(1e-9).contains(t) for t in mine.geometry)
    # The same triangles as flood.triangulate gives the row alone.
    t = flood.triangulate(HOLED)
    assert [list(g.exterior.coords)[:3] for g in tri.geometry[:8]] == \
        [[tuple(t.vertices[i]) for i in tri_] for tri_ in t.triangles]
    # The attributes come back by the documented join.
    joined = tri.join(gdf.drop(columns=gdf.geometry.name), on="source")
    assert list(joined["name"]) == ["parcel a"] * 8 + ["parcel b"] * 3


def test_a_bad_row_is_warned_about_and_the_others_triangulated():
    gdf = frame([HOLED, BOWTIE, None, TWO], index=[10, 11, 12, 13])
    with pytest.warns(flood.FloodWarning) as caught:
        tri = flood.triangulate_frame(gdf)
    messages = [str(w.message) for w in caught]
    assert len(messages) == 2, messages
    assert messages[0].startswith("row 11: ring 0") and "row skipped" in messages[0]
    assert "intersect" in messages[0] or "cross" in messages[0], messages[0]
    assert messages[1] == "row 12: no geometry; row skipped"
    assert sorted(set(tri["source"])) == [10, 13]
    assert len(tri) == 8 + 3

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        quiet = flood.triangulate_frame(gdf, errors="ignore")
    assert quiet.equals(tri)

    with pytest.raises(flood.InvalidPolygon) as e:
        flood.triangulate_frame(gdf, errors="raise")
    assert e.value.code == 4 and e.value.message.startswith("row 11: ")

    with pytest.raises(ValueError, match="errors must be one of warn, raise, ignore"):
        flood.triangulate_frame(gdf, errors="coerce")


def test_an_empty_or_all_bad_frame_gives_an_empty_frame_in_its_crs():
    tri = flood.triangulate_frame(frame([BOWTIE], index=[0]), errors="ignore")
    assert len(tri) == 0 and tri.crs.to_epsg() == 2263
    assert list(tri.columns) == ["source", "triangle", "geometry"]
