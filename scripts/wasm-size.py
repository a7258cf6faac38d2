#!/usr/bin/env python3
"""What each part of the page's index.wasm costs (docs/BENCHMARKS.md, issue 29).

    scripts/wasm-size.py [--list WORD] [BUILD_WEB]    (default build-web/, after scripts/web.sh)

--list WORD also lists the 40 largest functions of each part whose name has WORD.

Links flood-viewer again exactly as build-web/ does (its CMake link command) but into a
temporary folder, with --emit-symbol-map (which does not change the .wasm: checked against
site/index.wasm), and once more without -sASYNCIFY (a page that cannot run, measured only).
Each function body of the code section is then given to the input that defines it:
  - a strong definition in one object (llvm-nm) -> that object: a viewer or core source file,
    an archive's member (ImGui, simdjson, mini-gmp, musl, libc++'s iostream.o, ...);
  - a weak one (inline functions and templates, defined in every object that uses them) -> by
    its namespace: libc++'s templates, Flood's, ImGui's ...;
  - none (what Emscripten generates: ASYNCIFY's helpers, dynCall_*) -> "emscripten runtime".
Prints markdown tables: by part, then the largest source files and archive members.
"""
import collections
import gzip
import os
import re
import shlex
import subprocess
import sys
import tempfile

args = sys.argv[1:]
listed = args[args.index("--list") + 1] if "--list" in args else None
if listed:
    del args[args.index("--list"):args.index("--list") + 2]
build = os.path.abspath(args[0] if args else "build-web")
viewer_dir = os.path.join(build, "viewer")
link_txt = os.path.join(viewer_dir, "CMakeFiles/flood-viewer.dir/link.txt")
if not os.path.exists(link_txt):
    sys.exit(f"wasm-size: no {link_txt}: build the page first (scripts/web.sh)")
os.environ.setdefault("NODE_PATH", "/usr/share/nodejs")  # emcc's JS tools (docs/WEB.md)


def leb(b, p):
    value = shift = 0
    while True:
        x = b[p]
        p += 1
        value |= (x & 0x7F) << shift
        shift += 7
        if x < 0x80:
            return value, p


def parse_wasm(path):
    """Section sizes by name, and each defined function's body size by function index."""
    b = open(path, "rb").read()
    p, imported, bodies, sections = 8, 0, {}, collections.Counter()
    names = {1: "type", 2: "import", 3: "function", 4: "table", 5: "memory", 6: "global",
             7: "export", 8: "start", 9: "element", 10: "code", 11: "data", 12: "datacount"}
    while p < len(b):
        sid = b[p]
        size, start = leb(b, p + 1)
        end = start + size
        sections[names.get(sid, "custom")] += end - p
        if sid == 2:  # imports: functions come first in the index space
            count, q = leb(b, start)
            for _ in range(count):
                for _ in range(2):  # module, field
                    n, q = leb(b, q)
                    q += n
                kind = b[q]
                q += 1
                if kind == 0:
                    _, q = leb(b, q)
                    imported += 1
                elif kind == 1:  # table: reftype, limits
                    flags = b[q + 1]
                    _, q = leb(b, q + 2)
                    if flags & 1:
                        _, q = leb(b, q)
                elif kind == 2:  # memory: limits
                    flags = b[q]
                    _, q = leb(b, q + 1)
                    if flags & 1:
                        _, q = leb(b, q)
                else:  # global: type, mutability
                    q += 2
        elif sid == 10:
            count, q = leb(b, start)
            for i in range(count):
                n, body = leb(b, q)
                bodies[imported + i] = body + n - q
                q = body + n
        p = end
    return sections, bodies


