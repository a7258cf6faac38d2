// read_any.h built with GDAL: GIS datasets through the module, the rest by the core.
#include "flood/io/gdal/read_any.h"

namespace flood::gdal {

bool built() { return true; }

ReadResult readAny(const std::string& path, const Selection& s, uint64_t maxBytes,
                   ReadProgress* progress, const TaskRunner& run) {
    if (handles(path, s)) return readPolygon(path, s);
    return readPolygonFile(path, maxBytes, progress, run);
}

DatasetRead readAnyFeatures(const std::string& path, const Selection& s, uint64_t maxBytes,
                            bool keepSource, bool& gis, ReadProgress* progress,
                            const TaskRunner& run) {
    gis = handles(path, s);
    if (gis) return readFeatures(path, s);
    return readFeaturesFile(path, maxBytes, keepSource, progress, run);
}

bool listedFile(const std::string& path) { return polygonFileName(path) || gisFile(path); }

std::string listedFormats() {
    std::string list = polygonFormats();
    for (const std::string& ext : gisExtensions()) list += ", ." + ext;
    return list;
}

}  // namespace flood::gdal
