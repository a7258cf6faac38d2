// `flood triangulate IN -o OUT.gpkg` and every other GIS output (cli/triangulate_gis.h).
// A dataset is triangulated feature by feature, as QGIS's Tessellate does: neighbouring parcels
// share edges, so merged into one polygon they would be refused as overlapping, and one bad
// parcel must not cost the others their triangles.
#include "triangulate_gis.h"

#include <algorithm>
#include <iostream>
#include <memory>

#include "check/checker.h"
#include "check/touches.h"
#include "io/io.h"
#ifdef FLOOD_GDAL
#include "io/gdal/gdal_io.h"
#endif

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
    const std::string asked = format.empty() ? "." + ext : "--format " + format;
#ifdef FLOOD_GDAL
    if (std::string why = gdal::unavailable(out); !why.empty()) {
        std::cerr << "error: " << why << "\n";
        return int(Status::WriteFailed);
    }
    driver = gdal::outputDriver(format, out);
    if (driver.empty()) {
        std::cerr << "error: -o " << out << ": no format writes " << asked
                  << ": Flood writes .json, .svg and .obj, and through GDAL any vector format it "
                     "creates (.geojson, .shp, .gpkg, .fgb, .kml, .csv, ...: `ogrinfo --formats`)"
                  << (format.empty() ? "; name one with --format" : "") << "\n";
        return int(Status::Usage);
    }
    if (format.empty()) format = ext;
    if (out == "-") {
        std::cerr << "error: --format " << format << " needs a file: give -o FILE\n";
        return int(Status::Usage);
    }
    return 0;
#else
    (void)driver;  // only GDAL names one
    std::cerr << "error: -o " << out << ": " << asked << " is a GIS format, written through GDAL: "
              << "this flood was built without it (install libgdal-dev, reconfigure with "
                 "-DFLOOD_GDAL=ON)\n";
    return int(Status::Usage);
#endif
}

int triangulateGis(const GisTriangulation& t) {
#ifdef FLOOD_GDAL
    const std::string name = t.in == "-" ? "<stdin>" : t.in;
    gdal::Selection s{t.selection.layer, t.selection.feature, t.selection.where};
    DatasetRead d = t.in != "-" && gdal::handles(t.in, s)
                        ? gdal::readFeatures(t.in, s)
                        : readFeaturesFile(t.in, t.maxInputBytes, false);
    for (const std::string& w : d.skipped) std::cerr << "warning: " << w << "\n";
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
    std::vector<gdal::TriangulatedFeature> done;
    for (FeatureRead& f : d.features) {
        for (const std::string& w : f.read.warnings) std::cerr << "warning: " << w << "\n";
        if (f.read.warningsOmitted)
            std::cerr << "warning: " << name << ": \u2026 and " << f.read.warningsOmitted
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
            std::cerr << "warning: " << where << ": the search for T-junctions gave up (work "
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
        done.push_back({f.fid, &p, std::move(r.triangles)});
    }
    if (done.empty()) return int(worst);
    gdal::LayerOutput o;
    o.driver = t.driver;
    o.format = t.format;
    o.source = t.in;
    o.selection = s;
    o.multipolygon = t.multipolygon;
    std::vector<std::string> warnings;
    Diagnostic w = gdal::writeLayer(t.out, o, done, warnings);
    for (const std::string& m : warnings) std::cerr << "warning: " << m << "\n";
    if (!w.ok()) {
        std::cerr << "error: " << w.message << "\n";
        return int(w.status);
    }
    if (failed)
        std::cerr << "note: " << t.out << ": " << done.size() << " of " << done.size() + failed
                  << " features written; the " << failed
                  << (failed == 1 ? " above was" : " above were") << " left out\n";
    return int(worst);
#else
    (void)t;
    return int(Status::Usage);  // outputFormat() has refused it
#endif
}

}  // namespace flood::cli
