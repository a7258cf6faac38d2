// The diagnostics catalogue (docs/ERRORS.md), one row per error the core can report: the
// example file in polygons/invalid/, the `flood` arguments, the exit code and a substring of
// the exact message. Forbidden-machine examples run with --no-validate (validation would
// reject them first). A second test checks that every forbidden reason of the machine
// (FLOOD_FORBIDDEN in flood/machine/events.h) and every validation rule has a row.
#include <gtest/gtest.h>

#include "invalid_catalogue.h"
#include "test_support.h"

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <string>

#include "flood/machine/events.h"

using namespace flood::testing;

namespace {

RunResult run(const std::string& args) { return runCli(args); }

}  // namespace

TEST(Errors, EveryCatalogueEntryGivesItsExitCodeAndMessage) {
    for (const CatalogueRow& row : kInvalidCatalogue) {
        std::string file =
            *row.file ? std::string(FLOOD_SOURCE_DIR) + "/polygons/invalid/" + row.file : "";
        RunResult r = run(std::string(row.args) + " " + file);
        EXPECT_EQ(r.code, row.code) << row.args << " " << row.file << ":\n" << r.out;
        EXPECT_NE(r.out.find(row.message), std::string::npos)
            << row.args << " " << row.file << ": expected \"" << row.message << "\" in:\n"
            << r.out;
        if (row.code != 0 && std::string(row.args).rfind("triangulate", 0) == 0) {
            EXPECT_EQ(r.out.find("\"triangles\""), std::string::npos)
                << "no triangles on failure: " << row.file;
        }
    }
}

// With validation on (the default), every forbidden and checker example is refused by
// validate() first: the machine's diagnoses are unreachable after validation.
TEST(Errors, MachineExamplesAreCaughtByValidationFirst) {
    for (const CatalogueRow& row : kInvalidCatalogue) {
        if (row.code != 5 && row.code != 6) continue;
        RunResult r =
            run(std::string("triangulate ") + FLOOD_SOURCE_DIR + "/polygons/invalid/" + row.file);
        EXPECT_EQ(r.code, 4) << row.file << ":\n" << r.out;
    }
}

// Every forbidden reason of FLOOD_FORBIDDEN has an example row, except the one that no input
// reaches (documented in docs/ERRORS.md): NoProgress (the step budget and walk guards, a
// safety net; tests/machine/regress_test.cpp holds fuzzer inputs that end there).
TEST(Errors, CatalogueCoversEveryForbiddenReason) {
    for (int i = 1; i < int(flood::Forbidden::Count); ++i) {
        std::string name = flood::forbiddenName(flood::Forbidden(i));
        if (name == "NoProgress") continue;
        bool found = false;
        for (const CatalogueRow& row : kInvalidCatalogue)
            found |=
                std::string(row.message).find("forbidden transition " + name) != std::string::npos;
        EXPECT_TRUE(found) << "no catalogue example for forbidden reason " << name;
    }
}
