// Well-known binary polygons (core/io.h): what GEOS, shapely, PostGIS and OGR hand out, read
// without a text round trip. ISO WKB and PostGIS EWKB, either byte order; Polygon and
// MultiPolygon; z and m dropped (ISO 1000/2000/3000 codes, EWKB flags); an EWKB SRID skipped.
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "flood/io/io.h"

namespace flood {

namespace io_detail {
void addCleanRing(ReadResult& rr, const std::string& name, const std::vector<Point>& raw,
                  bool outer);
}

namespace {

constexpr uint32_t kPolygon = 3, kMultiPolygon = 6;
constexpr uint32_t kEwkbZ = 0x80000000u, kEwkbM = 0x40000000u, kEwkbSrid = 0x20000000u;

const char* typeName(uint32_t kind) {
    static const char* const names[] = {
        "Geometry",   "Point",           "LineString",   "Polygon",
        "MultiPoint", "MultiLineString", "MultiPolygon", "GeometryCollection"};
    return kind < 8 ? names[kind] : "an unknown geometry type";
}

uint32_t load32(const char* p, bool little) {
    uint8_t c[4];
    std::memcpy(c, p, 4);
    if (!little) std::swap(c[0], c[3]), std::swap(c[1], c[2]);
    return uint32_t(c[0]) | uint32_t(c[1]) << 8 | uint32_t(c[2]) << 16 | uint32_t(c[3]) << 24;
}

struct Truncated {
    size_t at, need;
};
struct Refused {
    std::string why;
};

class WkbReader {
public:
    explicit WkbReader(std::string_view b) : b_(b) {}

    // The header: byte order, type (returned with z/m/SRID stripped), coordinates per point.
    uint32_t header(int& dims) {
        need(5);
        const uint8_t order = uint8_t(b_[at_]);
        if (order > 1)
            throw Refused{"byte " + std::to_string(at_) + " is " + std::to_string(order) +
                          ", not a byte order (0 or 1)"};
        little_ = order == 1;
        ++at_;
        uint32_t code = u32();
        dims = 2 + int((code & kEwkbZ) != 0) + int((code & kEwkbM) != 0);
        if (code & kEwkbSrid) u32();  // the CRS is the caller's business
        code &= 0x0FFFFFFFu;
        if (const uint32_t iso = code / 1000; iso != 0)
            dims = 2 + int(iso == 1 || iso == 3) + int(iso == 2 || iso == 3);
        return code % 1000;
    }

    uint32_t count() { return u32(); }  // a MultiPolygon's parts, after its header

    void polygon(ReadResult& rr, const std::string& name, int dims) {
        const uint32_t rings = u32();
        std::vector<Point> raw;
        for (uint32_t r = 0; r < rings; ++r) {
            const uint32_t n = u32();
            need(size_t(n) * size_t(dims) * 8);
            raw.resize(n);
            for (uint32_t i = 0; i < n; ++i) {
                raw[i].x = f64();
                raw[i].y = f64();
                at_ += size_t(dims - 2) * 8;
            }
            io_detail::addCleanRing(rr, name, raw, r == 0);
        }
    }

    bool done() const { return at_ == b_.size(); }

private:
    void need(size_t n) const {
        if (b_.size() - at_ < n) throw Truncated{at_, n};
    }
    uint32_t u32() {
        need(4);
        at_ += 4;
        return load32(b_.data() + at_ - 4, little_);
    }
    double f64() {
        uint8_t c[8];
        std::memcpy(c, b_.data() + at_, 8);
        at_ += 8;
        uint64_t u = 0;
        for (int k = 0; k < 8; ++k) u |= uint64_t(c[little_ ? k : 7 - k]) << (8 * k);
        double d;
        std::memcpy(&d, &u, 8);
        return d;
    }

    std::string_view b_;
    size_t at_ = 0;
    bool little_ = true;
};

}  // namespace

bool wkbLike(std::string_view bytes) {
    if (bytes.size() < 5 || uint8_t(bytes[0]) > 1) return false;
    const uint32_t code = load32(bytes.data() + 1, bytes[0] == 1) & 0x0FFFFFFFu;
    return code % 1000 >= 1 && code % 1000 <= 7 && code / 1000 <= 3;
}

ReadResult parseWkb(std::string_view bytes, const std::string& name) {
    ReadResult rr;
    WkbReader in(bytes);
    try {
        int dims = 2;
        const uint32_t kind = in.header(dims);
        if (kind == kPolygon) {
            in.polygon(rr, name, dims);
        } else if (kind == kMultiPolygon) {
            const uint32_t parts = in.count();
            for (uint32_t p = 0; p < parts; ++p) {
                int partDims = 2;
                const uint32_t part = in.header(partDims);
                if (part != kPolygon)
                    throw Refused{std::string("a MultiPolygon holds a ") + typeName(part)};
                in.polygon(rr, name, partDims);
            }
        } else {
            throw Refused{std::string("flood triangulates Polygon and MultiPolygon geometries, "
                                      "not ") +
                          typeName(kind)};
        }
        if (!in.done()) throw Refused{"bytes left over after the geometry"};
    } catch (const Truncated& t) {
        rr.diagnostic = {Status::Malformed, name + ": WKB: truncated: " + std::to_string(t.need) +
                                                " bytes needed at byte " + std::to_string(t.at)};
    } catch (const Refused& r) {
        rr.diagnostic = {Status::Malformed, name + ": WKB: " + r.why};
    }
    if (rr.diagnostic.ok() && rr.polygon.rings.empty())
        rr.diagnostic = {Status::Malformed, name + ": WKB: the polygon is empty (no rings)"};
    return rr;
}

}  // namespace flood
