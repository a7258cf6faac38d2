// libFuzzer harness: parsePolygon on arbitrary bytes (GeoJSON, bare ring arrays, WKT).
// The reader must return a diagnostic for anything it cannot read, never crash, hang, leak
// or throw. A successful read must give a structurally consistent Polygon.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "flood/io/io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
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
