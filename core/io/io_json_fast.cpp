// The fast JSON reader: simdjson's On-Demand API (libsimdjson-dev, a Debian package) reads
// the coordinates straight from the text into the polygon, with no document tree: at 10^6
// vertices parsing drops from the most expensive step of `flood triangulate` to a few percent.
//
// It reads only documents it can read in one pass exactly as io_read.cpp's nlohmann reader
// would: bare ring arrays, and GeoJSON objects whose "type" comes before their payload, every
// other member walked and validated like nlohmann validates it. On anything else — a syntax
// error, a structure problem, a warning about a skipped feature, an unusual key order, a
// duplicate key (nlohmann keeps the last), an empty array — it gives up and the nlohmann
// reader runs instead. So every message, with its byte position, is the nlohmann reader's,
// and a document read here reads to the same polygon there (tests/io/json_fast_test.cpp
// compares them).
#include <simdjson.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "io/io_json.h"
#include "io/io_util.h"

namespace flood::io_detail {

namespace {

namespace od = simdjson::ondemand;
static_assert(kReadAhead >= simdjson::SIMDJSON_PADDING,
              "readInputFile must leave simdjson's padding");

class FastReader {
public:
    FastReader(ReadResult& rr, const std::string& name) : rr_(rr), name_(name) {}

    // A bare array of rings (depth 3) or of polygons (depth 4).
    bool bareArray(od::document& doc, int depth) {
        od::array a;
        if (doc.get_array().get(a)) return false;
        return depth == 3 ? rings(a) : polygons(a);
    }
    bool object(od::document& doc) {
        od::object o;
        return !doc.get_object().get(o) && geometry(o, 1);
    }
    // A piece of a coordinates array that cutCoordinates cut: polygons (depth 4) or rings,
    // the first of them a hole of the part before when the piece does not start the array.
    bool piece(od::document& doc, int depth, bool startsArray) {
        od::array a;
        if (doc.get_array().get(a)) return false;
        if (depth == 4) return polygons(a);
        if (!startsArray) rr_.polygon.parts.push_back({0, 0});  // that part's further holes
        return rings(a, startsArray);
    }

private:
    ReadResult& rr_;
    const std::string& name_;

    // A JSON number literal at the front of `s`: its length, or 0 when it is none.
    static size_t literalLength(std::string_view s) {
        size_t i = 0;
        auto digits = [&] {
            size_t from = i;
            while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
            return i > from;
        };
        if (i < s.size() && s[i] == '-') ++i;
        if (i < s.size() && s[i] == '0') ++i;
        else if (!digits()) return 0;
        if (i < s.size() && s[i] == '.' && (++i, !digits())) return 0;
        if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
            ++i;
            if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
            if (!digits()) return 0;
        }
        return i;
    }

    // A coordinate, read as std::from_chars reads it (correctly rounded, like the tree reader's strtod;
    // simdjson 3.0.1's own reading of literals past 19 digits is not: it read
    // 0.1000000000000000055511151231257827 as 4.1e-16). nlohmann reads an integer literal as
    // an integer, so "-0" is +0.0. A value beyond the double range, or a nonzero one below it
    // (from_chars says result_out_of_range for both), is left to the tree reader, which refuses it.
    static bool number(od::value v, double& d) {
        std::string_view token = v.raw_json_token();  // up to the next structural character
        size_t k = literalLength(token);
        if (k == 0 || token.find_first_not_of(" \t\r\n", k) != std::string_view::npos) return false;
        auto [end, error] = readDouble(token.data(), token.data() + k, d);
        if (error != std::errc() || end != token.data() + k) return false;
        if (d == 0 && std::signbit(d) &&
            token.substr(0, k).find_first_of(".eE") == std::string_view::npos)
            d = 0.0;
        return true;
    }

