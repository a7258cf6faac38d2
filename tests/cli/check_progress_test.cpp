// `flood check`'s progress line while a large file is read (cli/check_progress.h): it moves
// with the reading — bytes, then Features parsed, then read — where it sat at "0/0 features"
// before. On a terminal (script(1) gives one); the lines are counted, no clock is read.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "test_support.h"

using namespace flood::testing;
namespace fs = std::filesystem;

namespace {

// What a terminal shows of `flood ARGS` (its stderr and stdout), run through script(1).
std::string onATerminal(const std::string& args) {
    std::string inner = std::string(FLOOD_CLI) + " " + args + " > /dev/null";
    FILE* p = popen(("/usr/bin/script -qec '" + inner + "' /dev/null").c_str(), "r");
    if (!p) return "";
    std::string tty;
    char buf[4096];
    for (size_t k; (k = fread(buf, 1, sizeof buf, p)) > 0;) tty.append(buf, k);
    pclose(p);
    return tty;
}

// The redrawn lines: what follows each "\r\033[K".
std::vector<std::string> drawn(const std::string& tty) {
    std::vector<std::string> lines;
    const std::string erase = "\r\033[K";
    for (size_t at = tty.find(erase); at != std::string::npos;) {
        size_t next = tty.find(erase, at + erase.size());
        std::string line =
            tty.substr(at + erase.size(),
                       next == std::string::npos ? std::string::npos : next - at - erase.size());
        if (!line.empty()) lines.push_back(line);
        at = next;
    }
    return lines;
}

}  // namespace

TEST(CheckProgress, TheLineMovesWhileALargeFileIsRead) {
    if (!fs::exists("/usr/bin/script")) GTEST_SKIP() << "no script(1) to make a terminal";
    fs::path dir = scratch("check-progress");
    fs::path file = dir / "many.geojson";
    const size_t n = 20000;
    {
        std::ofstream out(file);
        out << "{\"type\": \"FeatureCollection\", \"features\": [\n";
        for (size_t i = 0; i < n; ++i) {
            const size_t x = 3 * (i % 1000), y = 3 * (i / 1000);
            out << (i ? ",\n" : "") << "{\"type\": \"Feature\", \"properties\": {\"name\": \"p" << i
                << "\"}, \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[[" << x << ", "
                << y << "], [" << x + 2 << ", " << y << "], [" << x + 2 << ", " << y + 2 << "], ["
                << x << ", " << y + 2 << "], [" << x << ", " << y << "]]]}}";
        }
        out << "\n]}\n";
    }
    const std::vector<std::string> lines = drawn(onATerminal("check -j 1 " + file.string()));
    ASSERT_FALSE(lines.empty());
    // Reading lines: "check: reading R/T MB[, P features parsed][, F read]; 0/0 features ...".
    const std::regex reading(
        R"(check: reading ([0-9.]+)/([0-9.]+) MB(, ([0-9,]+) features parsed)?(, ([0-9,]+) read)?; 0/0 features checked, 0/1 files read)");
    std::set<std::string> distinct;
    double lastMB = 0;
    size_t parsedLines = 0, readLines = 0, readingLines = 0;
    bool checking = false;
    for (const std::string& line : lines) {
        std::smatch m;
        if (std::regex_match(line, m, reading)) {
            EXPECT_FALSE(checking) << "reading after checking began: " << line;
            ++readingLines;
            distinct.insert(line);
            const double mb = std::stod(m[1]);
            EXPECT_GE(mb, lastMB) << line;
            lastMB = mb;
            parsedLines += m[3].matched;
            readLines += m[5].matched;
        } else if (line.find("features checked") != std::string::npos &&
                   line.find("0/0 features checked") == std::string::npos) {
            checking = true;
        }
    }
    // Bytes in several steps (3.8 MB in 64 KiB blocks), then thousands of features parsed,
    // then read: at least a line for each of the 20 thousands of each.
    EXPECT_GE(distinct.size(), 40u) << readingLines << " reading lines";
    EXPECT_GE(parsedLines, 20u);
    EXPECT_GE(readLines, 19u);
    // The check's own line is redrawn on a clock (10 a second), so a quick check may finish
    // before it shows: only its order after the reading is asserted (above).

    // -q: no progress line at all.
    const std::string quiet = onATerminal("check -q -j 1 " + file.string());
    EXPECT_EQ(quiet.find("check: "), std::string::npos) << quiet;
    fs::remove_all(dir);
}
