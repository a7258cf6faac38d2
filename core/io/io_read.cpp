// Reading polygons: format detection, GeoJSON and bare ring arrays (earcut fixtures).
// WKT lives in io_wkt.cpp. Every problem becomes a Malformed diagnostic, never an exception
// escaping to the caller and never a crash.
//
// JSON is read first by the fast reader (io_json_fast.cpp, simdjson, no document tree); what
// it cannot read as this file would goes through nlohmann::json here: a Debian package
// (nlohmann-json3-dev), header-only, whose parse errors carry the byte position, which we turn
// into NAME:LINE:COL. So nlohmann stays as the reader that explains failures, and for datasets
// (`flood check`), whose per-feature properties want a tree. Its parser is recursive, so
// nesting depth is bounded by a cheap bracket scan first.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <new>
#include <nlohmann/json.hpp>
#include <optional>

#include "flood/io/io.h"
#include "io/io_json.h"
#include "io/io_util.h"

namespace flood {

// Defined in io_wkt.cpp.
ReadResult parseWkt(std::string_view text, const std::string& name);

namespace io_detail {

// The ring's points as read are at `first`: repeated consecutive points are dropped with a warning, then a
// closing point equal to the first is dropped silently.
void cleanLastRing(ReadResult& rr, const std::string& name, Index first, bool outer) {
    const size_t ring = rr.polygon.rings.size();
    std::vector<Point>& v = rr.polygon.vertices;
    const size_t count = v.size() - first;
    size_t kept = 0;  // the cleaned points are v[first, first + kept): never ahead of the raw ones
    for (size_t i = 0; i < count; ++i) {
        const Point p = v[first + i];
        if (kept && p == v[first + kept - 1]) {
            // The last point repeating the first is a closing point, not a duplicate (also
            // of a point hole, written [p, p]).
            if (i + 1 == count && (kept > 1 || i == 1) && p == v[first]) continue;
            rr.warn([&] {
                return name + ": ring " + std::to_string(ring) + " vertex " + std::to_string(i) +
                       " " + formatPoint(p) + ": repeated point dropped";
            });
            continue;
        }
        v[first + kept++] = p;
    }
    if (kept >= 2 && v[first + kept - 1] == v[first]) --kept;
    v.resize(first + kept);
    if (outer) rr.polygon.parts.push_back({Index(rr.polygon.rings.size()), 0});
    rr.polygon.rings.push_back({first, Index(kept)});
    rr.polygon.parts.back().ringCount++;
}

void addCleanRing(ReadResult& rr, const std::string& name, const std::vector<Point>& raw,
                  bool outer) {
    const Index first = Index(rr.polygon.vertices.size());
    rr.polygon.vertices.insert(rr.polygon.vertices.end(), raw.begin(), raw.end());
    cleanLastRing(rr, name, first, outer);
}

}  // namespace io_detail

namespace {

using io_detail::echo;
using io_detail::jsonReason;
using io_detail::kMaxJsonDepth;
using io_detail::tooDeep;
using io_detail::where;
using nlohmann::json;

struct BadStructure {
    std::string message;
};

Point readVertex(const json& v, const std::string& ctx) {
    if (!v.is_array() || v.size() < 2 || !v[0].is_number() || !v[1].is_number())
        throw BadStructure{ctx + ": coordinate is not a pair of numbers (got " + echo(v.dump()) +
                           ")"};
    return {v[0].get<double>(), v[1].get<double>()};
}

void readRings(ReadResult& rr, const std::string& name, const json& rings, const std::string& ctx) {
    if (!rings.is_array()) throw BadStructure{ctx + ": polygon is not an array of rings"};
    if (rings.empty()) throw BadStructure{ctx + ": polygon has no rings"};
    for (size_t r = 0; r < rings.size(); ++r) {
        std::string rctx = ctx + " ring " + std::to_string(r);
        const json& ring = rings[r];
        if (!ring.is_array()) throw BadStructure{rctx + ": ring is not an array of points"};
        std::vector<Point> raw;
        raw.reserve(ring.size());
        for (size_t v = 0; v < ring.size(); ++v)
            raw.push_back(readVertex(ring[v], rctx + " vertex " + std::to_string(v)));
        io_detail::addCleanRing(rr, name, raw, r == 0);
    }
}

// Depth of nested arrays at the front of `j`: 1 for [x,...], 2 for a ring, 3 for a polygon.
// An empty array ends the descent early ([] has no rings, [[]] is a ring with no points):
// such a document is read as a polygon, so the message says what is missing.
int arrayDepth(const json& j) {
    int d = 0;
    const json* p = &j;
    while (p->is_array() && !p->empty()) {
        ++d;
        p = &(*p)[0];
    }
    return p->is_array() ? std::max(d, 3) : d;
}

void readGeometry(ReadResult& rr, const std::string& name, const json& g, const std::string& ctx,
                  int& polygonCount);

void readPolygonOrMulti(ReadResult& rr, const std::string& name, const json& coords, bool multi,
                        const std::string& ctx, int& polygonCount) {
    if (!multi) {
        readRings(rr, name, coords, ctx + "polygon " + std::to_string(polygonCount++));
        return;
    }
    if (!coords.is_array()) throw BadStructure{ctx + "multipolygon is not an array of polygons"};
    for (const json& poly : coords)
        readRings(rr, name, poly, ctx + "polygon " + std::to_string(polygonCount++));
}

void readGeometry(ReadResult& rr, const std::string& name, const json& g, const std::string& ctx,
                  int& polygonCount) {
    if (!g.is_object() || !g.contains("type") || !g["type"].is_string())
        throw BadStructure{ctx + "GeoJSON object without a \"type\" string"};
    const std::string type = g["type"].get<std::string>();
    if (type == "Polygon" || type == "MultiPolygon") {
        if (!g.contains("coordinates")) throw BadStructure{ctx + type + " without \"coordinates\""};
        readPolygonOrMulti(rr, name, g["coordinates"], type == "MultiPolygon", ctx, polygonCount);
    } else if (type == "Feature") {
        if (!g.contains("geometry") || g["geometry"].is_null())
            throw BadStructure{ctx + "Feature without geometry"};
        readGeometry(rr, name, g["geometry"], ctx, polygonCount);
    } else if (type == "FeatureCollection" || type == "GeometryCollection") {
        const char* key = type == "FeatureCollection" ? "features" : "geometries";
        if (!g.contains(key) || !g[key].is_array())
            throw BadStructure{ctx + type + " without a \"" + key + "\" array"};
        const json& items = g[key];
        for (size_t i = 0; i < items.size(); ++i) {
            const json& item = items[i];
            const json* geom = &item;
            if (type == "FeatureCollection") {
                if (!item.is_object() || !item.contains("geometry"))
                    throw BadStructure{ctx + "feature " + std::to_string(i) +
                                       ": not a Feature with a geometry"};
                geom = &item["geometry"];
            }
            std::string gtype =
                geom->is_object() && geom->contains("type") && (*geom)["type"].is_string()
                    ? echo((*geom)["type"].get<std::string>())
                    : std::string();
            bool polygonal = gtype == "Polygon" || gtype == "MultiPolygon" ||
                             gtype == "GeometryCollection" || gtype == "Feature";
            if (!polygonal) {
                rr.warn([&] {
                    return name + ": " + ctx +
                           (type == "FeatureCollection" ? "feature " : "geometry ") +
                           std::to_string(i) + ": not polygonal (" +
                           (gtype.empty() ? "null" : gtype) + "), skipped";
                });
                continue;
            }
            // Its polygons numbered within it, as `flood check` reads each feature alone: the
            // place named is one the user finds in that feature.
            int itemPolygons = 0;
            readGeometry(rr, name, *geom,
                         ctx + (type == "FeatureCollection" ? "feature " : "geometry ") +
                             std::to_string(i) + " ",
                         itemPolygons);
        }
    } else {
        throw BadStructure{ctx + "unsupported GeoJSON type \"" + echo(type) +
                           "\" (expected Polygon, MultiPolygon, Feature or FeatureCollection)"};
    }
}

}  // namespace

ReadResult io_detail::parseJsonTree(std::string_view text, const std::string& name) {
    ReadResult rr;
    size_t deep = tooDeep(text);
    if (deep != std::string_view::npos) {
        rr.diagnostic = {Status::Malformed, where(name, text, deep) + ": JSON nested deeper than " +
                                                std::to_string(kMaxJsonDepth) +
                                                " levels; refusing to parse"};
        return rr;
    }
    json doc;
    try {
        doc = json::parse(text.begin(), text.end());
    } catch (const json::parse_error& e) {
        // e.byte is the 1-based position of the last character read.
        size_t off = e.byte > 0 ? e.byte - 1 : 0;
        rr.diagnostic = {Status::Malformed,
                         where(name, text, off) + ": JSON syntax error: " + jsonReason(e.what())};
        return rr;
    } catch (const json::out_of_range& e) {
        // A number literal beyond the double range (e.g. 1e999): nlohmann gives no position,
        // only the literal in quotes; find it in the text (found by fuzz_read).
        std::string w = e.what();
        size_t q1 = w.find('\''), q2 = q1 == std::string::npos ? q1 : w.find('\'', q1 + 1);
        std::string literal = q2 == std::string::npos ? "" : w.substr(q1 + 1, q2 - q1 - 1);
        size_t at = literal.empty() ? std::string_view::npos : text.find(literal);
        rr.diagnostic = {Status::Malformed,
                         (at == std::string_view::npos ? name : where(name, text, at)) +
                             ": number out of range: " + echo(literal.empty() ? w : literal) +
                             " does not fit a double"};
        return rr;
    } catch (const json::exception& e) {  // any other nlohmann failure: never escape
        rr.diagnostic = {Status::Malformed, name + ": JSON error: " + jsonReason(e.what())};
        return rr;
    }
    // nlohmann reads a literal below the doubles (1e-400) as 0, where it refuses 1e400.
    if (size_t at = firstUnderflow(text); at != std::string_view::npos) {
        rr.diagnostic = {Status::Malformed,
                         where(name, text, at) + ": " + underflowReason(literalAt(text, at))};
        return rr;
    }
    try {
        int polygonCount = 0;
        if (doc.is_object()) {
            readGeometry(rr, name, doc, "", polygonCount);
        } else {
            int d = arrayDepth(doc);
            if (d == 3) readRings(rr, name, doc, "polygon 0");
            else if (d == 4) readPolygonOrMulti(rr, name, doc, true, "", polygonCount);
            else
                throw BadStructure{
                    "expected an array of rings [[[x,y],...],...] or of polygons "
                    "[[[[x,y],...],...],...], or a GeoJSON object"};
        }
        if (rr.polygon.rings.empty()) throw BadStructure{"no polygon found"};
    } catch (const BadStructure& b) {
        rr.polygon = Polygon{};
        rr.diagnostic = {Status::Malformed, name + ": " + b.message};
    } catch (const json::exception& e) {  // e.g. a number too large for the conversion
        rr.polygon = Polygon{};
        rr.diagnostic = {Status::Malformed, name + ": " + e.what()};
    }
    return rr;
}

namespace {

// `capacity` is how many bytes from text.data() may be read (the fast reader reads ahead).
ReadResult parseText(std::string_view text, size_t capacity, const std::string& name,
                     const TaskRunner& run = {}) {
    size_t nul = text.find('\0');
    if (nul != std::string_view::npos) {
        ReadResult rr;
        rr.diagnostic = {Status::Malformed, io_detail::binaryData(name, nul, "GeoJSON or WKT")};
        return rr;
    }
    size_t i = 0;
    if (text.substr(0, 3) == "\xEF\xBB\xBF") i = 3;  // UTF-8 byte order mark
    while (i < text.size() && std::strchr(" \t\r\n", text[i])) ++i;
    if (i == text.size()) {
        ReadResult rr;
        rr.diagnostic = {Status::Malformed, name + ":1:1: empty input, no polygon"};
        return rr;
    }
    if (text[i] == '[' || text[i] == '{') {
        if (std::optional<ReadResult> fast = io_detail::parseJsonFast(text, capacity, i, name, run))
            return std::move(*fast);
        return io_detail::parseJsonTree(text, name);
    }
    return parseWkt(text, name);
}

}  // namespace

ReadResult parsePolygon(std::string_view text, const std::string& name, const TaskRunner& run) {
    ReadResult rr = parseText(text, text.size(), name, run);
    rr.polygon.vertices.shrink_to_fit();
    return rr;
}

// POSIX reads, not iostreams: they give the system's reason (errno) for each failure.
// The input so far (`text`, then `k` bytes of `buf`) starts with `magic`.
static bool binaryMagicAt(const std::string& text, const char* buf, size_t k, const char* magic) {
    if (!magic) return false;
    const size_t m = std::strlen(magic);
    std::string head = text.substr(0, m);
    if (head.size() < m) head.append(buf, std::min(k, m - head.size()));
    return head == magic;
}

Diagnostic readInputFile(const std::string& path, std::string& text, uint64_t maxBytes,
                         const char* expected, const char* binaryMagic, ReadProgress* progress) {
    text.clear();
    const std::string name = path == "-" ? "<stdin>" : path;
    const int fd = path == "-" ? STDIN_FILENO : ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return {Status::Malformed, name + ": cannot open file: " + std::strerror(errno)};
    struct Closer {
        int fd;
        ~Closer() {
            if (fd != STDIN_FILENO) ::close(fd);
        }
    } closer{fd};
    struct stat st = {};
    if (::fstat(fd, &st) == 0) {
        if (S_ISDIR(st.st_mode)) return {Status::Malformed, name + ": is a directory, not a file"};
        if (S_ISREG(st.st_mode) && uint64_t(st.st_size) > maxBytes)
            return {Status::Malformed, name + ": input is larger than the limit of " +
                                           std::to_string(maxBytes) + " bytes (--max-input-bytes)"};
    }
    try {
        // The padding lets the fast JSON reader read ahead without a copy of the text.
        if (S_ISREG(st.st_mode)) text.reserve(size_t(st.st_size) + io_detail::kReadAhead);
        if (progress && S_ISREG(st.st_mode)) {
            progress->bytesTotal += uint64_t(st.st_size);
            progress->tell();
        }
        char buf[1 << 16];
        for (;;) {
            ssize_t k = ::read(fd, buf, sizeof buf);
            if (k < 0 && errno == EINTR) continue;
            if (k < 0)
                return {Status::Malformed, name + ": read error after " +
                                               std::to_string(text.size()) +
                                               " bytes: " + std::strerror(errno)};
            if (k == 0) break;
            if (const void* z = binaryMagicAt(text, buf, size_t(k), binaryMagic)
                                    ? nullptr
                                    : std::memchr(buf, 0, size_t(k)))
                return {
                    Status::Malformed,
                    io_detail::binaryData(
                        name, text.size() + size_t(static_cast<const char*>(z) - buf), expected)};
            if (text.size() + uint64_t(k) > maxBytes)
                return {Status::Malformed, name + ": input is larger than the limit of " +
                                               std::to_string(maxBytes) +
                                               " bytes (--max-input-bytes); stopped reading"};
            text.append(buf, size_t(k));
            if (progress) {
                progress->bytesRead += uint64_t(k);
                progress->tell();
            }
        }
    } catch (const std::bad_alloc&) {
        size_t got = text.size();
        text = std::string();
        return {Status::Malformed, name + ": out of memory after reading " + std::to_string(got) +
                                       " bytes (a lower --max-input-bytes refuses it sooner)"};
    }
    return {};
}

ReadResult readPolygonFile(const std::string& path, uint64_t maxBytes, ReadProgress* progress,
                           const TaskRunner& run) {
    std::string text;
    Diagnostic d = readInputFile(path, text, maxBytes, "GeoJSON or WKT", nullptr, progress);
    if (!d.ok()) {
        ReadResult rr;
        rr.diagnostic = d;
        return rr;
    }
    if (text.capacity() < text.size() + io_detail::kReadAhead)
        text.reserve(text.size() + io_detail::kReadAhead);
    ReadResult rr = parseText(text, text.capacity(), path == "-" ? "<stdin>" : path, run);
    // The vertices' spare room is given back after the text, so the two copies of them that
    // shrinking makes never coexist with it.
    std::string().swap(text);
    rr.polygon.vertices.shrink_to_fit();
    return rr;
}

// Splitting a dataset for `flood check`. Only a document that mentions "FeatureCollection"
// is parsed here; everything else (and any document that fails to parse) goes to
// parsePolygon as a whole, so its messages are exactly those of the other commands.
namespace {

// A property echoed into the report: strings as they are, other values as JSON text.
std::string propertyText(const json& v) {
    return echo(v.is_string() ? v.get<std::string>() : v.dump());
}

FeatureRead readFeature(const std::string& name, const json& item, size_t i, int64_t fid,
                        bool keepSource) {
    FeatureRead f;
    f.wholeFile = false;
    f.index = i;
    f.fid = fid;
    const std::string ctx = "feature " + std::to_string(fid);
    try {
        if (item.is_object() && item.contains("id") && !item["id"].is_null())
            f.id = propertyText(item["id"]);
        // "name", else "NAME" (Natural Earth's), as GDAL finds a field by name in any case.
        if (item.is_object() && item.contains("properties") && item["properties"].is_object())
            for (const char* key : {"name", "NAME"})
                if (f.name.empty() && item["properties"].contains(key) &&
                    !item["properties"][key].is_null())
                    f.name = propertyText(item["properties"][key]);
        if (item.is_object() && item.contains("properties") && item["properties"].is_object())
            for (const auto& [key, value] : item["properties"].items())
                if (!value.is_null()) f.attributes.emplace_back(echo(key), propertyText(value));
        if (keepSource) f.source = item.dump();
        if (!item.is_object() || !item.contains("geometry"))
            throw BadStructure{ctx + ": not a Feature with a geometry"};
        int polygonCount = 0;
        readGeometry(f.read, name, item["geometry"], ctx + " ", polygonCount);
        io_detail::nameFeature(f.read.warnings, name, ctx);
        if (f.read.polygon.rings.empty()) throw BadStructure{ctx + ": no polygon found"};
    } catch (const BadStructure& b) {
        f.read.polygon = Polygon{};
        f.read.diagnostic = {Status::Malformed, name + ": " + b.message};
    } catch (const json::exception& e) {
        f.read.polygon = Polygon{};
        f.read.diagnostic = {Status::Malformed, name + ": " + ctx + ": " + jsonReason(e.what())};
    }
    return f;
}

// As parsePolygon decides: a missing geometry is malformed (reported), a null or other one skipped.
bool polygonal(const json& item) {
    if (!item.is_object() || !item.contains("geometry")) return true;
    const json& g = item["geometry"];
    if (!g.is_object() || !g.contains("type") || !g["type"].is_string()) return false;
    const std::string t = g["type"].get<std::string>();
    return t == "Polygon" || t == "MultiPolygon" || t == "GeometryCollection" || t == "Feature";
}

// The FID GDAL's GeoJSON driver gives each feature: its "id" when every feature has an integer
// one and no two the same, else its position. So a feature is the same number whichever
// reader reads the file (--where and --feature read it through GDAL).
std::vector<int64_t> gdalFids(const json& items) {
    std::vector<int64_t> ids;
    for (const json& item : items) {
        if (!item.is_object() || !item.contains("id") || !item["id"].is_number_integer()) break;
        ids.push_back(item["id"].get<int64_t>());
    }
    std::vector<int64_t> sorted = ids;
    std::sort(sorted.begin(), sorted.end());
    if (ids.size() == items.size() &&
        std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end())
        return ids;
    ids.resize(items.size());
    for (size_t i = 0; i < ids.size(); ++i) ids[i] = int64_t(i);
    return ids;
}

}  // namespace

// A GeoJSON text sequence (RFC 8142; GDAL's GeoJSONSeq, .geojsonl/.geojsons; what
// `ogr2ogr -f GeoJSONSeq /vsistdout/` pipes): a Feature per line, or after each record
// separator (0x1E). The features as an array, or null when `text` is not one: fewer than two
// records without a separator, or a record that is not a Feature (then the text is read as
// one document, and its reader's message says what is wrong).
json featureSequence(std::string_view text) {
    const bool separated = text.find('\x1e') != std::string_view::npos;
    const char cut = separated ? '\x1e' : '\n';
    std::vector<std::string_view> records;
    for (size_t pos = 0; pos <= text.size();) {
        size_t end = text.find(cut, pos);
        if (end == std::string_view::npos) end = text.size();
        std::string_view record = text.substr(pos, end - pos);
        pos = end + 1;
        if (record.find_first_not_of(" \t\r\n") != std::string_view::npos)
            records.push_back(record);
    }
    // Counted first: a document on one line is not parsed twice.
    if (records.empty() || (!separated && records.size() < 2)) return nullptr;
    json items = json::array();
    for (std::string_view record : records) {
        if (tooDeep(record) != std::string_view::npos) return nullptr;
        json f = json::parse(record.begin(), record.end(), nullptr, false);
        if (!f.is_object() || !f.contains("type") || f["type"] != "Feature") return nullptr;
        items.push_back(std::move(f));
    }
    return items;
}

namespace {

// The "features" array of a FeatureCollection document, or null when `doc` is not one (or was
// discarded by a failed parse).
json* featuresOf(json& doc) {
    if (!doc.is_object() || !doc.contains("type") || doc["type"] != "FeatureCollection" ||
        !doc.contains("features") || !doc["features"].is_array())
        return nullptr;
    return &doc["features"];
}

// A slice of the features array is at least this long (64 KiB), and there are at most
// kMaxSlices: enough for the threads to share, each copied alone while it is parsed.
constexpr size_t kSliceBytes = size_t(1) << 16;
constexpr size_t kMaxSlices = 256;
// The features are made polygons in about this many tasks (a feature is one at least): a
// dataset's largest feature can be many times its average.
constexpr size_t kConvertTasks = 1024;

// Counts each Feature object closing at `depth` (the features array's elements) as the parser
// meets it: the parse is most of a large file's read.
json::parser_callback_t featureCounter(ReadProgress* progress, int depth) {
    if (!progress) return nullptr;
    return [progress, depth](int d, json::parse_event_t event, json&) {
        if (d == depth && event == json::parse_event_t::object_end) {
            ++progress->featuresParsed;
            progress->tell();
        }
        return true;
    };
}

// The features of a FeatureCollection parsed in slices, as tasks of `run`: the document
// around the array with the array emptied, then each slice of elements as an array of its
// own. Null when any piece fails, or is not what the one-piece parse would find: that parse
// then runs and says why. Valid JSON cut at its array's commas gives valid pieces, and valid
// pieces put back together give the same document.
json parseInSlices(std::string_view text, const std::optional<io_detail::FeatureCut>& cut,
                   ReadProgress* progress, const TaskRunner& run) {
    if (!cut) return nullptr;
    std::string around;
    around.reserve(text.size() - (cut->close - cut->open) + 1);
    around.append(text.substr(0, cut->open + 1)).append(text.substr(cut->close));
    json doc = json::parse(around, nullptr, false);
    const json* emptied = featuresOf(doc);
    if (!emptied || !emptied->empty()) return nullptr;
    std::vector<size_t> bounds{cut->open};
    const size_t step = std::max(kSliceBytes, (cut->close - cut->open) / kMaxSlices);
    for (size_t comma : cut->commas)
        if (comma - bounds.back() >= step) bounds.push_back(comma);
    bounds.push_back(cut->close);
    std::vector<json> slices(bounds.size() - 1);
    run(slices.size(), [&](size_t k) {
        std::string piece = "[";
        piece.append(text.substr(bounds[k] + 1, bounds[k + 1] - bounds[k] - 1)).push_back(']');
        slices[k] = json::parse(piece, featureCounter(progress, 1), false);
    });
    size_t count = 0;
    for (const json& slice : slices) {
        if (slice.is_discarded() || !slice.is_array() || slice.empty()) return nullptr;
        count += slice.size();
    }
    json items = json::array();
    items.get_ref<json::array_t&>().reserve(count);
    for (json& slice : slices)
        for (json& item : slice) items.push_back(std::move(item));
    return items;
}

}  // namespace

DatasetRead parseFeatures(std::string_view text, const std::string& name, bool keepSource,
                          ReadProgress* progress, const TaskRunner& run) {
    DatasetRead out;
    auto whole = [&] {
        FeatureRead f;
        f.read = parsePolygon(text, name);
        out.features.push_back(std::move(f));
        return std::move(out);
    };
    if (text.find("\"Feature") == std::string_view::npos ||
        text.find('\0') != std::string_view::npos)
        return whole();
    // The scans of the whole text, at once when there are threads.
    const size_t npos = std::string_view::npos;
    size_t underflow = npos, deep = npos;
    std::optional<io_detail::FeatureCut> cut;
    if (run) {
        run(3, [&](size_t k) {
            if (k == 0) underflow = io_detail::firstUnderflow(text);
            else if (k == 1) deep = tooDeep(text);
            else cut = io_detail::cutFeatures(text);
        });
    } else {
        underflow = io_detail::firstUnderflow(text);
    }
    if (underflow != npos) return whole();  // as 1e400
    json items = featureSequence(text);
    if (items.is_null()) {
        if (text.find("\"FeatureCollection\"") == npos || (run ? deep : tooDeep(text)) != npos)
            return whole();
        if (run) items = parseInSlices(text, cut, progress, run);
        if (items.is_null()) {
            json doc = json::parse(text.begin(), text.end(), featureCounter(progress, 2), false);
            json* features = featuresOf(doc);
            if (!features || features->empty()) return whole();  // parsePolygon says why
            items = std::move(*features);
        }
    }
    const std::vector<int64_t> fid = gdalFids(items);
    // Each range of features on its own, then in order: the same lists for any `run`. Each
    // feature's tree is freed once read, by the task that read it: freeing a large document
    // is a good part of its parse's time.
    const size_t count = items.size();
    const size_t per = std::max<size_t>(1, run ? count / kConvertTasks : count);
    const size_t tasks = std::max<size_t>(1, (count + per - 1) / per);
    std::vector<DatasetRead> parts(tasks);
    auto convert = [&](size_t k) {
        for (size_t i = k * per; i < std::min(count, (k + 1) * per); ++i) {
            const json& item = items[i];
            if (polygonal(item)) {
                parts[k].features.push_back(readFeature(name, item, i, fid[i], keepSource));
                if (progress) {
                    ++progress->featuresRead;
                    progress->tell();
                }
            } else {
                const json& g = item["geometry"];
                std::string type = g.is_object() && g.contains("type") && g["type"].is_string()
                                       ? echo(g["type"].get<std::string>())
                                       : "null";
                parts[k].skipped.push_back(name + ": feature " + std::to_string(fid[i]) +
                                           ": not polygonal (" + type + "), skipped");
            }
            items[i] = nullptr;
        }
    };
    if (run) run(tasks, convert);
    else convert(0);
    for (DatasetRead& part : parts) {
        for (FeatureRead& f : part.features) out.features.push_back(std::move(f));
        for (std::string& s : part.skipped) out.skipped.push_back(std::move(s));
    }
    if (out.features.empty()) return whole();  // "no polygon found"
    return out;
}

DatasetRead readFeaturesFile(const std::string& path, uint64_t maxBytes, bool keepSource,
                             ReadProgress* progress, const TaskRunner& run) {
    std::string text;
    Diagnostic d = readInputFile(path, text, maxBytes, "GeoJSON or WKT", nullptr, progress);
    if (!d.ok()) {
        DatasetRead out;
        out.features.emplace_back();
        out.features.back().read.diagnostic = d;
        return out;
    }
    return parseFeatures(text, path == "-" ? "<stdin>" : path, keepSource, progress, run);
}

}  // namespace flood
