// The core's atomic outputs (flood/io/output.h), as the CLI and the viewer use them: a file
// appears whole on commit, an output never committed leaves the old file and no temporary,
// and a failed commit says which path and why.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>

#include "flood/io/output.h"
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

// Through a symbolic link the target is replaced (atomically, beside it) and the link stays;
// an existing file keeps its permissions.
TEST(Output, ASymlinkIsFollowedAndTheModeKept) {
    fs::path dir = scratch("output-link");
    fs::create_directories(dir / "real");
    fs::path target = dir / "real" / "a.txt", link = dir / "link.txt";
    std::ofstream(target) << "old";
    fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write);
    fs::create_symlink("real/a.txt", link);
    Output out(link.string());
    out.stream() << "new";
    EXPECT_EQ(entries(dir / "real"), 2u);  // the temporary is beside the target
    EXPECT_EQ(out.commit(), Status::Ok);
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(slurp(target), "new");
    EXPECT_EQ(fs::status(target).permissions(), fs::perms::owner_read | fs::perms::owner_write);
    EXPECT_EQ(entries(dir / "real"), 1u);
    OutputTarget t = outputTarget(link.string());
    EXPECT_EQ(t.file, (dir / "real" / "a.txt").string());
    EXPECT_TRUE(t.regular());
}

// IfExists::Fail never touches an existing name (a file, a link, even a dangling one) and
// says EEXIST; a free name is written whole.
TEST(Output, IfExistsFailKeepsEveryExistingName) {
    fs::path dir = scratch("output-noreplace");
    std::ofstream(dir / "a.txt") << "old";
    fs::create_symlink("nowhere", dir / "dangling.txt");
    for (const char* name : {"a.txt", "dangling.txt"}) {
        Output out((dir / name).string(), Output::IfExists::Fail);
        out.stream() << "new";
        std::string message;
        EXPECT_EQ(out.commit(&message), Status::WriteFailed) << name;
        EXPECT_EQ(out.error(), EEXIST) << name;
    }
    EXPECT_EQ(slurp(dir / "a.txt"), "old");
    EXPECT_TRUE(fs::is_symlink(dir / "dangling.txt"));
    EXPECT_FALSE(fs::exists(dir / "nowhere"));
    Output fresh((dir / "b.txt").string(), Output::IfExists::Fail);
    fresh.stream() << "new";
    EXPECT_EQ(fresh.commit(), Status::Ok);
    EXPECT_EQ(slurp(dir / "b.txt"), "new");
    EXPECT_EQ(entries(dir), 3u);
}

// A signal in the middle of a write removes the temporary, then acts as it would have: the
// default ends the process by the signal; a handler installed before is still called.
TEST(Output, ASignalRemovesTheTemporary) {
    fs::path dir = scratch("output-signal");
    for (bool ownHandler : {false, true})
        for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
            SCOPED_TRACE(std::to_string(sig) + (ownHandler ? " with a handler" : ""));
            pid_t pid = fork();
            ASSERT_GE(pid, 0);
            if (pid == 0) {
                if (ownHandler) std::signal(sig, [](int) { _exit(42); });
                else std::signal(sig, SIG_DFL);
                Output out((dir / "a.txt").string());
                out.stream() << "half";
                raise(sig);
                _exit(0);  // not reached
            }
            int st = 0;
            ASSERT_EQ(waitpid(pid, &st, 0), pid);
            if (ownHandler) EXPECT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 42) << st;
            else EXPECT_TRUE(WIFSIGNALED(st) && WTERMSIG(st) == sig) << st;
            EXPECT_EQ(entries(dir), 0u);
        }
}
