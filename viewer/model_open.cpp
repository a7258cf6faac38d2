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

// A gallery file opens the gallery: its first polygon (returned), and its list in the Open
// panel. Any other file is itself.
static std::string galleryFirst(const std::string& path, std::string& galleryDir,
                                uint32_t& galleryOpens) {
    if (std::filesystem::path(path).filename() != "gallery.json") return path;
    std::string dir = std::filesystem::path(path).parent_path().string();
    if (dir.empty()) dir = ".";
    std::vector<GalleryEntry> entries = readGallery(dir);
    if (entries.empty()) return path;
    galleryDir = dir;
    ++galleryOpens;
    return galleryFirst(entries.front().file, galleryDir, galleryOpens);
}

void Model::open(const std::string& file) {
    cancelOpen();  // this open is the one the user asked for last
    const std::string path = galleryFirst(file, galleryDir_, galleryOpens_);
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
        failedOpen(path, r.diagnostic);
        return;
    }
    // What the window's open runs in its job (open_job.h), here at once.
    PreparedRun run;
    if (isTrace) judgeTrace(std::move(t), path, run);
    else floodRun(std::move(r.polygon), path, up_, run);
    adoptOpen(path, std::move(r.warnings), std::move(run));
    remember(path);
}

// A failed open keeps what was loaded; with nothing loaded, the failure is the verdict.
void Model::failedOpen(const std::string& path, const Diagnostic& why) {
    openDiag_ = why;
    if (trace_->polygon.vertices.empty()) {
        openPolygon({}, path, why);
        openDiag_ = why;
    }
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
    // The trace holds the run; validation of a copy only says whether its input was valid.
    PreparedRun run;
    judgeTrace(std::move(trace), name, run);
    adoptOpen(name, {}, std::move(run));
}

void Model::openPolygon(Polygon polygon, const std::string& name, Diagnostic input,
                        std::vector<std::string> warnings) {
    PreparedRun run;
    floodRun(std::move(polygon), name, up_, run, {}, std::move(input));
    adoptOpen(name, std::move(warnings), std::move(run));
}

void Model::adoptOpen(const std::string& name, std::vector<std::string> warnings, PreparedRun run) {
    playing_ = false;
    ++generation_;
    path_ = name;
    openDiag_ = run.input.status == Status::Malformed ? run.input : Diagnostic{};
    warnings_ = std::move(warnings);
    up_ = run.trace->up;  // a trace's, as recorded
    cancelInvariants();   // the scan reads the trace about to be replaced
    adopt(std::move(run));
}

// ---- the window's open, in the background (open_job.h) ----------------------------------
void Model::openInBackground(const std::string& file) {
    cancelOpen();
    const std::string path = galleryFirst(file, galleryDir_, galleryOpens_);
    OpenJob::Request request;
    request.path = path;
    request.gisLayer = gisLayer, request.gisWhere = gisWhere;
    request.up = up_;
    request.trace = isTracePath(path);
    request.onPhase = openHook;
    opening_ = std::make_unique<OpenJob>();
    outlineShown_ = false;
    opening_->start(std::move(request));
}

const std::string& Model::openingPath() const {
    static const std::string none;
    return opening_ ? opening_->request().path : none;
}
OpenPhase Model::openPhase() const { return opening_ ? opening_->phase() : OpenPhase::Done; }
uint32_t Model::openProgress() const { return opening_ ? opening_->progress() : 0; }
uint32_t Model::openTotal() const { return opening_ ? opening_->total() : 0; }

// An outline's verdict is its note alone (prepared_run.h).
void Model::setNote(std::string note) {
    note_ = std::move(note);
    setVerdict(noteVerdict(note_));
}

void Model::adoptOutline() {
    OpenJob& j = *opening_;
    playing_ = false;
    ++generation_;
    path_ = j.request().path;
    openDiag_ = {};
    warnings_ = j.warnings();
    cancelInvariants();      // the scan reads the trace about to be replaced
    adopt(j.takeOutline());  // prepared by the job, its note "validating... N vertices"
    const std::string note =
        openNote(std::max(j.phase(), OpenPhase::Validate), trace_->polygon.vertices.size());
    if (note != note_) setNote(note);
    outlineShown_ = true;
}

void Model::adoptOpened() {
    OpenJob& j = *opening_;
    // The outline was fitted already: a view the user moved meanwhile stays.
    const bool fit = !outlineShown_ || needsFit_;
    const bool trace = j.request().trace;
    const Up up = up_;
    adoptOpen(j.request().path, j.warnings(), j.takeRun());
    if (!trace) up_ = up;  // a polygon's open floods along the dial's direction, kept
    needsFit_ = fit;
    remember(j.request().path);
}

bool Model::pollOpen() {
    retired_.erase(std::remove_if(retired_.begin(), retired_.end(),
                                  [](const std::unique_ptr<OpenJob>& j) { return j->done(); }),
                   retired_.end());
    if (!opening_) return false;
    OpenJob& j = *opening_;
    const bool done = j.done();
    const OpenPhase phase = j.phase();
    if (!done) {
        // A failed read has no outline to show: what it ended with waits for done().
        if (!j.outlineReady()) return false;
        if (!outlineShown_) adoptOutline();
        else if (phase != OpenPhase::Read && phase != OpenPhase::Done &&
                 openNote(phase, trace_->polygon.vertices.size()) != note_)
            setNote(openNote(phase, trace_->polygon.vertices.size()));
        return false;
    }
    const Diagnostic& read = j.readDiagnostic();
    if (!read.ok()) failedOpen(j.request().path, read);  // as open()
    else adoptOpened();
    opening_.reset();
    outlineShown_ = false;
    return true;
}

void Model::cancelOpen() {
    if (!opening_) return;
    opening_->requestCancel();
    // Read and shown: the outline stays, saying it was not flooded.
    if (outlineShown_)
        setNote("not flooded: the open was cancelled while " +
                std::string(openPhaseName(opening_->phase())) + " (" +
                std::to_string(trace_->polygon.vertices.size()) + " vertices read)");
    // It ends its phase in the background; pollOpen forgets it then, ~Model joins it.
    retired_.push_back(std::move(opening_));
    outlineShown_ = false;
}

void Model::waitOpen() {
    while (opening_) {
        opening_->wait();
        pollOpen();
    }
}

bool Model::openFeature(const std::string& path, size_t index) {
    cancelOpen();
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
    PreparedRun run;
    floodRun(std::move(f.read.polygon), name, up_, run);
    adoptOpen(name, std::move(f.read.warnings), std::move(run));
    feature_ = index;
    remember(path);
    return true;
}

void Model::openShrunk(const ShrinkResult& result) {
    const std::string from = path_;
    const size_t fromFeature = feature_;
    PreparedRun run;
    floodRun(result.polygon, from + " (shrunk)", up_, run);
    adoptOpen(from + " (shrunk)", {}, std::move(run));
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
