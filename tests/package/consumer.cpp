// A program that uses the installed Flood as a user would: triangulate a square with a hole
// and a MultiPolygon, refuse a bow-tie with its diagnostic, replay a recorded trace. Built by
// scripts/package-test.sh against a temporary prefix, once with CMake and once with pkg-config.
// It includes the two umbrella headers, so every installed header must compile on its own
// include path (an installed header that includes an internal one fails here).
#include <flood/flood.h>
#include <flood/teach.h>
#include <cstdio>

namespace {
int failures = 0;
void expect(bool ok, const char* what) {
    if (!ok) std::fprintf(stderr, "consumer: FAILED: %s\n", what), ++failures;
}
}  // namespace

int main() {
    using flood::Rings;
    const Rings squareWithHole = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                                  {{3, 3}, {3, 7}, {7, 7}, {7, 3}}};
    flood::Triangulation t = flood::triangulateParts({squareWithHole});
    expect(t.ok(), "a square with a square hole triangulates");
    expect(t.triangles.size() == 8, "n + 2h - 2 = 8 triangles");  // §1 of the paper
    for (const flood::Triangle& tri : t.triangles)
        for (flood::Index v : tri)
            expect(v < t.polygon.vertices.size(), "indices name input vertices");

    const Rings a = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, b = {{{5, 0}, {6, 0}, {6, 1}, {5, 1}}};
    expect(flood::triangulateParts({a, b}).triangles.size() == 4, "two squares: 4 triangles");

    const Rings bowtieRings = {{{0, 0}, {4, 2}, {4, 0}, {0, 3}}};  // edges 0-1 and 2-3 cross
    flood::Polygon bowtie = flood::makePolygon({bowtieRings});
    flood::Diagnostic d = flood::validate(bowtie, "bowtie");
    expect(d.status == flood::Status::Invalid, "a bow-tie is invalid");
    expect(d.message.rfind("bowtie: ring 0", 0) == 0, "the diagnostic names the ring");
    flood::Triangulation refused = flood::triangulateParts({bowtieRings});
    expect(!refused.ok() && refused.triangles.empty(), "no triangles for it");

    flood::Trace trace = flood::traceParts({squareWithHole});
    flood::Replay replay(trace);
    expect(!trace.events.empty() && trace.diagnostic.ok(), "a trace is recorded");
    expect(replay.seek(replay.size()).triangleCount == 8, "the replay ends with every triangle");
    expect(replay.seek(0).triangleCount == 0, "and starts with none");

    const std::string paper = flood::transcript(trace.events);  // the teaching layer
    expect(paper.rfind("Raise", 0) == 0, "the transcript starts as the paper's: Raise ...");

    std::printf("consumer: %zu triangles, %zu events, bow-tie: %s\n", t.triangles.size(),
                trace.events.size(), d.message.c_str());
    return failures == 0 ? 0 : 1;
}
