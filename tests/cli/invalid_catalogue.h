// The diagnostics catalogue (docs/ERRORS.md), written once for every test that runs it: one
// row per error the `flood` command can report, with its example file in polygons/invalid/,
// the arguments, the exit code and a substring of the exact message.
#pragma once

namespace flood::testing {

struct CatalogueRow {
    const char* file;  // in polygons/invalid/ ("" for a path given in `args`)
    const char* args;  // before the file
    int code;
    const char* message;
};

inline const CatalogueRow kInvalidCatalogue[] = {
    // Malformed (3)
    {"malformed-json.json", "triangulate", 3, "malformed-json.json:2:3: JSON syntax error"},
    {"deep-nesting.json", "triangulate", 3,
     "deep-nesting.json:1:65: JSON nested deeper than 64 levels; refusing to parse"},
    {"bad-structure.json", "triangulate", 3,
     "bad-structure.json: polygon 0 ring 0 vertex 2: coordinate is not a pair of numbers"},
    {"number-overflow.json", "triangulate", 3,
     "number-overflow.json:2:6: number out of range: 1e999 does not fit a double"},
    {"wkt-syntax.wkt", "triangulate", 3, "wkt-syntax.wkt:1:27: WKT: expected ')', found 'x'"},
    {"wkt-empty.wkt", "triangulate", 3,
     "wkt-empty.wkt:1:9: WKT: POLYGON EMPTY: polygon has no rings"},
    {"empty-input.json", "triangulate", 3, "empty-input.json:1:1: empty input, no polygon"},
    {"does-not-exist.json", "triangulate", 3,
     "does-not-exist.json: cannot open file: No such file or directory"},
    {"nul-bytes.json", "triangulate", 3,
     "nul-bytes.json: binary data (a NUL byte at byte 0), not GeoJSON or WKT"},
    {"", "verify /dev/zero", 3,
     "/dev/zero: binary data (a NUL byte at byte 0), not GeoJSON or WKT"},
    {"", "triangulate /", 3, "/: is a directory, not a file"},
    {"malformed-json.json", "verify --max-input-bytes 16", 3,
     "malformed-json.json: input is larger than the limit of 16 bytes (--max-input-bytes)"},
    // Invalid (4): validation rules, in the order validate() checks them
    {"nan.wkt", "triangulate", 4,
     "nan.wkt: ring 0 vertex 2 (10, nan): coordinate is not a finite number"},
    {"empty-ring.json", "triangulate", 4,
     "empty-ring.json: ring 1: ring is empty, it needs at least 3 distinct points"},
    {"too-few-points.json", "triangulate", 4,
     "too-few-points.json: ring 0 vertex 0 (0, 0): ring has 2 distinct points, at least 3 are "
     "needed"},
    {"zero-area.json", "triangulate", 4,
     "zero-area.json: ring 0 vertex 0 (0, 0): ring has zero area"},
    {"self-intersection.json", "triangulate", 4,
     "self-intersection.json: ring 0 vertex 0 (0, 0): edge ring 0 edge 0-1 (0, 0)-(10, 10) crosses "
     "edge ring 0 edge 2-3"},
    {"hole-crossing-outer.json", "triangulate", 4,
     "hole-crossing-outer.json: ring 0 vertex 1 (10, 0): edge ring 0 edge 1-2 (10, 0)-(10, 10) "
     "crosses edge ring 1 edge 0-1"},
    {"collinear-overlap.json", "triangulate", 4,
     "collinear-overlap.json: ring 1 vertex 1 (4, 2): edge ring 1 edge 1-2 (4, 2)-(4, 4) overlaps "
     "collinear edge ring 2 edge 3-0"},
    {"spike.json", "triangulate", 4,
     "spike.json: ring 0 vertex 4 (5, 5): the ring folds back on itself here (spike)"},
    {"vertex-on-own-edge.json", "triangulate", 4,
     "vertex-on-own-edge.json: ring 0 vertex 4 (5, 0): the ring touches itself here: the vertex "
     "lies on its own edge ring 0 edge 0-1"},
    {"point-hole-on-edge.json", "triangulate", 4,
     "point-hole-on-edge.json: ring 2 vertex 0 (10, 4): point hole lies on edge ring 0 edge 1-2"},
    {"crossing-at-shared-vertex.json", "triangulate", 4,
     "ring 0 vertex 2 (5, 5): the boundary crosses itself at this shared vertex (ring 0 vertex 5 "
     "(5, 5) passes through"},
    {"parts-crossing-at-junction.json", "triangulate", 4,
     "parts-crossing-at-junction.json: ring 1 vertex 0 (2, 0): the boundary crosses itself at this "
     "touching point (edge ring 0 edge 0-1 (0, 0)-(4, 0) passes through to the other side)"},
    {"overlap-at-shared-vertex.json", "triangulate", 4,
     "ring 1 vertex 0 (2, 2): the interior overlaps itself at this shared vertex (ring 2 vertex 0 "
     "(2, 2)"},
    {"hole-outside.json", "triangulate", 4,
     "hole-outside.json: ring 1 vertex 0 (20, 20): hole (ring 1) lies outside its outer ring (ring "
     "0)"},
    {"holes-overlapping.json", "triangulate", 4,
     "holes-overlapping.json: ring 2 vertex 0 (3, 3): hole (ring 2) lies inside another hole (ring "
     "1): holes overlap"},
    {"parts-overlapping.json", "triangulate", 4,
     "parts-overlapping.json: ring 1 vertex 0 (2, 2): outer ring 1 lies inside the outer ring 0 of "
     "another part: parts overlap"},
    // Forbidden (5): the machine's own diagnosis, validation skipped
    {"forbidden-short-loop.json", "triangulate --no-validate", 5,
     "forbidden transition ShortLoop at step 1"},
    {"nan.wkt", "triangulate --no-validate", 5,
     "forbidden transition NotFinite at step 1; at = vertex 2"},
    {"forbidden-start-not-bottom.json", "triangulate --no-validate", 5,
     "forbidden transition StartNotBottom at step 1; at = vertex 1 (ring 0 vertex 1, 0, 4)"},
    {"forbidden-ceiling-as-end.json", "triangulate --no-validate", 5,
     "forbidden transition CeilingAsEnd at step 3; at = vertex 3 (ring 0 vertex 3, 2, 5)"},
    {"forbidden-jump-wrong-side.json", "triangulate --no-validate", 5,
     "forbidden transition JumpWrongSide at step 7"},
    {"forbidden-spill-no-bottom.json", "triangulate --no-validate", 5,
     "forbidden transition SpillNoBottom at step 3; at = vertex 0 (ring 0 vertex 0, 7, 4)"},
    {"forbidden-bad-triangle.json", "triangulate --no-validate", 5,
     "forbidden transition BadTriangle at step 4"},
    {"forbidden-fill-open.json", "triangulate --no-validate", 5,
     "forbidden transition FillOpen at step 4"},
    {"forbidden-left-behind.json", "triangulate --no-validate", 5,
     "forbidden transition LeftBehind at step 5; at = vertex 4 (ring 1 vertex 0, 20, 20)"},
    {"forbidden-spill-no-bottom.json", "trace --no-validate", 5,
     "forbidden transition SpillNoBottom"},
    {"forbidden-ceiling-as-end.json", "transcript --no-validate", 5, "Forbidden"},
    // Internal (6): the checker rejects what the machine produced (only reachable unvalidated)
    {"checker-rejects.json", "triangulate --no-validate", 6,
     "the exact checker rejects our triangulation: triangle-count"},
    // Usage (2)
    {"", "triangulate --format png x.json", 2, "--format"},
    // The finding: CLI11 said "A subcommand is required" for a misspelt one.
    {"", "frobnicate", 2,
     "unknown subcommand 'frobnicate'; expected one of triangulate, trace, transcript"},
    // (an input that is refused before any write even without the check: a regression cannot
    // overwrite the example; tests/cli/cli_test.cpp tries shrink on copies)
    {"zero-area.json", "triangulate -o " FLOOD_SOURCE_DIR "/polygons/invalid/zero-area.json", 2,
     "zero-area.json is the input file"},
    // Write failed (8): the system's reason; an existing output is left as it was
    {"", "generate circle-jagged 100 -o /dev/full", 8,
     "/dev/full: cannot write: No space left on device"},
    {"", "triangulate " FLOOD_SOURCE_DIR "/polygons/hole.json -o /dev/full/x.json", 8,
     "/dev/full/x.json: cannot write: Not a directory"},
};

}  // namespace flood::testing
