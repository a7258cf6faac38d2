#include "export_job.h"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <optional>

#include "download.h"
#include "flood/io/output.h"  // atomic files
#include "offscreen.h"
#include "quantize.h"
#ifdef FLOOD_GIF
#include "gif_writer.h"
#endif

namespace flood::view {

namespace {

double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// Draws a draw list of our own (not a window's) into the bound framebuffer.
void renderList(ImDrawList& dl, int width, int height) {
    dl._PopUnusedDrawCmd();
    ImDrawList* lists[] = {&dl};
    ImDrawData data;
    data.Valid = true;
    data.CmdLists = lists;
    data.CmdListsCount = 1;
    data.TotalVtxCount = dl.VtxBuffer.Size;
    data.TotalIdxCount = dl.IdxBuffer.Size;
    data.DisplayPos = ImVec2(0, 0);
    data.DisplaySize = ImVec2(float(width), float(height));
    data.FramebufferScale = ImVec2(1, 1);
    ImGui_ImplOpenGL3_RenderDrawData(&data);
}

}  // namespace

struct ExportJob::Impl {
    Ui& ui;
    ExportSettings s;
    uint32_t startStep;
    Camera camera;                // the canvas's view at the export's size
    Rect area;                    // the canvas in the picture: all of it but the caption band
    std::vector<uint32_t> steps;  // the frames of an animation
    enum class Phase { Still, Frames, Encode, Done } phase = Phase::Still;
    size_t frame = 0;
    Offscreen fb;
    std::vector<uint8_t> rgba;
    PaletteBuilder colours;
    Status status = Status::Ok;
    std::string message;
    std::vector<std::string> written;  // what the message lists
    std::vector<std::string> files;    // every file complete, each offered in the page
    bool cancelled = false;
    // The caption band: the font scaled by a whole factor (the default font is a bitmap),
    // the head column as wide as the widest head, the band as tall as the tallest narration.
    float fontSize = 13, headWidth = 0, pad = 6;
#ifdef FLOOD_GIF
    std::unique_ptr<Output> gifFile;
    std::unique_ptr<GifWriter> gif;
    std::unique_ptr<PaletteMap> map;
    std::vector<uint8_t> indices;
#endif

    Impl(Ui& u, ExportSettings settings)
        : ui(u), s(std::move(settings)), startStep(u.model.step()) {
        const Model& m = ui.model;
        if (s.animated()) steps = exportSteps(s.first, s.last, s.every, m.steps());
        area = {0, 0, double(s.width), double(s.height)};
        if (s.caption) layoutCaption();
        camera = exportCamera(m.camera(), area);
    }

    ImFont* font() const { return ImGui::GetIO().Fonts->Fonts[0]; }

    void layoutCaption() {
        ImFont* f = font();
        fontSize = f->FontSize * std::max(1.f, std::floor(float(s.height) / 600.f));
        pad = fontSize / 2;
        std::vector<uint32_t> shown = steps;
        if (!s.png.empty() || !s.svg.empty()) shown.push_back(startStep);
        for (uint32_t st : shown)
            headWidth = std::max(
                headWidth,
                f->CalcTextSizeA(fontSize, FLT_MAX, 0, captionOf(ui.model, st).head.c_str()).x);
        float textHeight = fontSize;
        for (uint32_t st : shown)
            textHeight = std::max(textHeight, f->CalcTextSizeA(fontSize, FLT_MAX, wrapWidth(),
                                                               captionOf(ui.model, st).text.c_str())
                                                  .y);
        double band = std::min<double>(textHeight + 2 * pad, s.height / 3.0);
        area.h = s.height - std::floor(band);
    }
    float textX() const { return pad + headWidth + 2 * fontSize; }
    float wrapWidth() const { return std::max(4 * fontSize, float(s.width) - textX() - pad); }

    void fail(Status st, const std::string& why) {
        if (status == Status::Ok) status = st, message = why;
        phase = Phase::Done;
    }

    // The canvas at `step` into rgba; false (and failed) when the GL cannot.
    bool render(uint32_t step) {
        Model& m = ui.model;
        if (m.step() != step) m.seek(step);
        Camera keep = m.camera();
        Rect keepCanvas = ui.layout.canvas;
        m.setCamera(camera);
        ui.layout.canvas = area;
        ImDrawList dl(ImGui::GetDrawListSharedData());
        dl._ResetForNewFrame();
        dl.PushTextureID(ImGui::GetIO().Fonts->TexID);
        dl.PushClipRect(ImVec2(0, 0), ImVec2(float(s.width), float(s.height)));
        paintCanvas(ui, &dl);
        if (s.caption) {
            CaptionLine c = captionOf(m, step);
            float y = float(area.h) + pad;
            dl.AddText(font(), fontSize, ImVec2(pad, y), toImU32(c.headColor), c.head.c_str());
            dl.AddText(font(), fontSize, ImVec2(textX(), y), toImU32(palette::kBoundary),
                       c.text.c_str(), nullptr, wrapWidth());
        }
        m.setCamera(keep);
        ui.layout.canvas = keepCanvas;
        ui.canvas.thinKey = {};  // the markers were thinned for the export's camera
        std::string error;
        if (!fb.bind(s.width, s.height, &error)) {
            fail(Status::Internal, error);
            return false;
        }
        ui.renderer.render(Vec2{double(s.width), double(s.height)}, s.width, s.height, area,
                           palette::kBackground, ui.canvas.view);
        renderList(dl, s.width, s.height);
        bool ok = fb.read(rgba);
        fb.unbind();
        if (!ok) fail(Status::Internal, "cannot read back the offscreen picture");
        return ok;
    }

