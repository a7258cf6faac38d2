// Adapters to the peer triangulators (see peers.h). Each adapter is the peer's documented
// usage; nothing here is copied from the peers' sources or examples.
#include "peers.h"

#include <cstring>
#include <deque>
#include <memory>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <GL/glu.h>
#include <geos_c.h>
#ifdef FLOOD_EARCUT_HPP
#include <array>
#include <mapbox/earcut.hpp>
#endif

#include "flood/geometry/predicates.h"

namespace bench {

using flood::Index;
using flood::kNone;
using flood::Point;
using flood::Polygon;
using flood::Triangle;

// [SECTION] coordinate lookup

namespace {
uint64_t bitsOf(double d) {
    if (d == 0) d = 0;  // -0 and +0 are the same point
    uint64_t b;
    std::memcpy(&b, &d, 8);
    return b;
}
uint64_t hashPoint(Point q) {
    uint64_t h = bitsOf(q.x) * 0x9e3779b97f4a7c15ULL ^ (bitsOf(q.y) + 0x632be59bd9b4e019ULL);
    h ^= h >> 29;
    h *= 0xbf58476d1ce4e5b9ULL;
    return h ^ (h >> 32);
}
}  // namespace

CoordIndex::CoordIndex(const Polygon& p) : polygon_(&p) {
    size_t cap = 16;
    while (cap < p.vertices.size() * 2) cap <<= 1;
    slots_.assign(cap, kNone);
    mask_ = cap - 1;
    canonical_.resize(p.vertices.size());
    for (Index v = 0; v < p.vertices.size(); ++v) {
        for (size_t i = hashPoint(p.vertices[v]) & mask_;; i = (i + 1) & mask_) {
            if (slots_[i] == kNone) {
                slots_[i] = v;
                canonical_[v] = v;
                break;
            }
            if (p.vertices[slots_[i]] == p.vertices[v]) {
                canonical_[v] = slots_[i];
                break;
            }
        }
    }
}

Index CoordIndex::find(Point q) const {
    for (size_t i = hashPoint(q) & mask_;; i = (i + 1) & mask_) {
        if (slots_[i] == kNone) return kNone;
        if (polygon_->vertices[slots_[i]] == q) return slots_[i];
    }
}

void orientCounterClockwise(const Polygon& p, std::vector<Triangle>& t) {
    for (auto& tri : t)
        if (flood::orient(p.vertices[tri[0]], p.vertices[tri[1]], p.vertices[tri[2]]) < 0)
            std::swap(tri[1], tri[2]);
}

// [SECTION] GLU

namespace {

struct GluRun {
    PeerOutput out;
    std::vector<Index> corner;       // indices of the triangle being emitted
    std::deque<Index> addedMarkers;  // vertex data for combined (new) vertices: kNone
    std::deque<std::array<GLdouble, 3>> addedCoords;
};

void gluBegin(GLenum, void*) {}
void gluEdgeFlag(GLboolean, void*) {}  // its presence makes GLU emit GL_TRIANGLES only
void gluEnd(void*) {}
void gluVertexData(void* vertex, void* run) {
    auto* r = static_cast<GluRun*>(run);
    r->corner.push_back(*static_cast<Index*>(vertex));
    if (r->corner.size() == 3) {
        if (r->corner[0] != kNone && r->corner[1] != kNone && r->corner[2] != kNone)
            r->out.triangles.push_back({r->corner[0], r->corner[1], r->corner[2]});
        r->corner.clear();
    }
}
void gluCombine(GLdouble coords[3], void* [4], GLfloat[4], void** outData, void* run) {
    auto* r = static_cast<GluRun*>(run);
    r->addedCoords.push_back({coords[0], coords[1], coords[2]});
    r->addedMarkers.push_back(kNone);
    r->out.added++;
    *outData = &r->addedMarkers.back();
}
void gluError(GLenum code, void* run) {
    auto* r = static_cast<GluRun*>(run);
    if (r->out.error.empty()) r->out.error = reinterpret_cast<const char*>(gluErrorString(code));
}

template <class F>
_GLUfuncptr cb(F* f) {
    return reinterpret_cast<_GLUfuncptr>(f);
}

}  // namespace

PeerOutput runGlu(const Polygon& p) {
    GluRun run;
    std::vector<GLdouble> coords(p.vertices.size() * 3);
    std::vector<Index> ids(p.vertices.size());
    for (Index v = 0; v < p.vertices.size(); ++v) {
        coords[3 * v] = p.vertices[v].x;
        coords[3 * v + 1] = p.vertices[v].y;
        coords[3 * v + 2] = 0;
        ids[v] = v;
    }
    run.out.triangles.reserve(p.vertices.size() + 2 * p.rings.size());
    GLUtesselator* tess = gluNewTess();
    gluTessCallback(tess, GLU_TESS_BEGIN_DATA, cb(gluBegin));
    gluTessCallback(tess, GLU_TESS_EDGE_FLAG_DATA, cb(gluEdgeFlag));
    gluTessCallback(tess, GLU_TESS_VERTEX_DATA, cb(gluVertexData));
    gluTessCallback(tess, GLU_TESS_END_DATA, cb(gluEnd));
    gluTessCallback(tess, GLU_TESS_COMBINE_DATA, cb(gluCombine));
    gluTessCallback(tess, GLU_TESS_ERROR_DATA, cb(gluError));
    gluTessProperty(tess, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_ODD);
    gluTessNormal(tess, 0, 0, 1);
    gluTessBeginPolygon(tess, &run);
    for (const auto& ring : p.rings) {
        gluTessBeginContour(tess);
        for (Index v = ring.first; v < ring.first + ring.count; ++v)
            gluTessVertex(tess, &coords[3 * v], &ids[v]);
        gluTessEndContour(tess);
    }
    gluTessEndPolygon(tess);
    gluDeleteTess(tess);
    return std::move(run.out);
}

// [SECTION] CGAL

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
struct VertexInfo {
    Index v = kNone;  // input vertex; kNone for a vertex CGAL created (constraint intersection)
};
struct FaceInfo {
    int nesting = -1;  // number of constrained edges crossed from the outside; odd = inside
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, K>;
using Fbb = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbb>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

// Sets every face's nesting level: faces reachable from the infinite face without crossing a
// constraint get 0, then each crossing adds one. Regions are filled level by level.
void markNesting(CDT& cdt) {
    std::deque<std::pair<CDT::Face_handle, int>> next{{cdt.infinite_face(), 0}};
    std::vector<CDT::Face_handle> region;
    while (!next.empty()) {
        auto [seed, level] = next.front();
        next.pop_front();
        if (seed->info().nesting != -1) continue;
        seed->info().nesting = level;
        region.push_back(seed);
        while (!region.empty()) {
            CDT::Face_handle f = region.back();
            region.pop_back();
            for (int i = 0; i < 3; ++i) {
                CDT::Face_handle n = f->neighbor(i);
                if (n->info().nesting != -1) continue;
                if (cdt.is_constrained({f, i})) {
                    next.push_back({n, level + 1});
                } else {
                    n->info().nesting = level;
                    region.push_back(n);
                }
            }
        }
    }
}

}  // namespace

PeerOutput runCgal(const Polygon& p, const CoordIndex& index) {
    PeerOutput out;
    const size_t n = p.vertices.size();
    std::vector<std::pair<K::Point_2, VertexInfo>> points(n);
    for (Index v = 0; v < n; ++v) points[v] = {{p.vertices[v].x, p.vertices[v].y}, {v}};
    CDT cdt;
    cdt.insert(points.begin(), points.end());  // spatially sorted bulk insertion
    std::vector<CDT::Vertex_handle> handle(n);
    for (CDT::Vertex_handle h : cdt.finite_vertex_handles()) handle[h->info().v] = h;
    // Coincident input points (rings touching) are one CGAL vertex: share its handle.
    for (Index v = 0; v < n; ++v)
        if (handle[v] != CDT::Vertex_handle() && handle[index.canonical(v)] == CDT::Vertex_handle())
            handle[index.canonical(v)] = handle[v];
    for (Index v = 0; v < n; ++v)
        if (handle[v] == CDT::Vertex_handle()) handle[v] = handle[index.canonical(v)];
    for (const auto& ring : p.rings)
        for (Index i = 0; i < ring.count; ++i) {
            Index a = ring.first + i, b = ring.first + (i + 1) % ring.count;
            if (handle[a] != handle[b]) cdt.insert_constraint(handle[a], handle[b]);
        }
    markNesting(cdt);
    out.triangles.reserve(n + 2 * p.rings.size());
    for (CDT::Face_handle f : cdt.finite_face_handles()) {
        if (f->info().nesting % 2 != 1) continue;
        Triangle t{f->vertex(0)->info().v, f->vertex(1)->info().v, f->vertex(2)->info().v};
        if (t[0] == kNone || t[1] == kNone || t[2] == kNone) continue;
        out.triangles.push_back(t);
    }
    for (CDT::Vertex_handle h : cdt.finite_vertex_handles())
        if (h->info().v == kNone) out.added++;
    return out;
}

// [SECTION] GEOS

namespace {

void geosMessage(const char* message, void* userdata) {
    auto* error = static_cast<std::string*>(userdata);
    if (error->empty()) *error = message;
}

struct GeosContext {
    GEOSContextHandle_t ctx = GEOS_init_r();
    std::string error;
    GeosContext() { GEOSContext_setErrorMessageHandler_r(ctx, geosMessage, &error); }
    ~GeosContext() { GEOS_finish_r(ctx); }
};

}  // namespace

#ifdef FLOOD_EARCUT_HPP
PeerOutput runEarcut(const Polygon& p) {
    PeerOutput out;
    for (const flood::Part& part : p.parts) {
        // A part's rings are numbered consecutively, so earcut's indices (into the part's
        // rings laid end to end) are the input's less the part's first vertex.
        std::vector<std::vector<std::array<double, 2>>> rings;
        for (Index r = part.firstRing; r < part.firstRing + part.ringCount; ++r) {
            rings.emplace_back();
            for (Index v = p.rings[r].first; v < p.rings[r].first + p.rings[r].count; ++v)
                rings.back().push_back({p.vertices[v].x, p.vertices[v].y});
        }
        const Index first = p.rings[part.firstRing].first;
        const std::vector<uint32_t> indices = mapbox::earcut<uint32_t>(rings);
        for (size_t k = 0; k + 2 < indices.size(); k += 3)
            out.triangles.push_back({Index(first + indices[k]), Index(first + indices[k + 1]),
                                     Index(first + indices[k + 2])});
    }
    orientCounterClockwise(p, out.triangles);
    return out;
}
#endif

PeerOutput runGeos(const Polygon& p, const CoordIndex* index) {
    static GeosContext g;  // one per process, like a GEOS user's
    g.error.clear();
    GEOSContextHandle_t ctx = g.ctx;
    PeerOutput out;
    std::vector<GEOSGeometry*> polys;
    std::vector<double> buf;
    for (const auto& part : p.parts) {
        std::vector<GEOSGeometry*> rings;
        for (Index r = part.firstRing; r < part.firstRing + part.ringCount; ++r) {
            const auto& ring = p.rings[r];
            buf.resize(2 * (ring.count + 1));
            for (Index i = 0; i <= ring.count; ++i) {
                Point q = p.vertices[ring.first + i % ring.count];
                buf[2 * i] = q.x;
                buf[2 * i + 1] = q.y;
            }
            GEOSCoordSequence* seq =
                GEOSCoordSeq_copyFromBuffer_r(ctx, buf.data(), ring.count + 1, 0, 0);
            rings.push_back(GEOSGeom_createLinearRing_r(ctx, seq));
        }
        polys.push_back(
            GEOSGeom_createPolygon_r(ctx, rings[0], rings.data() + 1, unsigned(rings.size() - 1)));
    }
    GEOSGeometry* input = polys.size() == 1
                              ? polys[0]
                              : GEOSGeom_createCollection_r(ctx, GEOS_MULTIPOLYGON, polys.data(),
                                                            unsigned(polys.size()));
    GEOSGeometry* result = GEOSConstrainedDelaunayTriangulation_r(ctx, input);
    GEOSGeom_destroy_r(ctx, input);
    if (!result) {
        out.error = g.error.empty() ? "GEOS returned no result" : g.error;
        return out;
    }
    int count = GEOSGetNumGeometries_r(ctx, result);
    if (!index) {
        out.triangles.resize(size_t(std::max(0, count)));  // counted only
    } else {
        for (int i = 0; i < count; ++i) {
            const GEOSGeometry* tri = GEOSGetGeometryN_r(ctx, result, i);
            const GEOSCoordSequence* seq =
                GEOSGeom_getCoordSeq_r(ctx, GEOSGetExteriorRing_r(ctx, tri));
            Triangle t{};
            bool known = true;
            for (unsigned k = 0; k < 3; ++k) {
                double x = 0, y = 0;
                GEOSCoordSeq_getXY_r(ctx, seq, k, &x, &y);
                t[k] = index->find({x, y});
                known = known && t[k] != kNone;
            }
            if (known) out.triangles.push_back(t);
            else out.added++;
        }
    }
    GEOSGeom_destroy_r(ctx, result);
    return out;
}

}  // namespace bench
