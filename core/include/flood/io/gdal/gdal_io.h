// Vector datasets through GDAL/OGR (Shapefile, GeoPackage, FlatGeobuf, GeoJSONSeq, GML, KML,
// ...): each feature's polygonal geometry read as a Flood polygon, and Flood's layers (triangles,
// findings, a feature kept as it was) written. Built only when GDAL is found (FLOOD_GDAL).
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <variant>
#include <vector>

#include "flood/io/io.h"

namespace flood::gdal {

// Which features of a dataset are read: --layer NAME, --feature FID, --where 'attr = x'.
struct Selection {
    std::string layer;     // "" = the dataset's only layer
    int64_t feature = -1;  // an FID, or -1 for all
    std::string where;     // an OGR SQL attribute filter, or ""
    // flood check: a dataset of several layers is read layer by layer (FeatureRead::layer),
    // not refused, when no layer is named.
    bool allLayers = false;
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

// A layer Flood writes (the triangles of `flood triangulate -o`, the findings of `flood check
// --findings`, a feature kept by `flood check --extract`), in any vector format GDAL creates,
// by one writer: writeLayers().
enum class GisGeometry { Point, LineString, Polygon, MultiPolygon, Source };
struct GisField {
    std::string name;
    bool integer = false;  // a 64-bit integer, else text
};
using GisValue = std::variant<std::monostate, int64_t, std::string>;  // monostate: null
struct GisFeature {
    int64_t source = -1;  // the source feature (its FID) whose fields, or geometry, it copies
    int64_t fid = -1;     // kept as its FID where the format can (else a new one), or -1
    std::vector<GisValue> values;  // one per GisLayer::fields
    // Point: parts[0][0]; LineString: parts[0]; Polygon: its rings, the outer first;
    // MultiPolygon: one polygon of one ring per part. No part: a null geometry.
    std::vector<std::vector<Point>> parts;
    void clear() { source = fid = -1, values.clear(), parts.clear(); }
};
struct GisLayer {
    std::string name;
    GisGeometry geometry = GisGeometry::Point;  // Source: each feature's source geometry
    // With `sourceFields`, the source layer's fields come first (each feature's values from
    // its source feature, as ogr2ogr copies them), then these; one the source already has
    // is named "flood_" + its name.
    bool sourceFields = false;
    std::vector<GisField> fields;
    size_t count = 0;
    std::function<void(size_t, GisFeature&)> feature;  // fills feature i of count (cleared)
};

// A layer read: the dataset and which of its layers, with which filter.
struct LayerSource {
    std::string file;  // "" or "-" or a file GDAL cannot open (a ring array): none
    Selection selection;
};

struct DatasetOutput {
    std::string driver;  // outputDriver()
    std::string format;  // as the user named it (--format, or OUT's extension), for messages
    // The layer whose fields and features the layers copy (the first), and the layers whose
    // CRS the output takes: the one they agree on; when they disagree, none, with a warning
    // naming them. Sources without a CRS (a ring array, WKT) have no say.
    std::vector<LayerSource> sources;
    bool noReplace = false;  // an existing OUT (or side file) is an error, never replaced
};

// Writes `layers` to the dataset `path` with `o.driver`. The files are made beside `path` and
// renamed over it once complete and read back (each layer's count); an existing GeoPackage
// keeps its other layers (those of the same names are replaced). Returns WriteFailed with a
// message naming the file on failure; `warnings` gets what was written but not as asked.
Diagnostic writeLayers(const std::string& path, const DatasetOutput& o,
                       const std::vector<GisLayer>& layers, std::vector<std::string>& warnings);

// Whether the driver keeps several layers in one file (GeoPackage, SQLite): else a second
// layer goes to a file of its own.
inline bool severalLayers(const std::string& driver) {
    return driver == "GPKG" || driver == "SQLite";
}

}  // namespace flood::gdal
