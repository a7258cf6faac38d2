// `flood check`: the pipeline of the other commands (read -> validate -> flood -> exact
// check) run on every feature of every file, in parallel, one row per feature.
//
// The unit of failure is the feature: a MultiPolygon's parts may touch or overlap, which is
// a failure of the feature (validate() names the ring, the row adds its part). A file that
// is no FeatureCollection is one feature; a file that cannot be read or parsed is one row.
//
// Work is a queue of jobs: reading a file puts its features at the front, so files are read
// only when no feature waits and a few files are in memory at a time. Rows are kept in
// input order and printed at the end: the output is the same for any -j.
#include "check.h"

#include "check_progress.h"
#include "check_rows.h"
#include "task_runner.h"
#include "verbosity.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <new>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "flood/check/checker.h"
#include "flood/check/diagnostic_where.h"
#include "flood/check/verdict.h"
#include "flood/io/io.h"
#include "flood/io/output.h"
#include "flood/machine/flood.h"
#include "flood/tools/shrink.h"

namespace flood::cli {
namespace {

namespace fs = std::filesystem;

// One input file: its features while they wait, then their rows.
struct File {
    explicit File(std::string p, std::string e = "") : path(std::move(p)), error(std::move(e)) {}
    std::string path;
    std::string error;  // a folder that could not be listed or holds no polygon file
    std::vector<FeatureRead> features;
    std::vector<std::string> warnings;
    std::vector<Row> rows;
};

std::string displayName(const std::string& path) { return path == "-" ? "<stdin>" : path; }

std::string oneLine(std::string s) {
    std::replace_if(
        s.begin(), s.end(), [](char c) { return c == '\n' || c == '\r' || c == '\t'; }, ' ');
    return s;
}

// A diagnostic split into where (from its culprits) and why; the ring's part is added when the
// feature has several.
Finding findingOf(const Diagnostic& d, const std::string& name, const Polygon& p) {
    Finding f;
    Where where = whereOf(p, d.culprits);
    f.at = where.text;
    f.reason = oneLine(reasonOf(d.message, name, where));
    f.message = oneLine(d.message);
    f.ring = where.ring, f.vertex = where.vertex;
    for (uint32_t e : d.culprits.edges)
        if (e < p.vertices.size()) {
            const Index r = p.ringOf(e);
            const Ring& ring = p.rings[r];
            const Index next = e + 1 == ring.first + ring.count ? ring.first : e + 1;
            f.edges.push_back({r, e - ring.first, p.vertices[e], p.vertices[next]});
        }
    Point q;
    if (diagnosticPoint(p, d.culprits, q, true)) f.located = true, f.x = q.x, f.y = q.y;
    if (p.parts.size() > 1 && where.ring != kNone)
        for (size_t k = 0; k < p.parts.size(); ++k)
            if (where.ring >= p.parts[k].firstRing &&
                where.ring < p.parts[k].firstRing + p.parts[k].ringCount)
                f.at += " (part " + std::to_string(k) + ")";
    return f;
}

// validate()'s verdict, and every other finding of the feature.
void splitInvalid(Row& row, const std::string& name, const Polygon& p, Diagnostic verdict,
                  size_t maxFindings) {
    Findings all = validateAll(p, name, std::move(verdict), maxFindings);
    for (const Diagnostic& d : all.list) row.findings.push_back(findingOf(d, name, p));
    row.findingsOmitted = all.omitted;
    row.findingsComplete = all.complete;
    if (!row.findings.empty()) row.at = row.findings[0].at, row.reason = row.findings[0].reason;
}

// Numbered as describeForbidden() numbers them (steps from 1).
std::string forbiddenAt(const Polygon& p, const Event& e) {
    std::string at =
        std::string(forbiddenName(e.reason)) + " at step " + std::to_string(e.step + 1);
    if (e.culprit != kNone && e.culprit < p.vertices.size()) {
        Index r = p.ringOf(e.culprit);
        at += ", ring " + std::to_string(r) + " vertex " +
              std::to_string(e.culprit - p.rings[r].first);
    }
    return at;
}

std::string polygonJson(const Polygon& p) {
    std::ostringstream s;
    writePolygonJson(s, p);
    return s.str();
}

// Read, validate, flood, check: the first failure is the verdict.
void checkFeature(FeatureRead& f, Row& row, const CheckOptions& o) {
    const std::string name = displayName(row.file);
    row.wholeFile = f.wholeFile;
    row.feature = f.fid;
    row.id = f.id;
    row.name = f.name;
    row.layer = f.layer;
    row.attributes = f.attributes;
    bool readable = f.read.diagnostic.ok();
    try {
        Polygon& p = f.read.polygon;
        row.vertices = p.vertices.size();
        Judgement j = judge(f.read, name, {o.validate, true, {}});
        row.verdict = j.verdict;
        if (!readable) {
            row.reason = reasonOf(j.diagnostic.message, name, {});  // the name has a column
        } else if (j.verdict == Verdict::Invalid) {
            splitInvalid(row, name, p, std::move(j.diagnostic), o.maxFindings);
        } else if (j.verdict == Verdict::Forbidden) {
            row.at = forbiddenAt(p, j.failure);
            row.reason = j.diagnostic.message;
            row.place = findingOf(j.diagnostic, name, p);
        } else if (j.verdict == Verdict::Checker) {
            row.reason = "the exact checker rejects the triangulation: " + j.check.reason;
        }
        // A whole file is copied at extraction (cannot be re-read from stdin: written anew).
        if (row.verdict != Verdict::Ok && !o.extractDir.empty())
            // A GIS feature has no GeoJSON source: its polygon is written as read.
            row.repro = !f.wholeFile
                            ? (f.source.empty() && readable ? polygonJson(p) : std::move(f.source))
                        : row.file == "-" && readable ? polygonJson(p)
                                                      : "";
    } catch (const std::bad_alloc&) {
        row.verdict = Verdict::Internal;
        row.reason = "out of memory";
    } catch (const std::exception& e) {
        row.verdict = Verdict::Internal;
        row.reason = std::string("exception: ") + e.what();
    } catch (...) {
        row.verdict = Verdict::Internal;
        row.reason = "unknown exception";
    }
    row.reason = oneLine(std::move(row.reason));
    f = FeatureRead{};  // the polygon is done with: free it now
}

}  // namespace

std::string grouped(size_t n) {
    std::string s = std::to_string(n);
    for (size_t i = s.size(); i > 3; i -= 3) s.insert(i - 3, ",");
    return s;
}

std::string folderFormats() { return gdal::listedFormats(); }

namespace {

// Folders become their polygon files, recursively, in sorted order.
std::vector<File> expand(const std::vector<std::string>& inputs) {
    std::vector<File> files;
    for (const std::string& in : inputs) {
        std::error_code ec;
        if (in == "-" || !fs::is_directory(in, ec)) {
            files.emplace_back(in);
            continue;
        }
        std::vector<std::string> found;
        fs::recursive_directory_iterator it(in, ec), end;
        for (; !ec && it != end; it.increment(ec)) {
            std::error_code fe;
            if (it->is_regular_file(fe) && gdal::listedFile(it->path().string()))
                found.push_back(it->path().string());
        }
        std::sort(found.begin(), found.end());
        for (std::string& f : found) files.emplace_back(std::move(f));
        if (ec) files.emplace_back(in, in + ": cannot list folder: " + ec.message());
        else if (found.empty())
            files.emplace_back(in, in + ": folder holds no polygon file (" + folderFormats() + ")");
    }
    return files;
}

// The job queue shared by the workers (see the header comment).
class Scheduler {
public:
    Scheduler(std::vector<File>& files, const CheckOptions& o) : files_(files), o_(o) {
        for (size_t i = 0; i < files.size(); ++i) queue_.push_back({i, kRead});
    }

