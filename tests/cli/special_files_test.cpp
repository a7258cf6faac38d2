// Every writer against the files an output can hurt (docs/ERRORS.md, exit 8; issue 25): a
// device node, a FIFO, a symbolic link, a read-only folder, an existing file's permissions, an
// existing multi-layer GeoPackage, and a signal in the middle of a write.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "test_support.h"
#ifdef FLOOD_GDAL
#include <gdal_priv.h>
#include <ogrsf_frmts.h>
#endif

using namespace flood::testing;
namespace fs = std::filesystem;

namespace {

std::string src(const std::string& rel) { return std::string(FLOOD_SOURCE_DIR) + "/" + rel; }

bool has(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

std::vector<std::string> listing(const fs::path& d) {
    std::vector<std::string> names;
    for (auto& e : fs::directory_iterator(d)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// One writer of the command line: its arguments before `-o OUT`, and whether it writes a GIS
// dataset (which needs a regular file: it seeks).
struct Writer {
    std::string name, args;
    bool gis = false;
    std::string ext = ".out";   // of OUT: a GIS writer's choice of format is explicit anyway
    std::string option = "-o";  // what names OUT
};

std::vector<Writer> writers() {
    const std::string hole = src("polygons/hole.json");
    std::vector<Writer> w = {
        // .out is no format's extension (exit 2): the format is named.
        {"triangulate json", "triangulate --format json " + hole},
        {"triangulate svg", "triangulate --format svg " + hole},
        {"triangulate obj", "triangulate --format obj " + hole},
        {"trace", "trace " + hole},
        {"generate", "generate circle-jagged 100"},
        {"shrink", "shrink -q " + src("polygons/invalid/forbidden-ceiling-as-end.json")},
    };
#ifdef FLOOD_GDAL
    w.push_back({"triangulate gpkg", "triangulate --format gpkg " + hole, true, ".gpkg"});
    w.push_back({"triangulate fgb", "triangulate --format fgb " + hole, true, ".fgb"});
    // A valid input: exit 0, its findings layer empty.
    w.push_back({"check --findings gpkg", "check " + hole, true, ".gpkg", "--findings"});
#endif
    return w;
}

// Runs flood with `args` in a child whose SIGINT and SIGTERM are at their defaults (a test run
// in the background has SIGINT ignored); stdout and stderr go to `log`.
pid_t spawn(const std::vector<std::string>& args, const fs::path& log) {
    pid_t pid = fork();
    if (pid == 0) {
        signal(SIGINT, SIG_DFL);
        signal(SIGTERM, SIG_DFL);
        FILE* f = std::fopen(log.c_str(), "w");
        if (f) {
            dup2(fileno(f), 1);
            dup2(fileno(f), 2);
        }
        std::vector<char*> argv{const_cast<char*>(FLOOD_CLI)};
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv(FLOOD_CLI, argv.data());
        _exit(127);
    }
    return pid;
}

// Waits up to 60 s for a hidden entry (a temporary) to appear in `dir`.
bool temporaryAppears(const fs::path& dir, pid_t pid) {
    auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < until) {
        for (auto& e : fs::directory_iterator(dir))
            if (e.path().filename().string()[0] == '.') return true;
        int st;
        if (waitpid(pid, &st, WNOHANG) == pid) return false;  // finished first
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    return false;
}

}  // namespace

// `--format gpkg -o /dev/null` used to rename its dataset over /dev/null (a regular file
// replaced the machine's device), a FIFO became a file, and `-o /dev/full` exited 0.
TEST(SpecialFiles, GisFormatsRefuseDevicesAndFifosAndLeaveThemAlone) {
#ifndef FLOOD_GDAL
    GTEST_SKIP() << "built without GDAL: no GIS writer";
#else
    fs::path d = scratch("gis-special");
    const std::string hole = src("polygons/hole.json");
    ASSERT_EQ(mkfifo((d / "fifo").c_str(), 0644), 0);
    fs::create_symlink(d / "fifo", d / "link-to-fifo.gpkg");
    struct Case {
        std::string out, shown, kind;
    };
    std::vector<Case> cases = {
        {(d / "fifo").string(), (d / "fifo").string(), "a FIFO"},
        {(d / "link-to-fifo.gpkg").string(), (d / "link-to-fifo.gpkg").string(), "a FIFO"},
    };
    // Device nodes of our own (as /dev/null and /dev/full are: char 1,3 and 1,7), which only
    // root may make; never the machine's own as root, which a regressed writer would replace
    // (/dev/full was, by 5889d69). Without root /dev/full is safe: /dev is not writable then.
    std::vector<std::string> made;
    for (const auto& [name, minor] : {std::pair<const char*, int>{"null", 3}, {"full", 7}})
        if (mknod((d / name).c_str(), S_IFCHR | 0666, makedev(1, minor)) == 0) {
            cases.push_back({(d / name).string(), (d / name).string(), "a character device"});
            made.push_back(name);
        }
    if (made.empty() && access("/dev", W_OK) != 0) {
        std::cout << "note: not root (mknod: " << std::strerror(errno)
                  << "): /dev/full stands for the device nodes\n";
        cases.push_back({"/dev/full", "/dev/full", "a character device"});
    }
    for (const Case& c : cases)
        for (const char* format : {"gpkg", "fgb"}) {
            SCOPED_TRACE(std::string(format) + " -o " + c.out);
            struct stat before, after;
            ASSERT_EQ(stat(c.out.c_str(), &before), 0);
            RunResult r = runShell("timeout 60 " + std::string(FLOOD_CLI) + " triangulate " + hole +
                                   " --format " + format + " -o " + c.out + " 2>&1");
            EXPECT_EQ(r.code, 8) << r.out;
            EXPECT_EQ(r.out, "error: " + c.out + ": cannot write: --format " + format +
                                 " needs a regular file, and " + c.shown + " is " + c.kind +
                                 " (it was left untouched; write to a file)\n");
            ASSERT_EQ(stat(c.out.c_str(), &after), 0);
            EXPECT_EQ(after.st_mode, before.st_mode);
            EXPECT_EQ(after.st_ino, before.st_ino);
            EXPECT_EQ(after.st_rdev, before.st_rdev);
        }
    EXPECT_TRUE(fs::is_symlink(d / "link-to-fifo.gpkg"));
    std::vector<std::string> want = {"fifo", "link-to-fifo.gpkg"};
    want.insert(want.end(), made.begin(), made.end());
    std::sort(want.begin(), want.end());
    EXPECT_EQ(listing(d), want);  // nothing left beside them
    fs::remove_all(d);
#endif
}

// A FIFO is written in place by the stream writers (a reader gets the output) and refused by
// the GIS writers (above); never replaced by a regular file.
TEST(SpecialFiles, EveryStreamWriterWritesAFifoInPlace) {
    fs::path d = scratch("fifo-writers");
    const fs::path fifo = d / "fifo", got = d / "got";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
    for (const Writer& w : writers()) {
        if (w.gis) continue;
        SCOPED_TRACE(w.name);
        RunResult r =
            runShell("cat " + fifo.string() + " > " + got.string() + " & timeout 60 " + FLOOD_CLI +
                     " " + w.args + " " + w.option + " " + fifo.string() + " 2>&1; wait");
        EXPECT_EQ(r.code, 0) << r.out;
        EXPECT_GT(fs::file_size(got), 10u);
        EXPECT_TRUE(fs::is_fifo(fifo));
        // A device likewise (shrink used to read /dev/null back and exit 6), and /dev/stdout
        // (a link through /proc to the pipe runShell reads).
        r = runCli(w.args + " -o /dev/null");
        EXPECT_EQ(r.code, 0) << r.out;
        r = runShell(std::string(FLOOD_CLI) + " " + w.args + " -o /dev/stdout 2>/dev/null");
        EXPECT_EQ(r.code, 0);
        EXPECT_GT(r.out.size(), 10u);
    }
    fs::remove_all(d);
}

// `-o LINK` used to replace the link by a regular file (its target kept the old content), and
// an existing 0600 file became 0644: the target is written, the link stays, the mode stays.
TEST(SpecialFiles, EveryWriterWritesThroughASymlinkAndKeepsTheMode) {
    const fs::path top = scratch("symlink-writers");
    for (const Writer& w : writers()) {
        SCOPED_TRACE(w.name);
        std::string folder = w.name;
        std::replace(folder.begin(), folder.end(), ' ', '-');
        const fs::path d = top / folder;
        fs::create_directories(d / "real");
        const std::string& ext = w.ext;
        const fs::path target = d / "real" / ("target" + ext), link = d / ("link" + ext);
        { std::ofstream(target) << "old"; }
        ASSERT_EQ(chmod(target.c_str(), 0600), 0);
        fs::create_symlink(fs::path("real") / target.filename(), link);  // relative
        RunResult r = runCli(w.args + " " + w.option + " " + link.string());
        EXPECT_EQ(r.code, 0) << r.out;
        EXPECT_TRUE(fs::is_symlink(link));
        EXPECT_NE(slurp(target), "old");
        EXPECT_GT(fs::file_size(target), 10u);
        struct stat st;
        ASSERT_EQ(stat(target.c_str(), &st), 0);
        EXPECT_EQ(st.st_mode & 07777, 0600u);
        // A chain of links, the last one dangling: its target is made, with a new file's mode.
        fs::remove(target);
        fs::create_symlink(link.filename(), d / ("chain" + ext));
        r = runCli(w.args + " " + w.option + " " + (d / ("chain" + ext)).string());
        EXPECT_EQ(r.code, 0) << r.out;
        EXPECT_TRUE(fs::is_symlink(link));
        EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(target)));
        fs::remove(d / ("chain" + ext));
        // Without a link, an existing file keeps its mode too.
        ASSERT_EQ(chmod(target.c_str(), 0640), 0);
        r = runCli(w.args + " " + w.option + " " + target.string());
        EXPECT_EQ(r.code, 0) << r.out;
        ASSERT_EQ(stat(target.c_str(), &st), 0);
        EXPECT_EQ(st.st_mode & 07777, 0640u);
        EXPECT_EQ(listing(d / "real"), std::vector<std::string>{target.filename().string()});
    }
    // A loop of links is named, not followed forever.
    const fs::path& d = top;
    fs::create_symlink("loop-b", d / "loop-a");
    fs::create_symlink("loop-a", d / "loop-b");
    fs::create_symlink("loop-b.gpkg", d / "loop-a.gpkg");  // --findings: its format by its name
    fs::create_symlink("loop-a.gpkg", d / "loop-b.gpkg");
    for (const Writer& w : writers()) {
        const std::string loop = (d / "loop-a").string() + (w.option == "-o" ? "" : w.ext);
        RunResult r = runCli(w.args + " " + w.option + " " + loop);
        EXPECT_EQ(r.code, 8) << w.name << ": " << r.out;
        EXPECT_TRUE(has(r.out, fs::path(loop).filename().string() +
                                   ": cannot write: Too many levels of symbolic links"))
            << w.name << ": " << r.out;
    }
    fs::remove_all(d);
}

// A folder that cannot be written: exit 8 naming OUT, nothing made, nothing left.
TEST(SpecialFiles, EveryWriterFailsInAReadOnlyFolderLeavingNothing) {
    fs::path d = scratch("read-only-writers");
    fs::path ro = d / "ro";
    fs::create_directories(ro);
    { std::ofstream(ro / "old.out") << "old"; }
    { std::ofstream(ro / "old.gpkg") << "old"; }
    fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec);
    // Root writes anywhere: then /proc, which no one may create files in.
    const fs::path dir = access(ro.c_str(), W_OK) == 0 ? fs::path("/proc") : ro;
    for (const Writer& w : writers()) {
        SCOPED_TRACE(w.name);
        for (const std::string name : {"new", "old"}) {
            // (--findings: its format by its name)
            const std::string out = (dir / name).string() + (w.option == "-o" ? ".out" : w.ext);
            RunResult r = runCli(w.args + " " + w.option + " " + out);
            EXPECT_EQ(r.code, 8) << r.out;
            EXPECT_EQ(r.out.rfind("error: " + out + ": cannot write: ", 0), 0u) << r.out;
        }
    }
    fs::permissions(ro, fs::perms::owner_all);
    EXPECT_EQ(listing(ro), (std::vector<std::string>{"old.gpkg", "old.out"}));
    EXPECT_EQ(slurp(ro / "old.out"), "old");
    EXPECT_EQ(slurp(ro / "old.gpkg"), "old");
    fs::remove_all(d);
}

