// The verdict on one polygon, and the one judge every front end calls (flood triangulate and
// flood check, the viewer's open, edit and feature list, the Python module): read -> validate
// -> flood -> exact check, the first failure being the verdict. What each front end prints
// about it is its own; which verdict, and its exit status, is decided here.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "flood/check/checker.h"
#include "flood/geometry/status.h"
#include "flood/io/io.h"
#include "flood/machine/flood.h"

namespace flood {

// The verdicts, in increasing severity (a run of many features exits with its worst): name,
// the word the outputs use (flood check's table and --json, the viewer), the exit status, and
// what it means.
#define FLOOD_VERDICTS(X)                                                                    \
    X(Ok, "ok", Ok, "read, valid, flooded, and the exact checker accepts the triangles")     \
    X(Malformed, "malformed", Malformed, "the input cannot be read as a polygon")            \
    X(Invalid, "invalid", Invalid, "the polygon breaks a validity rule (docs/ERRORS.md)")    \
    X(Forbidden, "forbidden", Forbidden, "the flood machine stopped in a forbidden state")   \
    X(Checker, "checker", Internal, "the exact checker rejects the machine's triangulation") \
    X(Internal, "internal", Internal, "a failure of Flood itself: an exception, out of memory")

enum class Verdict : uint8_t {
#define FLOOD_X(name, word, status, meaning) name,
    FLOOD_VERDICTS(FLOOD_X)
#undef FLOOD_X
        Count
};

const char* verdictName(Verdict v);     // "ok", "malformed", ...
Status verdictStatus(Verdict v);        // the exit status: Checker and Internal are both 6
const char* verdictMeaning(Verdict v);  // one line, for help texts

// A read's verdict: Ok, Malformed, or Internal when the reader failed itself (an exception).
Verdict verdictOfRead(const Diagnostic& read);

struct JudgeOptions {
    // false (--no-validate): the machine and the exact check are what catch invalid input.
    // The polygon is flooded as it is: T-junctions the caller has not recorded in it
    // (findTouches(), as `flood triangulate --no-validate` does) are not seen.
    bool validate = true;
    bool exactCheck = true;  // false (--no-exact-check): a flooded polygon is Ok, unproven
    Options flood;           // the machine's options (--up)
};

struct Judgement {
    Verdict verdict = Verdict::Ok;
    // Why, when not Ok: the read's, validation's or the machine's diagnostic as it was; for
    // Checker, Internal with "NAME: the exact checker rejects the triangulation: REASON".
    Diagnostic diagnostic;
    Event failure;                    // Forbidden: the forbidden event (FloodResult::failure)
    CheckResult check;                // the exact check's result, when it ran
    std::vector<Triangle> triangles;  // judge(): the flood's triangles (complete when Ok)
    bool ok() const { return verdict == Verdict::Ok; }
};

// A finished flood of `polygon` (its triangles and the machine's diagnostic `run`): Forbidden
// when the machine stopped in a forbidden state, Internal when it failed otherwise, else the exact check's verdict (skipped without `exactCheck`).
// `triangleCheck`, when given, waits for checkTriangles() run on another thread.
Judgement judgeRun(const Polygon& polygon, const std::vector<Triangle>& triangles,
                   const Diagnostic& run, const std::string& name, bool exactCheck = true,
                   const std::function<TriangleCheck()>& triangleCheck = {});

// The whole pipeline on a polygon read: validate (which records its T-junctions in it),
// flood, check. `name` names it in the diagnostics.
Judgement judge(Polygon& polygon, const std::string& name, const JudgeOptions& options = {});
// The same from a read result: its failure, if any, is the verdict.
Judgement judge(ReadResult& read, const std::string& name, const JudgeOptions& options = {});

}  // namespace flood
