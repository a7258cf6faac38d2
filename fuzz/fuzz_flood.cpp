// libFuzzer harness: the flood machine on polygons built from the fuzzer's bytes (fuzz_poly.h:
// small-integer and raw-double coordinates, several rings and parts).
// Valid per validate() -> triangulate() must succeed and the exact checker must accept the
// result (abort otherwise). Invalid -> triangulate() still runs, to prove the machine ends in a
// diagnostic (Forbidden) or a result, never a crash or a hang; if it claims success on an
// invalid polygon the claim is not checked (the machine may legitimately triangulate some
// inputs validation rejects, e.g. a hole touching an edge).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "flood/check/checker.h"
#include "flood/io/io.h"
#include "flood/machine/flood.h"
#include "fuzz_poly.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    fuzzpoly::Decoded d = fuzzpoly::decode(data, size);
    if (d.polygon.rings.empty()) return 0;
    flood::Diagnostic v = flood::validate(d.polygon, "fuzz");
    flood::FloodResult r = flood::triangulate(d.polygon, nullptr, d.options);
    if (v.ok()) {
        if (!r.diagnostic.ok()) {
            std::fprintf(stderr, "valid polygon, machine failed: %s\n",
                         r.diagnostic.message.c_str());
            std::abort();
        }
        flood::CheckResult c = flood::checkTriangulation(d.polygon, r.triangles);
        if (!c.ok) {
            std::fprintf(stderr, "valid polygon, checker rejects: %s\n", c.reason.c_str());
            std::abort();
        }
    } else if (v.status != flood::Status::Invalid) {
        std::abort();
    }
    return 0;
}
