// read_any.h built without GDAL: every file to the core's readers; a selection of features,
// which only GDAL reads, refused.
#include "flood/io/gdal/read_any.h"

namespace flood::gdal {

bool built() { return false; }

namespace {
Diagnostic refused(const std::string& path) {
    return {Status::Usage, (path == "-" ? "<stdin>" : path) +
                               ": --layer, --feature and --where read GIS datasets through GDAL: "
                               "this program was built without it (install libgdal-dev, "
                               "reconfigure)"};
}
}  // namespace

ReadResult readAny(const std::string& path, const Selection& s, uint64_t maxBytes,
                   ReadProgress* progress, const TaskRunner& run) {
    if (!s.any()) return readPolygonFile(path, maxBytes, progress, run);
    ReadResult r;
    r.diagnostic = refused(path);
    return r;
}

DatasetRead readAnyFeatures(const std::string& path, const Selection& s, uint64_t maxBytes,
                            bool keepSource, bool& gis, ReadProgress* progress,
                            const TaskRunner& run) {
    gis = false;
    if (!s.any()) return readFeaturesFile(path, maxBytes, keepSource, progress, run);
    DatasetRead d;
    d.features.emplace_back();
    d.features[0].read.diagnostic = refused(path);
    return d;
}

bool listedFile(const std::string& path) { return polygonFileName(path); }

std::string listedFormats() { return polygonFormats(); }

}  // namespace flood::gdal
