#!/usr/bin/env python3
"""Fails on an #include "..." that climbs the stack of core/LAYERS or reaches past the public
headers (scripts/lint.sh).

core/LAYERS lists the layers bottom up: a folder, then the layers its files may include besides
their own; what those may include is allowed too. A layer's files are in core/<layer>/ (sources
and internal headers) and flood/<layer>/ (public headers); a file belongs to the
longest folder listed that holds it, `.` holding only the files of core/ and flood/
themselves. Public headers are included as "flood/<layer>/x.h", internal ones as "<layer>/x.h".
Besides the layers:
  - a public header includes only public headers (they are installed, the others are not);
  - cli/ and python/ include only public headers, as any program linking Flood;
  - viewer/ includes an internal header only if viewer/CORE_INTERNALS lists it.
Prints each forbidden include as FILE:LINE with the edge, and exits 1 if there is any.
    scripts/check-layers.py [ROOT]   (default: the checkout this script is in)
"""
import os
import re
import sys

root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
core = os.path.join(root, "core")
public = os.path.join(core, "include")  # holds flood/<layer>/...
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
    """The layer of a file given by its layer path ("machine/flood.h", from core/ or from
    flood/), or None when no layer holds it."""
    folder = os.path.dirname(path)
    if folder == "":
        return "." if "." in uses else None
    best = None
    for layer in uses:
        if layer != "." and (folder == layer or folder.startswith(layer + "/")):
            if best is None or len(layer) > len(best):
                best = layer
    return best


def resolve(target):
    """(layer path, is public) of a core header named in an #include, or None if it is none."""
    if target.startswith("flood/") and os.path.isfile(os.path.join(public, target)):
        return os.path.normpath(target[len("flood/"):]), True
    if os.path.isfile(os.path.join(core, target)) and not target.startswith("include/"):
        return os.path.normpath(target), False
    return None


include = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def includes(path):
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            m = include.match(line)
            if m:
                yield number, m.group(1)


def walk(top):
    for folder, dirs, files in os.walk(top):
        dirs.sort()
        for name in sorted(files):
            if name.endswith((".h", ".cpp", ".c")):
                yield os.path.join(folder, name)


# ---- the core: layers, and public headers that include only public headers ------------------
for path in walk(core):
    rel = os.path.relpath(path, core)
    is_public = rel.startswith("include" + os.sep)
    if is_public:
        inner = os.path.relpath(path, public)
        if not inner.startswith("flood" + os.sep):
            problems.append(f"core/{rel}: a public header outside flood/")
            continue
        rel_layer = inner[len("flood/"):]
    else:
        rel_layer = rel
    layer = layer_of(rel_layer)
    if layer is None:
        problems.append(f"core/{rel}: in no layer of core/LAYERS (add its folder there)")
        continue
    for number, target in includes(path):
        where = f"core/{rel}:{number}: #include \"{target}\""
        found = resolve(target)
        if found is None:
            problems.append(f"{where}: not a core header by its path (write \"flood/layer/x.h\" "
                            "for a public header, \"layer/x.h\" for an internal one)")
            continue
        to_path, to_public = found
        if is_public and not to_public:
            problems.append(f"{where}: a public header may include only public headers "
                            "(flood/), and this one is internal")
        to = layer_of(to_path)
        if to is None or to not in allowed[layer]:
            problems.append(f"{where}: {layer} may not include {to or 'a folder in no layer'}, "
                            "which is not below it (core/LAYERS: "
                            f"{layer} uses {' '.join(uses[layer]) or 'nothing'})")

# ---- the front ends: the public headers, and the viewer's list -------------------------------
listed = set()
internals_file = os.path.join(root, "viewer", "CORE_INTERNALS")
if os.path.isfile(internals_file):
    with open(internals_file, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            words = line.split("#", 1)[0].split()
            if not words:
                continue
            if resolve(words[0]) is None or resolve(words[0])[1]:
                problems.append(f"viewer/CORE_INTERNALS:{number}: {words[0]} is not an internal "
                                "header of core/")
            listed.add(words[0])
for front in ("cli", "python", "viewer"):
    for path in walk(os.path.join(root, front)):
        rel = os.path.relpath(path, root)
        for number, target in includes(path):
            if os.path.isfile(os.path.join(os.path.dirname(path), target)):
                continue  # the front end's own header
            found = resolve(target)
            if found is None or found[1]:
                continue
            if front == "viewer" and target in listed:
                continue
            rule = ("list it in viewer/CORE_INTERNALS with why, or use a public one"
                    if front == "viewer" else "it builds against the public headers only")
            problems.append(f"{rel}:{number}: #include \"{target}\": an internal header of core/ "
                            f"({rule})")

for p in problems:
    print(f"check-layers: {p}")
if problems:
    print(f"check-layers: {len(problems)} include(s) against the stack of core/LAYERS or past the "
          "public headers (docs/LAYOUT.md)")
    sys.exit(1)
print(f"check-layers: {len(uses)} layers, every include of core/ goes down the stack, the front "
      "ends use the public headers (the viewer also viewer/CORE_INTERNALS)")
