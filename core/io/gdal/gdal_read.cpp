// Reading OGR vector datasets. Coordinates are the doubles OGR gives, unchanged; curves are
// linearised by OGR (getLinearGeometry) before they become rings. Every problem becomes a
// Malformed diagnostic naming the file (and layer, feature), never an exception or a crash.
#include <cpl_error.h>
#include <gdal_priv.h>
#include <ogrsf_frmts.h>
#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <mutex>

#include "io/gdal/gdal_handles.h"
#include "io/gdal/gdal_module.h"
#include "io/io_util.h"

namespace flood {
namespace io_detail {
// Defined in core/io/io_read.cpp: the ring cleaning every reader shares.
void addCleanRing(ReadResult& rr, const std::string& name, const std::vector<Point>& raw,
                  bool outer);
}  // namespace io_detail

namespace gdal::direct {
namespace {

constexpr const char* kGeoJsonLimit = "OGR_GEOJSON_MAX_OBJ_SIZE";

void registerOnce() {
    static std::once_flag once;
    std::call_once(once, [] {
        GDALAllRegister();
        // Errors are reported through our diagnostics, not printed by GDAL on stderr.
        CPLSetErrorHandler(CPLQuietErrorHandler);
        // GDAL's GeoJSON driver refuses an object over 200 MB, saying only "Failed to read
        // GeoJSON data" (the world's countries at 1:1M are 213 MB). --max-input-bytes is
        // the limit here, so the driver's is lifted, unless the user set it.
        if (!CPLGetConfigOption(kGeoJsonLimit, nullptr)) CPLSetConfigOption(kGeoJsonLimit, "0");
    });
}

// When the user's OGR_GEOJSON_MAX_OBJ_SIZE (in MB) is what refused the file, says so: GDAL
// does not.
std::string geoJsonLimitNote(const std::string& path) {
    const char* limit = CPLGetConfigOption(kGeoJsonLimit, nullptr);
    struct stat st;
    if (!limit || std::atof(limit) <= 0 || ::stat(path.c_str(), &st) != 0 ||
        double(st.st_size) <= std::atof(limit) * 1024 * 1024 ||
        !std::strstr(CPLGetLastErrorMsg(), "GeoJSON"))
        return "";
    return " (the file has " + std::to_string((st.st_size + (1 << 20) - 1) >> 20) + " MB, over " +
           kGeoJsonLimit + "=" + io_detail::echo(limit) +
           ", the most GDAL's GeoJSON driver reads: unset it, or set it to 0 for no limit)";
}

// GDAL's last message, or `silent` (what failed, said by us) when GDAL gave none.
std::string lastError(const std::string& silent) {
    std::string m = CPLGetLastErrorMsg();
    return m.empty() ? silent : io_detail::echo(m);
}

// A GDAL error that came without a message, named by its class (cpl_error.h) and number.
std::string silentError(CPLErrorNum number) {
    static const char* const names[] = {
        "",           "AppDefined",   "OutOfMemory",     "FileIO",        "OpenFailed",
        "IllegalArg", "NotSupported", "AssertionFailed", "NoWriteAccess", "UserInterrupt",
        "ObjectNull"};
    const bool named = number > 0 && number < CPLErrorNum(sizeof names / sizeof names[0]);
    return std::string("GDAL reported a failure without a message (") +
           (named ? std::string("CPLE_") + names[number] + ", " : "") + "error number " +
           std::to_string(number) + ")";
}

// GDAL's failures while a feature is read, collected in this thread (flood check reads files
// on several; CPL's handler stack and last error are per thread) for as long as it lives.
class Failures {
public:
    Failures() { CPLPushErrorHandlerEx(collect, this); }
    ~Failures() { CPLPopErrorHandler(); }
    Failures(const Failures&) = delete;
    Failures& operator=(const Failures&) = delete;

