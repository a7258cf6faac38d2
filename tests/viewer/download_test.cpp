// Saving in the page (viewer/download.h, issue 29): a written file is read back whole, bytes
// and name, to be handed to the browser; what cannot be read back is said, naming the file.
// On the desktop offerDownload leaves the file where the user put it and does nothing else.
// Compiles to nothing when the viewer is not built.
#if __has_include("download.h")
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "download.h"
#include "test_support.h"

using namespace flood::view;
using flood::testing::scratch;
using flood::testing::slurp;

namespace {

TEST(Download, ReadsTheWholeFileBackWithItsNameWithoutFolders) {
    const auto dir = scratch("download-read");
    const std::string bytes("\x89PNG\r\n\x1a\n\0\0\0\rIHDR tail", 21);  // NUL bytes inside
    const auto file = dir / "fig7-step23.png";
    std::ofstream(file, std::ios::binary) << bytes;
    Download d;
    std::string error;
    ASSERT_TRUE(readDownload(file.string(), d, &error)) << error;
    EXPECT_EQ(d.bytes, bytes);
    EXPECT_EQ(d.name, "fig7-step23.png");
    std::filesystem::create_directories(dir / "a" / "b");
    std::ofstream(dir / "a" / "b" / "fig7.svg") << "<svg/>";
    ASSERT_TRUE(readDownload((dir / "a" / "b" / "fig7.svg").string(), d, &error)) << error;
    EXPECT_EQ(d.name, "fig7.svg");
    EXPECT_EQ(d.bytes, "<svg/>");
}

TEST(Download, AFileThatCannotBeReadBackIsSaidNamingIt) {
    const auto dir = scratch("download-missing");
    Download d;
    std::string error;
    EXPECT_FALSE(readDownload((dir / "gone.png").string(), d, &error));
    EXPECT_NE(error.find((dir / "gone.png").string()), std::string::npos) << error;
    EXPECT_NE(error.find("cannot read it back"), std::string::npos) << error;
    error.clear();
    EXPECT_FALSE(readDownload(dir.string(), d, &error));  // a folder is no file to hand over
    EXPECT_NE(error.find(dir.string()), std::string::npos) << error;
}

#ifndef __EMSCRIPTEN__
TEST(Download, TheDesktopLeavesTheFileAsWrittenAndSaysNothing) {
    const auto dir = scratch("download-desktop");
    const auto file = dir / "polygon-edited.json";
    std::ofstream(file) << "{\"type\": \"Polygon\"}\n";
    std::string error;
    EXPECT_TRUE(offerDownload(file.string(), &error));
    EXPECT_TRUE(error.empty()) << error;
    EXPECT_EQ(slurp(file), "{\"type\": \"Polygon\"}\n");
    // Nothing is read on the desktop, so nothing can fail there either.
    EXPECT_TRUE(offerDownload((dir / "gone.png").string(), &error));
}
#endif

}  // namespace
#endif