    void work() {
        for (;;) {
            std::unique_lock<std::mutex> lock(m_);
            cv_.wait(lock, [&] { return !queue_.empty() || active_ == 0; });
            if (queue_.empty()) return;
            Job j = queue_.front();
            queue_.pop_front();
            ++active_;
            lock.unlock();
            std::vector<Job> more;
            if (j.feature == kRead) read(j.file, more);
            else {
                checkFeature(files_[j.file].features[j.feature], files_[j.file].rows[j.feature],
                             o_);
                ++featuresDone;
            }
            lock.lock();
            queue_.insert(queue_.begin(), more.begin(), more.end());
            --active_;
            lock.unlock();
            cv_.notify_all();
        }
    }

    std::atomic<size_t> filesRead{0}, featuresKnown{0}, featuresDone{0};
    ReadProgress* progress = nullptr;  // for the progress line, when there is one

private:
    static constexpr size_t kRead = SIZE_MAX;
    struct Job {
        size_t file, feature;
    };

    // GIS datasets through GDAL (core/io/gdal/), the rest by the core's readers.
    DatasetRead readDataset(const std::string& path, bool& gis) {
        Selection s = o_.selection;
        s.allLayers = true;  // each layer's features, each row naming its layer
        // A file is read only when no feature waits, so the other workers would mostly wait:
        // they parse slices of a large FeatureCollection beside this one.
        return gdal::readAnyFeatures(path, s, o_.maxInputBytes, !o_.extractDir.empty(), gis,
                                     progress, threadRunner(o_.jobs));
    }

