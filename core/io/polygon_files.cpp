// Which files are polygons (flood/io/io.h): by name, and a folder's.
#include <algorithm>
#include <cctype>
#include <filesystem>

#include "flood/io/io.h"

namespace flood {

bool polygonFileName(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return ext == ".json" || ext == ".geojson" || ext == ".wkt";
}

std::string polygonFormats() { return ".json, .geojson, .wkt"; }

std::vector<std::string> polygonFiles(const std::string& dir) {
    namespace fs = std::filesystem;
    std::vector<std::string> out;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        std::error_code fe;
        if (it->is_regular_file(fe) && polygonFileName(it->path().string()) &&
            it->path().filename() != "gallery.json")
            out.push_back(it->path().string());
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace flood
