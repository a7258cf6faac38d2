// Flood's library in one include: read a polygon, validate it, flood it (recording the events
// when asked), replay and check the result, write it. `#include <flood/flood.h>` and link
// Flood::core (CMake) or `flood` (pkg-config); docs/LIBRARY.md shows a whole program. The
// teaching layer (narration, Fig. 9 and Fig. 10 as data) is <flood/teach.h>.
#pragma once
#include "flood/check/checker.h"           // checkTriangulation: the exact checker
#include "flood/check/diagnostic_where.h"  // where a diagnostic points: ring, vertex, x, y
#include "flood/check/invariants.h"        // the machine's invariants on a replayed step
#include "flood/check/touches.h"           // T-junctions without validating (--no-validate)
#include "flood/check/verdict.h"           // the verdict on a polygon, and the one judge
#include "flood/check/verify.h"            // the paper's verification by the complement
#include "flood/flood_api.h"               // rings in, triangles out, validated
#include "flood/geometry/polygon.h"        // Point, Polygon
#include "flood/geometry/predicates.h"     // the exact predicates convex, below, inside
#include "flood/geometry/status.h"         // Status, Diagnostic, culprits, exit codes
#include "flood/geometry/up.h"             // the direction the water rises along
#include "flood/io/io.h"                   // reading GeoJSON, ring arrays, WKT; validate()
#include "flood/io/output.h"               // outputs written completely or not at all
#include "flood/io/svg.h"                  // the SVG writer
#include "flood/log/replay.h"              // Trace, Replay: seek to any step
#include "flood/log/trace_io.h"            // trace files, JSON Lines and binary
#include "flood/machine/events.h"          // the event log, one record per action
#include "flood/machine/flood.h"           // triangulate(), Triangulator, Options
#include "flood/tools/generate.h"          // seeded polygon families
#include "flood/tools/shrink.h"            // a small polygon that fails the same way
