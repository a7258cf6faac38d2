// Vector datasets through GDAL/OGR (Shapefile, GeoPackage, FlatGeobuf, GeoJSONSeq, GML, KML,
// ...): each feature's polygonal geometry read as a Flood polygon, and triangles written as a
// layer of triangle polygons. Built only when GDAL is found (FLOOD_GDAL).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "flood/io/io.h"

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

// "" when Flood's GDAL module can be loaded, else why not: one line naming `path` (the file
// being read or written) and every place the module was looked for.
std::string unavailable(const std::string& path);

// The GDAL vector driver `flood triangulate` writes with: the one named by `format` (GDAL's
// short name, any case, e.g. "GPKG", "GeoJSON", "ESRI Shapefile", or an extension: "gpkg",
// "fgb", "shp", "csv"), else the one whose extension `path` has (".geojson", ".kml", ...).
// "" when no driver that creates vector datasets matches.
std::string outputDriver(const std::string& format, const std::string& path);

// One source feature's triangles, as `flood triangulate` writes them.
struct TriangulatedFeature {
    int64_t fid = 0;  // the source feature's FID (FeatureRead::fid)
    const Polygon* polygon = nullptr;
    std::vector<Triangle> triangles;
};

struct LayerOutput {
    std::string driver;  // outputDriver()
    std::string format;  // as the user named it (--format, or OUT's extension), for messages
    // The dataset read: its layer's CRS and fields are copied, and each feature's values from
    // the source feature of the same FID ("" or a file GDAL cannot open: FID only, no CRS).
    std::string source;
    Selection selection;        // which layer of it, which filter
    bool multipolygon = false;  // one MultiPolygon per feature, else one Polygon per triangle
};

// Writes the features' triangles as a layer "triangles" to `path` with `o.driver`: the source
// fields, then "src_fid" (the source FID) and, per triangle, "triangle" (its number in its
// feature); "flood_src_fid", "flood_triangle" when the source has fields so named. The files
// are made beside `path` and renamed over it once complete. Returns WriteFailed with a message
// naming the file on failure; `warnings` gets what was written but not as asked.
Diagnostic writeLayer(const std::string& path, const LayerOutput& o,
                      const std::vector<TriangulatedFeature>& features,
                      std::vector<std::string>& warnings);

}  // namespace flood::gdal
