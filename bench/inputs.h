// Benchmark inputs: earcut's fixtures and seeded generated families, stored as small binary
// files so the C++ driver and the Python earcut driver read exactly the same vertices.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "flood/geometry/polygon.h"

namespace bench {

// One row of the manifest written by `flood-bench dump`.
struct InputInfo {
    std::string name;    // "fixture/water-huge", "circle-smooth/1000000"
    std::string family;  // "fixture" or the generated family
    size_t size = 0;     // requested size (fixtures: vertex count)
    size_t vertices = 0;
    size_t holes = 0;
    bool valid = true;    // Flood's validate() verdict
    std::string verdict;  // validate()'s message when invalid
    std::string path;     // the .poly file
};

// The generated families of the benchmark: every family of the core generator (familyNames()).
std::vector<std::string> benchFamilies();
// The sizes a family is run at: 10^3..10^6, and 10^7 when it is one of `large` (a few cheap
// families, so the growth is seen one decade further).
std::vector<size_t> benchSizes(const std::string& family, const std::vector<std::string>& large);

// Generates a family with the core generator.
flood::Polygon benchGenerate(const std::string& family, uint64_t seed, size_t size);

// Binary .poly: "FLPOLY2\n", u64 ring count, per ring (u64 vertex count, u64 outer flag),
// then x, y as float64 pairs for every vertex in order, then u64 T-junction count and per
// T-junction u64 (edge << 32 | vertex) (Polygon::splits). Little-endian, as the machine.
void writePoly(const std::string& path, const flood::Polygon& p);
flood::Polygon readPoly(const std::string& path);

void writeManifest(const std::string& path, const std::vector<InputInfo>& rows);
std::vector<InputInfo> readManifest(const std::string& path);

}  // namespace bench
