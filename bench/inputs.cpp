// Benchmark inputs (see inputs.h).
#include "inputs.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "flood/tools/generate.h"

namespace bench {

using flood::Point;
using flood::Polygon;

std::vector<std::string> benchFamilies() { return flood::familyNames(); }

std::vector<size_t> benchSizes(const std::string& family, const std::vector<std::string>& large) {
    std::vector<size_t> sizes{1000, 10000, 100000, 1000000};
    if (std::find(large.begin(), large.end(), family) != large.end()) sizes.push_back(10000000);
    return sizes;
}

Polygon benchGenerate(const std::string& family, uint64_t seed, size_t size) {
    return flood::generate(family, seed, size);
}

void writePoly(const std::string& path, const Polygon& p) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw std::runtime_error("cannot write " + path);
    out.write("FLPOLY2\n", 8);
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
    // The T-junctions validate() found (Polygon::splits): the flood and the checker need them.
    u64(p.splits.size());
    for (const flood::EdgeSplit& s : p.splits) u64(uint64_t(s.edge) << 32 | s.vertex);
}

Polygon readPoly(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[8];
    if (!in.read(magic, 8) || std::string(magic, 8) != "FLPOLY2\n")
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
    p.splits.resize(u64());
    for (flood::EdgeSplit& s : p.splits) {
        uint64_t v = u64();
        s = {flood::Index(v >> 32), flood::Index(v)};
    }
    if (!in) throw std::runtime_error("truncated .poly file: " + path);
    return p;
}

void writeManifest(const std::string& path, const std::vector<InputInfo>& rows) {
    std::ofstream out(path);
    out << "name\tfamily\tsize\tvertices\tholes\tvalid\tpath\tverdict\n";
    for (const auto& r : rows)
        out << r.name << '\t' << r.family << '\t' << r.size << '\t' << r.vertices << '\t' << r.holes
            << '\t' << (r.valid ? 1 : 0) << '\t' << r.path << '\t' << r.verdict << '\n';
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
