// libFuzzer harness: parsePolygon on arbitrary bytes (GeoJSON, bare ring arrays, WKT).
// The reader must return a diagnostic for anything it cannot read, never crash, hang, leak
// or throw. A successful read must give a structurally consistent Polygon. The fast JSON
// reader, asked to read in pieces at any size, must read what it reads in one.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "flood/io/io.h"
#include "io/io_json.h"

namespace {

bool same(const flood::ReadResult& a, const flood::ReadResult& b) {
    return flood::sameGeometry(a.polygon, b.polygon) && a.warnings == b.warnings &&
           a.warningsOmitted == b.warningsOmitted;
}

// The JSON document, read in one and in pieces (tasks run here, last first).
void piecesReadAsOne(std::string_view text) {
    size_t start = text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
    while (start < text.size() && std::strchr(" \t\r\n", text[start]) && text[start]) ++start;
    if (start == text.size() || (text[start] != '[' && text[start] != '{') ||
        text.find('\0') != std::string_view::npos)
        return;
    const flood::TaskRunner backwards = [](size_t n, const std::function<void(size_t)>& task) {
        for (size_t k = n; k-- > 0;) task(k);
    };
    namespace io = flood::io_detail;
    std::optional<flood::ReadResult> one = io::parseJsonFast(text, text.size(), start, "fuzz");
    std::optional<flood::ReadResult> pieces =
        io::parseJsonFast(text, text.size(), start, "fuzz", backwards, 0);
    if (one.has_value() != pieces.has_value() || (one && !same(*one, *pieces))) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    piecesReadAsOne(text);
    flood::ReadResult r = flood::parsePolygon(text, "fuzz");
    if (!r.diagnostic.ok()) {
        // Bad input must say so with a Malformed status and a message.
        if (r.diagnostic.status != flood::Status::Malformed || r.diagnostic.message.empty())
            std::abort();
        return 0;
    }
    // Structure invariants: rings tile the vertex array, parts tile the rings.
    const flood::Polygon& p = r.polygon;
    size_t v = 0;
    for (const flood::Ring& ring : p.rings) {
        if (ring.first != v) std::abort();
        v += ring.count;
    }
    if (v != p.vertices.size()) std::abort();
    size_t rg = 0;
    for (const flood::Part& part : p.parts) {
        if (part.firstRing != rg || part.ringCount == 0) std::abort();
        rg += part.ringCount;
    }
    if (rg != p.rings.size()) std::abort();
    return 0;
}
