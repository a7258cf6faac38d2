// What `flood check` finds, feature by feature (cli/check.cpp), as its outputs read it: the
// table and --json (check.cpp), --findings and --extract of GIS features (check_findings.cpp).
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "check.h"
#include "flood/check/verdict.h"  // Verdict: the rows' verdicts
#include "flood/geometry/polygon.h"
#include "flood/geometry/status.h"

namespace flood::cli {

// A culprit edge of a finding: its ring, its first vertex within the ring, its two ends.
struct FindingEdge {
    Index ring = kNone, vertex = kNone;
    Point a, b;
};

// One problem of an invalid feature (validateAll()): where and why, and the point it is at.
struct Finding {
    std::string at, reason;
    std::string message;                 // the whole line, as validation said it
    Index ring = kNone, vertex = kNone;  // vertex within its ring
    bool located = false;                // x, y known (a crossing's is computed, not exact)
    double x = 0, y = 0;
    std::vector<FindingEdge> edges;  // its culprit edges (two crossing edges, ...)
};

struct Row {
    std::string file;
    std::string layer;  // a GIS dataset's layer, or ""
    bool wholeFile = true;
    int64_t feature = 0;  // the FID (FeatureRead::fid), what --feature and the viewer take
    std::string id, name;
    std::vector<std::pair<std::string, std::string>> attributes;  // the feature's properties
    size_t vertices = 0;
    Verdict verdict = Verdict::Ok;
    std::string at;                 // ring and vertex, or the forbidden transition
    std::string reason;             // one line
    std::vector<Finding> findings;  // invalid: every finding, the first being at/reason
    Finding place;                  // failing without findings: where (a forbidden culprit)
    size_t findingsOmitted = 0;     // beyond --max-findings
    bool findingsComplete = true;   // false: the search for crossings gave up
    std::string repro;              // --extract: GeoJSON text that fails the same way ("" = none)
    bool gis = false;               // read through GDAL: extracted through GDAL
    bool severalLayers = false;     // its dataset was checked layer by layer
    std::string extracted;
};

// `--findings OUT`: every finding of the failing rows as a layer of points "findings" and
// their culprit edges as a layer of lines "finding_edges" (in OUT, or beside it in
// OUT_edges.EXT for a format of one layer). Returns 0, or the exit code after a message.
int writeFindings(const std::vector<Row*>& rows, const std::string& out);

// `--extract DIR` for a feature read through GDAL: written as the feature it was (its fields,
// its FID, its CRS) in its dataset's format, or GeoJSON where GDAL cannot write that, as
// DIR/STEM_featureFID.EXT (STEM_LAYER_featureFID.EXT when its dataset has several layers).
// Returns false after a message when it could not be written.
bool extractGis(Row& row, const std::string& dir, const std::string& stem);

}  // namespace flood::cli
