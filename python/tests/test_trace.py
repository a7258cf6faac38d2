"""trace(): the event array and the replay agree with each other and with triangulate()."""
import numpy as np

import flood
from conftest import SOURCE_DIR


def test_replay_reads_what_the_events_say():
    polygon = (SOURCE_DIR / "polygons" / "holes.json").read_text()
    t = flood.trace(polygon)
    assert t.diagnostic.ok
    assert t.triangles.tolist() == flood.triangulate(polygon).triangles.tolist()
    events = t.events
    assert events.dtype == flood.EVENT_DTYPE and len(events) == len(t.replay) > 0
    assert (events["step"] == np.arange(len(events))).all()
    assert {flood.ACTIONS[a] for a in events["action"]} >= {"Start", "Raise", "Bridge", "Fill"}
    start = t.replay.seek(0)
    assert (start.left, start.right, start.chain) == (flood.NONE, flood.NONE, [])
    # Forwards, then backwards (keyframes both ways): after step k, the fingers are event k-1's.
    for k in list(range(1, len(events) + 1)) + list(range(len(events), 0, -7)):
        s = t.replay.seek(k)
        after = events[k - 1]["after"]
        assert s.step == k
        assert (s.left, s.right) == (after["left"], after["right"])
        assert (s.fingers.nextLeft, s.fingers.nextRight) == (after["nextLeft"], after["nextRight"])
        assert s.triangleCount == events["firstTriangle"][k - 1] + events["triangleCount"][k - 1]
        if s.chain:
            assert (s.chain[0], s.chain[-1]) == (s.left, s.right)
    assert t.replay.seek(len(events)).triangleCount == len(t.triangles)


def test_a_forbidden_run_is_traced_and_an_invalid_one_raises():
    hole_outside = [[(0, 0), (10, 0), (10, 10), (0, 10)], [(20, 20), (22, 20), (22, 22), (20, 22)]]
    t = flood.trace(hole_outside, validate=False)
    assert t.diagnostic.status == "forbidden"
    last = t.events[-1]
    assert flood.ACTIONS[last["action"]] == "Forbidden" and flood.FORBIDDEN[last["reason"]] == "LeftBehind"
    assert t.replay.seek(len(t.events)).forbidden
    try:
        flood.trace(hole_outside)
    except flood.InvalidPolygon as e:
        assert e.code == 4
    else:
        raise AssertionError("an invalid polygon must raise")
