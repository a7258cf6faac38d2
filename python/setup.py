"""The extension flood._flood for `pip install`: the binding and the core's sources compiled
as CMake compiles them (C++17, no fused multiply-add contraction: results equal the CLI's).
With them the flood command's sources (cli/, all but its main()), for `python -m flood` and the
`flood` console script; GIS datasets need the CMake build's GDAL module, not built here.
Needs pybind11-dev, nlohmann-json3-dev, libsimdjson-dev, libcli11-dev and libgmp-dev
(scripts/install-deps.sh)."""
import glob
import os
import re

from setuptools import Extension, setup

here = os.path.dirname(os.path.abspath(__file__))
core = os.path.relpath(os.path.join(here, "..", "core"), here)
# Every layer's sources (core/LAYERS) but core/io/gdal's, the GDAL module CMake builds apart:
# built without GDAL, the choice of reader is read_any_none.cpp (core/CMakeLists.txt's seam).
gdal = os.path.join(core, "io", "gdal") + os.sep
core_sources = sorted(s for s in glob.glob(os.path.join(core, "**", "*.cpp"), root_dir=here,
                                           recursive=True) if not s.startswith(gdal))
core_sources.append(os.path.join(gdal, "read_any_none.cpp"))
cli = os.path.relpath(os.path.join(here, "..", "cli"), here)
cli_sources = sorted(s for s in glob.glob(os.path.join(cli, "*.cpp"), root_dir=here)
                     if os.path.basename(s) != "flood.cpp")  # main() is the program's
with open(os.path.join(here, "flood", "_version.py"), encoding="utf-8") as f:
    version = re.search(r'__version__ = "([^"]+)"', f.read()).group(1)

setup(ext_modules=[Extension(
    "flood._flood",
    sources=["flood_module.cpp"] + core_sources + cli_sources,
    # The public headers (core/include: all the binding may use, as CMake's Flood::core gives
    # it), core/ for the core's own sources' internal ones, and the repository for "cli/run.h".
    include_dirs=[os.path.join(core, "include"), core, os.path.join(core, "..")],
    define_macros=[("FLOOD_VERSION", f'"{version}"')],
    libraries=["gmp", "simdjson"],
    language="c++",
    extra_compile_args=["-std=c++17", "-O2", "-ffp-contract=off", "-fvisibility=hidden"],
)],
    # The core's sources compiled side by side: about a minute instead of several.
    options={"build_ext": {"parallel": os.cpu_count() or 1}})
