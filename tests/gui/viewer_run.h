// Running flood-viewer from a GUI test (tests/gui/*_test.cpp, each its own program): the
// viewer's output echoed into the test's log, and what --print-layout prints read back.
#pragma once
#include <sys/wait.h>

#include <cstdio>
#include <map>
#include <string>

#include "geometry.h"  // Rect

namespace flood::view::testing {

struct ViewerRun {
    int exitCode = -1;                   // -1: it did not run, or did not exit normally
    std::string output;                  // stdout (and stderr, when the command joins it)
    std::map<std::string, Rect> layout;  // "flood-viewer: layout NAME x y w h"
    double cameraX = 0, cameraY = 0;     // "flood-viewer: camera CX CY SCALE"
    double cameraScale = 0;              // 0: no camera printed
};

// Runs the shell command line `command` (the viewer and its arguments) and reads its output.
inline ViewerRun runViewer(const std::string& command) {
    std::printf("%s\n", command.c_str());
    std::fflush(stdout);
    ViewerRun run;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return run;
    char line[1024];
    while (std::fgets(line, sizeof line, pipe)) {
        std::fputs(line, stdout);
        run.output += line;
        char key[64];
        Rect r;
        if (std::sscanf(line, "flood-viewer: layout %63s %lf %lf %lf %lf", key, &r.x, &r.y, &r.w,
                        &r.h) == 5)
            run.layout[key] = r;
        std::sscanf(line, "flood-viewer: camera %lf %lf %lf", &run.cameraX, &run.cameraY,
                    &run.cameraScale);
    }
    const int status = pclose(pipe);
    run.exitCode = status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

inline int failWith(const std::string& what) {
    std::fprintf(stderr, "FAIL: %s\n", what.c_str());
    return 1;
}

inline bool within(const Rect& in, const Rect& out) {
    return in.x >= out.x && in.y >= out.y && in.x + in.w <= out.x + out.w &&
           in.y + in.h <= out.y + out.h;
}

inline bool overlaps(const Rect& a, const Rect& b) {
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

}  // namespace flood::view::testing
