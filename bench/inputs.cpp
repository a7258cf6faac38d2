// Benchmark inputs (see inputs.h).
#include "inputs.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "generate.h"

namespace bench {

using flood::Point;
using flood::Polygon;

std::vector<std::string> benchFamilies() {
    return {"circle-smooth", "circle-jagged", "circle-sqrt-holes", "circle-holes",
            "comb",          "ortho-histogram", "spiral"};
}

std::vector<size_t> benchSizes() { return {1000, 10000, 100000, 1000000}; }

namespace {

uint64_t splitmix(uint64_t& s) {
    uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}
double unit(uint64_t& s) { return double(splitmix(s) >> 11) * 0x1p-53; }

// Regular n-gon around c with radius r (counter-clockwise): convex, hence simple.
std::vector<Point> regular(Point c, double r, size_t n, double phase) {
    std::vector<Point> ring(n);
    for (size_t i = 0; i < n; ++i) {
        double a = phase + 2 * M_PI * double(i) / double(n);
        ring[i] = {c.x + r * std::cos(a), c.y + r * std::sin(a)};
    }
    return ring;
}

// Circle (1% radial noise, star-shaped around the origin, hence simple) with K = sqrt(N)/2
// regular holes, one per cell of a square grid, each cell well inside the circle.
Polygon circleSqrtHoles(uint64_t seed, size_t size) {
    size_t k = std::max<size_t>(1, size_t(std::lround(std::sqrt(double(size)) / 2)));
    size_t outerN = std::max<size_t>(8, size / 2);
    size_t holeN = std::max<size_t>(3, (size - outerN) / k);
    std::vector<Point> outer(outerN);
    for (size_t i = 0; i < outerN; ++i) {
        double a = 2 * M_PI * double(i) / double(outerN), r = 1.0 + 0.01 * unit(seed);
        outer[i] = {r * std::cos(a), r * std::sin(a)};
    }
    Polygon p;
    p.addRing(outer, true);
    std::vector<Point> cells;
    double cell = 0;
    for (int g = 2;; ++g) {
        cells.clear();
        cell = 2.0 / g;
        for (int i = 0; i < g; ++i)
            for (int j = 0; j < g; ++j) {
                Point c{-1 + cell * (i + 0.5), -1 + cell * (j + 0.5)};
                if (std::hypot(c.x, c.y) + cell * 0.75 < 0.95) cells.push_back(c);
            }
        if (cells.size() >= k) break;
    }
    while (cells.size() > k) cells.erase(cells.begin() + long(splitmix(seed) % cells.size()));
    for (Point c : cells) {
        std::vector<Point> hole = regular(c, cell * 0.5 * (0.4 + 0.5 * unit(seed)), holeN,
                                          2 * M_PI * unit(seed));
        p.addRing(hole, false);
    }
    return p;
}

}  // namespace

Polygon benchGenerate(const std::string& family, uint64_t seed, size_t size) {
    if (family == "circle-sqrt-holes") return circleSqrtHoles(seed, size);
    return flood::generate(family, seed, size);
}

void writePoly(const std::string& path, const Polygon& p) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw std::runtime_error("cannot write " + path);
    out.write("FLPOLY1\n", 8);
    auto u64 = [&](uint64_t v) { out.write(reinterpret_cast<const char*>(&v), 8); };
    u64(p.rings.size());
    for (size_t r = 0; r < p.rings.size(); ++r) {
        bool outer = false;
        for (const auto& part : p.parts) outer = outer || part.firstRing == r;
        u64(p.rings[r].count);
        u64(outer ? 1 : 0);
    }
    static_assert(sizeof(Point) == 16, "Point must be two packed doubles");
    out.write(reinterpret_cast<const char*>(p.vertices.data()),
              std::streamsize(p.vertices.size() * sizeof(Point)));
}

Polygon readPoly(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[8];
    if (!in.read(magic, 8) || std::string(magic, 8) != "FLPOLY1\n")
        throw std::runtime_error("not a .poly file: " + path);
    auto u64 = [&] {
        uint64_t v = 0;
        in.read(reinterpret_cast<char*>(&v), 8);
        return v;
    };
    uint64_t rings = u64();
    std::vector<std::pair<uint64_t, bool>> shape(rings);
    uint64_t total = 0;
    for (auto& s : shape) {
        s.first = u64();
        s.second = u64() != 0;
        total += s.first;
    }
    Polygon p;
    p.vertices.resize(total);
    in.read(reinterpret_cast<char*>(p.vertices.data()), std::streamsize(total * sizeof(Point)));
    if (!in) throw std::runtime_error("truncated .poly file: " + path);
    flood::Index first = 0;
    for (auto& s : shape) {
        if (s.second) p.parts.push_back({flood::Index(p.rings.size()), 0});
        p.rings.push_back({first, flood::Index(s.first)});
        p.parts.back().ringCount++;
        first += flood::Index(s.first);
    }
    return p;
}

void writeManifest(const std::string& path, const std::vector<InputInfo>& rows) {
    std::ofstream out(path);
    out << "name\tfamily\tsize\tvertices\tholes\tvalid\tpath\tverdict\n";
    for (const auto& r : rows)
        out << r.name << '\t' << r.family << '\t' << r.size << '\t' << r.vertices << '\t'
            << r.holes << '\t' << (r.valid ? 1 : 0) << '\t' << r.path << '\t' << r.verdict << '\n';
}

std::vector<InputInfo> readManifest(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path);
    std::vector<InputInfo> rows;
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
        std::istringstream s(line);
        InputInfo r;
        std::string size, vertices, holes, valid;
        std::getline(s, r.name, '\t');
        std::getline(s, r.family, '\t');
        std::getline(s, size, '\t');
        std::getline(s, vertices, '\t');
        std::getline(s, holes, '\t');
        std::getline(s, valid, '\t');
        std::getline(s, r.path, '\t');
        std::getline(s, r.verdict);
        r.size = std::stoull(size);
        r.vertices = std::stoull(vertices);
        r.holes = std::stoull(holes);
        r.valid = valid == "1";
        rows.push_back(r);
    }
    return rows;
}

}  // namespace bench
