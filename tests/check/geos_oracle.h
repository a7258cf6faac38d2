// GEOS 3.11 (C API) as a test oracle for validate(): the same geometry, built from the same
// doubles through GEOS's coordinate sequences, judged by GEOSisValid_r. Only the test suite
// links GEOS (tests/CMakeLists.txt); the product never does.
#pragma once
#include <geos_c.h>

#include <string>
#include <vector>

#include "flood/geometry/polygon.h"

namespace flood::testing {

class GeosOracle {
public:
    GeosOracle() : h_(GEOS_init_r()) {}
    ~GeosOracle() { GEOS_finish_r(h_); }
    GeosOracle(const GeosOracle&) = delete;
    GeosOracle& operator=(const GeosOracle&) = delete;

    struct Verdict {
        bool valid = false;
        std::string reason;  // GEOSisValidReason_r's text
    };

    // Every ring closed by repeating its first point; one Polygon per part, a MultiPolygon
    // when there are several. Rings need at least 3 points (GEOS cannot build fewer).
    Verdict judge(const Polygon& p) const {
        std::vector<GEOSGeometry*> polys;
        for (const Part& part : p.parts) {
            GEOSGeometry* shell = ring(p, p.rings[part.firstRing]);
            std::vector<GEOSGeometry*> holes;
            for (Index r = part.firstRing + 1; r < part.firstRing + part.ringCount; ++r)
                holes.push_back(ring(p, p.rings[r]));
            polys.push_back(
                GEOSGeom_createPolygon_r(h_, shell, holes.data(), unsigned(holes.size())));
        }
        GEOSGeometry* g = polys.size() == 1
                              ? polys[0]
                              : GEOSGeom_createCollection_r(h_, GEOS_MULTIPOLYGON, polys.data(),
                                                            unsigned(polys.size()));
        Verdict v;
        v.valid = GEOSisValid_r(h_, g) == 1;
        char* why = GEOSisValidReason_r(h_, g);
        v.reason = why ? why : "";
        GEOSFree_r(h_, why);
        GEOSGeom_destroy_r(h_, g);
        return v;
    }

private:
    GEOSGeometry* ring(const Polygon& p, const Ring& r) const {
        GEOSCoordSequence* s = GEOSCoordSeq_create_r(h_, r.count + 1, 2);
        for (Index i = 0; i <= r.count; ++i) {
            Point q = p.vertices[r.first + i % r.count];
            GEOSCoordSeq_setXY_r(h_, s, i, q.x, q.y);
        }
        return GEOSGeom_createLinearRing_r(h_, s);
    }
    GEOSContextHandle_t h_;
};

}  // namespace flood::testing
