// flood-viewer's command line (viewer/args.cpp, through CLI11 as the flood command's), parsed
// in-process: every option lands in Args, a bad value is named with the option and the value
// (exit 2), --help and --version exit 0 with their text.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "args.h"
#include "platform_glfw.h"

using namespace flood;
using namespace flood::view;

namespace {

struct Parsed {
    int rc = -1;  // parseArgs' value: 0 go on, else exit code + 1
    Args args;
    std::string out, err;
};

Parsed parse(std::vector<std::string> words) {
    words.insert(words.begin(), "flood-viewer");
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    Parsed p;
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    p.rc = parseArgs(int(argv.size()), argv.data(), p.args);
    p.out = testing::internal::GetCapturedStdout();
    p.err = testing::internal::GetCapturedStderr();
    return p;
}

bool has(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

}  // namespace

TEST(ViewerArgs, EveryOptionLandsInArgs) {
    Parsed p = parse({"x.json",
                      "--step",
                      "40",
                      "--step",
                      "5",
                      "--feature",
                      "3",
                      "--layer",
                      "roads",
                      "--where",
                      "id > 2",
                      "--show-error",
                      "--predicates",
                      "--gorge-focus",
                      "--screenshot",
                      "a.png",
                      "--size",
                      "640x480",
                      "--mouse",
                      "10.5,20",
                      "--scale",
                      "2",
                      "--presenter",
                      "--theme",
                      "light",
                      "--print-layout",
                      "--press",
                      "tab",
                      "--press",
                      "ctrl+plus",
                      "--quiz",
                      "raise,jump",
                      "--answer",
                      "jump",
                      "--state-table",
                      "--up=-y"});
    ASSERT_EQ(p.rc, 0) << p.err;
    const Args& a = p.args;
    EXPECT_EQ(a.file, "x.json");
    EXPECT_EQ(a.steps, (std::vector<uint32_t>{40, 5}));
    EXPECT_EQ(a.feature, 3);
    EXPECT_EQ(a.layer, "roads");
    EXPECT_EQ(a.where, "id > 2");
    EXPECT_TRUE(a.showError && a.predicates && a.gorgeFocus && a.presenter && a.printLayout);
    EXPECT_EQ(a.screenshot, "a.png");
    EXPECT_TRUE(a.sizeGiven);
    EXPECT_EQ(a.width, 640);
    EXPECT_EQ(a.height, 480);
    EXPECT_TRUE(a.mouse);
    EXPECT_FLOAT_EQ(a.mouseX, 10.5f);
    EXPECT_FLOAT_EQ(a.mouseY, 20);
    EXPECT_FLOAT_EQ(a.scale, 2);
    EXPECT_TRUE(a.themeGiven);
    EXPECT_EQ(a.theme, Theme::Light);
    ASSERT_EQ(a.presses.size(), 2u);
    EXPECT_EQ(a.presses[0].key, platform::kKeyTab);
    EXPECT_EQ(a.presses[1].key, platform::kKeyPlus[0]);
    EXPECT_TRUE(a.presses[1].ctrl);
    EXPECT_TRUE(a.quiz);
    EXPECT_EQ(a.quizAsked.bits, uint8_t((1u << int(Action::Raise)) | (1u << int(Action::Jump))));
    EXPECT_EQ(a.answer, Action::Jump);
    EXPECT_TRUE(a.stateTable);
    EXPECT_EQ(a.up, "-y");
    EXPECT_FALSE(a.exporting());

    Parsed none = parse({});
    ASSERT_EQ(none.rc, 0);
    EXPECT_EQ(none.args.file, "");
    EXPECT_EQ(none.args.feature, -1);
    EXPECT_TRUE(none.args.steps.empty());
    EXPECT_FALSE(none.args.themeGiven || none.args.sizeGiven || none.args.quiz);
}

TEST(ViewerArgs, ExportsTakeTheirSizeAndRange) {
    Parsed p = parse({"x.json", "--export-png-dir", "frames", "--steps", "3:9", "--every", "2",
                      "--size", "320x200", "--caption"});
    ASSERT_EQ(p.rc, 0) << p.err;
    EXPECT_EQ(p.args.exports.pngDir, "frames");
    EXPECT_EQ(p.args.exports.first, 3u);
    EXPECT_EQ(p.args.exports.last, 9u);
    EXPECT_EQ(p.args.exports.every, 2u);
    EXPECT_TRUE(p.args.exports.caption);
    EXPECT_EQ(p.args.exports.width, 320);  // the pictures' size; the hidden window's is fixed
    EXPECT_EQ(p.args.width, 1280);
    Parsed svg = parse({"x.json", "--screenshot", "c.svg"});
    ASSERT_EQ(svg.rc, 0);
    EXPECT_EQ(svg.args.exports.svg, "c.svg");
}

TEST(ViewerArgs, ABadValueIsNamedWithItsOptionAndExits2) {
    struct Case {
        std::vector<std::string> words;
        std::string said;
    };
    const std::vector<Case> cases = {
        {{"--step", "x"}, "--step: wants a number >= 0, got 'x'"},
        {{"--feature", "-1"}, "--feature: wants a number >= 0, got '-1'"},
        {{"--size", "10x10"}, "--size: wants WxH (64..16384), got '10x10'"},
        {{"--size", "640x480junk"}, "--size: wants WxH (64..16384), got '640x480junk'"},
        {{"--scale", "9"}, "--scale: wants a number in 0.5..4, got '9'"},
        {{"--theme", "blue"}, "--theme: wants light or dark, got 'blue'"},
        {{"--press", "f3"},
         "--press: wants tab, f11, ctrl+plus, ctrl+minus, ctrl+0, f8, "
         "shift+f8 or p, got 'f3'"},
        {{"--mouse", "1"}, "--mouse: wants X,Y, got '1'"},
        {{"--every", "0"}, "--every: wants a number of steps >= 1, got '0'"},
        {{"--fps", "60"}, "--fps: wants frames per second from 0.1 to 50, got '60'"},
        {{"--answer", "swim"}, "--answer: wants raise, bridge, spill, jump or fill, got 'swim'"},
        {{"--quiz", "swim"}, "--quiz: "},
        {{"--up", "sideways"}, "--up: "},
        {{"--steps", "9:3"}, "--steps: "},
        {{"--step"}, "--step"},
        {{"--bogus"}, "--bogus"},
        {{"a.json", "b.json"}, "b.json"},
        {{"--canvas-only"}, "--canvas-only needs --screenshot OUT"},
        {{"--fps", "5"}, "--fps needs --export-gif"},
        {{"--answer", "jump"}, "--answer needs --quiz"},
    };
    for (const Case& c : cases) {
        Parsed p = parse(c.words);
        EXPECT_EQ(p.rc, 2 + 1) << c.said;
        EXPECT_EQ(p.err.rfind("flood-viewer: ", 0), 0u) << p.err;
        EXPECT_TRUE(has(p.err, c.said)) << "wanted '" << c.said << "' in: " << p.err;
        EXPECT_TRUE(has(p.err, "Run with --help")) << p.err;
        EXPECT_EQ(p.out, "");
    }
}

TEST(ViewerArgs, HelpAndVersionExit0) {
    Parsed help = parse({"--help"});
    EXPECT_EQ(help.rc, 1);  // exit 0
    for (const char* option : {"--step", "--feature", "--screenshot", "--export-gif", "--presenter",
                               "--quiz", "--up", "--version", "FILE", "Exit codes"})
        EXPECT_TRUE(has(help.out, option)) << option << " in:\n" << help.out;
    EXPECT_EQ(parse({"-h"}).rc, 1);
    Parsed version = parse({"--version"});
    EXPECT_EQ(version.rc, 1);
    EXPECT_EQ(version.out, std::string("flood-viewer ") + FLOOD_VERSION + "\n");
}