    void read(size_t i, std::vector<Job>& more) {
        File& f = files_[i];
        bool gis = false;
        if (!f.error.empty()) {
            FeatureRead failed;
            failed.read.diagnostic = {Status::Malformed, f.error};
            f.features.push_back(std::move(failed));
        } else {
            try {
                DatasetRead d = readDataset(f.path, gis);
                f.features = std::move(d.features);
                f.warnings = std::move(d.skipped);
            } catch (const std::bad_alloc&) {
                f.features.assign(1, FeatureRead{});
                f.features[0].read.diagnostic = {
                    Status::Malformed, displayName(f.path) + ": out of memory while reading"};
            } catch (const std::exception& e) {
                f.features.assign(1, FeatureRead{});
                f.features[0].read.diagnostic = {
                    Status::Internal,
                    displayName(f.path) + ": exception while reading: " + e.what()};
            }
            for (const FeatureRead& r : f.features) {
                f.warnings.insert(f.warnings.end(), r.read.warnings.begin(), r.read.warnings.end());
                if (r.read.warningsOmitted)
                    f.warnings.push_back(displayName(f.path) + ": \u2026 and " +
                                         std::to_string(r.read.warningsOmitted) +
                                         " more warnings like these");
            }
        }
        f.rows.resize(f.features.size());
        std::set<std::string> layers;
        for (const FeatureRead& r : f.features) layers.insert(r.layer);
        for (size_t k = 0; k < f.features.size(); ++k) {
            f.rows[k].file = f.path;
            f.rows[k].gis = gis;
            f.rows[k].severalLayers = layers.size() > 1;
            more.push_back({i, k});
        }
        featuresKnown += f.features.size();
        ++filesRead;
    }

