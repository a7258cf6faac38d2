"""scripts/check-layers.py passes on the tree as it is and fails, naming file and rule, on each
kind of include it exists to refuse: one that climbs core/LAYERS, a public header including an
internal one, the CLI or the Python module reaching an internal header, the viewer reaching one
viewer/CORE_INTERNALS does not list. Each case is a copy of the checked folders with one line added.
    python3 tests/check_layers_test.py SOURCE_DIR
"""
import os
import shutil
import subprocess
import sys
import tempfile

src = sys.argv[1]
script = os.path.join(src, "scripts", "check-layers.py")
failures = 0


def check(root):
    r = subprocess.run([sys.executable, script, root], capture_output=True, text=True)
    return r.returncode, r.stdout


def expect(ok, what):
    global failures
    if not ok:
        print(f"check_layers_test: FAILED: {what}")
        failures += 1


rc, out = check(src)
expect(rc == 0, f"the tree passes as it is (got {rc}: {out.strip()})")

cases = [  # (file, line added, what the message must hold)
    ("core/machine/flood.cpp", '#include "flood/teach/narrate.h"',
     "core/machine/flood.cpp:", "machine may not include teach"),
    ("core/include/flood/geometry/predicates.h", '#include "geometry/coincident.h"',
     "core/include/flood/geometry/predicates.h:", "a public header may include only public"),
    ("cli/check.cpp", '#include "check/validator.h"',
     "cli/check.cpp:", "builds against the public headers only"),
    ("python/flood_module.cpp", '#include "machine/machine.h"',
     "python/flood_module.cpp:", "builds against the public headers only"),
    ("viewer/model.cpp", '#include "machine/machine.h"',
     "viewer/model.cpp:", "viewer/CORE_INTERNALS"),
    ("core/io/io_read.cpp", '#include "flood.h"',
     "core/io/io_read.cpp:", "not a core header by its path"),
]
with tempfile.TemporaryDirectory() as tmp:
    for file, line, where, why in cases:
        root = os.path.join(tmp, "tree")
        shutil.rmtree(root, ignore_errors=True)
        for part in ("core", "cli", "python", "viewer", "scripts"):
            shutil.copytree(os.path.join(src, part), os.path.join(root, part),
                            ignore=shutil.ignore_patterns("build*", "*.so", "__pycache__"))
        with open(os.path.join(root, file), "a", encoding="utf-8") as f:
            f.write(line + "\n")
        rc, out = check(root)
        expect(rc == 1 and where in out and why in out,
               f"{line} in {file} is refused with '{why}' (got {rc}: {out.strip()})")

print("check_layers_test: " + ("ok" if failures == 0 else f"{failures} failed"))
sys.exit(1 if failures else 0)
