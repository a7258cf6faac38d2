// `flood check FILE...`: every polygon of a dataset validated, triangulated and exactly
// checked, one row each (docs/ERRORS.md, "flood check").
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "flood/io/gdal/read_any.h"  // Selection, the choice of reader

namespace flood::cli {

// --layer, --feature, --where: which features of a GIS dataset are read (through GDAL).
using Selection = gdal::Selection;

struct CheckOptions {
    std::vector<std::string> inputs;  // files and folders ("-" is stdin)
    bool json = false;                // one JSON document instead of the table
    std::string extractDir;           // write each failing feature there ("" = do not)
    std::string findingsOut;          // write every finding there as a GIS layer ("" = do not)
    unsigned jobs = 1;                // worker threads
    uint64_t maxInputBytes = 0;       // per file, as --max-input-bytes
    bool validate = true;             // false: --no-validate, the machine diagnoses
    Selection selection;              // GIS datasets only
    size_t maxFindings = 100;         // an invalid feature's findings listed, the rest counted
};

// 1234567 -> "1,234,567".
std::string grouped(size_t n);

// What a folder search finds, for messages and the help: ".json, .geojson, .wkt" and, built
// with GDAL, the GIS formats (".shp, .gpkg, ...").
std::string folderFormats();

// Whether `--findings OUT` can be written (its format known, GDAL there): 0, or the usage
// exit code after a message; asked before any feature is checked (cli/check_findings.cpp).
int findingsFormat(const std::string& out);

// Returns the exit code: 0 when every feature passed, else the largest code of a failing
// feature's class (3 malformed < 4 invalid < 5 forbidden < 6 checker/internal), or 8 when an
// extracted file or the findings could not be written.
int runCheck(const CheckOptions& options);

}  // namespace flood::cli
