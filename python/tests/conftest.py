"""Where the tests find the built `flood` command and the repository's polygons: from the
environment ctest sets (python/CMakeLists.txt), else the default build directory."""
import os
import pathlib

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("FLOOD_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
FLOOD_CLI = os.environ.get("FLOOD_CLI", str(SOURCE_DIR / "build" / "flood"))

# The sample polygons: every input at the top of polygons/ (gallery.json is the teaching
# gallery's index, not a polygon).
SAMPLES = sorted(p for p in (SOURCE_DIR / "polygons").glob("*.json") if p.name != "gallery.json")
INVALID = sorted((SOURCE_DIR / "polygons" / "invalid").iterdir())


@pytest.fixture(scope="session")
def flood_cli():
    if not os.access(FLOOD_CLI, os.X_OK):
        pytest.fail(f"the flood command is not built at {FLOOD_CLI} (set FLOOD_CLI)")
    return FLOOD_CLI
