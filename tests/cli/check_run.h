// What the tests of `flood check` share (tests/cli/check_*_test.cpp): the command run with its
// stdout and stderr apart, its --json parsed.
#pragma once
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "test_support.h"

namespace flood::testing {

inline const std::string kMixed = sourcePath("polygons/datasets/mixed.geojson");

struct CheckRun {
    int code = -1;
    std::string out, err;
};

// stdout and stderr apart: the table and the JSON are stdout only.
inline CheckRun cli(const std::string& args) {
    namespace fs = std::filesystem;
    fs::path err = fs::temp_directory_path() / ("flood-check-stderr-" + std::to_string(getpid()));
    std::string cmd = std::string(FLOOD_CLI) + " " + args + " 2>" + err.string();
    RunResult run = runShell(cmd);
    CheckRun r;
    r.code = run.code;
    r.out = std::move(run.out);
    r.err = slurp(err);
    fs::remove(err);
    return r;
}

inline nlohmann::json checkJson(const std::string& args, int* code = nullptr) {
    CheckRun r = cli("check --json " + args);
    if (code) *code = r.code;
    nlohmann::json doc = nlohmann::json::parse(r.out, nullptr, false);
    EXPECT_FALSE(doc.is_discarded()) << r.out << r.err;
    return doc;
}

inline bool has(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

// The only part of the output that depends on the run: the time.
inline std::string timeless(std::string s) {
    s = std::regex_replace(s, std::regex("; [0-9.]+ s\n"), "; T s\n");
    return std::regex_replace(s, std::regex("\"seconds\": [0-9.e+-]+"), "\"seconds\": T");
}

}  // namespace flood::testing
