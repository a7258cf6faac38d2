"""flood.dask on a local cluster of 2 worker processes gives the single-process verdicts."""
import dask.bag as db
import distributed
import pytest
import shapely.geometry as sg

import flood
import flood.dask

BOW_TIE = "POLYGON ((0 0, 10 10, 10 0, 0 12, 0 0))"
HOLE_OUTSIDE = "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (20 20, 22 20, 22 22, 20 22, 20 20))"


def wkt(parts):
    """Exact WKT (repr round-trips every double) of generate()'s parts."""
    def ring(a):
        return "(" + ", ".join(f"{x!r} {y!r}" for x, y in list(a) + [a[0]]) + ")"
    polygons = ["(" + ", ".join(ring(r) for r in rings) + ")" for rings in parts]
    return "MULTIPOLYGON (" + ", ".join(polygons) + ")"


def features(count=3000):
    """Generated valid features (WKT and shapely), every 50th a bow-tie or a hole outside."""
    families = flood.families()
    out = []
    for i in range(count):
        if i % 50 == 7:
            out.append(BOW_TIE if i % 100 == 7 else sg.Polygon(*[[(0, 0), (10, 0), (10, 10), (0, 10)],
                                                                  [[(20, 20), (22, 20), (22, 22), (20, 22)]]]))
        else:
            parts = flood.generate(families[i % len(families)], 24, seed=i)
            out.append(wkt(parts) if i % 2 else sg.MultiPolygon([sg.Polygon(r[0], r[1:]) for r in parts]))
    return out


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as c:
        yield c


def expected_failures(geoms):
    return [(i, v.code, v.message) for i, v in enumerate(flood.check(geoms, threads=1)) if not v.ok]


def test_bag_on_two_workers_equals_one_process(client):
    geoms = features()
    expected = expected_failures(geoms)
    assert len(expected) == 60 and {code for _, code, _ in expected} == {4}
    bag = db.from_sequence(list(enumerate(geoms)), npartitions=8)
    got = flood.dask.failures(bag)
    assert [(r["id"], r["code"], r["message"]) for r in got] == expected
    assert {r["ring"] for r in got} == {0, 1}
    assert len(client.scheduler_info()["workers"]) == 2


def test_dataframe_partitions(client):
    pd = pytest.importorskip("pandas")
    import dask.dataframe as dd

    geoms = [g if isinstance(g, str) else g.wkt for g in features(600)]
    frame = pd.DataFrame({"geometry": geoms, "name": [f"f{i}" for i in range(len(geoms))]})
    failing = flood.dask.check_dataframe(dd.from_pandas(frame, npartitions=4)).compute()
    expected = expected_failures(geoms)
    assert list(failing.index) == [i for i, _, _ in expected]
    assert list(failing["name"]) == [f"f{i}" for i, _, _ in expected]
    assert list(failing["message"]) == [m for _, _, m in expected]
