// Which reader a file goes to: GIS datasets to GDAL (flood-gdal.so, gdal_io.h), everything
// else to the core's own readers (flood/io/io.h). The one place the choice is made, for the
// CLI (flood triangulate, trace, check, ...) and the viewer; built with or without GDAL: the
// build seam is core/CMakeLists.txt, which compiles read_any.cpp or, without GDAL,
// read_any_none.cpp, so no caller writes #ifdef FLOOD_GDAL.
#pragma once
#include <cstdint>
#include <string>

#include "flood/io/gdal/gdal_io.h"  // Selection
#include "flood/io/io.h"

namespace flood::gdal {

// True when this program reads and writes GIS datasets (built with GDAL).
bool built();

// The polygon of `path` (a MultiPolygon of the selected features for a GIS dataset). Without
// GDAL, a selection is refused (Usage, naming `path`) and every file goes to the core.
// `progress` follows the core's reading (the viewer's open), not a GIS dataset's.
ReadResult readAny(const std::string& path, const Selection& s,
                   uint64_t maxBytes = kDefaultMaxInputBytes, ReadProgress* progress = nullptr,
                   const TaskRunner& run = {});

// The features of `path`, one entry each (gdal::readFeatures or readFeaturesFile, which keeps
// each feature's GeoJSON text with `keepSource`); `gis` says which reader it was. `progress`
// follows the core's reading (a GIS dataset's is not followed); `run` lends threads to the
// core's reading (parseFeatures).
DatasetRead readAnyFeatures(const std::string& path, const Selection& s, uint64_t maxBytes,
                            bool keepSource, bool& gis, ReadProgress* progress = nullptr,
                            const TaskRunner& run = {});

// A file a folder listing offers (flood check DIR, the viewer's browser): a polygon file
// (polygonFileName(), flood/io/io.h) or, built with GDAL, a GIS dataset (gisFile()).
bool listedFile(const std::string& path);
// The extensions listedFile() takes, for messages and the help: ".json, .geojson, .wkt" and,
// built with GDAL, ".shp, .gpkg, ...".
std::string listedFormats();

}  // namespace flood::gdal
