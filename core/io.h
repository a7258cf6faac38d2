// Reading polygons: GeoJSON, bare ring arrays (earcut fixtures) and WKT; writing results.
#pragma once
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "polygon.h"
#include "status.h"

namespace flood {

struct ReadResult {
    Polygon polygon;
    std::vector<std::string> warnings;  // e.g. repeated consecutive points dropped
    Diagnostic diagnostic;              // Ok, or Malformed with "FILE:LINE:COL: ..."
};

// Detects the format from the content. `name` is used in messages ("-" means stdin).
ReadResult parsePolygon(std::string_view text, const std::string& name);
ReadResult readPolygonFile(const std::string& path);  // "-" reads stdin

// Validity rules checked before flooding (docs/ERRORS.md): finite coordinates, rings with at
// least 3 distinct points (holes may be single Steiner points), non-zero area, no
// self-intersection, holes inside their outer ring and not overlapping, parts not overlapping.
// Rings may touch at single points without crossing: shared vertices, or a vertex inside
// another ring's edge (a T-junction; within a part it is recorded in polygon.splits for the
// flood machine and the checker — so validate before triangulating). Returns Invalid with
// "NAME: ring R vertex V (x, y): reason" on the first problem found.
Diagnostic validate(Polygon& polygon, const std::string& name);

void writeJson(std::ostream& out, const Polygon& p, const std::vector<Triangle>& t);
void writeSvg(std::ostream& out, const Polygon& p, const std::vector<Triangle>& t);
void writeObj(std::ostream& out, const Polygon& p, const std::vector<Triangle>& t);

}  // namespace flood