def link(out_dir, drop=None):
    """flood-viewer linked as build-web links it, into out_dir, with a symbol map; -v gives
    wasm-ld's command, whose inputs are the objects and libraries to attribute. `drop`: the
    options that start so are left out."""
    cmd = open(link_txt).read().strip().replace(" -o ../site/index.html", "")
    args = [a for a in shlex.split(cmd) if not (drop and a.startswith(drop))]
    args += ["-o", os.path.join(out_dir, "index.html"), "--emit-symbol-map", "-v"]
    r = subprocess.run(args, cwd=viewer_dir, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("wasm-size: the link failed:\n" + r.stderr[-3000:])
    ld = next(shlex.split(l) for l in r.stderr.splitlines() if "wasm-ld" in l)
    symbols = {}  # demangled, with \XX escapes and a ".N" suffix on a repeated name
    for line in open(os.path.join(out_dir, "index.html.symbols")):
        i, _, name = line.rstrip("\n").partition(":")
        name = re.sub(r"\\([0-9a-f]{2})", lambda m: chr(int(m.group(1), 16)), name)
        symbols[int(i)] = re.sub(r"\.[0-9]+$", "", name)
    return ld, symbols, os.path.join(out_dir, "index.wasm")


def inputs_of(ld):
    """wasm-ld's objects and archives, the -l libraries found on its -L paths."""
    dirs = [a[2:] for a in ld if a.startswith("-L")]
    files = []
    for a in ld[1:]:
        if a.startswith("-l"):
            files += [p for d in dirs for p in [os.path.join(d, f"lib{a[2:]}.a")] if os.path.exists(p)][:1]
        elif a.endswith((".o", ".a")) and not a.startswith("-"):
            files.append(os.path.normpath(os.path.join(viewer_dir, a)))
    return files


def demangle(names):
    r = subprocess.run(["llvm-cxxfilt"], input="\n".join(names), capture_output=True, text=True)
    return dict(zip(names, r.stdout.splitlines()))


def definitions(files):
    """Function name (demangled, as the symbol map has it) -> where it is strongly defined
    (archive:member or object path); the names defined weakly."""
    strong, weak, found = collections.defaultdict(set), set(), []
    r = subprocess.run(["llvm-nm", "--defined-only", "-A"] + files, capture_output=True, text=True)
    for line in r.stdout.splitlines():
        m = re.match(r"(.*?): ?[0-9a-f]* ([A-Za-z]) (.*)$", line)
        if m and m.group(2) in "TtWw":
            found.append(m.groups())
    dem = demangle(sorted({name for _, _, name in found}))
    for where, kind, name in found:
        (weak.add(dem[name]) if kind in "Ww" else strong[dem[name]].add(where))
    return strong, weak


# Where an object or archive member is, as a part of the page.
core_layer = {}  # object basename -> core layer
for layer_dir in os.listdir(os.path.join(build, "core/CMakeFiles")):
    for root, _, fs in os.walk(os.path.join(build, "core/CMakeFiles", layer_dir)):
        for f in fs:
            if f.endswith(".o"):
                core_layer[f] = layer_dir.replace(".dir", "").replace("floodcore_", "core: ")
IOSTREAM = {"ios.o", "iostream.o", "locale.o", "strstream.o", "ios.instantiations.o"}


def part_of_file(where):
    archive, _, member = where.rpartition(".a:")
    base = os.path.basename(member or where)
    lib = os.path.basename(archive)
    if "/flood-viewer.dir/" in where:
        return "viewer: panels (panel_*.cpp)" if base.startswith("panel_") else "viewer: the rest"
    if lib == "libfloodviewmodel": return "viewer: model, jobs, exports (libfloodviewmodel)"
    if lib == "libfloodcore": return core_layer.get(base, "core")
    if lib == "libfloodgdal": return "core: gdal"
    if lib == "libfloodweb_imgui": return "Dear ImGui (+ GLFW, OpenGL 3 backends)"
    if lib == "libfloodweb_simdjson": return "simdjson"
    if lib == "libfloodweb_deps":
        return ("GMP (mini-gmp)" if base.startswith("mini_gmp") else
                "stb PNG writer" if base.startswith("stb") else
                "std::thread shim" if base.startswith("inline_threads") else "double-conversion")
    if lib.startswith("libc++abi"): return "libc++abi (exceptions, demangler)"
    if lib.startswith("libc++"):
        return "libc++: iostream, locale (compiled)" if base in IOSTREAM else "libc++: the rest (compiled)"
    if lib.startswith("libc") or lib.startswith("libstubs"): return "libc (musl)"
    if lib.startswith("libdlmalloc"): return "malloc (dlmalloc)"
    if lib.startswith("libcompiler_rt"): return "compiler-rt (long double soft float)"
    return lib or base


STREAM = re.compile(r"\bstd::__2::(basic_(i|o|io|f|if|of|string)?stream|basic_(stream|string|file)buf|"
                    r"basic_ios|ios_base|locale|ctype|num_(get|put)|codecvt|numpunct|__num_(get|put)|"
                    r"(i|o)streambuf_iterator|use_facet|__pad_and_output|__stdoutbuf|__stdinbuf)")


def part_of_weak(name):
    """An inline or template function: by the name it is declared under (before its
    parameters), the first project namespace named there, else the library's."""
    head = name.replace("(anonymous namespace)", "anon")
    depth = 0
    for i, ch in enumerate(head):
        depth += ch in "<{" and 1 or ch in ">}" and -1 or 0
        if ch == "(" and depth == 0:
            head = head[:i]
            break
    if re.match(r"(.* )?std::__2::basic_regex|.*std::__2::__(match|owns|bracket|loop|state|node|r_anchor|l_anchor|back_ref|word_boundary|lookahead)", head):
        return "libc++: regex (templates)"
    if STREAM.search(head):
        return "libc++: iostream, locale (templates)"
    for key, part in (("flood::view::", "viewer: inline, templates"), ("flood::", "core: inline, templates"),
                      ("ImGui", "Dear ImGui (+ GLFW, OpenGL 3 backends)"), ("Im", "Dear ImGui (+ GLFW, OpenGL 3 backends)"),
                      ("simdjson::", "simdjson"), ("nlohmann::", "nlohmann-json (templates)"),
                      ("CLI::", "CLI11 (the viewer's options; header-only)"),
                      ("double_conversion::", "double-conversion"), ("std::", "libc++: containers, strings, algorithms (templates)")):
        if key in head:
            return part
    return "other inline code"


def attribute(symbols, bodies, strong, weak):
    parts, files, functions = collections.Counter(), collections.Counter(), collections.Counter()
    for index, size in bodies.items():
        name = symbols.get(index, "")
        where = strong.get(name, set())
        if len(where) == 1:
            w = next(iter(where))
            part = part_of_file(w)
            files[(part, os.path.basename(w.replace(".a:", ".a: ")))] += size
        elif name in weak or len(where) > 1:
            part = part_of_weak(name)
        else:
            part = "emscripten runtime (generated: ASYNCIFY, dynCall, ...)"
        parts[part] += size
        functions[(part, name)] += size
    return parts, files, functions


def gz(path):
    return len(gzip.compress(open(path, "rb").read(), 9))


with tempfile.TemporaryDirectory() as tmp:
    page, plain = os.path.join(tmp, "page"), os.path.join(tmp, "plain")
    os.makedirs(page), os.makedirs(plain)
    ld, symbols, wasm = link(page)
    site = os.path.join(build, "site/index.wasm")
    same = os.path.exists(site) and open(site, "rb").read() == open(wasm, "rb").read()
    sections, bodies = parse_wasm(wasm)
    strong, weak = definitions(inputs_of(ld))
    parts, files, functions = attribute(symbols, bodies, strong, weak)
    _, symbols2, wasm2 = link(plain, drop="-sASYNCIFY")
    sections2, bodies2 = parse_wasm(wasm2)
    parts2, _, _ = attribute(symbols2, bodies2, strong, weak)

    total = os.path.getsize(wasm)
    print(f"index.wasm: {total:,} bytes ({gz(wasm):,} gzip -9); "
          f"{'the same bytes as' if same else 'NOT the same as'} {os.path.relpath(site)}")
    print(f"without -sASYNCIFY: {os.path.getsize(wasm2):,} bytes ({gz(wasm2):,} gzip -9)\n")
    print("| section | bytes | without ASYNCIFY |\n|---|---:|---:|")
    for s, n in sections.most_common():
        print(f"| {s} | {n:,} | {sections2[s]:,} |")
    code = sum(bodies.values())
    print(f"\n| part (code section: function bodies) | bytes | share | without ASYNCIFY |\n|---|---:|---:|---:|")
    for part, n in parts.most_common():
        print(f"| {part} | {n:,} | {100 * n / code:.1f} % | {parts2[part]:,} |")
    print(f"| **all functions ({len(bodies):,})** | **{code:,}** | | **{sum(bodies2.values()):,}** |")
    print("\n| largest compiled files (strong definitions) | part | bytes |\n|---|---|---:|")
    for (part, f), n in files.most_common(25):
        print(f"| {f} | {part} | {n:,} |")
    if listed:
        print(f"\n| largest functions of the parts named *{listed}* | part | bytes |\n|---|---|---:|")
        for (part, name), n in [f for f in functions.most_common() if listed in f[0][0]][:40]:
            print(f"| `{name[:150]}` | {part} | {n:,} |")