    void clear() {
        messages_.clear();
        CPLErrorReset();
    }
    bool any() const { return !messages_.empty(); }
    // "first; second" on one line, each cut to 160 bytes.
    std::string text() const {
        std::string t;
        for (const std::string& m : messages_) t += (t.empty() ? "" : "; ") + m;
        return t;
    }

private:
    static void CPL_STDCALL collect(CPLErr level, CPLErrorNum number, const char* message) {
        auto* self = static_cast<Failures*>(CPLGetErrorHandlerUserData());
        if (level < CE_Failure || !self || self->messages_.size() >= 4) return;
        std::string m = message ? message : "";
        std::replace_if(
            m.begin(), m.end(), [](char c) { return c == '\n' || c == '\r' || c == '\t'; }, ' ');
        size_t n = std::min<size_t>(m.size(), 160);
        while (n > 0 && n < m.size() && (static_cast<unsigned char>(m[n]) & 0xC0) == 0x80) --n;
        if (n < m.size()) m.resize(n), m += "\u2026";
        self->messages_.push_back(m.empty() ? silentError(number) : m);
    }
    std::vector<std::string> messages_;
};

void addPolygon(ReadResult& rr, const std::string& name, const OGRPolygon& poly) {
    auto ring = [&](const OGRLinearRing* r, bool outer) {
        std::vector<Point> raw;
        raw.reserve(size_t(r->getNumPoints()));
        for (int i = 0; i < r->getNumPoints(); ++i) raw.push_back({r->getX(i), r->getY(i)});
        io_detail::addCleanRing(rr, name, raw, outer);
    };
    if (poly.IsEmpty()) return;
    ring(poly.getExteriorRing(), true);
    for (int k = 0; k < poly.getNumInteriorRings(); ++k) ring(poly.getInteriorRing(k), false);
}

// Polygons, and collections of them (MultiPolygon parts, GeometryCollection members), after
// linearisation. Returns the first geometry that is none of these (nullptr when all were).
const OGRGeometry* addGeometry(ReadResult& rr, const std::string& name, const OGRGeometry& g) {
    OGRwkbGeometryType t = wkbFlatten(g.getGeometryType());
    if (t == wkbPolygon) {
        addPolygon(rr, name, *g.toPolygon());
        return nullptr;
    }
    if (t == wkbMultiPolygon || t == wkbGeometryCollection) {
        const OGRGeometryCollection* c = g.toGeometryCollection();
        for (int k = 0; k < c->getNumGeometries(); ++k)
            if (const OGRGeometry* other = addGeometry(rr, name, *c->getGeometryRef(k)))
                return other;
        return nullptr;
    }
    return &g;
}

bool polygonalType(OGRwkbGeometryType t) {
    t = wkbFlatten(t);
    return OGR_GT_IsSurface(t) || OGR_GT_IsSubClassOf(t, wkbMultiSurface) ||
           t == wkbGeometryCollection;
}

std::string fieldText(OGRFeature& f, const char* field) {
    int i = f.GetFieldIndex(field);
    if (i < 0 || !f.IsFieldSetAndNotNull(i)) return "";
    return io_detail::echo(f.GetFieldAsString(i));
}

// The feature's geometry as a polygon; a whole-dataset failure is reported in `failure`.
struct Reader {
    std::string name;
    DatasetRead out;
    Diagnostic failure;

    void malformed(const std::string& message) {
        failure = {Status::Malformed, name + ": " + message};
    }

