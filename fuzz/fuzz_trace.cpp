// libFuzzer harness: parseTrace (flood/log/trace_io.h) on arbitrary bytes, then a Replay of the
// loaded trace seeking to pseudo-random steps (forward, backward, past the end), and the
// invariant scan the viewer runs on every trace it opens (flood/check/invariants.h), which reads the
// vertices the events name.
// A malformed trace must be a diagnostic; a loaded one must replay and scan without crashing.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "flood/check/invariants.h"
#include "flood/log/replay.h"
#include "flood/log/trace_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    flood::Trace trace;
    flood::Diagnostic d = flood::parseTrace(text, "fuzz", trace);
    if (!d.ok()) {
        if (d.status != flood::Status::Malformed || d.message.empty()) std::abort();
        return 0;
    }
    // Seek positions from a hash of the input, so every seed is also a valid trace.
    uint64_t h = 1469598103934665603ull;
    for (size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 1099511628211ull;
    uint32_t interval = 1 + uint32_t(h % 7);  // small keyframe intervals exercise keyframes
    flood::Replay replay(trace, interval);
    uint32_t n = replay.size();
    replay.seek(n);
    for (int k = 0; k < 16; ++k) {
        h = h * 6364136223846793005ull + 1442695040888963407ull;
        uint32_t step = uint32_t(h >> 33) % (n + 2);  // n + 1: one past the end
        const flood::ReplayState& s = replay.seek(step);
        if (s.step > n) std::abort();
    }
    replay.seek(0);
    for (const flood::Violation& v : flood::checkInvariants(trace))
        if (v.step == 0 || v.step > n) std::abort();
    return 0;
}
