// The two JSON readers behind parsePolygon (internal to core/, not a public API): the fast one
// (io_json_fast.cpp, simdjson) and the one that explains every failure (io_read.cpp, nlohmann).
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "flood/io/io.h"

namespace flood::io_detail {

// Reads a JSON polygon document in one pass, or returns nothing when it cannot read it as
// parseJsonTree would (then parseJsonTree must run). `capacity` bytes from text.data() are
// readable (at least text.size() + kReadAhead avoids a copy); `start` is the offset of the
// document's first bracket.
// With `run`, a document of at least `piecesFrom` bytes that cutCoordinates cuts is read in
// pieces as tasks given to it; the result is the same (fuzz/fuzz_read.cpp holds it to that).
constexpr size_t kPiecesFrom = size_t(4) << 20;
std::optional<ReadResult> parseJsonFast(std::string_view text, size_t capacity, size_t start,
                                        const std::string& name, const TaskRunner& run = {},
                                        size_t piecesFrom = kPiecesFrom);

// Reads any JSON document through a document tree: every message of docs/ERRORS.md, with its
// line and column.
ReadResult parseJsonTree(std::string_view text, const std::string& name);

// The "features" array of a document `{..., "features": [...], ...}`: its brackets and the
// commas between its elements, found by a scan of the bytes (io_json_cut.cpp). Nothing when
// the text is not such an object or the scan could misread it (a member name with escapes, two
// "features" arrays, an unclosed string or bracket). What it finds is only where to cut: the
// pieces must still be parsed, and the document around the array too.
struct FeatureCut {
    size_t open = 0, close = 0;  // the array's '[' and ']'
    std::vector<size_t> commas;  // between its elements, in order
};
std::optional<FeatureCut> cutFeatures(std::string_view text);

// Where the coordinates array of a large geometry may be cut between whole elements (the
// polygons of a MultiPolygon, the rings of a Polygon), so that parseJsonFast can read it in
// pieces on several threads. Found by a scan of a few bytes after each of `pieces - 1` evenly
// spaced points, for a document that is a bare array of rings or polygons (`bareDepth` 3 or 4,
// as leadingArrayDepth finds it) or exactly {"type": "Polygon" or "MultiPolygon",
// "coordinates": [...]}; nothing otherwise. Like cutFeatures it says only where to cut: a cut
// in the wrong place leaves a piece that does not parse, and the whole is then read in one.
struct CoordinateCut {
    int depth = 0;               // 4: the elements are polygons; 3: rings
    size_t open = 0, close = 0;  // the array's '[' and ']'
    std::vector<size_t> commas;  // the cuts: commas between elements, in order
};
std::optional<CoordinateCut> cutCoordinates(std::string_view doc, int bareDepth, size_t pieces);

// The document in the pieces cutCoordinates finds, each parsed as a task given to `run`,
// then joined (io_json_fast.cpp). Nothing when there is no cut, a piece is over a quarter of
// the document, or a piece does not parse or warns (a warning names its ring by its number in
// the whole): read the document in one.
std::optional<ReadResult> parsePieces(std::string_view doc, int bareDepth, const std::string& name,
                                      const TaskRunner& run);

// Cleans the ring just appended to `rr.polygon.vertices` at `first`, in place, and records it
// (io_read.cpp).
void cleanLastRing(ReadResult& rr, const std::string& name, Index first, bool outer);

}  // namespace flood::io_detail