    void read(const std::string& path, const Selection& s) {
        registerOnce();
        CPLErrorReset();
        DatasetPtr ds(static_cast<GDALDataset*>(GDALOpenEx(
            path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
        if (!ds) {
            // GDAL says nothing of a missing file; GDAL's own names (/vsizip/..., PG:...) are
            // not files, so only a plain path is checked.
            struct stat st;
            if (path.rfind("/vsi", 0) != 0 && path.find(':') == std::string::npos &&
                ::stat(path.c_str(), &st) != 0)
                return malformed(std::string("cannot open file: ") + std::strerror(errno));
            // GDAL says nothing either of a file a driver knows with nothing it opens (a
            // GeoPackage without vector tables): named as the dataset without layers it is.
            if (CPLGetLastErrorMsg()[0] == '\0')
                if (GDALDriverH known =
                        GDALIdentifyDriverEx(path.c_str(), GDAL_OF_VECTOR, nullptr, nullptr))
                    return malformed(std::string("the dataset has no layers (GDAL's ") +
                                     GDALGetDriverLongName(known) + " driver finds none)");
            return malformed("not a vector dataset GDAL can open: " +
                             lastError("no GDAL driver recognises it") + geoJsonLimitNote(path));
        }
        std::vector<OGRLayer*> layers;
        if (!s.layer.empty()) {
            OGRLayer* layer = ds->GetLayerByName(s.layer.c_str());
            if (!layer)
                return malformed("no layer \"" + io_detail::echo(s.layer) + "\"" + layerList(*ds));
            layers.push_back(layer);
        } else if (ds->GetLayerCount() == 1 || (s.allLayers && ds->GetLayerCount() > 1)) {
            for (int k = 0; k < ds->GetLayerCount(); ++k) layers.push_back(ds->GetLayer(k));
        } else if (ds->GetLayerCount() == 0) {
            return malformed("the dataset has no layers");
        } else {
            return malformed(std::to_string(ds->GetLayerCount()) +
                             " layers: choose one with --layer" + layerList(*ds));
        }
        // Of several layers, one without polygons (points, lines) is skipped with a warning;
        // none with any is the dataset's failure.
        size_t polygonal = 0;
        for (OGRLayer* layer : layers) {
            const size_t before = out.features.size();
            if (!readLayer(*ds, *layer, s, layers.size() == 1)) return;
            if (out.features.size() > before) ++polygonal;
            else if (layers.size() > 1)
                out.skipped.push_back(name + ": layer " + layer->GetName() +
                                      ": no polygon found, skipped");
        }
        if (layers.size() > 1 && polygonal == 0)
            return malformed("no polygon found in any of its " + std::to_string(layers.size()) +
                             " layers" + layerList(*ds));
    }

    // Reads one layer's features into `out`; false after a failure of the whole dataset (a
    // layer of no polygon is one when it is the `only` layer read).
    bool readLayer(GDALDataset& ds, OGRLayer& layerRef, const Selection& s, bool only) {
        OGRLayer* layer = &layerRef;
        const size_t first = out.features.size();
        const std::string lname = layer->GetName();
        if (!s.where.empty() && layer->SetAttributeFilter(s.where.c_str()) != OGRERR_NONE) {
            malformed("layer " + lname + ": --where '" + io_detail::echo(s.where) +
                      "' is not a valid attribute filter: " +
                      lastError("GDAL's SetAttributeFilter failed without a message"));
            return false;
        }
        // What the layer says it holds, where that is exactly what reading gives (FlatGeobuf's
        // header; not a Shapefile's, which counts records marked deleted too): -1 otherwise,
        // or with a filter. Elsewhere GDAL's errors are what tells a cut file.
        const GDALDriver* driver = ds.GetDriver();
        const bool exactCount = driver && std::string(driver->GetDescription()) == "FlatGeobuf" &&
                                layer->TestCapability(OLCFastFeatureCount);
        const GIntBig announced =
            s.feature < 0 && s.where.empty() && exactCount ? layer->GetFeatureCount(FALSE) : -1;
        auto features = [&](size_t n) {
            return std::to_string(n) + (announced >= 0 ? " of " + std::to_string(announced) : "") +
                   (n == 1 && announced < 0 ? " feature" : " features");
        };
        layer->ResetReading();
        // A feature GDAL fails to read (a truncated or corrupt file: "Error in fread()", a cut
        // geometry blob) is a failure of its own, never skipped as a feature without geometry,
        // and a read that stops early on an error, or short of the count the layer announces,
        // is a failure after the last feature read: nothing is lost silently.
        size_t index = 0;
        Failures failures;
        for (;; ++index) {
            failures.clear();
            FeaturePtr f(layer->GetNextFeature());
            if (!f) {
                if (failures.any())
                    unreadable(index, "",
                               "layer " + lname + ": reading stopped after " + features(index) +
                                   ": " + failures.text());
                break;
            }
            if (s.feature >= 0 && f->GetFID() != s.feature) continue;
            if (failures.any())
                unreadable(
                    index, std::to_string(f->GetFID()),
                    "feature " + std::to_string(f->GetFID()) + ": unreadable: " + failures.text());
            else readOne(*f, index);
        }
        if (announced > GIntBig(index) && !failures.any())
            unreadable(index, "",
                       "layer " + lname + ": reading stopped after " + features(index) +
                           " without an error: the file is "
                           "truncated or corrupt");
        for (size_t k = first; k < out.features.size(); ++k) out.features[k].layer = lname;
        if (out.features.size() == first && only) {
            malformed("layer " + lname + ": no polygon found" +
                      (s.feature >= 0 ? " (FID " + std::to_string(s.feature) + ")" : "") +
                      (s.where.empty() ? "" : " where " + io_detail::echo(s.where)));
            return false;
        }
        return true;
    }

    static std::string layerList(GDALDataset& ds) {
        if (ds.GetLayerCount() == 0) return " (the dataset has no layers)";
        std::string l;
        for (int k = 0; k < ds.GetLayerCount(); ++k)
            l += (k ? ", " : " (layers: ") + std::string(ds.GetLayer(k)->GetName());
        return l.empty() ? l : l + ")";
    }

    // A failure row where feature `index` (FID `fid`, or "" when unknown) should be.
    void unreadable(size_t index, const std::string& fid, const std::string& message) {
        FeatureRead r;
        r.wholeFile = false;
        r.index = index;
        r.id = fid;
        r.fid = fid.empty() ? -1 : std::stoll(fid);
        r.read.diagnostic = {Status::Malformed, name + ": " + message};
        out.features.push_back(std::move(r));
    }

    void readOne(OGRFeature& f, size_t index) {
        const std::string fid = std::to_string(f.GetFID());
        const std::string ctx = "feature " + fid;
        const OGRGeometry* g = f.GetGeometryRef();
        if (!g || !polygonalType(g->getGeometryType())) {
            out.skipped.push_back(name + ": " + ctx + ": not polygonal (" +
                                  (g ? OGRGeometryTypeToName(g->getGeometryType()) : "null") +
                                  "), skipped");
            return;
        }
        FeatureRead r;
        r.wholeFile = false;
        r.index = index;
        r.id = fid;
        r.fid = f.GetFID();
        r.name = fieldText(f, "name");
        for (int i = 0; i < f.GetFieldCount(); ++i)
            if (f.IsFieldSetAndNotNull(i))
                r.attributes.emplace_back(io_detail::echo(f.GetFieldDefnRef(i)->GetNameRef()),
                                          io_detail::echo(f.GetFieldAsString(i)));
        // Its WKT name (POLYGON, CURVEPOLYGON, ...), as the user's tools show it.
        const std::string type = g->getGeometryName();
        std::unique_ptr<OGRGeometry> linear;
        if (g->hasCurveGeometry()) {
            linear.reset(g->getLinearGeometry());
            if (linear) g = linear.get();
        }
        std::string problem;
        const OGRGeometry* other = g->IsEmpty() ? nullptr : addGeometry(r.read, name, *g);
        io_detail::nameFeature(r.read.warnings, name, ctx);
        if (g->IsEmpty()) {
            problem = type + " EMPTY has no rings";
        } else if (other) {
            problem = other == g ? "a " + type +
                                       " is not read: only POLYGON, MULTIPOLYGON and collections "
                                       "of them are triangulated"
                                 : "the " + type + " holds a " + other->getGeometryName() +
                                       ": only polygons are triangulated";
        } else if (r.read.polygon.rings.empty()) {
            problem = "every polygon of the " + type + " is empty: it has no rings";
        }
        if (!problem.empty()) {
            r.read.polygon = Polygon{};
            r.read.diagnostic = {Status::Malformed, name + ": " + ctx + ": " + problem};
        }
        out.features.push_back(std::move(r));
    }
};

}  // namespace

DatasetRead readFeatures(const std::string& path, const Selection& s) {
    Reader r;
    r.name = path;
    try {
        r.read(path, s);
    } catch (const std::exception& e) {
        r.failure = {Status::Malformed, path + ": GDAL: " + e.what()};
    }
    if (r.failure.ok()) return std::move(r.out);
    DatasetRead whole;
    whole.skipped = std::move(r.out.skipped);
    whole.features.emplace_back();
    whole.features.back().read.diagnostic = r.failure;
    return whole;
}

ReadResult readPolygon(const std::string& path, const Selection& s) {
    DatasetRead d = direct::readFeatures(path, s);
    ReadResult rr;
    for (const std::string& w : d.skipped) rr.warn([&] { return w; });
    for (FeatureRead& f : d.features) {
        for (std::string& w : f.read.warnings) rr.warn([&] { return std::move(w); });
        rr.warningsOmitted += f.read.warningsOmitted;
        if (!f.read.diagnostic.ok()) {
            rr.polygon = Polygon{};
            rr.diagnostic = f.read.diagnostic;
            return rr;
        }
        const Polygon& p = f.read.polygon;
        for (size_t k = 0; k < p.parts.size(); ++k)
            for (Index r = p.parts[k].firstRing; r < p.parts[k].firstRing + p.parts[k].ringCount;
                 ++r) {
                const Ring& ring = p.rings[r];
                rr.polygon.addRing(
                    {p.vertices.begin() + ring.first, p.vertices.begin() + ring.first + ring.count},
                    r == p.parts[k].firstRing);
            }
    }
    return rr;
}

std::string readBackProblem(const std::string& file,
                            const std::vector<std::pair<std::string, long long>>& layers) {
    registerOnce();
    CPLErrorReset();
    DatasetPtr ds(static_cast<GDALDataset*>(
        GDALOpenEx(file.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
    if (!ds) return "it does not open: " + lastError("GDALOpenEx failed without a message");
    for (const auto& [name, features] : layers) {
        // By name in a dataset of several (a GeoPackage keeps its other layers); a format of
        // one layer names it after the file (Shapefile, CSV, GeoJSON) or a folder (KML).
        OGRLayer* layer =
            ds->GetLayerCount() == 1 ? ds->GetLayer(0) : ds->GetLayerByName(name.c_str());
        if (!layer) return "it has no layer " + name;
        Failures failures;
        long long n = 0;
        for (FeaturePtr f; (f.reset(layer->GetNextFeature()), f) && !failures.any();) ++n;
        const std::string of = std::to_string(n) + " of " + std::to_string(features);
        if (failures.any())
            return "reading it back fails after " + of + " features: " + failures.text();
        if (n != features) return "reading it back gives " + of + " features";
    }
    return "";
}

}  // namespace gdal::direct
}  // namespace flood
