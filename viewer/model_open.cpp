// The model's session: opening files, traces, features and shrunk polygons; recent files;
// the flood direction.
#include "model.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <utility>

#include "flood/check/diagnostic_where.h"
#include "flood/geometry/predicates.h"
#include "flood/io/gdal/read_any.h"
#include "flood/io/io.h"
#include "flood/log/trace_io.h"
#include "view_fit.h"

namespace flood::view {

// A trace by its name (*.jsonl, what `flood trace` is given) or by its header line, so a
// trace saved under any name opens as one.
static bool isTracePath(const std::string& path) {
    if (path.size() > 6 && path.compare(path.size() - 6, 6, ".jsonl") == 0) return true;
    std::ifstream in(path, std::ios::binary);
    char head[64] = {};
    in.read(head, sizeof head - 1);
    std::string h(head, size_t(in.gcount()));
    h.erase(std::remove_if(h.begin(), h.end(),
                           [](char c) { return std::isspace(static_cast<unsigned char>(c)); }),
            h.end());
    return h.rfind("{\"format\":\"flood-trace\"", 0) == 0 || isBinaryTrace(h);
}

void Model::open(const std::string& path) {
    // A gallery file opens the gallery: its first polygon, and its list in the Open panel.
    if (std::filesystem::path(path).filename() == "gallery.json") {
        std::string dir = std::filesystem::path(path).parent_path().string();
        if (dir.empty()) dir = ".";
        if (std::vector<GalleryEntry> entries = readGallery(dir); !entries.empty()) {
            galleryDir_ = dir;
            ++galleryOpens_;
            return open(entries.front().file);
        }
    }
    ReadResult r;
    Trace t;
    const bool isTrace = isTracePath(path);
    try {
        if (isTrace) r.diagnostic = readTraceFile(path, t);
        // GIS datasets (Shapefile, GeoPackage, ...) through GDAL: the selected layer's
        // polygonal features as one polygon, as `flood triangulate FILE` reads them.
        else r = gdal::readAny(path, {gisLayer, -1, gisWhere});
    } catch (const std::exception& ex) {
        r.diagnostic = {Status::Malformed, path + ": " + ex.what()};
    }
    if (!r.diagnostic.ok()) {
        // A failed open keeps what was loaded; with nothing loaded, the failure is the verdict.
        openDiag_ = r.diagnostic;
        if (trace_->polygon.vertices.empty()) {
            openPolygon({}, path, r.diagnostic);
            openDiag_ = r.diagnostic;
        }
        return;
    }
    if (isTrace) {
        openTrace(std::move(t), path);
    } else {
        Diagnostic d = validate(r.polygon, path);
        openPolygon(std::move(r.polygon), path, d, std::move(r.warnings));
    }
    remember(path);
}

void Model::remember(const std::string& path) {
    std::error_code ec;
    std::string abs = std::filesystem::absolute(path, ec).lexically_normal().string();
    if (ec || path == "-") abs = path;
    recent_.erase(std::remove(recent_.begin(), recent_.end(), abs), recent_.end());
    recent_.insert(recent_.begin(), abs);
    if (recent_.size() > 10) recent_.resize(10);
    if (!recentPath.empty()) saveRecent(recentPath);
}

void Model::openTrace(Trace trace, const std::string& name) {
    playing_ = false;
    ++generation_;
    path_ = name;
    openDiag_ = {};
    warnings_.clear();
    // The trace holds the run; validation of a copy only says whether its input was valid.
    Polygon copy = trace.polygon;
    input_ = copy.vertices.empty() ? Diagnostic{} : validate(copy, name);
    up_ = trace.up;
    adopt(std::make_unique<Trace>(std::move(trace)));
}

void Model::openPolygon(Polygon polygon, const std::string& name, Diagnostic input,
                        std::vector<std::string> warnings) {
    playing_ = false;
    ++generation_;
    path_ = name;
    openDiag_ = input.status == Status::Malformed ? input : Diagnostic{};
    input_ = std::move(input);
    warnings_ = std::move(warnings);
    cancelInvariants();  // the scan reads the trace about to be replaced
    auto trace = std::make_unique<Trace>();
    if (!polygon.vertices.empty()) {
        try {
            *trace = record(polygon, Options{up_});
        } catch (const std::exception& ex) {
            trace->diagnostic = {Status::Internal, name + ": " + ex.what()};
        }
    }
    trace->polygon = std::move(polygon);
    adopt(std::move(trace));
}

bool Model::openFeature(const std::string& path, size_t index) {
    DatasetRead d;
    try {
        // A GIS layer's features, by FID (--where keeps some of them: the others are not there).
        bool gis = false;
        d = gdal::readAnyFeatures(path, {gisLayer, -1, gisWhere}, kDefaultMaxInputBytes, false,
                                  gis);
    } catch (const std::exception& ex) {
        openDiag_ = {Status::Malformed, path + ": " + ex.what()};
        return false;
    }
    if (d.features.size() == 1 && d.features[0].wholeFile) {
        const Diagnostic& r = d.features[0].read.diagnostic;
        openDiag_ = !r.ok() ? r
                            : Diagnostic{Status::Usage,
                                         path + ": not a FeatureCollection, it has no feature " +
                                             std::to_string(index)};
        return false;
    }
    // By FID, as `flood check` and `flood --feature` name them (FeatureRead::fid); a
    // non-polygonal feature has none here.
    auto it = std::find_if(d.features.begin(), d.features.end(),
                           [&](const FeatureRead& f) { return f.fid == int64_t(index); });
    if (it == d.features.end()) {
        int64_t first = INT64_MAX, last = INT64_MIN;
        for (const auto& f : d.features)
            first = std::min(first, f.fid), last = std::max(last, f.fid);
        openDiag_ = {Status::Usage,
                     path + ": no polygonal feature " + std::to_string(index) +
                         " (the collection's " +
                         (d.features.empty()
                              ? std::string("features are not polygons")
                              : "FIDs run " + std::to_string(first) + ".." + std::to_string(last)) +
                         ")"};
        return false;
    }
    FeatureRead& f = *it;
    const std::string name = path + "#" + std::to_string(index);
    if (!f.read.diagnostic.ok()) {
        openDiag_ = f.read.diagnostic;
        return false;
    }
    Diagnostic v = validate(f.read.polygon, name);
    openPolygon(std::move(f.read.polygon), name, v, std::move(f.read.warnings));
    feature_ = index;
    remember(path);
    return true;
}

void Model::openShrunk(const ShrinkResult& result) {
    const std::string from = path_;
    const size_t fromFeature = feature_;
    Polygon p = result.polygon;
    Diagnostic v = validate(p, from + " (shrunk)");
    openPolygon(std::move(p), from + " (shrunk)", v);
    // What it came from: a file (the feature's file for "FILE#N"), one click away.
    originName_ = from;
    origin_ = fromFeature == kNoFeature ? from : from.substr(0, from.rfind('#'));
    originFeature_ = fromFeature;
}

void Model::openOrigin() {
    if (origin_.empty()) return;
    const std::string file = origin_;
    if (originFeature_ == kNoFeature) open(file);
    else openFeature(file, originFeature_);
}

void Model::loadRecent(const std::string& file) {
    std::ifstream in(file);
    for (std::string line; std::getline(in, line) && recent_.size() < 10;)
        if (!line.empty()) recent_.push_back(line);
}

void Model::saveRecent(const std::string& file) const {
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(file).parent_path(), ec);
    std::ofstream out(file);
    for (const auto& r : recent_) out << r << "\n";
}

std::string Model::galleryDir() const { return galleryDir_.empty() ? polygonsDir() : galleryDir_; }

bool Model::setUp(Up up) {
    if (!up.valid() || up == trace_->up) return false;
    previousSummary_ = summary();
    hasPrevious_ = true;
    up_ = up;
    const uint32_t at = step_;
    // What opened stays what it was: the name, the input's verdict, the feature or the
    // shrink's origin; only the run is new.
    const std::string name = path_;
    Diagnostic input = input_;
    std::vector<std::string> warnings = warnings_;
    const size_t feature = feature_, originFeature = originFeature_;
    const std::string origin = origin_, originName = originName_;
    const bool fit = needsFit_;  // the polygon does not move: fit only if not yet fitted
    openPolygon(trace_->polygon, name, std::move(input), std::move(warnings));
    feature_ = feature, originFeature_ = originFeature;
    origin_ = origin, originName_ = originName;
    needsFit_ = fit;
    seek(at);
    return true;
}

}  // namespace flood::view
