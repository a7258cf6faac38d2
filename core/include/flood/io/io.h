// Reading polygons: GeoJSON, bare ring arrays (earcut fixtures) and WKT; writing results.
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "flood/geometry/polygon.h"
#include "flood/geometry/status.h"
#include "flood/geometry/task_runner.h"

namespace flood {

// Inputs larger than this are refused while reading (`--max-input-bytes` changes it): a
// pipe or /dev/zero has no size to check up front.
constexpr uint64_t kDefaultMaxInputBytes = uint64_t(4) << 30;  // 4 GiB

// Only the first warnings are kept, the rest counted: 10^6 repeated points must not print
// 10^6 lines.
constexpr size_t kMaxWarnings = 10;

struct ReadResult {
    Polygon polygon;
    std::vector<std::string> warnings;  // e.g. repeated consecutive points dropped
    size_t warningsOmitted = 0;         // warnings beyond the first kMaxWarnings
    Diagnostic diagnostic;              // Ok, or Malformed with "FILE:LINE:COL: ..."

    // `make` builds the message only when it is kept.
    template <typename Make>
    void warn(Make&& make) {
        if (warnings.size() < kMaxWarnings) warnings.push_back(make());
        else ++warningsOmitted;
    }
};

// Detects the format from the content. `name` is used in messages ("-" means stdin). With
// `run`, a large GeoJSON geometry (a bare Polygon or MultiPolygon, or its coordinates alone)
// is parsed in pieces as tasks given to it; the result is the same.
ReadResult parsePolygon(std::string_view text, const std::string& name, const TaskRunner& run = {});
// `progress`, when given, follows the bytes read (ReadProgress, below).
struct ReadProgress;
ReadResult readPolygonFile(const std::string& path,  // "-" reads stdin
                           uint64_t maxBytes = kDefaultMaxInputBytes,
                           ReadProgress* progress = nullptr, const TaskRunner& run = {});

// Well-known binary, as GEOS, shapely, PostGIS and OGR hand it out (the Python module reads
// it): ISO WKB and PostGIS EWKB, either byte order, a Polygon or a MultiPolygon, z and m
// dropped, an SRID skipped; rings cleaned as every reader cleans them. Malformed, naming the
// byte, when truncated or not a polygon. wkbLike(): a byte order then a known geometry type —
// no text starts so.
bool wkbLike(std::string_view bytes);
ReadResult parseWkb(std::string_view bytes, const std::string& name);

// One polygon of a dataset (`flood check`): a Feature of a FeatureCollection, or a whole file.
struct FeatureRead {
    bool wholeFile = true;  // not a FeatureCollection's feature (any other document, or unreadable)
    size_t index = 0;       // position in the collection's "features" array (or the layer)
    // The feature's FID, as GDAL numbers it (core/io/gdal/): a GeoJSON Feature's integer "id"
    // when every feature has a distinct one, else its position; 0 for a whole file. What
    // --feature, `flood check`'s FEATURE column and messages ("feature N") call it.
    int64_t fid = 0;
    std::string id,
        name;  // the Feature's "id" and its "name" or "NAME" property (cut to 60 bytes), or ""
    std::string layer;  // a GIS dataset's layer it is in, or "" (Flood's own readers)
    // Every property (a GIS feature's fields) as text, in file order, each cut to 60 bytes:
    // what `flood check --json` reports beside the verdict. Null values are left out.
    std::vector<std::pair<std::string, std::string>> attributes;
    std::string source;  // the Feature as GeoJSON text, when asked for (for extraction)
    ReadResult read;     // as parsePolygon reads it alone; messages say "NAME: feature N ..."
};

struct DatasetRead {
    std::vector<FeatureRead> features;
    std::vector<std::string> skipped;  // warnings for non-polygonal features
};

// A file Flood's own readers take by its name: .json, .geojson or .wkt, in any case.
bool polygonFileName(const std::string& path);
// Those extensions, for messages: ".json, .geojson, .wkt".
std::string polygonFormats();
// Which files of a folder are polygons: its own regular files (not its subfolders') that
// polygonFileName() takes, but for gallery.json, the teaching gallery's index; sorted. The
// one listing of polygons/ the viewer's gallery, the tests and pytest
// (flood._flood.polygon_files) use. Empty when the folder cannot be listed.
std::vector<std::string> polygonFiles(const std::string& dir);

// Splits a FeatureCollection into its features, each read on its own so one broken feature
// does not hide the others (a MultiPolygon feature stays one polygon: its parts may
// interact). Any other document, or one that cannot be parsed, is one whole-file entry read
// by parsePolygon, with its diagnostic unchanged.
//
// `progress`, when given, is told how far the read has come (for a progress line: a 65 MB
// file takes seconds to read and parse before its first feature can be checked).
struct ReadProgress {
    // Summed over every read given this record (flood check reads files on several threads).
    std::atomic<uint64_t> bytesTotal{0};  // the sizes of the regular files opened so far
    std::atomic<uint64_t> bytesRead{0};
    std::atomic<size_t> featuresParsed{0};  // Features met while parsing the JSON
    std::atomic<size_t> featuresRead{0};    // features made polygons so far
    // Called on the reading thread after each change (each 64 KiB block, each feature).
    std::function<void()> changed;
    void tell() {
        if (changed) changed();
    }
};
// With `run`, a FeatureCollection is parsed in slices and its features made polygons in
// ranges, as tasks given to `run`; the result is the same as without it.
DatasetRead parseFeatures(std::string_view text, const std::string& name, bool keepSource,
                          ReadProgress* progress = nullptr, const TaskRunner& run = {});
DatasetRead readFeaturesFile(const std::string& path, uint64_t maxBytes, bool keepSource,
                             ReadProgress* progress = nullptr, const TaskRunner& run = {});

// Reads all of `path` ("-" is stdin) into `text`. Malformed, naming the file, when it cannot
// be opened or read, is a directory, holds a NUL byte (binary data, not `expected`: reading
// stops there, so /dev/zero ends at once; unless the input starts with `binaryMagic`, a
// binary format's first bytes) or grows beyond `maxBytes`.
Diagnostic readInputFile(const std::string& path, std::string& text, uint64_t maxBytes,
                         const char* expected, const char* binaryMagic = nullptr,
                         ReadProgress* progress = nullptr);

// Validity rules checked before flooding (docs/ERRORS.md): finite coordinates, rings with at
// least 3 distinct points (holes may be single Steiner points), non-zero area, no
// self-intersection, holes inside their outer ring and not overlapping, parts not overlapping.
// Rings may touch at single points without crossing: shared vertices, or a vertex inside
// another ring's edge (a T-junction; within a part it is recorded in polygon.splits for the
// flood machine and the checker — so validate before triangulating). Returns Invalid with
// "NAME: ring R vertex V (x, y): reason" on the first problem found. With `run`, the parts of
// a MultiPolygon that lines set apart are validated as tasks given to it; the result is the
// same as without it.
Diagnostic validate(Polygon& polygon, const std::string& name, const TaskRunner& run = {});

// Every problem validate() would find, not only the first (as QGIS's "Check validity" lists
// them): the first is validate()'s own diagnostic, the verdict; the others follow, check by
// check. Checks stop after the first check with findings, since each later check needs the
// earlier ones clean (no crossing is looked for among non-finite points, no hole nesting
// among crossing edges). Empty exactly when validate() accepts the polygon.
struct Findings {
    std::vector<Diagnostic> list;
    size_t omitted = 0;    // found beyond maxFindings
    bool complete = true;  // false: the search for crossings gave up at its work cap
};
Findings validateAll(const Polygon& polygon, const std::string& name, size_t maxFindings = 100);
// The same when validate(polygon, name) has run already and gave `verdict` (flood check has
// it): the polygon is not validated a second time.
Findings validateAll(const Polygon& polygon, const std::string& name, Diagnostic verdict,
                     size_t maxFindings);

// Writes a polygon as a bare ring array [[[x,y],...],...] (one part) or a GeoJSON
// MultiPolygon (several parts), coordinates in shortest round-trip form, rings closed.
void writePolygonJson(std::ostream& out, const Polygon& polygon);
// The polygon as a GeoJSON geometry: a Polygon for one part, a MultiPolygon for several.
std::string geoJsonGeometry(const Polygon& polygon);
// Saves the polygon as a GeoJSON geometry to `path`, atomically (flood/io/output.h): the old
// file stays whole on failure, which is WriteFailed naming the path and the system's reason.
Diagnostic saveGeoJson(const Polygon& polygon, const std::string& path);

void writeJson(std::ostream& out, const Polygon& p, const std::vector<Triangle>& t);
void writeSvg(std::ostream& out, const Polygon& p, const std::vector<Triangle>& t);
void writeObj(std::ostream& out, const Polygon& p, const std::vector<Triangle>& t);

}  // namespace flood
