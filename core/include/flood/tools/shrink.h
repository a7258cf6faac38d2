// The shrinker behind `flood shrink`: given a polygon that fails, find a small polygon that
// fails the same way. Failures are classified by running the flood machine with validation
// skipped, in a forked child so that a crash or a hang is a failure class, not our death.
//
// Greedy, to a fixed point: remove parts and holes, then runs of vertices (halving the run
// length down to one), then coordinate precision (all coordinates rounded to integers, then
// to fewer significant bits, then vertex by vertex to integers). A candidate is kept when its
// failure has the same class (and the same forbidden reason) as the original and, when the
// original was valid per validate(), the candidate is still valid.
//
// A candidate is judged as the user will meet it: its bytes as written, read back by the same
// reader and prepared as `flood triangulate` prepares it (validated, or with --no-validate the
// T-junction search). A candidate the reader would change (two vertices made equal by rounding,
// then dropped as a repeated point) is refused: the repair could remove the very failure.
//
// A second mode (ShrinkOptions::slipping) shrinks an input that slips through the paper's
// verification unvalidated (§6's open conjecture): the kept candidates are those validate()
// refuses while verify() — the polygon and its complement flooded and checked, T-junctions
// from findTouches() — passes.
#pragma once
#include <functional>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "flood/geometry/polygon.h"
#include "flood/machine/events.h"
#include "flood/machine/flood.h"

namespace flood {

struct Failure {
    enum class Kind : uint8_t {
        None,            // triangulates and the exact checker accepts: nothing to shrink
        Forbidden,       // the machine stopped in a forbidden state (`reason`)
        CheckerRejects,  // the machine finished but the exact checker rejects its triangles
        Crash,           // the child died (signal, sanitizer report, exception)
        Hang,            // the child did not finish within the time limit
        Slips            // slipping mode: validate() refuses it, the unvalidated verify passes
    };
    Kind kind = Kind::None;
    Forbidden reason = Forbidden::None;  // Kind::Forbidden only
    std::string message;                 // human-readable, one line

    bool sameClass(const Failure& o) const { return kind == o.kind && reason == o.reason; }
};

const char* failureKindName(Failure::Kind k);

struct ShrinkOptions {
    Options flood;                 // the vertical
    bool fork = true;              // classify in a child process (crash/hang become classes)
    unsigned timeoutSeconds = 10;  // child time limit (a hang), with fork only
    size_t maxTries = 20000;       // classifications allowed during shrinking
    // Test-only hook: applied to the machine's triangles before the exact check, so a test
    // can plant a checker failure. Null in normal use.
    std::function<void(std::vector<Triangle>&)> corrupt;
    bool slipping = false;  // classify as Slips or None instead (see above)
    // Called before each classification with the tries made so far and the vertex count of
    // the smallest failing polygon found until then; returning false stops the shrink there
    // (the viewer's Cancel, the CLI's progress line).
    std::function<bool(size_t tries, size_t vertices)> onTry;
};

// Runs the machine (validation skipped) and the exact checker on `polygon`.
Failure classify(const Polygon& polygon, const ShrinkOptions& options);

struct ShrinkResult {
    Polygon polygon;            // the smallest failing polygon found (the input if none smaller)
    Failure failure;            // its failure (same class as the input's)
    bool inputValid = false;    // validate() accepted the input, so every candidate was kept valid
    size_t tries = 0;           // classifications made
    bool cancelled = false;     // onTry returned false
    std::vector<Index> origin;  // for each vertex of `polygon`, its index in the input
    // The written repro (writePolygonJson), read back, fails as `failure` says. Every kept
    // candidate does by construction; false only when the input itself does not survive being
    // written (nothing smaller was found and its own bytes read back differently).
    bool reproduces = false;
};

// Shrinks a failing polygon. If `polygon` does not fail, returns it with Failure::Kind::None.
ShrinkResult shrink(const Polygon& polygon, const ShrinkOptions& options);

// Reads `text` as `flood triangulate` does (validated when `validated`, else with the
// T-junction search of --no-validate) and classifies what it reads. Malformed or refused
// input is Kind::None with the reader's or validation's message: it does not fail the same way.
Failure classifyText(std::string_view text, const ShrinkOptions& options, bool validated);

// Where a repro came from, written into it so the engineer can find the spot in the full face.
struct ReproSource {
    std::string file;     // the input as named ("-" for stdin, "" when unknown)
    std::string feature;  // the feature of a dataset (its FID), "" for a whole file
    std::string up;       // the flood direction (--up), "" for the default
    std::string output;   // where the repro is written, for the command that shows it
};

// The command that shows the repro's failure, as the shrinker read it back: `flood triangulate`
// (with --no-validate when the input was invalid), or `flood verify --no-validate` (slipping).
std::string reproduceCommand(const ShrinkResult& result, const ReproSource& source);

// The repro as `flood shrink` writes it: a GeoJSON Feature whose geometry is the shrunk polygon
// and whose properties say where it came from (source file and feature, the input's vertex
// indices that remain, ring by ring, and their bounding box in the input's coordinates), what
// fails and the command that shows it. `input` is the polygon that was shrunk.
std::string reproJson(const Polygon& input, const ShrinkResult& result, const ReproSource& source);

}  // namespace flood
