// The shrinker in the page (docs/WEB.md): a browser has no fork(), so a try that traps would
// take the whole page down with it, and a shrink run inline would hold the page still. There
// the shrink runs in a Web Worker (web/shrink_worker.js) that runs the flood CLI built for it,
// `flood shrink` on the polygon's bytes: its progress line comes back as tries and vertices,
// its repro file as the result, and a crash or trap ends only the worker. Cancel terminates
// the worker. On the desktop ShrinkJob shrinks in a thread, each try in a forked child, and
// none of this is used (available() is false).
#pragma once
#include <cstddef>
#include <string>

#include "flood/geometry/up.h"
#include "flood/io/io.h"
#include "flood/tools/shrink.h"

namespace flood::view {

// What a worker reported. How it ended decides what the panel shows.
struct WorkerReport {
    enum class End { Running, Finished, Crashed, Cancelled };
    End end = End::Running;
    size_t tries = 0, vertices = 0;  // the last progress line (0: none yet)
    int exitCode = -1;               // Finished: the CLI's exit code
    std::string repro;               // Finished: the repro file's bytes ("" when none written)
    std::string log;                 // the CLI's messages, a line each (its stderr)
    std::string error;               // Crashed: the worker's error ("RuntimeError: ...")
};

// The shrink the panel opens, from a worker that finished: the repro read back as `flood
// triangulate` reads it, its failure from its properties, the tries from the CLI's summary
// line. When no repro was written, Failure::Kind::None with the CLI's error line.
ShrinkResult shrinkResultFromWorker(const WorkerReport& report, const std::string& name);

// The panel's note when a worker ended without a result (crashed, cancelled); "" otherwise.
std::string workerStopNote(const WorkerReport& report);

// One shrink in a Web Worker. In the page only; on the desktop start() does nothing.
class ShrinkWorker {
public:
    static bool available();  // true in the page
    ShrinkWorker() = default;
    ShrinkWorker(const ShrinkWorker&) = delete;
    ShrinkWorker& operator=(const ShrinkWorker&) = delete;
    ~ShrinkWorker() { reset(); }

    // Starts `flood shrink` on `polygon` written as GeoJSON (and --up when not the default),
    // after ending the one before.
    void start(const Polygon& polygon, const ShrinkOptions& options);
    bool started() const { return id_ != 0; }
    const WorkerReport& poll();  // asks the page how the worker is doing
    void cancel();               // terminates the worker; poll() then says Cancelled
    void reset();                // cancels and forgets

private:
    int id_ = 0;  // the page's number for the worker
    WorkerReport report_;
};

}  // namespace flood::view
