// The machine's public entry points (flood.h): triangulate() and Triangulator, which lend the
// machine its buffers (machine.h) from run to run.
#include "machine/machine.h"

namespace flood {

// Inputs up to this size reuse their thread's buffers: a program flooding many small polygons
// allocates little more than each result, and a thread keeps at most ~1 MB after a big one.
constexpr size_t kThreadBufferVertices = 4096;

// A MultiPolygon of at least this many vertices is flooded as tasks when a runner is given:
// below it a task's set-up costs more than it saves.
constexpr size_t kPartTasksFrom = 32768;
constexpr size_t kPartTasks = 8;

// The parts in runs of about equal size, each flooded alone as a task, the triangles joined
// in part order: the parts' floods share nothing but the polygon, so the result is the
// serial run's. When a run reaches a forbidden state, the whole polygon is flooded again
// serially, so that the failure and its message are the serial run's too.
static bool floodAsTasks(const Polygon& polygon, const Options& options, const TaskRunner& run,
                         FloodResult& result) {
    const std::vector<size_t> runs = cutEvenly(
        polygon.parts.size(), kPartTasks, [&](size_t k) { return polygon.partVertices(Index(k)); });
    std::vector<FloodResult> pieces(runs.size() - 1);
    std::vector<char> flooded(pieces.size(), 0);
    run(pieces.size(), [&](size_t t) {
        flooded[t] =
            floodParts(polygon, options, uint32_t(runs[t]), uint32_t(runs[t + 1]), pieces[t]);
    });
    for (char f : flooded)
        if (!f) return false;
    size_t triangles = 0;
    for (const FloodResult& piece : pieces) triangles += piece.triangles.size();
    result.triangles.reserve(triangles);
    for (const FloodResult& piece : pieces) {
        result.triangles.insert(result.triangles.end(), piece.triangles.begin(),
                                piece.triangles.end());
        result.steps += piece.steps;
    }
    return true;
}

FloodResult triangulate(const Polygon& polygon, Listener* listener, const Options& options,
                        const TaskRunner& run) {
    // Off +y every task would turn or rank the whole polygon's heights again (heights.h).
    if (run && !listener && polygon.parts.size() >= 2 &&
        polygon.vertices.size() >= kPartTasksFrom && options.up.x == 0 && options.up.y > 0 &&
        polygon.tiled()) {
        FloodResult result;
        if (floodAsTasks(polygon, options, run, result)) return result;
    }
    return triangulate(polygon, listener, options);
}

FloodResult triangulate(const Polygon& polygon, Listener* listener, const Options& options) {
    thread_local MachineBuffers buffers;
    thread_local bool lent = false;  // a listener that triangulates too gets buffers of its own
    struct Lending {
        bool active;
        ~Lending() {
            if (active) lent = false;
        }
    } lending{!lent && polygon.vertices.size() <= kThreadBufferVertices};
    if (lending.active) lent = true;
    FloodResult result;
    flood(polygon, listener, options, result, lending.active ? &buffers : nullptr);
    return result;
}

struct Triangulator::Workspace {
    MachineBuffers buffers;
    FloodResult result;
};
Triangulator::Triangulator() : workspace_(new Workspace) {}
Triangulator::~Triangulator() = default;
Triangulator::Triangulator(Triangulator&&) noexcept = default;
Triangulator& Triangulator::operator=(Triangulator&&) noexcept = default;
const FloodResult& Triangulator::run(const Polygon& polygon, Listener* listener,
                                     const Options& options) {
    Workspace& w = *workspace_;
    flood(polygon, listener, options, w.result, &w.buffers);  // refills the last result
    return w.result;
}

}  // namespace flood
