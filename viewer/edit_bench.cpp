// flood-edit-bench: how long an edit takes to show, on a generated polygon (issue 12: a
// few thousand vertices must not stall the viewer). Not a test: it prints times.
//   flood-edit-bench [FAMILY] [SIZE] [EDITS]     default: circle-holes 5000 20
// Each edit moves vertex 0 (to where it is, so every run floods the same valid polygon) and
// is timed in the editor's two halves: the flood (validate, record, exact checker, which the
// viewer runs in a background thread) and the adoption on the UI thread (classes, transcript,
// replay keyframes, verdict), then the canvas's buffers built again (before their GL upload). Edits follow each other as in a drag, so the invariant scan
// waits for the drag's end (Model::adoptEdit); it runs in its own thread after that.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "canvas_geometry.h"
#include "edit.h"
#include "flood/tools/generate.h"

using namespace flood;
using namespace flood::view;

namespace {
double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}
double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0 : v[v.size() / 2] * 1e3;
}
double maximum(const std::vector<double>& v) {
    return v.empty() ? 0 : *std::max_element(v.begin(), v.end()) * 1e3;
}
}  // namespace

int main(int argc, char** argv) {
    const std::string family = argc > 1 ? argv[1] : "circle-holes";
    const size_t size = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 5000;
    const int edits = argc > 3 ? std::atoi(argv[3]) : 20;
    const std::vector<std::string> names = familyNames();
    if (std::find(names.begin(), names.end(), family) == names.end() || size == 0 || edits <= 0) {
        std::fprintf(stderr, "usage: flood-edit-bench [FAMILY] [SIZE] [EDITS]\n");
        return 2;
    }
    Model model;
    Polygon p = generate(family, 1, size);
    model.openPolygon(p, family, validate(p, family));
    model.seek(model.steps() / 2);
    std::vector<double> flood, adopt, canvas, total;
    for (int i = 0; i < edits; ++i) {
        Polygon edited = model.polygon();
        double t0 = now();
        Model::EditedRun run = Model::floodEdit(std::move(edited), family);
        double t1 = now();
        model.adoptEdit(std::move(run), true);  // as in a drag: the invariant scan waits
        double t2 = now();
        // What the canvas then does on the UI thread before the GL upload (panel_canvas.cpp):
        // takes the arrays prepared with the flood, builds the step's overlay.
        std::shared_ptr<PreparedCanvas> prepared = model.takeCanvas();
        CanvasOverlay o = buildCanvasOverlay(model, {}, prepared->geometry.origin);
        double t3 = now();
        flood.push_back(t1 - t0), adopt.push_back(t2 - t1), canvas.push_back(t3 - t2),
            total.push_back(t3 - t0);
    }
    std::printf("flood-edit-bench: %s %zu: %zu vertices, %u events, %zu triangles, %s\n",
                family.c_str(), size, model.polygon().vertices.size(), model.steps(),
                model.trace().triangles.size(), model.failed() ? "FAILED" : "valid");
    std::printf("flood-edit-bench: edit -> new trace ready, median / max of %d edits (ms):\n",
                edits);
    std::printf(
        "  flood (validate, record, exact checker, prepare; background thread) %.1f / %.1f\n",
        median(flood), maximum(flood));
    std::printf("  adopt (the prepared run moved in; UI thread) %.1f / %.1f\n", median(adopt),
                maximum(adopt));
    std::printf("  canvas (the step's overlay; UI thread) %.1f / %.1f\n", median(canvas),
                maximum(canvas));
    std::printf("  total %.1f / %.1f\n", median(total), maximum(total));
    model.cancelInvariants();
    return model.failed() ? 1 : 0;
}
