// The flood machine (flood.cpp) as the rest of the core sees it: the memory it lends from run
// to run, and one run. The public entry points (triangulate.cpp) are built on it.
// Internal to core/, not a public API.
#pragma once
#include <vector>

#include "flood/machine/flood.h"
#include "machine/dry_bottoms.h"
#include "machine/heights.h"
#include "machine/loops.h"
#include "machine/sags/sag_search.h"
#include "machine/stretches.h"

namespace flood {

// A gorge waiting to be flooded again: pending on the to-do list, or held at a top.
struct GorgeRec {
    NodeId left, right, water;
    bool held = false;  // held at a top (Spill) rather than pending (Bridge)
    bool done = false;
};

// What the machine allocates, lent by a Triangulator (or the thread, for small inputs)
// from run to run, so that a run on an input no larger than the last one allocates nothing.
struct MachineBuffers {
    std::vector<Point> rotated;
    std::vector<uint32_t> ranks;  // off the axes (heights.h)
    std::vector<Index> rankOrder;
    Nodes nodes;
    std::vector<NodeId> partVertices, points;
    std::vector<uint32_t> todo;
    SagSearch sags;
    DryBottoms bottoms;
    std::vector<GorgeRec> gorges;
    Stretches walked;
    LoopScratch loops;
};

// Floods every part of `poly` into `out` (its triangles' capacity reused), with the buffers
// `keep` lends, or buffers of its own when it is null.
void flood(const Polygon& poly, Listener* listener, const Options& options, FloodResult& out,
           MachineBuffers* keep);

// Floods only the parts [firstPart, endPart) of a tiled polygon (Polygon::tiled()) into `out`,
// unrecorded, with buffers of its own; its steps are counted from 0. Parts are flooded each
// alone, so these triangles are the ones flood() gives those parts. False when a forbidden
// state was reached: `out` then has no failure event (flood() the whole polygon for it).
bool floodParts(const Polygon& poly, const Options& options, uint32_t firstPart, uint32_t endPart,
                FloodResult& out);

}  // namespace flood
