// Where a FeatureCollection's features begin and end, found by one scan of the bytes, without
// building the document: so parseFeatures can hand slices of a large collection to several
// threads (a 200 MB dataset spends most of its read in the JSON parser). The scan trusts
// nothing: whatever it finds is parsed again, and any doubt returns nothing, which sends the
// text to the one-piece parse whose messages say what is wrong.
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

}  // namespace flood::io_detail
