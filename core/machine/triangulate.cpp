// The machine's public entry points (flood.h): triangulate() and Triangulator, which lend the
// machine its buffers (machine.h) from run to run.
#include "machine/machine.h"

namespace flood {

// Inputs up to this size reuse their thread's buffers: a program flooding many small polygons
// allocates little more than each result, and a thread keeps at most ~1 MB after a big one.
constexpr size_t kThreadBufferVertices = 4096;

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
