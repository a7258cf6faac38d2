// Public entry point of the core: triangulate a polygon by flooding (Ronfard & Rossignac 1994).
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "flood/geometry/polygon.h"
#include "flood/geometry/status.h"
#include "flood/geometry/task_runner.h"
#include "flood/geometry/up.h"
#include "flood/machine/events.h"

namespace flood {

struct Options {
    Up up = Up::PlusY;  // the chosen vertical (§3), any direction (up.h)
};

struct FloodResult {
    std::vector<Triangle> triangles;  // counter-clockwise, numbered in the order flooded
    Diagnostic diagnostic;            // Ok, or Forbidden with the explanation
    Event failure;                    // the Forbidden event when diagnostic is not Ok
    uint32_t steps = 0;               // events emitted
};

// Floods every part of `polygon`. The polygon should have passed validate(); invalid input
// ends in a Forbidden diagnostic, never a crash or a hang. `listener` may be null.
FloodResult triangulate(const Polygon& polygon, Listener* listener = nullptr,
                        const Options& options = {});
// The same result, the parts of a large MultiPolygon flooded as tasks given to `run` (several
// at once if it has threads): with no listener, on +y (the default), from kPartTasksFrom
// vertices (triangulate.cpp).
FloodResult triangulate(const Polygon& polygon, Listener* listener, const Options& options,
                        const TaskRunner& run);

// Triangulates polygon after polygon keeping its working memory (the machine's loops, sag
// lists, gorges, and the result) from call to call, as earcut keeps its node pool: once its
// buffers have grown to the largest input seen, a call allocates nothing. Results equal
// triangulate()'s. One per thread, and not re-entrant: a listener must not call run() on the
// Triangulator that calls it. The result is valid until the next run().
class Triangulator {
public:
    Triangulator();
    ~Triangulator();
    Triangulator(Triangulator&&) noexcept;
    Triangulator& operator=(Triangulator&&) noexcept;
    const FloodResult& run(const Polygon& polygon, Listener* listener = nullptr,
                           const Options& options = {});

    struct Workspace;  // core/machine/triangulate.cpp

private:
    std::unique_ptr<Workspace> workspace_;
};

// triangulate(polygon, listener, options) cut in slices, for a caller that must not hold still
// for a large run and has no thread to give it (the web page floods between its frames): each
// advance() takes at most `steps` of the machine's steps (an event each). The same events,
// triangles and diagnostic as triangulate(). `polygon` and `listener` must outlive it.
class SteppedRun {
public:
    SteppedRun(const Polygon& polygon, Listener* listener, const Options& options = {});
    ~SteppedRun();
    SteppedRun(const SteppedRun&) = delete;
    SteppedRun& operator=(const SteppedRun&) = delete;
    bool advance(uint64_t steps);  // false once the run has ended
    uint32_t steps() const;        // taken so far
    FloodResult& result();         // whole once advance() returned false

private:
    struct Impl;  // core/machine/flood.cpp
    std::unique_ptr<Impl> impl_;
};

// Human-readable description of a forbidden event, naming the vertices (index, ring, x, y).
std::string describeForbidden(const Polygon& polygon, const Event& e);
// The event's vertices as data (its culprits first, then the fingers before it) and their rings.
Culprits forbiddenCulprits(const Polygon& polygon, const Event& e);

}  // namespace flood