    bool png(const std::string& path) {
        std::string error;
        if (!writePng(path, s.width, s.height, rgba, &error)) {
            fail(Status::WriteFailed, error);
            return false;
        }
        files.push_back(path);
        return true;
    }

    void still() {
        if (!s.png.empty() && render(startStep) && png(s.png)) written.push_back(s.png);
        if (!s.svg.empty() && status == Status::Ok) {
            Output out(s.svg);
            std::optional<CaptionLine> c;
            if (s.caption) c = captionOf(ui.model, startStep);
            writeSceneSvg(out.stream(), buildScene(ui.model, ui.sceneOptions), camera, s.width,
                          s.height, c ? &*c : nullptr);
            std::string error;
            if (out.commit(&error) != Status::Ok) fail(Status::WriteFailed, error);
            else written.push_back(s.svg), files.push_back(s.svg);
        }
        if (status != Status::Ok) return;
        phase = steps.empty() ? Phase::Done : Phase::Frames;
        if (!s.pngDir.empty() && !steps.empty()) {
            std::string error;
            if (!makeDirectory(s.pngDir, &error)) fail(Status::WriteFailed, error);
        }
    }

    void nextFrame() {
        if (!render(steps[frame])) return;
        if (!s.pngDir.empty() && !png(sequenceFile(s.pngDir, frame, steps.size()))) return;
        if (!s.gif.empty()) colours.add(rgba.data(), rgba.size() / 4);
        if (++frame < steps.size()) return;
        if (!s.pngDir.empty())
            written.push_back(std::to_string(steps.size()) + " frames in " + s.pngDir);
        frame = 0;
        phase = s.gif.empty() ? Phase::Done : Phase::Encode;
    }

    void encodeFrame() {
#ifdef FLOOD_GIF
        if (!gif) {
            gifFile = std::make_unique<Output>(s.gif);
            map = std::make_unique<PaletteMap>(colours.build(256));
            int delay = std::max(2, int(std::lround(100 / std::clamp(s.fps, kMinFps, kMaxFps))));
            gif = std::make_unique<GifWriter>(gifFile->stream(), s.width, s.height, map->palette(),
                                              delay);
        }
        if (!render(steps[frame])) return;
        indices.resize(rgba.size() / 4);
        map->map(rgba.data(), indices.size(), indices.data());
        bool ok = gif->addFrame(indices);
        if (ok && ++frame < steps.size()) return;
        ok = gif->finish() && ok;
        std::string error;
        Status st = gifFile->commit(&error);  // an encoder failure is a write failure too
        if (!ok || st != Status::Ok) {
            fail(Status::WriteFailed,
                 st != Status::Ok ? error : "error: " + s.gif + ": cannot write: " + gif->error());
            return;
        }
        files.push_back(s.gif);
        written.push_back(s.gif + " (" + std::to_string(steps.size()) + " frames, " +
                          std::to_string(map->palette().size()) + " colours)");
        phase = Phase::Done;
#else
        fail(Status::Usage,
             "error: " + s.gif + ": this flood-viewer was built without giflib (FLOOD_GIF)");
#endif
    }

    void finish() {
        if (ui.model.step() != startStep) ui.model.seek(startStep);
        // In the page each file reaches the user as a download, a sequence's frames one by one
        // (download.h); a cancelled export's complete files too, as they are kept.
        for (const std::string& f : files) {
            std::string error;
            if (status == Status::Ok && !offerDownload(f, &error)) fail(Status::WriteFailed, error);
        }
        if (status == Status::Ok) {
            message = cancelled ? "export cancelled; wrote" : "wrote";
            for (size_t i = 0; i < written.size(); ++i) message += (i ? ", " : " ") + written[i];
            if (written.empty()) message = cancelled ? "export cancelled" : "nothing to export";
        }
    }
};

ExportJob::ExportJob(Ui& ui, ExportSettings settings)
    : impl_(std::make_unique<Impl>(ui, std::move(settings))) {}

ExportJob::~ExportJob() {
    if (impl_->phase != Impl::Phase::Done) impl_->finish();
}

bool ExportJob::advance(double seconds) {
    Impl& j = *impl_;
    double until = now() + seconds;
    while (j.phase != Impl::Phase::Done) {
        if (j.cancelled) j.phase = Impl::Phase::Done;
        else if (j.phase == Impl::Phase::Still) j.still();
        else if (j.phase == Impl::Phase::Frames) j.nextFrame();
        else j.encodeFrame();
        if (j.phase == Impl::Phase::Done) j.finish();
        else if (seconds > 0 && now() >= until) return true;
    }
    return false;
}

void ExportJob::cancel() { impl_->cancelled = true; }
Status ExportJob::status() const { return impl_->status; }
const std::string& ExportJob::message() const { return impl_->message; }

double ExportJob::progress() const {
    const Impl& j = *impl_;
    if (j.phase == Impl::Phase::Done) return 1;
    if (j.steps.empty()) return 0;
    double passes = j.s.gif.empty() ? 1 : 2;
    double done =
        j.phase == Impl::Phase::Encode ? double(j.steps.size()) + j.frame : double(j.frame);
    return done / (passes * double(j.steps.size()));
}

}  // namespace flood::view
