// GUI test: the quiz at 1280x800 (Fig. 7, bridges and spills asked). Before the first bridge the
// Quiz window shows the five choices in their actions' colours and no verdict; answered right,
// the choices are gone, the verdict is green and the Decision panel lights the path; answered
// wrong, the verdict is red. Exit 77 (skipped) without a display, except in CI.
#include <stb_image.h>  // implementation lives in Debian's libstb

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include "flood/teach/quiz.h"
#include "gui_test_display.h"
#include "model.h"
#include "palette.h"

using namespace flood;
using namespace flood::view;

namespace {

constexpr int W = 1280, H = 800;

struct Shot {
    bool ok = false;
    Rect quizBox;
    unsigned char* px = nullptr;
    ~Shot() { stbi_image_free(px); }
    long count(const Rect& r, Rgba want) const {
        long n = 0;
        for (int y = int(r.y); y < int(r.y + r.h) && y < H; ++y)
            for (int x = int(r.x); x < int(r.x + r.w) && x < W; ++x) {
                const unsigned char* p = px + (size_t(y) * W + x) * 4;
                n += std::abs(p[0] - want.r) <= 6 && std::abs(p[1] - want.g) <= 6 &&
                     std::abs(p[2] - want.b) <= 6;
            }
        return n;
    }
};

// `flood-viewer INPUT ARGS --print-layout --screenshot PNG`, the picture read and the quiz
// window's rectangle taken from the printed layout.
void shoot(const std::string& input, const std::string& args, const std::string& png, Shot& s) {
    std::remove(png.c_str());
    const std::string cmd = std::string("'") + FLOOD_VIEWER + "' '" + input + "' " + args +
                            " --print-layout --screenshot '" + png + "' --size " +
                            std::to_string(W) + "x" + std::to_string(H);
    std::printf("%s\n", cmd.c_str());
    std::fflush(stdout);
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return;
    std::string out;
    char buf[4096];
    for (size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
    const int rc = pclose(p);
    if (!WIFEXITED(rc) || WEXITSTATUS(rc) != 0) {
        std::fprintf(stderr, "FAIL: flood-viewer did not exit 0\n%s", out.c_str());
        return;
    }
    std::istringstream lines(out);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("flood-viewer: layout quiz-box ", 0) == 0)
            std::istringstream(line.substr(30)) >> s.quizBox.x >> s.quizBox.y >> s.quizBox.w >>
                s.quizBox.h;
    int w = 0, h = 0, channels = 0;
    s.px = stbi_load(png.c_str(), &w, &h, &channels, 4);
    s.ok = s.px && w == W && h == H && s.quizBox.w > 0;
    if (!s.ok) std::fprintf(stderr, "FAIL: no %dx%d picture or no quiz box\n%s", W, H, out.c_str());
}

}  // namespace

int main() {
    if (int skip = displayOrSkip()) return skip;
    const std::string input = std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json";
    const std::string dir = FLOOD_WORK_DIR;
    // The step before Fig. 7's first bridge, whatever the machine's order: its events.
    Model m;
    m.open(input);
    uint32_t bridge = 0;
    while (bridge < m.steps() && m.trace().events[bridge].action != Action::Bridge) ++bridge;
    QuizActions asked;
    asked.set(Action::Bridge, true), asked.set(Action::Spill, true);
    int firstBridgeQuestion = QuizSession(m.trace().events, asked).questionOf(bridge);
    if (bridge == m.steps() || firstBridgeQuestion < 0) {
        std::fprintf(stderr, "FAIL: Fig. 7 has no bridge asked about\n");
        return 1;
    }
    const std::string quiz = "--quiz bridge,spill --step " + std::to_string(bridge);
    Shot pending, right, wrong;
    shoot(input, quiz, dir + "/quiz-pending.png", pending);
    shoot(input, quiz + " --answer bridge", dir + "/quiz-right.png", right);
    shoot(input, quiz + " --answer raise", dir + "/quiz-wrong.png", wrong);
    if (!pending.ok || !right.ok || !wrong.ok) return 1;
    int failures = 0;
    auto expect = [&](bool ok, const char* what, long n) {
        std::printf("%s %s (%ld pixels)\n", ok ? "ok:" : "FAIL:", what, n);
        failures += !ok;
    };
    // Pending: the five choices, each a button of its action's colour; no verdict yet.
    for (Action a : kQuizChoices) {
        long n = pending.count(pending.quizBox, palette::action(a));
        expect(n > 400,
               (std::string("pending: a button in ") + actionName(a) + "'s colour").c_str(), n);
    }
    long verdict = pending.count(pending.quizBox, palette::kOk) +
                   pending.count(pending.quizBox, palette::kCulprit);
    expect(verdict == 0, "pending: no verdict shown", verdict);
    // Answered right: the buttons gone, "right!" in green, the path lit in the Decision panel.
    long raiseLeft = right.count(right.quizBox, palette::action(Action::Raise));
    expect(raiseLeft < 50, "right: the choices are gone", raiseLeft);
    long green = right.count(right.quizBox, palette::kOk);
    expect(green > 10, "right: the verdict in green", green);
    long red = right.count(right.quizBox, palette::kCulprit);
    expect(red == 0, "right: nothing in red", red);
    const Rect col = computeLayout(W, H, 1).left;
    const Rect decision{col.x, col.y + col.h * 0.38, col.w, col.h * 0.27};
    long lit = right.count(decision, palette::kTreePath);
    expect(lit > 40, "right: the Fig. 9 path lit in the Decision panel", lit);
    // Answered wrong: the verdict in red, none in green.
    long wrongRed = wrong.count(wrong.quizBox, palette::kCulprit);
    expect(wrongRed > 10, "wrong: the verdict in red", wrongRed);
    long wrongGreen = wrong.count(wrong.quizBox, palette::kOk);
    expect(wrongGreen == 0, "wrong: nothing in green", wrongGreen);
    return failures ? 1 : 0;
}