    // [x, y, ...]: further members (z, m) are ignored, as the nlohmann reader ignores them,
    // but must be valid JSON.
    bool point(od::value v) {
        od::array a;
        if (v.get_array().get(a)) return false;
        Point p;
        int k = 0;
        for (auto item : a) {
            od::value e;
            if (item.get(e)) return false;
            if (k == 0 ? !number(e, p.x) : k == 1 ? !number(e, p.y) : !valid(e, 8)) return false;
            ++k;
        }
        if (k < 2) return false;
        rr_.polygon.vertices.push_back(p);
        return true;
    }

    // The ring's points go straight into the polygon, cleaned there (io_read.cpp).
    bool ring(od::value v, bool outer) {
        od::array a;
        if (v.get_array().get(a)) return false;
        const Index first = Index(rr_.polygon.vertices.size());
        for (auto item : a) {
            od::value e;
            if (item.get(e) || !point(e)) return false;
        }
        if (rr_.polygon.vertices.size() == first) return false;  // [] : the nlohmann reader says so
        cleanLastRing(rr_, name_, first, outer);
        return true;
    }

    bool rings(od::array a, bool outer = true) {
        bool any = false;
        for (auto item : a) {
            od::value e;
            if (item.get(e) || !ring(e, outer)) return false;
            outer = false, any = true;
        }
        return any;
    }
    bool rings(od::value v) {
        od::array a;
        return !v.get_array().get(a) && rings(a);
    }

    bool polygons(od::array a) {
        bool any = false;
        for (auto item : a) {
            od::value e;
            if (item.get(e) || !rings(e)) return false;
            any = true;
        }
        return any;
    }

    // Any JSON value, walked to the end so that it is checked as strictly as nlohmann checks
    // it (On-Demand would skip it unchecked). `depth` bounds the recursion.
    static bool valid(od::value v, int depth) {
        if (depth > kMaxJsonDepth) return false;
        od::json_type t;
        if (v.type().get(t)) return false;
        switch (t) {
            case od::json_type::array: {
                od::array a;
                if (v.get_array().get(a)) return false;
                for (auto item : a) {
                    od::value e;
                    if (item.get(e) || !valid(e, depth + 1)) return false;
                }
                return true;
            }
            case od::json_type::object: {
                od::object o;
                if (v.get_object().get(o)) return false;
                for (auto member : o) {
                    od::field f;
                    std::string_view key;
                    if (std::move(member).get(f) || f.unescaped_key().get(key) ||
                        !valid(f.value(), depth + 1))
                        return false;
                }
                return true;
            }
            case od::json_type::number: {
                double d;
                return number(v, d);
            }
            case od::json_type::string: {
                std::string_view s;
                return !v.get_string().get(s);
            }
            case od::json_type::boolean: {
                bool b;
                return !v.get_bool().get(b);
            }
            case od::json_type::null: {
                bool isNull = false;
                return !v.is_null().get(isNull) && isNull;
            }
        }
        return false;
    }

    // A GeoJSON object, as readGeometry() in io_read.cpp reads it.
    bool geometry(od::object o, int depth) {
        if (depth > kMaxJsonDepth) return false;
        std::string type;
        bool typed = false, done = false;
        for (auto member : o) {
            od::field f;
            std::string_view key;
            if (std::move(member).get(f) || f.unescaped_key().get(key)) return false;
            if (key == "type") {
                std::string_view s;
                if (typed || f.value().get_string().get(s)) return false;
                type = s;
                typed = true;
                continue;
            }
            const bool payload = key == "coordinates" || key == "geometry" || key == "features" ||
                                 key == "geometries";
            if (!typed) {
                if (payload) return false;  // "type" after its payload: not in one pass
                if (!valid(f.value(), depth + 1)) return false;
                continue;
            }
            const char* wanted = type == "Polygon" || type == "MultiPolygon" ? "coordinates"
                                 : type == "Feature"                         ? "geometry"
                                 : type == "FeatureCollection"               ? "features"
                                 : type == "GeometryCollection"              ? "geometries"
                                                                             : nullptr;
            if (!wanted) return false;  // unsupported type: the nlohmann reader says so
            if (key != wanted) {
                if (!valid(f.value(), depth + 1)) return false;
                continue;
            }
            if (done) return false;  // a duplicate payload: nlohmann keeps the last one
            done = true;
            bool ok = type == "Polygon"        ? rings(f.value())
                      : type == "MultiPolygon" ? multi(f.value())
                      : type == "Feature"
                          ? nested(f.value(), depth + 1)
                          : collection(f.value(), type == "FeatureCollection", depth + 1);
            if (!ok) return false;
        }
        return done;
    }

