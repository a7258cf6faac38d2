// Where a FeatureCollection's features begin and end, found by one scan of the bytes, without
// building the document: so parseFeatures can hand slices of a large collection to several
// threads (a 200 MB dataset spends most of its read in the JSON parser). And where a large
// geometry's coordinates may be cut, found by a few short scans. The scan trusts
// nothing: whatever it finds is parsed again, and any doubt returns nothing, which sends the
// text to the one-piece parse whose messages say what is wrong.
#include <algorithm>

#include "io/io_json.h"

namespace flood::io_detail {

std::optional<FeatureCut> cutFeatures(std::string_view t) {
    FeatureCut cut;
    bool found = false;
    int depth = 0;
    bool keyNext = false;      // in the root object: the next string is a member's name
    bool featuresKey = false;  // the last member named was "features"
    bool inArray = false;      // between the features array's brackets
    for (size_t i = 0; i < t.size(); ++i) {
        switch (t[i]) {
            case '"': {
                size_t j = i + 1;
                bool escaped = false;
                while (j < t.size() && t[j] != '"') {
                    if (t[j] == '\\') {
                        escaped = true;
                        ++j;
                    }
                    ++j;
                }
                if (j >= t.size()) return std::nullopt;
                if (depth == 1 && keyNext) {
                    // A name with escapes would be decoded by the parser: not ours to judge.
                    if (escaped) return std::nullopt;
                    featuresKey = t.substr(i + 1, j - i - 1) == "features";
                    keyNext = false;
                }
                i = j;
                break;
            }
            case '{':
            case '[':
                if (depth == 0 && t[i] != '{') return std::nullopt;
                if (++depth == 1) keyNext = true;
                if (depth == 2) {
                    if (t[i] == '[' && featuresKey) {
                        if (found) return std::nullopt;  // two "features" arrays: which one wins?
                        found = inArray = true;
                        cut.open = i;
                    }
                    featuresKey = false;
                }
                break;
            case '}':
            case ']':
                if (depth == 0) return std::nullopt;
                if (depth == 2 && inArray) {
                    if (t[i] != ']') return std::nullopt;
                    cut.close = i;
                    inArray = false;
                }
                --depth;
                break;
            case ',':
                if (depth == 1) {
                    keyNext = true;
                    featuresKey = false;
                } else if (depth == 2 && inArray) {
                    cut.commas.push_back(i);
                }
                break;
            default: break;
        }
    }
    if (!found || inArray || depth != 0) return std::nullopt;
    return cut;
}

namespace {

bool space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// Skips white space from i; then expects `word` there: the position after it, or npos.
size_t expect(std::string_view t, size_t i, std::string_view word) {
    while (i < t.size() && space(t[i])) ++i;
    return t.substr(i, word.size()) == word ? i + word.size() : std::string_view::npos;
}

}  // namespace

std::optional<CoordinateCut> cutCoordinates(std::string_view t, int bareDepth, size_t pieces) {
    CoordinateCut cut;
    size_t i = 0;
    if (bareDepth == 3 || bareDepth == 4) {
        cut.depth = bareDepth;
        i = expect(t, 0, "[");
    } else {
        for (std::string_view word : {"{", "\"type\"", ":"})
            if (i != std::string_view::npos) i = expect(t, i, word);
        if (i == std::string_view::npos) return std::nullopt;
        if (size_t m = expect(t, i, "\"MultiPolygon\""); m != std::string_view::npos)
            cut.depth = 4, i = m;
        else if (size_t p = expect(t, i, "\"Polygon\""); p != std::string_view::npos)
            cut.depth = 3, i = p;
        else return std::nullopt;
        for (std::string_view word : {",", "\"coordinates\"", ":", "["})
            if (i != std::string_view::npos) i = expect(t, i, word);
    }
    if (i == std::string_view::npos) return std::nullopt;
    cut.open = i - 1;
    // The last bracket: the array's if the document is what it seems; else the last piece
    // holds what follows the array, and does not parse.
    size_t end = t.size();
    while (end > 0 && space(t[end - 1])) --end;
    if (bareDepth == 0) {
        if (end == 0 || t[end - 1] != '}') return std::nullopt;
        --end;
        while (end > 0 && space(t[end - 1])) --end;
    }
    if (end <= cut.open + 1 || t[end - 1] != ']') return std::nullopt;
    cut.close = end - 1;
    // An element ends in depth - 1 closing brackets and a comma, "]]]," between polygons: a
    // point ends in one, a ring in two, a polygon in three. A run of brackets is read whole.
    const size_t length = cut.close - cut.open;
    size_t from = cut.open + 1;
    for (size_t k = 1; k < pieces; ++k) {
        const size_t target = std::max(from, cut.open + length * k / pieces);
        const size_t limit = cut.open + length * (k + 1) / pieces;
        for (size_t j = target; j < limit && j < cut.close; ++j) {
            if (t[j] != ']') continue;
            size_t before = j;
            while (before > cut.open && space(t[before - 1])) --before;
            if (t[before - 1] == ']') continue;  // inside a run: its start was before target
            int run = 0;
            size_t after = j;
            while (after < cut.close && (t[after] == ']' || space(t[after])))
                run += t[after++] == ']';
            if (run == cut.depth - 1 && t[after] == ',') {
                cut.commas.push_back(after);
                from = after + 1;
                break;
            }
            j = after;
        }
    }
    return cut;
}

}  // namespace flood::io_detail