    std::vector<File>& files_;
    const CheckOptions& o_;
    std::mutex m_;
    std::condition_variable cv_;
    std::deque<Job> queue_;
    size_t active_ = 0;
};

// Names tried for one extracted feature before giving up (DIR/STEM_featureN-10000.json).
constexpr int kMaxExtractNames = 10000;

// Each failing feature as DIR/STEM_featureN.json (a second file of the same stem gets
// STEM-2_...); a failing whole file is copied as DIR/STEM_feature0.EXT, its format kept (JSON
// cannot hold the NaN of a WKT file). A name taken gets -2, -3, ... before the extension.
// Returns false when one could not be written.
bool extract(std::vector<Row*>& rows, const CheckOptions& o) {
    std::error_code ec;
    fs::create_directories(o.extractDir, ec);
    if (ec) {
        std::cerr << "error: " << o.extractDir
                  << ": cannot create the --extract folder: " << ec.message() << "\n";
        return false;
    }
    bool ok = true;
    std::set<std::string> stems;
    std::string lastFile, stem;
    for (Row* r : rows) {
        if (r->verdict == Verdict::Ok) continue;
        if (r->file != lastFile) {
            lastFile = r->file;
            std::string base = r->file == "-" ? "stdin" : fs::path(r->file).stem().string();
            stem = base;
            for (int k = 2; !stems.insert(stem).second; ++k) stem = base + "-" + std::to_string(k);
        }
        // A GIS feature, copied as it was through GDAL (an unreadable one has no FID).
        if (r->gis) {
            if (!r->wholeFile && r->feature >= 0 && !extractGis(*r, o.extractDir, stem)) ok = false;
            continue;
        }
        std::string text = std::move(r->repro), ext = ".json";
        if (r->wholeFile && r->file != "-") {
            ext = fs::path(r->file).extension().string();
            if (!readInputFile(r->file, text, o.maxInputBytes, "GeoJSON or WKT").ok()) continue;
        }
        if (text.empty()) continue;  // unreadable: there is nothing to extract
        // Never over an existing file (an earlier run's, or an input being checked): the
        // first free name of STEM_featureN.EXT, STEM_featureN-2.EXT, ... (made atomically).
        const std::string base =
            (fs::path(o.extractDir) / (stem + "_feature" + std::to_string(r->feature))).string();
        for (int k = 1;; ++k) {
            std::string path = base + (k == 1 ? "" : "-" + std::to_string(k)) + ext;
            Output out(path, Output::IfExists::Fail);
            if (out.error() != EEXIST) out.stream() << text;
            std::string message;
            if (out.commit(&message) == Status::Ok) {
                r->extracted = path;
                break;
            }
            if (out.error() == EEXIST && k < kMaxExtractNames) continue;
            std::cerr << (out.error() == EEXIST
                              ? "error: " + base + ext + ": " + std::to_string(k) +
                                    " names taken, nothing extracted"
                              : message)
                      << "\n";
            ok = false;
            break;
        }
    }
    return ok;
}

// Warnings of one kind (what follows a warning's last ": ", as "repeated point dropped") shown
// per file before the rest of that kind is counted: 2,000 features with a repeated point were
// 2,000 lines.
constexpr size_t kWarningsShownPerKind = 3;

// A file's warnings as printed: the first of each kind in full (each names its feature), then
// "FILE: ... and N more like it (KIND)" for each kind, in the order the kinds first came.
std::vector<std::string> folded(const std::vector<std::string>& warnings, const std::string& file) {
    std::vector<std::string> out;
    std::vector<std::pair<std::string, size_t>> kinds;  // each kind and how many
    for (const std::string& w : warnings) {
        const size_t colon = w.rfind(": ");
        const std::string kind = colon == std::string::npos ? w : w.substr(colon + 2);
        auto k = std::find_if(kinds.begin(), kinds.end(),
                              [&](const auto& seen) { return seen.first == kind; });
        if (k == kinds.end()) k = kinds.insert(kinds.end(), {kind, 0});
        if (k->second++ < kWarningsShownPerKind) out.push_back(w);
    }
    for (const auto& [kind, n] : kinds)
        if (n > kWarningsShownPerKind)
            out.push_back(file + ": \u2026 and " + grouped(n - kWarningsShownPerKind) +
                          " more like it (" + kind + ")");
    return out;
}

size_t width(const std::string& s) {  // UTF-8 code points
    return size_t(std::count_if(s.begin(), s.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

// Control characters made visible (\n, \t, \r, \e, \xHH; C1 controls \u0080 ... \u009f): a
// feature's name or a file name must not move the terminal's cursor, change its colours or
// forge a row of the table. JSON escapes them itself.
std::string printable(const std::string& s) {
    std::string out;
    out.reserve(s.size());
    char hex[8];
    for (size_t i = 0; i < s.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(s[i]);
        if (c == 0xC2 && i + 1 < s.size() && static_cast<unsigned char>(s[i + 1]) >= 0x80 &&
            static_cast<unsigned char>(s[i + 1]) <= 0x9F) {
            std::snprintf(hex, sizeof hex, "\\u%04x", unsigned(static_cast<unsigned char>(s[++i])));
            out += hex;
        } else if (c >= 0x20 && c != 0x7F) {
            out += char(c);
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\t') {
            out += "\\t";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == 0x1B) {
            out += "\\e";
        } else {
            std::snprintf(hex, sizeof hex, "\\x%02x", unsigned(c));
            out += hex;
        }
    }
    return out;
}

// Cut to one table cell, never inside a UTF-8 sequence.
std::string cell(const std::string& s, size_t max) {
    if (s.size() <= max) return s;
    size_t n = max;
    while (n > 0 && (static_cast<unsigned char>(s[n]) & 0xC0) == 0x80) --n;
    return s.substr(0, n) + "\u2026";
}

void printTable(const std::vector<Row*>& rows) {
    std::vector<std::array<std::string, 7>> cells;
    cells.push_back({"FILE", "FEATURE", "ID/NAME", "VERTICES", "VERDICT", "AT", "REASON"});
    for (const Row* r : rows) {
        const std::string& label = !r->id.empty() ? r->id : r->name;
        // A dataset of several layers: each row says its layer.
        cells.push_back(
            {printable(r->file) + (r->severalLayers ? " (layer " + printable(r->layer) + ")" : ""),
             r->wholeFile ? "-" : std::to_string(r->feature),
             label.empty() ? "-" : printable(label), std::to_string(r->vertices),
             verdictName(r->verdict), r->at.empty() ? "-" : cell(printable(r->at), 80),
             r->reason.empty() ? "-" : cell(printable(r->reason), 120)});
        // The feature's other findings under it, in the AT and REASON columns.
        for (size_t k = 1; k < r->findings.size(); ++k)
            cells.push_back({"", "", "", "", "", cell(printable(r->findings[k].at), 80),
                             cell(printable(r->findings[k].reason), 120)});
        if (r->findingsOmitted)
            cells.push_back(
                {"", "", "", "", "", "\u2026",
                 "and " + std::to_string(r->findingsOmitted) + " more findings (--max-findings)"});
        if (!r->findingsComplete)
            cells.push_back({"", "", "", "", "", "\u2026",
                             "the search for further crossings gave up (work cap)"});
    }
    std::array<size_t, 7> w{};
    for (const auto& c : cells)
        for (size_t k = 0; k < c.size(); ++k) w[k] = std::max(w[k], width(c[k]));
    for (const auto& c : cells) {
        std::string line;
        for (size_t k = 0; k < c.size(); ++k) {
            line += c[k];
            if (k + 1 < c.size()) line += std::string(w[k] - width(c[k]) + 2, ' ');
        }
        std::cout << line << "\n";
    }
}

}  // namespace

int runCheck(const CheckOptions& o) {
    auto t0 = std::chrono::steady_clock::now();
    std::vector<File> files = expand(o.inputs);
    Scheduler scheduler(files, o);
    ReadProgress reading;
    std::mutex m;  // one writer of the line at a time
    auto draw = [&] {
        std::fprintf(stderr, "\r\033[K%s",
                     progressLine(reading, scheduler.featuresDone, scheduler.featuresKnown,
                                  scheduler.filesRead, files.size())
                         .c_str());
        std::fflush(stderr);
    };
    // A progress line, redrawn at most 10 times a second and at each step of the reading
    // (readingStep), erased at the end. Hooked to the reading before any worker starts: a
    // worker quicker than the hook read a whole file with no line at all.
    const bool showProgress = verbosity != Verbosity::Quiet && isatty(STDERR_FILENO);
    std::atomic<uint64_t> shown{~uint64_t(0)};
    if (showProgress) {
        reading.changed = [&] {
            if (uint64_t step = readingStep(reading); shown.exchange(step) != step) {
                std::lock_guard<std::mutex> lock(m);
                draw();
            }
        };
        scheduler.progress = &reading;
    }
    std::vector<std::thread> workers;
    for (unsigned k = 0; k < std::max(1u, o.jobs); ++k)
        workers.emplace_back([&] { scheduler.work(); });
    double seconds = 0;
    auto joinWorkers = [&] {
        for (std::thread& t : workers) t.join();
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    };
    if (showProgress) {
        std::condition_variable cv;
        bool finished = false;
        std::thread progress([&] {
            std::unique_lock<std::mutex> lock(m);
            do {
                draw();
            } while (!cv.wait_for(lock, std::chrono::milliseconds(100), [&] { return finished; }));
            std::fprintf(stderr, "\r\033[K");
            std::fflush(stderr);
        });
        joinWorkers();
        {
            std::lock_guard<std::mutex> lock(m);
            finished = true;
        }
        cv.notify_one();
        progress.join();
    } else {
        joinWorkers();
    }

    std::vector<Row*> rows;
    for (File& f : files) {
        for (const std::string& w : folded(f.warnings, displayName(f.path)))
            warning() << printable(w) << "\n";
        for (Row& r : f.rows) {
            rows.push_back(&r);
            detail() << "check: " << printable(displayName(r.file))
                     << (r.wholeFile ? "" : ": feature " + std::to_string(r.feature)) << ": "
                     << verdictName(r.verdict) << ", " << r.vertices << " vertices\n";
        }
    }
    int code = 0;
    std::array<size_t, size_t(Verdict::Count)> count{};
    for (const Row* r : rows) {
        ++count[size_t(r->verdict)];
        code = std::max(code, int(verdictStatus(r->verdict)));
    }
    if (!o.extractDir.empty() && !extract(rows, o)) code = int(Status::WriteFailed);
    if (!o.findingsOut.empty() && writeFindings(rows, o.findingsOut) != 0)
        code = int(Status::WriteFailed);

    std::string summary = "check: " + std::to_string(rows.size()) +
                          (rows.size() == 1 ? " feature in " : " features in ") +
                          std::to_string(files.size()) +
                          (files.size() == 1 ? " file: " : " files: ");
    for (size_t v = 0; v < count.size(); ++v)
        summary += (v ? ", " : "") + std::to_string(count[v]) + " " + verdictName(Verdict(v));
    char time[32];
    std::snprintf(time, sizeof time, "; %.2f s", seconds);
    if (!o.json) {
        printTable(rows);
        std::cout << summary << time << "\n";
        return code;
    }
    using json = nlohmann::ordered_json;  // fields in the order of the table
    auto orNull = [](const std::string& s) { return s.empty() ? json(nullptr) : json(s); };
    // Locations as numbers, so a script needs not parse "(x, y)" out of the text.
    auto findingX = [](const Row* r, size_t k) {
        return k < r->findings.size() && r->findings[k].located ? json(r->findings[k].x)
                                                                : json(nullptr);
    };
    auto findingY = [](const Row* r, size_t k) {
        return k < r->findings.size() && r->findings[k].located ? json(r->findings[k].y)
                                                                : json(nullptr);
    };
    auto findingsJson = [&](const Row& r) {
        json list = json::array();
        for (const Finding& f : r.findings)
            list.push_back({{"ring", f.ring == kNone ? json(nullptr) : json(f.ring)},
                            {"vertex", f.vertex == kNone ? json(nullptr) : json(f.vertex)},
                            {"x", f.located ? json(f.x) : json(nullptr)},
                            {"y", f.located ? json(f.y) : json(nullptr)},
                            {"at", orNull(f.at)},
                            {"reason", f.reason}});
        return list;
    };
    json records = json::array();
    for (const Row* r : rows) {
        json attributes = json::object();
        for (const auto& [key, value] : r->attributes) attributes[key] = value;
        records.push_back({{"file", r->file},
                           {"layer", orNull(r->layer)},
                           {"feature", r->wholeFile ? json(nullptr) : json(r->feature)},
                           {"id", orNull(r->id)},
                           {"name", orNull(r->name)},
                           {"attributes", attributes},
                           {"vertices", r->vertices},
                           {"verdict", verdictName(r->verdict)},
                           {"code", int(verdictStatus(r->verdict))},
                           {"at", orNull(r->at)},
                           {"reason", orNull(r->reason)},
                           {"x", findingX(r, 0)},
                           {"y", findingY(r, 0)},
                           {"findings", findingsJson(*r)},
                           {"findings_omitted", r->findingsOmitted},
                           {"findings_complete", r->findingsComplete},
                           {"extracted", orNull(r->extracted)}});
    }
    json counts = json::object();
    for (size_t v = 0; v < count.size(); ++v) counts[verdictName(Verdict(v))] = count[v];
    json doc = {{"features", records},
                {"summary",
                 {{"files", files.size()},
                  {"features", rows.size()},
                  {"verdicts", counts},
                  {"code", code},
                  {"seconds", seconds}}}};
    // Invalid UTF-8 in a property or path is replaced, never a throw.
    std::cout << doc.dump(1, ' ', false, json::error_handler_t::replace) << "\n";
    return code;
}

}  // namespace flood::cli
