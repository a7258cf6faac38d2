// flood-viewer's command line: what each flag asks for, parsed and checked before any window.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "export.h"  // ExportSettings
#include "flood/teach/quiz.h"
#include "palette.h"  // Theme

namespace flood::view {

struct Args {
    std::string file;
    std::vector<uint32_t> steps;  // every --step in order: one frame at each before the last
                                  // (none: where the model lands by itself)
    std::string screenshot;
    int width = 1280, height = 800;
    bool bench = false;      // measure open, seek and frame times, print them, exit
    bool timeOpen = false;   // time the window's open of FILE (outline, flooded frame), exit
    bool showError = false;  // open in the error view (as the E key does)
    long feature = -1;       // --feature N: that feature of a FeatureCollection
    float scale = 0;         // --scale S: the content scale, instead of the monitor's
    bool presenter = false;  // --presenter: start in presenter view (Tab)
    bool themeGiven = false;
    Theme theme = Theme::Dark;  // --theme
    bool printLayout = false;   // --print-layout: where the caption and toolbar end were
    struct Press {
        int key;
        bool ctrl;
        bool shift = false;
    };
    std::vector<Press> presses;  // --press KEY: keys pressed before a screenshot
    bool canvasOnly = false;     // --canvas-only: --screenshot renders the canvas alone
    bool sizeGiven = false;
    ExportSettings exports;  // canvas-only PNG, SVG, GIF, PNG sequence (export.h)
    bool rangeGiven = false, everyGiven = false, fpsGiven = false;
    bool exporting() const {
        return !exports.png.empty() || !exports.svg.empty() || exports.animated();
    }
    std::string layer, where;  // --layer, --where: a GIS dataset's layer and feature filter
    bool predicates = false;   // --predicates: the predicate inspector open
    bool gorgeFocus = false;   // --gorge-focus: "current gorge only"
    bool mouse = false;        // --mouse X,Y (screenshots): the pointer there, for hover pictures
    float mouseX = 0, mouseY = 0;
    std::string up;     // --up: flood along this direction, with the dial open
    bool quiz = false;  // --quiz ACTIONS: start in the quiz, asking about those
    QuizActions quizAsked;
    Action answer = Action::Count;  // --answer ACTION: answer the question at the last --step
    bool stateTable = false;        // --state-table: the State table (Fig. 10) open
};

// Parses argv into `a`. Returns 0 to go on, or an exit code + 1 (so 1 means "exit 0", e.g.
// after --help); a bad flag is said on stderr with the usage.
int parseArgs(int argc, char** argv, Args& a);

}  // namespace flood::view
