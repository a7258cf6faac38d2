#include "shrink_worker.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "download.h"

#ifdef __EMSCRIPTEN__
#include <emscripten.h>

// The page's side of the worker. Each shrink is Module.floodShrinks[id]: how it ended (0
// running, 1 finished, 2 crashed, 3 cancelled), the last progress, the CLI's exit code. When
// it ends, what C++ reads is written into the page's file system: /shrink/ID.geojson (the
// repro), ID.log (the CLI's messages), ID.error (a crash's). Every message wakes the frame
// loop (the "flood-wake" event, viewer/platform_glfw.cpp). A test-only URL parameter,
// test-shrink-crash=N, makes the worker trap at its Nth clock reading (about the Nth try);
// test-shrink-slow=MS makes each reading MS longer (a shrink long enough to watch).
// clang-format off
EM_JS(int, flood_web_shrink_start, (const char* input, const char* up), {
    const all = Module["floodShrinks"] = Module["floodShrinks"] || { next: 1 };
    const id = all.next++;
    const s = all[id] = { end: 0, tries: 0, vertices: 0, code: -1, log: [] };
    const file = UTF8ToString(input);
    const finish = (end, error) => {
        if (s.end) return;
        s.end = end;
        s.worker && s.worker.terminate();
        FS.writeFile("/shrink/" + id + ".log", s.log.join("\n"));
        FS.writeFile("/shrink/" + id + ".error", error || "");
        window.dispatchEvent(new Event("flood-wake"));
    };
    // Frames go on while it runs, so its progress moves (the frame loop idles otherwise).
    const ticks = setInterval(() => window.dispatchEvent(new Event("flood-wake")), 1000 / 30);
    s.finish = (end, error) => { clearInterval(ticks); finish(end, error); };
    try {
        s.worker = new Worker("shrink-worker.js");
    } catch (e) {
        s.finish(2, "no worker: " + e);
        return id;
    }
    s.worker.onmessage = (e) => {
        const m = e.data;
        if (m.progress) s.tries = m.progress[0], s.vertices = m.progress[1];
        if (typeof m.line === "string") s.log.push(m.line);
        if (typeof m.done === "number") {
            s.code = m.done;
            if (m.repro) FS.writeFile("/shrink/" + id + ".geojson", m.repro);
            s.finish(1);
        }
        window.dispatchEvent(new Event("flood-wake"));
    };
    // A trap, an abort or a script that does not load: the worker's error, not the page's.
    s.worker.onerror = (e) => {
        e.preventDefault();
        console.warn("flood-viewer: the shrink's worker stopped: " + e.message);
        s.finish(2, e.message || "the worker stopped");
    };
    const query = new URLSearchParams(location.search);
    const crashAt = Number(query.get("test-shrink-crash")) || 0;
    const slowMs = Number(query.get("test-shrink-slow")) || 0;
    s.worker.postMessage({ name: file.slice(file.lastIndexOf("/") + 1), bytes: FS.readFile(file),
                           args: UTF8ToString(up) ? ["--up", UTF8ToString(up)] : [], crashAt,
                           slowMs });
    return id;
});
EM_JS(double, flood_web_shrink_number, (int id, int what), {
    const s = (Module["floodShrinks"] || {})[id];
    return s ? [s.end, s.tries, s.vertices, s.code][what] : 3;
});
EM_JS(void, flood_web_shrink_end, (int id, int forget), {
    const s = (Module["floodShrinks"] || {})[id];
    if (!s) return;
    s.finish(3);
    if (forget) delete Module["floodShrinks"][id];
});
// clang-format on
#endif

