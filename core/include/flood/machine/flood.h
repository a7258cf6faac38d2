// Public entry point of the core: triangulate a polygon by flooding (Ronfard & Rossignac 1994).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "flood/geometry/polygon.h"
#include "flood/geometry/status.h"
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

// Human-readable description of a forbidden event, naming the vertices (index, ring, x, y).
std::string describeForbidden(const Polygon& polygon, const Event& e);
// The event's vertices as data (its culprits first, then the fingers before it) and their rings.
Culprits forbiddenCulprits(const Polygon& polygon, const Event& e);

}  // namespace flood
