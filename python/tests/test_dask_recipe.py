"""docs/PYTHON.md's Dask recipe, run as written: its ogr2ogr line on a GeoPackage made here,
then its Python block. The rows' ids must be the FIDs (the recipe once split `WKT<TAB>name`
rows at the first tab, so every id was a WKT)."""
import os
import pathlib
import re
import shutil
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR

PARCELS = """{"type":"FeatureCollection","features":[
{"type":"Feature","properties":{"name":"France"},"geometry":{"type":"Polygon","coordinates":[[[0,0],[2,0],[2,2],[0,2],[0,0]]]}},
{"type":"Feature","properties":{"name":"Spain"},"geometry":{"type":"Polygon","coordinates":[[[2,0],[4,0],[4,2],[2,2],[2,0]]]}},
{"type":"Feature","properties":{"name":"Bow-tie"},"geometry":{"type":"Polygon","coordinates":[[[0,5],[2,7],[2,5],[0,7],[0,5]]]}}]}"""


def recipe():
    """The shell line and the Python block of the recipe, as PYTHON.md shows them."""
    text = (SOURCE_DIR / "docs" / "PYTHON.md").read_text()
    start = text.index("**Dask** (`flood.dask`)")
    blocks = re.findall(r"\n\n((?:    .*\n)+)", text[start:])
    shell = next(b for b in blocks if b.lstrip().startswith("ogr2ogr"))
    python = next(b for b in blocks if "flood.dask.failures" in b)
    strip = lambda b: "\n".join(line[4:] for line in b.splitlines()) + "\n"
    return strip(shell), strip(python)


def test_the_dask_recipe_gives_fids(tmp_path):
    if not shutil.which("ogr2ogr"):
        pytest.skip("ogr2ogr (gdal-bin) is not installed: the recipe's export cannot run")
    pytest.importorskip("distributed", reason="python3-distributed is not installed")
    (tmp_path / "parcels.geojson").write_text(PARCELS)
    subprocess.run(["ogr2ogr", "-f", "GPKG", "-nln", "parcels", "parcels.gpkg", "parcels.geojson"],
                   cwd=tmp_path, check=True)
    shell, python = recipe()
    subprocess.run(shell, shell=True, cwd=tmp_path, check=True)
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    out = subprocess.run([sys.executable, "-c", python], cwd=tmp_path, env=env, check=True,
                         capture_output=True, text=True, timeout=240).stdout
    rows = [line.split(" ", 2) for line in out.splitlines()]
    assert [r[:2] for r in rows] == [["3", "4"]], out
    assert "crosses" in rows[0][2], out
