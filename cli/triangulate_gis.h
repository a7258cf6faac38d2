// `flood triangulate IN -o OUT` when OUT is a GIS dataset (GeoJSON, Shapefile, GeoPackage,
// FlatGeobuf, KML, CSV, ...: any vector format GDAL writes): the input triangulated feature by
// feature, each feature's triangles written with its FID and attributes in the input's CRS.
#pragma once
#include <string>

#include "check.h"
#include "flood/machine/flood.h"

namespace flood::cli {

// Which writer `-o out` with `--format format` needs: Flood's own ("json", "svg", "obj":
// `format` is set to it, `driver` left empty) or a GDAL driver (`driver` set). Returns 0, or
// the usage exit code after a message when nothing writes it (`-o tri.png`), when a GIS format
// is asked for stdout, or when this flood has no GDAL.
int outputFormat(const std::string& out, std::string& format, std::string& driver);

// The GIS part of outputFormat(), for any option writing a GIS dataset (`-o`, `flood check
// --findings`): the GDAL driver for `out` (by `format`, else its extension), or the usage
// exit code after a message naming `option` and `out`.
int gisFormat(const std::string& option, const std::string& out, std::string& format,
              std::string& driver);

struct GisTriangulation {
    std::string in, out;
    std::string format, driver;  // as outputFormat() gave them
    bool multipolygon = false;   // --per-feature multipolygon
    Selection selection;
    uint64_t maxInputBytes = 0;
    Options options;
    bool validate = true, exactCheck = true;
};

// Reads every selected feature of `in`, floods and checks each on its own, and writes those
// that pass as one layer. A feature that fails is reported on stderr (FILE: feature FID: ...)
// and left out; the exit code is then the largest of their codes, as `flood check` gives
// (3 malformed < 4 invalid < 5 forbidden < 6 internal), or 8 when OUT cannot be written.
// Nothing is written when no feature passes.
int triangulateGis(const GisTriangulation& t);

}  // namespace flood::cli
