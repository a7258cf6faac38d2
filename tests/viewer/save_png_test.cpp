// Save PNG's file name and folder (viewer/export.h, issue 27 §4): named after the polygon and
// the step, in the last export's folder, else the user's Pictures folder as xdg-user-dir finds
// it, else home, never the working directory while there is a home.
// Compiles to nothing when the viewer is not built.
#if __has_include("export.h")
#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "export.h"
#include "test_support.h"

using namespace flood;
using namespace flood::view;
using flood::testing::scratch;
using flood::testing::sourcePath;

namespace {

// Sets the environment variables a test names, and puts back what they were.
struct Env {
    std::vector<std::pair<std::string, std::optional<std::string>>> saved;
    void set(const std::string& name, const std::optional<std::string>& value) {
        const char* was = std::getenv(name.c_str());
        saved.push_back({name, was ? std::optional<std::string>(was) : std::nullopt});
        if (value) setenv(name.c_str(), value->c_str(), 1);
        else unsetenv(name.c_str());
    }
    ~Env() {
        for (auto it = saved.rbegin(); it != saved.rend(); ++it)
            if (it->second) setenv(it->first.c_str(), it->second->c_str(), 1);
            else unsetenv(it->first.c_str());
    }
};

}  // namespace

TEST(SavePng, NamedAfterThePolygonAndTheStep) {
    Model m;
    m.open(sourcePath("polygons/paper-figure-7.json"));
    m.seek(23);
    EXPECT_EQ(stepPngName(m), "paper-figure-7-step23.png");
    EXPECT_EQ(exportBaseName(Model{}), "flood");
    EXPECT_EQ(folderOf("/tmp/a/b.png"), "/tmp/a");
    EXPECT_EQ(folderOf("b.png"), ".");
    EXPECT_EQ(folderOf("/b.png"), "/");
}

TEST(SavePng, TheFolderRules) {
    const std::filesystem::path home = scratch("save-png-home");
    Env env;
    env.set("HOME", home.string());
    env.set("XDG_PICTURES_DIR", std::nullopt);
    env.set("XDG_CONFIG_HOME", std::nullopt);
    // No Pictures folder: home.
    EXPECT_EQ(pictureFolder(""), home.string());
    // ~/Pictures once it exists.
    std::filesystem::create_directories(home / "Pictures");
    EXPECT_EQ(pictureFolder(""), (home / "Pictures").string());
    // user-dirs.dirs, as xdg-user-dir reads it ($HOME expanded), over ~/Pictures.
    std::filesystem::create_directories(home / ".config");
    std::filesystem::create_directories(home / "Bilder");
    std::ofstream(home / ".config/user-dirs.dirs")
        << "# written by xdg-user-dirs-update\nXDG_DESKTOP_DIR=\"$HOME/Desktop\"\n"
           "XDG_PICTURES_DIR=\"$HOME/Bilder\"\n";
    EXPECT_EQ(pictureFolder(""), (home / "Bilder").string());
    // $XDG_PICTURES_DIR over both.
    std::filesystem::create_directories(home / "shots");
    env.set("XDG_PICTURES_DIR", (home / "shots").string());
    EXPECT_EQ(pictureFolder(""), (home / "shots").string());
    // A Pictures folder named but missing is passed over.
    env.set("XDG_PICTURES_DIR", (home / "missing").string());
    EXPECT_EQ(pictureFolder(""), (home / "Bilder").string());
    // The last export's folder first, when it still exists.
    std::filesystem::create_directories(home / "slides");
    EXPECT_EQ(pictureFolder((home / "slides").string()), (home / "slides").string());
    EXPECT_EQ(pictureFolder((home / "gone").string()), (home / "Bilder").string());
    // No home at all: the working directory.
    env.set("HOME", std::nullopt);
    env.set("XDG_PICTURES_DIR", std::nullopt);
    EXPECT_EQ(pictureFolder(""), ".");
    std::filesystem::remove_all(home);
}

#endif
