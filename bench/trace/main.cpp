// flood-trace-bench FAMILY N [SEED]: what opening a saved trace costs against recording it again
// (issue 26 §4: opening must be faster than re-flooding). For the generated polygon it prints
// the events, each form's bytes per event, and the median of 5 runs of: record() (flooding
// with the log, as the viewer does when it opens a polygon), parsing the JSON Lines trace, and
// parsing the binary trace — all from memory, so the disk is not measured.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "flood/log/replay.h"
#include "flood/log/trace_io.h"
#include "flood/tools/generate.h"

using namespace flood;

template <class F>
static double medianSeconds(F&& run) {
    std::vector<double> t;
    for (int k = 0; k < 5; ++k) {
        auto start = std::chrono::steady_clock::now();
        run();
        t.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(t.begin(), t.end());
    return t[2];
}

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: flood-trace-bench FAMILY N [SEED]\n");
        return 2;
    }
    const Polygon p = generate(argv[1], argc > 3 ? std::strtoull(argv[3], nullptr, 10) : 1,
                               std::strtoull(argv[2], nullptr, 10));
    Trace t = record(p);
    std::ostringstream json, bin;
    writeTrace(json, t);
    writeBinaryTrace(bin, t);
    const std::string jsonText = json.str(), binText = bin.str();
    Trace back;
    const double flood = medianSeconds([&] { back = record(p); });
    const double openJson = medianSeconds([&] { parseTrace(jsonText, "t.jsonl", back); });
    const double openBin = medianSeconds([&] { parseTrace(binText, "t.bin", back); });
    const double events = double(t.events.size());
    std::printf(
        "%s %zu vertices, %zu events: bytes/event jsonl %.0f bin %.1f; "
        "record %.3f s, open jsonl %.3f s (%.2fx record), open bin %.3f s (%.2fx record)\n",
        argv[1], p.vertices.size(), t.events.size(), double(jsonText.size()) / events,
        double(binText.size()) / events, flood, openJson, openJson / flood, openBin,
        openBin / flood);
    return 0;
}
