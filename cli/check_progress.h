// `flood check`'s progress line, on a terminal and not under -q: while files are read, how far
// the reading has come (bytes, then the features the JSON parser met and those made polygons:
// a 65 MB GeoJSON takes seconds before its first feature can be checked), then the checking.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "flood/io/io.h"

namespace flood::cli {

// The line's text, without "\r" and the erasing escape.
std::string progressLine(const ReadProgress& read, size_t featuresDone, size_t featuresKnown,
                         size_t filesRead, size_t files);

// What the reading part of the line shows, coarsely (whole percents of the bytes, thousands of
// features): the line is redrawn from the reading thread each time this changes, so it moves
// with the reading, not with a clock, and at most a few hundred times per file.
uint64_t readingStep(const ReadProgress& read);

}  // namespace flood::cli
