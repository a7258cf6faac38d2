// flood check's progress line (check_progress.h).
#include "check_progress.h"

#include <cstdio>

#include "check.h"  // grouped()

namespace flood::cli {

namespace {
std::string megabytes(uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", double(bytes) / 1e6);
    return text;
}
}  // namespace

std::string progressLine(const ReadProgress& read, size_t featuresDone, size_t featuresKnown,
                         size_t filesRead, size_t files) {
    std::string line = "check: ";
    const uint64_t total = read.bytesTotal, bytes = read.bytesRead;
    if (filesRead < files && (total || bytes)) {
        line += "reading " + megabytes(bytes) + (total ? "/" + megabytes(total) : "") + " MB";
        if (size_t parsed = read.featuresParsed)
            line += ", " + grouped(parsed) + " features parsed";
        if (size_t made = read.featuresRead) line += ", " + grouped(made) + " read";
        line += "; ";
    }
    return line + grouped(featuresDone) + "/" + grouped(featuresKnown) + " features checked, " +
           std::to_string(filesRead) + "/" + std::to_string(files) + " files read";
}

uint64_t readingStep(const ReadProgress& read) {
    const uint64_t total = read.bytesTotal, bytes = read.bytesRead;
    const uint64_t share = total ? bytes * 100 / total : bytes >> 20;  // a pipe: MiB
    return (share & 0xffff) | (uint64_t(read.featuresParsed / 1000) & 0xffffff) << 16 |
           uint64_t(read.featuresRead / 1000) << 40;
}

}  // namespace flood::cli
