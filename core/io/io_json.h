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
std::optional<ReadResult> parseJsonFast(std::string_view text, size_t capacity, size_t start,
                                        const std::string& name);

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

// Cleans the ring just appended to `rr.polygon.vertices` at `first`, in place, and records it
// (io_read.cpp).
void cleanLastRing(ReadResult& rr, const std::string& name, Index first, bool outer);

}  // namespace flood::io_detail
