// Helpers shared by the test files: paths, reading polygons, exact validity assertions.
#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "checker.h"
#include "flood.h"
#include "io.h"

namespace flood::testing {

inline std::string sourcePath(const std::string& rel) { return std::string(FLOOD_SOURCE_DIR) + "/" + rel; }
inline std::string sharedPath(const std::string& rel) { return std::string(FLOOD_SHARED_DIR) + "/" + rel; }

inline std::vector<std::string> filesIn(const std::string& dir, const std::string& ext) {
    std::vector<std::string> out;
    if (!std::filesystem::is_directory(dir)) return out;
    for (auto& e : std::filesystem::directory_iterator(dir))
        // polygons/gallery.json is the gallery's index (tests/gallery_test.cpp), not a polygon.
        if (e.is_regular_file() && e.path().extension() == ext &&
            e.path().filename() != "gallery.json")
            out.push_back(e.path().string());
    std::sort(out.begin(), out.end());
    return out;
}

inline Polygon readOrFail(const std::string& path) {
    ReadResult r = readPolygonFile(path);
    EXPECT_TRUE(r.diagnostic.ok()) << r.diagnostic.message;
    return r.polygon;
}

// Floods `p` and proves the result exact-valid; returns the run for further checks.
inline FloodResult expectTriangulates(const Polygon& p, const std::string& what,
                                      const Options& options = {}) {
    FloodResult r = triangulate(p, nullptr, options);
    EXPECT_TRUE(r.diagnostic.ok()) << what << ": " << r.diagnostic.message;
    CheckResult c = checkTriangulation(p, r.triangles);
    EXPECT_TRUE(c.ok) << what << ": " << c.reason;
    return r;
}

}  // namespace flood::testing
