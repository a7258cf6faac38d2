"""Invalid input: triangulate raises InvalidPolygon carrying the diagnostic; validate returns it."""
import pytest
import shapely.geometry as sg

import flood

BOW_TIE = [(0, 0), (10, 10), (10, 0), (0, 12)]
HOLE_OUTSIDE = [[(0, 0), (10, 0), (10, 10), (0, 10)], [(20, 20), (22, 20), (22, 22), (20, 22)]]


def test_bow_tie_raises_with_the_crossing():
    with pytest.raises(flood.InvalidPolygon) as caught:
        flood.triangulate(sg.Polygon(BOW_TIE))
    e = caught.value
    assert (e.status, e.code, e.ring, e.vertex) == ("invalid", 4, 0, 0)
    assert e.reason.startswith("edge ring 0 edge 0-1 (0, 0)-(10, 10) crosses edge ring 0 edge 2-3")
    assert str(e) == e.message and e.message.startswith("polygon: ring 0 vertex 0 (0, 0): ")


def test_hole_outside_raises_naming_the_hole():
    with pytest.raises(flood.InvalidPolygon) as caught:
        flood.triangulate(HOLE_OUTSIDE)
    d = caught.value.diagnostic
    assert (d.ring, d.vertex) == (1, 0)
    assert d.reason.startswith("hole (ring 1) lies outside its outer ring (ring 0)")


def test_validate_returns_the_diagnostic():
    assert flood.validate(sg.Polygon([(0, 0), (1, 0), (0, 1)])).ok
    d = flood.validate(HOLE_OUTSIDE, name="parcel 7")
    assert not d.ok and d.status == "invalid" and d.message.startswith("parcel 7: ring 1 vertex 0")


def test_without_validation_the_flood_machine_refuses_it():
    with pytest.raises(flood.InvalidPolygon) as caught:
        flood.triangulate(HOLE_OUTSIDE, validate=False)
    assert caught.value.status == "forbidden" and caught.value.code == 5
    assert "LeftBehind" in caught.value.reason


def test_check_verdicts_say_where_from_the_culprits():
    ok, hole, tie = flood.check([[(0, 0), (1, 0), (0, 1)], HOLE_OUTSIDE, BOW_TIE], threads=2)
    assert (ok.ring, ok.vertex, ok.reason) == (None, None, "")
    assert (hole.ring, hole.vertex) == (1, 0) and hole.reason.startswith("hole (ring 1) lies outside")
    assert (tie.ring, tie.vertex) == (0, 0) and tie.message.startswith("feature 2: ring 0 vertex 0 (0, 0): ")
