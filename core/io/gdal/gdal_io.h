// Vector datasets through GDAL/OGR (Shapefile, GeoPackage, FlatGeobuf, GeoJSONSeq, GML, KML,
// ...): each feature's polygonal geometry read as a Flood polygon, and triangles written as a
// layer of triangle polygons. Built only when GDAL is found (FLOOD_GDAL).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "io/io.h"

namespace flood::gdal {

// Which features of a dataset are read: --layer NAME, --feature FID, --where 'attr = x'.
struct Selection {
    std::string layer;     // "" = the dataset's only layer
    int64_t feature = -1;  // an FID, or -1 for all
    std::string where;     // an OGR SQL attribute filter, or ""
    bool any() const { return !layer.empty() || feature >= 0 || !where.empty(); }
};

// True when `path` is for GDAL rather than Flood's own readers: a selection is given, or the
// file is not stdin and not .json, .geojson or .wkt (those keep their exact messages).
bool handles(const std::string& path, const Selection& s);

// A file a folder listing offers as a GIS dataset (flood check DIR, the viewer's browser):
// .shp, .gpkg, .fgb, .geojsonl, .geojsons, .gml, .kml, .sqlite, .tab, .mif.
bool gisFile(const std::string& path);
// The extensions gisFile() knows, without their dot: what flood check --help lists.
const std::vector<std::string>& gisExtensions();

// One entry per polygonal feature: index is its position in the layer, id its FID, name its
// "name" field. Non-polygonal features are skipped with a warning in `skipped`; a dataset that
// cannot be opened or filtered is one whole-file Malformed entry naming the file.
DatasetRead readFeatures(const std::string& path, const Selection& s);

// The selected features as one polygon (a MultiPolygon of all their parts), as a GeoJSON
// FeatureCollection is read by readPolygonFile.
ReadResult readPolygon(const std::string& path, const Selection& s);

// Writes `triangles` as a layer "triangles" of triangle polygons (field "triangle": its
// index) to `path` in `format`: "gpkg" (GeoPackage) or "fgb" (FlatGeobuf). The file is made
// beside `path` and renamed over it once complete. Returns WriteFailed with a message naming
// the file on failure.
Diagnostic writeTriangles(const std::string& path, const std::string& format, const Polygon& p,
                          const std::vector<Triangle>& triangles);

}  // namespace flood::gdal
