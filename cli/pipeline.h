// The pipeline every command of `flood` that floods follows (cli/main.cpp's header): read
// (warnings to stderr; Malformed -> exit 3) -> validate (Invalid -> exit 4) -> flood
// (Forbidden -> exit 5) -> exact check of our own output (failure -> exit 6) -> write.
// Exit codes are flood::Status values.
#pragma once
#include <cstdint>
#include <exception>
#include <functional>
#include <future>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "check.h"  // Selection
#include "flood/check/checker.h"
#include "flood/check/verdict.h"
#include "flood/io/io.h"
#include "flood/machine/flood.h"

namespace flood::cli {

inline int code(Status s) { return int(s); }

// --max-input-bytes of the subcommand that reads.
extern uint64_t maxInputBytes;
// --layer, --feature, --where of the subcommand that reads (GDAL datasets).
extern Selection selection;
// -j of `flood triangulate` (all cores unless given; other commands that read take all):
// the threads lent to the reading of a large geometry, to validation and to the flood of a
// MultiPolygon's parts (flood/geometry/task_runner.h), and with two the exact check beside
// the writing.
extern unsigned jobs;

// GIS datasets go to GDAL (core/io/gdal/), everything else to the core's own readers
// (gdal::readAny, flood/io/gdal/read_any.h), so the core library never depends on GDAL.
// `run` lends threads to the reading of a large geometry.
ReadResult readInput(const std::string& path, const TaskRunner& run = {});

// Reads and validates; on failure prints the diagnostic and returns its status.
// With `check` false (--no-validate) validation is skipped, so the flood machine itself
// diagnoses invalid input (docs/ERRORS.md, forbidden transitions); the T-junctions the machine
// needs are then found by findTouches(), which is safe on invalid input.
// With `floodInvalid` an invalid polygon is still handed back, prepared as --no-validate
// prepares it, with the status Invalid (`flood trace` floods it anyway).
Status prepare(const std::string& path, Polygon& polygon, bool check = true,
               bool floodInvalid = false);

// Checks a finished run (the core's judgeRun(), flood/check/verdict.h) and says why it failed.
// Forbidden -> 5 (its explanation), checker rejects -> 6. The exact
// check runs with --no-validate too (`validated` false): there it is what catches invalid
// input the machine cannot see, such as overlapping parts (flooded apart). --no-exact-check
// (`exactCheck` false) skips it: the output is then unproven.
// `triangleCheck`, when given, waits for checkTriangles() run on another thread.
Status judge(const Polygon& polygon, const std::vector<Triangle>& triangles, const Diagnostic& run,
             bool validated = true, bool exactCheck = true,
             const std::function<TriangleCheck()>& triangleCheck = {});

// The options of a command's --up (addUp has checked it).
Options makeOptions(const std::string& up);

// The exact check and the writing at once, on two threads (the machine and CI have two
// cores): the other thread checks each triangle alone (checkTriangles, flood/check/checker.h), then
// writes, while this one checks the rest. The output must be discardable: a failed check
// leaves it uncommitted, so nothing of it is seen and every message is the serial path's.
template <typename Write>
Status checkWhileWriting(const Polygon& polygon, const std::vector<Triangle>& triangles,
                         bool validated, Write&& write) {
    std::promise<TriangleCheck> each;
    std::future<TriangleCheck> eachReady = each.get_future();
    std::exception_ptr failed;  // of the writing
    std::thread other;
    try {
        other = std::thread([&] {
            try {
                each.set_value(checkTriangles(polygon, triangles));
            } catch (...) {
                each.set_exception(std::current_exception());
                return;
            }
            try {
                write();
            } catch (...) {
                failed = std::current_exception();
            }
        });
    } catch (const std::system_error&) {  // no thread to be had: one after the other
        Status s = judge(polygon, triangles, Diagnostic{}, validated);
        if (s == Status::Ok) write();
        return s;
    }
    Status s;
    try {
        s = judge(polygon, triangles, Diagnostic{}, validated, true,
                  [&] { return eachReady.get(); });
    } catch (...) {
        other.join();
        throw;
    }
    other.join();
    if (failed) std::rethrow_exception(failed);
    return s;
}

}  // namespace flood::cli
