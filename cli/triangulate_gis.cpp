// `flood triangulate IN -o OUT.gpkg` and every other GIS output (cli/triangulate_gis.h).
// A dataset is triangulated feature by feature, as QGIS's Tessellate does: neighbouring parcels
// share edges, so merged into one polygon they would be refused as overlapping, and one bad
// parcel must not cost the others their triangles.
#include "triangulate_gis.h"

#include <algorithm>
#include <iostream>
#include <memory>
#include <thread>

#include "flood/check/checker.h"
#include "flood/check/touches.h"
#include "flood/io/gdal/gdal_io.h"
#include "flood/io/io.h"
#include "task_runner.h"
#include "verbosity.h"

namespace flood::cli {
namespace {

std::string extensionOf(const std::string& path) {
    size_t slash = path.rfind('/'), dot = path.rfind('.');
    if (path == "-" || dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return "";
    std::string ext = path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return ext;
}

bool own(const std::string& format) {
    return format == "json" || format == "svg" || format == "obj";
}

}  // namespace

int outputFormat(const std::string& out, std::string& format, std::string& driver) {
    std::string ext = extensionOf(out);
    if (format.empty() && (ext.empty() || own(ext))) {
        format = ext.empty() ? "json" : ext;  // stdout and a name without one: Flood's JSON
        return 0;
    }
    if (own(format)) return 0;
    return gisFormat("-o", out, format, driver);
}

int gisFormat(const std::string& option, const std::string& out, std::string& format,
              std::string& driver) {
    const std::string ext = extensionOf(out);
    const std::string asked = format.empty() ? "." + ext : "--format " + format;
    const bool o = option == "-o";
    if (out == "-" && format.empty() && !o) {
        std::cerr << "error: " << option << " needs a file (OUT.gpkg, .geojson, ...), not -\n";
        return int(Status::Usage);
    }
#ifdef FLOOD_GDAL
    if (std::string why = gdal::unavailable(out); !why.empty()) {
        std::cerr << "error: " << why << "\n";
        return int(Status::WriteFailed);
    }
    driver = gdal::outputDriver(format, out);
    if (driver.empty()) {
        std::cerr << "error: " << option << " " << out << ": no format writes " << asked << ": "
                  << (o ? "Flood writes .json, .svg and .obj, and through GDAL any vector format "
                          "it creates"
                        : "it is written through GDAL, in any vector format it creates")
                  << " (.geojson, .shp, .gpkg, .fgb, .kml, .csv, ...: `ogrinfo --formats`)"
                  << (format.empty() && o ? "; name one with --format" : "") << "\n";
        return int(Status::Usage);
    }
    if (format.empty()) format = ext;
    if (out == "-") {
        std::cerr << "error: --format " << format << " needs a file: give " << option << " FILE\n";
        return int(Status::Usage);
    }
    return 0;
#else
    (void)driver;
    std::cerr << "error: " << option << " " << out << ": " << asked
              << " is a GIS format, written through GDAL: "
              << "this flood was built without it (install libgdal-dev, reconfigure with "
                 "-DFLOOD_GDAL=ON)\n";
    return int(Status::Usage);
#endif
}

int triangulateGis(const GisTriangulation& t) {
#ifdef FLOOD_GDAL
    const std::string name = t.in == "-" ? "<stdin>" : t.in;
    // stdin is the core's to read, a selection or not.
    bool gis = false;
    // A large FeatureCollection is parsed on every core (parseFeatures' slices).
    DatasetRead d = gdal::readAnyFeatures(
        t.in, t.in == "-" ? Selection{} : t.selection, t.maxInputBytes, false, gis, nullptr,
        threadRunner(std::max(1u, std::thread::hardware_concurrency())));
    for (const std::string& w : d.skipped) warning() << w << "\n";
    if (d.features.size() == 1 && d.features[0].wholeFile && !d.features[0].read.diagnostic.ok()) {
        std::cerr << "error: " << d.features[0].read.diagnostic.message << "\n";
        return int(d.features[0].read.diagnostic.status);
    }
    Status worst = Status::Ok;
    size_t failed = 0;
    auto fail = [&](const char* what, const Diagnostic& why) {
        std::cerr << "error: " << what << why.message << "\n";
        worst = std::max(worst, why.status);
        ++failed;
    };
    struct Done {
        int64_t fid;
        const Polygon* polygon;
        std::vector<Triangle> triangles;
    };
    std::vector<Done> done;
    for (FeatureRead& f : d.features) {
        for (const std::string& w : f.read.warnings) warning() << w << "\n";
        if (f.read.warningsOmitted)
            warning() << name << ": \u2026 and " << f.read.warningsOmitted
                      << " more warnings like these\n";
        if (!f.read.diagnostic.ok()) {
            fail("", f.read.diagnostic);
            continue;
        }
        Polygon& p = f.read.polygon;
        const std::string where = f.wholeFile ? name : name + ": feature " + std::to_string(f.fid);
        if (Diagnostic v = t.validate ? validate(p, where) : Diagnostic{}; !v.ok()) {
            fail("invalid polygon: ", v);
            continue;
        }
        if (!t.validate && !findTouches(p).complete)
            warning() << where << ": the search for T-junctions gave up (work "
                      << "cap): the polygon is flooded without them\n";
        FloodResult r = triangulate(p, nullptr, t.options);
        if (!r.diagnostic.ok()) {
            fail("flooding stopped in a forbidden state: ",
                 {r.diagnostic.status, where + ": " + r.diagnostic.message});
            continue;
        }
        if (t.exactCheck)
            if (CheckResult c = checkTriangulation(p, r.triangles); !c.ok) {
                fail(t.validate ? "internal error: " : "",
                     {Status::Internal,
                      where + ": the exact checker rejects the triangulation: " + c.reason});
                continue;
            }
        detail() << "triangulate: " << where << ": " << r.triangles.size() << " triangles\n";
        done.push_back({f.fid, &p, std::move(r.triangles)});
    }
    if (done.empty()) return int(worst);
    // One feature per triangle (its number in its feature, "triangle"), or one MultiPolygon
    // per source feature (its FID kept); each with the source's fields and its FID, "src_fid".
    gdal::GisLayer layer;
    layer.name = "triangles";
    layer.geometry = t.multipolygon ? gdal::GisGeometry::MultiPolygon : gdal::GisGeometry::Polygon;
    layer.sourceFields = true;
    layer.fields = {{"src_fid", true}};
    if (!t.multipolygon) layer.fields.push_back({"triangle", true});
    std::vector<size_t> first;  // the first output feature of each done feature
    for (const Done& f : done) {
        first.push_back(layer.count);
        layer.count += t.multipolygon ? 1 : f.triangles.size();
    }
    layer.feature = [&](size_t i, gdal::GisFeature& g) {
        const size_t k =
            size_t(std::upper_bound(first.begin(), first.end(), i) - first.begin()) - 1;
        const Done& f = done[k];
        g.source = f.fid;
        g.values = {f.fid};
        auto corners = [&](const Triangle& tri) {
            const auto& v = f.polygon->vertices;
            return std::vector<Point>{v[tri[0]], v[tri[1]], v[tri[2]]};
        };
        if (t.multipolygon) {
            g.fid = f.fid;  // kept where the format can (ogr2ogr -preserve_fid)
            for (const Triangle& tri : f.triangles) g.parts.push_back(corners(tri));
        } else {
            g.values.emplace_back(int64_t(i - first[k]));
            g.parts.push_back(corners(f.triangles[i - first[k]]));
        }
    };
    gdal::DatasetOutput o;
    o.driver = t.driver;
    o.format = t.format;
    o.sources = {{t.in, t.selection}};
    std::vector<std::string> warnings;
    Diagnostic w = gdal::writeLayers(t.out, o, {layer}, warnings);
    for (const std::string& m : warnings) warning() << m << "\n";
    if (!w.ok()) {
        std::cerr << "error: " << w.message << "\n";
        return int(w.status);
    }
    if (failed)
        note() << "note: " << t.out << ": " << done.size() << " of " << done.size() + failed
               << " features written; the " << failed
               << (failed == 1 ? " above was" : " above were") << " left out\n";
    return int(worst);
#else
    (void)t;
    return int(Status::Usage);  // outputFormat() has refused it
#endif
}

}  // namespace flood::cli