    bool multi(od::value v) {
        od::array a;
        return !v.get_array().get(a) && polygons(a);
    }
    bool nested(od::value v, int depth) {
        od::object o;
        return !v.get_object().get(o) && geometry(o, depth);
    }

    // Features or geometries. A feature's own "type" is not looked at (nor is it by the
    // nlohmann reader); a non-polygonal one is skipped there with a warning: not here.
    bool collection(od::value v, bool features, int depth) {
        od::array a;
        if (v.get_array().get(a)) return false;
        for (auto item : a) {
            od::value e;
            if (item.get(e)) return false;
            if (!features) {
                if (!nested(e, depth + 1)) return false;
                continue;
            }
            od::object feature;
            if (e.get_object().get(feature)) return false;
            bool seen = false;
            for (auto member : feature) {
                od::field f;
                std::string_view key;
                if (std::move(member).get(f) || f.unescaped_key().get(key)) return false;
                if (key != "geometry") {
                    if (!valid(f.value(), depth + 2)) return false;
                    continue;
                }
                if (seen || !nested(f.value(), depth + 2)) return false;
                seen = true;
            }
            if (!seen) return false;
        }
        return true;
    }
};

// Nesting depth of a bare array as the nlohmann reader's arrayDepth() finds it, when the
// first innermost member is a number; 0 otherwise (the nlohmann reader decides).
int leadingArrayDepth(std::string_view text, size_t i) {
    int depth = 0;
    for (; i < text.size(); ++i) {
        char c = text[i];
        if (c == '[') ++depth;
        else if (c != ' ' && c != '\t' && c != '\r' && c != '\n') break;
    }
    return i < text.size() && (text[i] == '-' || (text[i] >= '0' && text[i] <= '9')) ? depth : 0;
}

}  // namespace

// The pieces a document is read in (each a task). Each is copied to be parsed, and its parser
// indexes it, so a piece larger than a quarter of the document (a ring that is most of it)
// would need more memory than reading it in one: such a document is read in one.
constexpr size_t kPieces = 16;