namespace flood::view {

namespace {

// The last line of `log` that says `marker`, from it on; "" when none.
std::string lastLineWith(const std::string& log, const std::string& marker) {
    const size_t at = log.rfind(marker);
    if (at == std::string::npos) return "";
    const size_t end = log.find('\n', at);
    return log.substr(at, end == std::string::npos ? std::string::npos : end - at);
}

Failure::Kind kindNamed(const std::string& name) {
    using K = Failure::Kind;
    for (K k : {K::Forbidden, K::CheckerRejects, K::Crash, K::Hang, K::Slips})
        if (name == failureKindName(k)) return k;
    return K::None;
}

Forbidden reasonNamed(const std::string& name) {
    for (int f = 0; f < int(Forbidden::Count); ++f)
        if (name == forbiddenName(Forbidden(f))) return Forbidden(f);
    return Forbidden::None;
}

std::string triesAndSize(const WorkerReport& r) {
    if (r.tries == 0) return "before its first progress report";
    return "after " + std::to_string(r.tries) + " tries, at " + std::to_string(r.vertices) +
           " vertices";
}

}  // namespace

ShrinkResult shrinkResultFromWorker(const WorkerReport& report, const std::string& name) {
    ShrinkResult r;
    auto none = [&](std::string why) {
        r.failure = {Failure::Kind::None, Forbidden::None, std::move(why)};
        return r;
    };
    if (report.exitCode != 0 || report.repro.empty()) {
        std::string error = lastLineWith(report.log, "error: ");
        return none(error.empty() ? "flood shrink ended with exit code " +
                                        std::to_string(report.exitCode) + " and no repro"
                                  : error.substr(7));
    }
    ReadResult read = parsePolygon(report.repro, name);
    if (!read.diagnostic.ok())
        return none("the repro does not read back: " + read.diagnostic.message);
    const nlohmann::json doc = nlohmann::json::parse(report.repro, nullptr, false);
    const nlohmann::json props =
        doc.is_object() && doc.contains("properties") ? doc["properties"] : nlohmann::json();
    if (!props.is_object() || !props.value("failure", nlohmann::json()).is_string())
        return none("the repro does not say how it fails");
    r.polygon = std::move(read.polygon);
    r.failure.kind = kindNamed(props["failure"].get<std::string>());
    if (props.contains("reason") && props["reason"].is_string())
        r.failure.reason = reasonNamed(props["reason"].get<std::string>());
    if (props.contains("message") && props["message"].is_string())
        r.failure.message = props["message"].get<std::string>();
    if (props.contains("source_vertices") && props["source_vertices"].is_array())
        for (const auto& ring : props["source_vertices"])
            if (ring.is_array())
                for (const auto& v : ring)
                    if (v.is_number_unsigned()) r.origin.push_back(v.get<Index>());
    // The CLI's summary: "shrink: KIND[ (input valid, kept valid)]: ... -> ... (N runs)". Found
    // without std::regex, which alone cost the page 90 KB of wasm (docs/BENCHMARKS.md).
    for (size_t at = report.log.find("shrink: "); at != std::string::npos;
         at = report.log.find("shrink: ", at + 1)) {
        const std::string line = report.log.substr(at, report.log.find('\n', at) - at);
        const size_t open = line.rfind(" ("), runs = line.size() - 6;
        if (line.size() < 6 || line.compare(runs, 6, " runs)") != 0 || open == std::string::npos ||
            open + 2 >= runs || line.find_first_not_of("0123456789", open + 2) != runs)
            continue;
        r.inputValid = line.find(" (input valid, kept valid): ") != std::string::npos;
        r.tries = std::stoul(line.substr(open + 2, runs - open - 2));
        break;
    }
    r.reproduces = true;  // the CLI writes a repro only once it failed the same way read back
    return r;
}

std::string workerStopNote(const WorkerReport& report) {
    switch (report.end) {
        case WorkerReport::End::Crashed:
            return "the shrink stopped with a crash " + triesAndSize(report) + " (" + report.error +
                   "). In the page every try runs in one worker, so a try that crashes ends "
                   "the shrink there; the polygon shown is unchanged.";
        case WorkerReport::End::Cancelled:
            return "shrink cancelled " + triesAndSize(report) +
                   "; in the page a shrink keeps its repro only once it ends.";
        default: return "";
    }
}

#ifdef __EMSCRIPTEN__
bool ShrinkWorker::available() { return true; }

void ShrinkWorker::start(const Polygon& polygon, const ShrinkOptions& options) {
    reset();
    std::filesystem::create_directories("/shrink");
    const std::string input = "/shrink/input.geojson";
    {
        std::ofstream out(input, std::ios::binary | std::ios::trunc);
        writePolygonJson(out, polygon);
    }
    const std::string up = options.flood.up == Up::PlusY ? "" : upName(options.flood.up);
    id_ = flood_web_shrink_start(input.c_str(), up.c_str());
}

const WorkerReport& ShrinkWorker::poll() {
    if (!id_ || report_.end != WorkerReport::End::Running) return report_;
    report_.tries = size_t(flood_web_shrink_number(id_, 1));
    report_.vertices = size_t(flood_web_shrink_number(id_, 2));
    const int end = int(flood_web_shrink_number(id_, 0));
    if (end == 0) return report_;
    report_.end = WorkerReport::End(end);
    report_.exitCode = int(flood_web_shrink_number(id_, 3));
    const std::string base = "/shrink/" + std::to_string(id_);
    auto text = [](const std::string& path) {  // "" when the worker wrote none
        Download d;
        return readDownload(path, d, nullptr) ? d.bytes : std::string();
    };
    report_.repro = text(base + ".geojson");
    report_.log = text(base + ".log");
    report_.error = text(base + ".error");
    for (const char* ext : {".geojson", ".log", ".error"}) std::remove((base + ext).c_str());
    return report_;
}

void ShrinkWorker::cancel() {
    if (id_) flood_web_shrink_end(id_, 0);
}

void ShrinkWorker::reset() {
    if (id_) {
        flood_web_shrink_end(id_, 1);
        for (const char* ext : {".geojson", ".log", ".error"})
            std::remove(("/shrink/" + std::to_string(id_) + ext).c_str());
    }
    id_ = 0;
    report_ = {};
}
#else
bool ShrinkWorker::available() { return false; }
void ShrinkWorker::start(const Polygon&, const ShrinkOptions&) {}
const WorkerReport& ShrinkWorker::poll() { return report_; }
void ShrinkWorker::cancel() {}
void ShrinkWorker::reset() {
    id_ = 0;
    report_ = {};
}
#endif

}  // namespace flood::view
