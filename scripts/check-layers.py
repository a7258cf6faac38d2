#!/usr/bin/env python3
"""Fails on an #include "..." in core/ that climbs the stack of core/LAYERS (scripts/lint.sh).

core/LAYERS lists the layers bottom up: a folder, then the layers its files may include besides
their own; what those may include is allowed too. A file belongs to the longest folder listed
that holds it, `.` holding only the files of core/ itself. Every include in core/ is written by
its path from core/ ("machine/flood.h"), so its layer is in its first words. Prints each
forbidden include as FILE:LINE with the edge, and exits 1 if there is any.
    scripts/check-layers.py [ROOT]   (default: the checkout this script is in)
"""
import os
import re
import sys

root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
core = os.path.join(root, "core")
layers_file = os.path.join(core, "LAYERS")
problems = []

uses = {}  # layer -> the layers it names, in file order (bottom up)
with open(layers_file, encoding="utf-8") as f:
    for number, line in enumerate(f, 1):
        words = line.split("#", 1)[0].split()
        if not words:
            continue
        layer, named = words[0], words[1:]
        for use in named:
            if use not in uses:
                problems.append(f"core/LAYERS:{number}: {layer} uses {use}, not a layer listed "
                                "above it")
        uses[layer] = named

allowed = {}  # layer -> every layer its files may include, its own among them
for layer, named in uses.items():
    allowed[layer] = {layer}.union(*(allowed.get(use, set()) for use in named))


def layer_of(path):
    """The layer of a file given by its path from core/, or None when no layer holds it."""
    folder = os.path.dirname(path)
    if folder == "":
        return "." if "." in uses else None
    best = None
    for layer in uses:
        if layer != "." and (folder == layer or folder.startswith(layer + "/")):
            if best is None or len(layer) > len(best):
                best = layer
    return best


include = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
for folder, dirs, files in os.walk(core):
    dirs.sort()
    for name in sorted(files):
        if not name.endswith((".h", ".cpp")):
            continue
        path = os.path.relpath(os.path.join(folder, name), core)
        layer = layer_of(path)
        if layer is None:
            problems.append(f"core/{path}: in no layer of core/LAYERS (add its folder there)")
            continue
        with open(os.path.join(core, path), encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                m = include.match(line)
                if not m:
                    continue
                target = m.group(1)
                where = f"core/{path}:{number}: #include \"{target}\""
                if not os.path.isfile(os.path.join(core, target)):
                    problems.append(f"{where}: not a path from core/ (write it as "
                                    "\"layer/file.h\")")
                    continue
                to = layer_of(os.path.normpath(target))
                if to is None or to not in allowed[layer]:
                    problems.append(f"{where}: {layer} may not include {to or 'a folder in no layer'}, which is not below "
                                    f"it (core/LAYERS: {layer} uses "
                                    f"{' '.join(uses[layer]) or 'nothing'})")

for p in problems:
    print(f"check-layers: {p}")
if problems:
    print(f"check-layers: {len(problems)} include(s) against the stack of core/LAYERS "
          "(docs/LAYOUT.md)")
    sys.exit(1)
print(f"check-layers: {len(uses)} layers, every include of core/ goes down the stack")