std::optional<ReadResult> parsePieces(std::string_view doc, int bareDepth, const std::string& name,
                                      const TaskRunner& run) {
    const std::optional<CoordinateCut> cut = cutCoordinates(doc, bareDepth, kPieces);
    if (!cut || cut->commas.empty()) return std::nullopt;
    std::vector<size_t> bounds{cut->open};
    bounds.insert(bounds.end(), cut->commas.begin(), cut->commas.end());
    bounds.push_back(cut->close);
    for (size_t k = 0; k + 1 < bounds.size(); ++k)
        if (bounds[k + 1] - bounds[k] > doc.size() / 4) return std::nullopt;
    std::vector<ReadResult> pieces(bounds.size() - 1);
    std::vector<char> read(pieces.size(), 0);
    run(pieces.size(), [&](size_t k) {
        // The piece's elements, bracketed: an array of its own, padded as simdjson reads.
        const std::string_view inside = doc.substr(bounds[k] + 1, bounds[k + 1] - bounds[k] - 1);
        std::string text;
        text.reserve(inside.size() + 2 + simdjson::SIMDJSON_PADDING);
        text.append(1, '[').append(inside).append(1, ']');
        od::parser parser;
        od::document json;
        if (parser.iterate(simdjson::padded_string_view(text.data(), text.size(), text.capacity()))
                .get(json))
            return;
        ReadResult& rr = pieces[k];
        try {
            rr.polygon.vertices.reserve(inside.size() / 6 + 1);
            FastReader reader(rr, name);
            const bool whole = reader.piece(json, cut->depth, k == 0);
            const bool atEnd = json.current_location().error() == simdjson::OUT_OF_BOUNDS;
            read[k] = whole && atEnd && rr.warnings.empty() && rr.warningsOmitted == 0;
        } catch (const std::bad_alloc&) {
            // read[k] stays 0: the document is read in one, which reports it
        }
    });
    for (char r : read)
        if (!r) return std::nullopt;
    ReadResult rr;
    size_t vertices = 0;
    for (const ReadResult& piece : pieces) vertices += piece.polygon.vertices.size();
    rr.polygon.vertices.reserve(vertices);
    for (ReadResult& piece : pieces) {
        Polygon& p = piece.polygon;
        const Index vertexBase = Index(rr.polygon.vertices.size());
        const Index ringBase = Index(rr.polygon.rings.size());
        rr.polygon.vertices.insert(rr.polygon.vertices.end(), p.vertices.begin(), p.vertices.end());
        for (const Ring& g : p.rings) rr.polygon.rings.push_back({g.first + vertexBase, g.count});
        size_t part = 0;
        if (cut->depth == 3 && &piece != &pieces.front())  // holes of the part before
            rr.polygon.parts.back().ringCount += p.parts[part++].ringCount;
        for (; part < p.parts.size(); ++part)
            rr.polygon.parts.push_back(
                {p.parts[part].firstRing + ringBase, p.parts[part].ringCount});
        p = {};  // given back as the whole grows
    }
    return rr;
}

std::optional<ReadResult> parseJsonFast(std::string_view text, size_t capacity, size_t start,
                                        const std::string& name, const TaskRunner& run,
                                        size_t piecesFrom) {
    const int depth = text[start] == '[' ? leadingArrayDepth(text, start) : 0;
    if (text[start] == '[' && depth != 3 && depth != 4) return std::nullopt;
    if (run && text.size() - start >= piecesFrom)
        if (std::optional<ReadResult> pieces = parsePieces(text.substr(start), depth, name, run))
            return pieces;
    // On-Demand reads up to SIMDJSON_PADDING bytes past the end: a text without that much
    // spare capacity (a caller's string_view) is copied once.
    std::optional<simdjson::padded_string> copy;
    simdjson::padded_string_view view;
    // From the first bracket: simdjson refuses a byte order mark.
    const std::string_view doc = text.substr(start);
    if (capacity >= text.size() + simdjson::SIMDJSON_PADDING) {
        view = simdjson::padded_string_view(doc.data(), doc.size(), capacity - start);
    } else {
        copy.emplace(doc.data(), doc.size());
        view = *copy;
    }
    od::parser parser;
    od::document json;
    if (parser.iterate(view).get(json)) return std::nullopt;
    ReadResult rr;
    try {
        // Room for every point the text could hold ("[0,0]," is 6 bytes): pages never written
        // are never resident, and the vector is never moved while it grows. The caller gives
        // back the rest once the text is gone (parseText in io_read.cpp).
        rr.polygon.vertices.reserve(doc.size() / 6 + 1);
        FastReader reader(rr, name);
        bool ok = depth ? reader.bareArray(json, depth) : reader.object(json);
        // Past the last token (nothing trails the document), the location is out of bounds.
        const bool atEnd = json.current_location().error() == simdjson::OUT_OF_BOUNDS;
        if (!ok || !atEnd || rr.polygon.rings.empty()) return std::nullopt;
    } catch (const std::bad_alloc&) {
        return std::nullopt;  // the nlohmann reader reports it
    }
    return rr;
}

}  // namespace flood::io_detail