// SIGINT or SIGTERM in the middle of a write used to leave the hidden temporary (49 MB seen):
// it is removed, and the command still ends by the signal.
TEST(SpecialFiles, ASignalDuringAWriteLeavesNoTemporary) {
    fs::path d = scratch("signal-writers");
    std::vector<std::vector<std::string>> commands = {
        {"generate", "circle-jagged", "1000000", "-o", (d / "out.json").string()}};
#ifdef FLOOD_GDAL
    RunResult g = runCli("generate circle-jagged 20000 -o " + (d / "in.json").string());
    ASSERT_EQ(g.code, 0) << g.out;
    fs::create_directories(d / "gis");
    for (const char* ext : {"gpkg", "fgb"})
        commands.push_back({"triangulate", (d / "in.json").string(), "-o",
                            (d / "gis" / (std::string("out.") + ext)).string()});
#endif
    for (const auto& args : commands)
        for (int sig : {SIGINT, SIGTERM}) {
            const fs::path out = args.back(), dir = out.parent_path();
            SCOPED_TRACE(args[0] + " -o " + out.string() + ", signal " + std::to_string(sig));
            pid_t pid = spawn(args, d / "log");
            ASSERT_GT(pid, 0);
            if (!temporaryAppears(dir, pid)) {
                std::cout << "note: the write ended before a signal could be sent\n";
                continue;
            }
            kill(pid, sig);
            int st = 0;
            ASSERT_EQ(waitpid(pid, &st, 0), pid);
            EXPECT_TRUE(WIFSIGNALED(st) && WTERMSIG(st) == sig) << st << " " << slurp(d / "log");
            for (auto& e : fs::directory_iterator(dir))
                EXPECT_NE(e.path().filename().string()[0], '.') << e.path();
            fs::remove(out);
        }
    fs::remove_all(d);
}

