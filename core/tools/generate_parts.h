// What the generator's two files share (internal to core/tools): the seeded PRNG, the family
// tables and the valid families the invalid ones start from. generate.cpp holds the valid
// families, generate_invalid.cpp the invalid ones (generate.h says what each is for).
#pragma once
#include <cassert>
#include <cstdint>
#include <string>
#include <vector>

#include "flood/geometry/polygon.h"

namespace flood {
namespace generate_detail {

struct Rng {
    uint64_t s;
    explicit Rng(uint64_t seed) : s(seed) {}
    uint64_t next() {  // splitmix64
        uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    int range(int lo, int hi) { return lo + int(next() % uint64_t(hi - lo + 1)); }  // [lo, hi]
    double unit() { return double(next() >> 11) * 0x1p-53; }                        // [0, 1)
};

using Pts = std::vector<Point>;
using Rings = std::vector<Pts>;

inline Point pt(double x, double y) { return {x, y}; }

struct Family {
    const char* name;
    const char* description;
    Polygon (*make)(Rng&, size_t);
};

// One family table's names, descriptions and generator (valid and invalid tables alike).
template <size_t N>
std::vector<std::string> namesOf(const Family (&table)[N]) {
    std::vector<std::string> names;
    for (const Family& f : table) names.emplace_back(f.name);
    return names;
}
template <size_t N>
std::string descriptionIn(const Family (&table)[N], const std::string& family) {
    for (const Family& f : table)
        if (family == f.name) return f.description;
    return "";
}
// `salt` keeps the valid and invalid families' random streams apart for the same seed.
template <size_t N>
Polygon makeFrom(const Family (&table)[N], const std::string& family, uint64_t seed, size_t size,
                 uint64_t salt) {
    for (const Family& f : table)
        if (family == f.name) {
            Rng rng(seed * 0x2545f4914f6cdd1dULL + salt);
            return f.make(rng, size);
        }
    assert(false && "generate()/generateInvalid(): unknown family; see familyNames()");
    return {};
}

// Valid families the invalid ones put a defect into (generate.cpp).
Polygon star(Rng& rng, size_t size);
Polygon gridHoles(Rng& rng, size_t size);
Polygon islands(Rng& rng, size_t size);

}  // namespace generate_detail
}  // namespace flood
