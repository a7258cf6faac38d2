// The core's atomic outputs (core/io/output.h), as the CLI and the viewer use them: a file
// appears whole on commit, an output never committed leaves the old file and no temporary,
// and a failed commit says which path and why.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/output.h"
#include "test_support.h"

using namespace flood;
using flood::testing::scratch;
using flood::testing::slurp;
namespace fs = std::filesystem;

namespace {
size_t entries(const fs::path& dir) {
    return size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}
}  // namespace

TEST(Output, CommitReplacesTheFileWhole) {
    fs::path dir = scratch("output-commit"), file = dir / "a.txt";
    std::ofstream(file) << "old";
    Output out(file.string());
    out.stream() << "new text";
    EXPECT_EQ(slurp(file), "old");  // written beside it until the commit
    EXPECT_EQ(out.commit(), Status::Ok);
    EXPECT_EQ(slurp(file), "new text");
    EXPECT_EQ(entries(dir), 1u);
}

TEST(Output, UncommittedLeavesTheOldFileAndNoTemporary) {
    fs::path dir = scratch("output-abandon"), file = dir / "a.txt";
    std::ofstream(file) << "old";
    {
        Output out(file.string());
        out.stream() << "half";
    }
    EXPECT_EQ(slurp(file), "old");
    EXPECT_EQ(entries(dir), 1u);
}

TEST(Output, AFailedCommitNamesThePathAndTheReason) {
    fs::path dir = scratch("output-fail");
    const std::string path = (dir / "missing" / "a.txt").string();
    Output out(path);
    out.stream() << "lost";
    std::string message;
    EXPECT_EQ(out.commit(&message), Status::WriteFailed);
    EXPECT_EQ(message, "error: " + path + ": cannot write: No such file or directory");
    EXPECT_FALSE(fs::exists(path));
}
