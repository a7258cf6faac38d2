#include "gallery.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "flood/io/io.h"

#ifndef FLOOD_DATA_SUBDIR  // share/flood, relative to the install prefix
#define FLOOD_DATA_SUBDIR "share/flood"
#define FLOOD_INSTALL_DATA_DIR "/usr/local/share/flood"
#endif
#ifndef FLOOD_SOURCE_DIR
#define FLOOD_SOURCE_DIR "."
#endif
#ifndef FLOOD_VIEWER_DEFAULT_POLYGON
#define FLOOD_VIEWER_DEFAULT_POLYGON "paper-figure-7.json"
#endif

namespace flood::view {

// The installed polygons are found beside the executable (PREFIX/bin/flood-viewer ->
// PREFIX/share/flood/polygons), so an installed tree can move; a build in the source tree
// finds the source's; the install path the build was configured with comes last.
std::string polygonsDir() {
    namespace fs = std::filesystem;
    if (const char* d = std::getenv("FLOOD_POLYGONS_DIR")) return d;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path installed = exe.parent_path().parent_path() / FLOOD_DATA_SUBDIR / "polygons";
        if (fs::is_directory(installed, ec)) return installed.string();
    }
    const std::string source = std::string(FLOOD_SOURCE_DIR) + "/polygons";
    if (fs::is_directory(source, ec)) return source;
    return std::string(FLOOD_INSTALL_DATA_DIR) + "/polygons";
}

std::vector<GalleryEntry> readGallery(const std::string& dir) {
    std::vector<GalleryEntry> out;
    std::ifstream in(dir + "/gallery.json");
    if (!in) return out;
    nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (!j.is_array()) return out;
    for (const auto& e : j) {
        if (!e.is_object() || !e.contains("file") || !e["file"].is_string()) continue;
        GalleryEntry g;
        g.file = dir + "/" + e["file"].get<std::string>();
        g.title = e.value("title", e["file"].get<std::string>());
        g.description = e.value("description", "");
        out.push_back(std::move(g));
    }
    return out;
}

std::string defaultPolygonPath() {
    std::string dir = polygonsDir();
    std::string preferred = dir + "/" FLOOD_VIEWER_DEFAULT_POLYGON;
    std::error_code ec;
    if (std::filesystem::exists(preferred, ec)) return preferred;
    auto files = polygonFiles(dir);
    return files.empty() ? std::string() : files.front();
}

}  // namespace flood::view
