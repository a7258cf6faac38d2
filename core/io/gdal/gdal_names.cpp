// Which paths are GIS datasets: plain string tests, so they need neither GDAL nor its module.
#include <algorithm>
#include <cctype>

#include "flood/io/gdal/gdal_io.h"

namespace flood::gdal {
namespace {
std::string extension(const std::string& path) {
    size_t dot = path.find_last_of("./");
    std::string ext = dot == std::string::npos || path[dot] == '/' ? "" : path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return ext;
}
}  // namespace

bool handles(const std::string& path, const Selection& s) {
    if (s.any()) return true;
    if (path == "-") return false;
    std::string ext = extension(path);
    return !ext.empty() && ext != "json" && ext != "geojson" && ext != "wkt";
}

const std::vector<std::string>& gisExtensions() {
    static const std::vector<std::string> known = {"shp", "gpkg", "fgb",    "geojsonl", "geojsons",
                                                   "gml", "kml",  "sqlite", "tab",      "mif"};
    return known;
}

bool gisFile(const std::string& path) {
    const std::vector<std::string>& known = gisExtensions();
    return std::find(known.begin(), known.end(), extension(path)) != known.end();
}

}  // namespace flood::gdal