#ifdef FLOOD_GDAL
namespace {
// The layers of a dataset and their feature counts.
std::vector<std::pair<std::string, long long>> layers(const fs::path& file) {
    std::vector<std::pair<std::string, long long>> out;
    GDALAllRegister();
    GDALDataset* ds = static_cast<GDALDataset*>(
        GDALOpenEx(file.c_str(), GDAL_OF_VECTOR, nullptr, nullptr, nullptr));
    if (!ds) return out;
    for (int k = 0; k < ds->GetLayerCount(); ++k)
        out.emplace_back(ds->GetLayer(k)->GetName(), ds->GetLayer(k)->GetFeatureCount());
    GDALClose(ds);
    return out;
}
}  // namespace

// `-o project.gpkg` used to replace a two-layer GeoPackage by one layer: only Flood's layer
// "triangles" is added, or replaced when it is there; the file's other layers stay.
TEST(SpecialFiles, AnExistingGeoPackageKeepsItsOtherLayers) {
    fs::path d = scratch("gpkg-layers");
    const fs::path project = d / "project.gpkg";
    RunResult r = runShell("ogr2ogr -f GPKG " + project.string() + " " +
                           src("polygons/datasets/mixed.geojson") + " -nln parcels 2>&1");
    ASSERT_EQ(r.code, 0) << r.out;
    r = runShell("ogr2ogr -update " + project.string() + " " +
                 src("polygons/datasets/mixed.geojson") + " -nln roads 2>&1");
    ASSERT_EQ(r.code, 0) << r.out;
    const auto before = layers(project);
    ASSERT_EQ(before.size(), 2u);
    ASSERT_EQ(chmod(project.c_str(), 0600), 0);
    r = runCli("triangulate " + src("polygons/hole.json") + " -o " + project.string());
    ASSERT_EQ(r.code, 0) << r.out;
    auto after = layers(project);
    ASSERT_EQ(after.size(), 3u);
    EXPECT_EQ(after[0], before[0]);
    EXPECT_EQ(after[1], before[1]);
    EXPECT_EQ(after[2].first, "triangles");
    const long long first = after[2].second;
    // Again, with another polygon: the layer is replaced, not added twice.
    r = runCli("triangulate " + src("polygons/comb.json") + " -o " + project.string());
    ASSERT_EQ(r.code, 0) << r.out;
    after = layers(project);
    ASSERT_EQ(after.size(), 3u);
    EXPECT_EQ(after[2].first, "triangles");
    EXPECT_EQ(after[2].second, 16);
    EXPECT_NE(after[2].second, first);
    EXPECT_EQ(after[0], before[0]);
    struct stat st;
    ASSERT_EQ(stat(project.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 07777, 0600u);
    // A file named .gpkg that is no GeoPackage is replaced, as -o replaces any file.
    { std::ofstream(d / "not.gpkg") << "not a geopackage"; }
    r = runCli("triangulate " + src("polygons/hole.json") + " -o " + (d / "not.gpkg").string());
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(layers(d / "not.gpkg").size(), 1u);
    EXPECT_EQ(listing(d), (std::vector<std::string>{"not.gpkg", "project.gpkg"}));
    fs::remove_all(d);
}
#endif

// `check --extract DIR` never writes through a name that is taken: a FIFO there is not opened
// (a write would block until a reader came), a dangling link not followed (its target is not
// made), a device not written; a folder that cannot be written is exit 8 naming the file, with
// nothing left in it.
TEST(SpecialFiles, ExtractNeverWritesThroughATakenName) {
    const fs::path d = scratch("extract-special"), out = d / "out";
    fs::create_directories(out);
    const std::string mixed = src("polygons/datasets/mixed.geojson");
    ASSERT_EQ(mkfifo((out / "mixed_feature1.json").c_str(), 0644), 0);
    fs::create_symlink(d / "victim", out / "mixed_feature1-2.json");
    fs::create_symlink("/dev/null", out / "mixed_feature3.json");
    const std::string check = std::string(FLOOD_CLI) + " check --extract ";
    RunResult r = runShell(check + out.string() + " " + mixed + " 2>&1 >/dev/null");
    EXPECT_EQ(r.code, 4) << r.out;
    EXPECT_TRUE(fs::is_fifo(out / "mixed_feature1.json"));
    EXPECT_TRUE(fs::is_symlink(out / "mixed_feature1-2.json"));
    EXPECT_FALSE(fs::exists(d / "victim"));
    EXPECT_TRUE(fs::is_symlink(out / "mixed_feature3.json"));
    EXPECT_GT(fs::file_size(out / "mixed_feature1-3.json"), 10u);
    EXPECT_GT(fs::file_size(out / "mixed_feature3-2.json"), 10u);
    // A folder that cannot be written (root writes anywhere: then /proc).
    const fs::path ro = d / "ro";
    fs::create_directories(ro);
    fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec);
    const fs::path dir = access(ro.c_str(), W_OK) == 0 ? fs::path("/proc") : ro;
    r = runShell(check + dir.string() + " " + mixed + " 2>&1 >/dev/null");
    EXPECT_EQ(r.code, 8) << r.out;
    EXPECT_TRUE(has(r.out, "error: " + (dir / "mixed_feature1.json").string() + ": cannot write: "))
        << r.out;
    fs::permissions(ro, fs::perms::owner_all);
    EXPECT_TRUE(listing(ro).empty());
    fs::remove_all(d);
}
