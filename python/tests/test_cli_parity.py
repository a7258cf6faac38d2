"""flood.triangulate gives what `flood triangulate -o FILE.json` writes, on every sample, and
fails with the command's exit code and message on every invalid input."""
import json
import subprocess

import numpy as np
import pytest

import flood
from conftest import INVALID, SAMPLES


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.name)
def test_samples_equal_the_cli(path, flood_cli, tmp_path):
    out = tmp_path / "out.json"
    subprocess.run([flood_cli, "triangulate", str(path), "-o", str(out)], check=True)
    expected = json.loads(out.read_text())
    result = flood.triangulate(path.read_text())
    assert result.triangles.dtype == np.int64 and result.triangles.shape[1] == 3
    assert result.vertices.tolist() == expected["vertices"]
    assert result.triangles.tolist() == expected["triangles"]
    # The same polygon as nested Python lists (when the file is a bare ring array).
    doc = json.loads(path.read_text())
    if isinstance(doc, list):
        assert flood.triangulate(doc).triangles.tolist() == expected["triangles"]


@pytest.mark.parametrize("path", INVALID, ids=lambda p: p.name)
def test_invalid_inputs_fail_as_the_cli_does(path, flood_cli, tmp_path):
    run = subprocess.run([flood_cli, "triangulate", str(path), "-o", str(tmp_path / "o.json")],
                         capture_output=True, text=True)
    assert run.returncode != 0
    d = flood.validate(path.read_bytes(), name=str(path))
    if d.ok:  # valid, but the flood machine or the checker refuses it
        with pytest.raises((flood.InvalidPolygon, flood.InternalError)) as caught:
            flood.triangulate(path.read_bytes(), name=str(path))
        d = caught.value.diagnostic
    assert d.code == run.returncode
    assert d.message in run.stderr


@pytest.mark.parametrize("up", ["17", "-x", "1,2", "333"])
def test_any_direction_equals_the_cli(up, flood_cli, tmp_path):
    path = next(p for p in SAMPLES if p.name == "holes.json")
    out = tmp_path / "out.json"
    subprocess.run([flood_cli, "triangulate", str(path), "--up=" + up, "-o", str(out)], check=True)
    result = flood.triangulate(path.read_text(), up=up)
    assert result.triangles.tolist() == json.loads(out.read_text())["triangles"]


def test_a_bad_direction_names_itself():
    with pytest.raises(ValueError, match="'banana'"):
        flood.triangulate([[[0, 0], [1, 0], [0, 1]]], up="banana")


# Empty lists at every depth: `[[]]` was malformed (3) from Python but invalid (4) from the
# command line. The same JSON, as a file and as nested lists, gets one verdict and one message.
@pytest.mark.parametrize("doc", ["[]", "[[]]", "[[], []]", "[[[]]]", "[[[[]]]]",
                                 "[[[0, 0], [1, 0], [0, 1]], []]",
                                 "[[[[0, 0], [1, 0], [0, 1]]], []]", "[[[0, 0], [1, 0]]]"])
def test_empty_lists_get_the_clis_verdict(doc, flood_cli, tmp_path):
    path = tmp_path / "t.json"
    path.write_text(doc)
    run = subprocess.run([flood_cli, "triangulate", str(path), "-o", str(tmp_path / "o.json")],
                         capture_output=True, text=True)
    assert run.returncode in (3, 4), run.stderr
    d = flood.validate(json.loads(doc), name=str(path))
    assert d.code == run.returncode, (d, run.stderr)
    if run.returncode == 4 or "no rings" in run.stderr:  # the readers' shared words
        assert d.message in run.stderr, (d.message, run.stderr)
