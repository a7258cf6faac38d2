"""Where the tests find the built `flood` command and the repository's polygons: from the
environment ctest sets (python/CMakeLists.txt), else the default build directory."""
import os
import pathlib

import pytest

from flood import _flood

SOURCE_DIR = pathlib.Path(os.environ.get("FLOOD_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
FLOOD_CLI = os.environ.get("FLOOD_CLI", str(SOURCE_DIR / "build" / "flood"))

# The sample polygons: every GeoJSON input at the top of polygons/, and every file of
# polygons/invalid/, as the core lists polygons (polygonFiles, flood/io/io.h: gallery.json is
# the teaching gallery's index, not a polygon).
SAMPLES = [
    pathlib.Path(p)
    for p in _flood.polygon_files(str(SOURCE_DIR / "polygons"))
    if p.endswith(".json")
]
INVALID = [pathlib.Path(p) for p in _flood.polygon_files(str(SOURCE_DIR / "polygons" / "invalid"))]


@pytest.fixture(scope="session")
def flood_cli():
    if not os.access(FLOOD_CLI, os.X_OK):
        pytest.fail(f"the flood command is not built at {FLOOD_CLI} (set FLOOD_CLI)")
    return FLOOD_CLI
