#include "gif_writer.h"

#include <gif_lib.h>

#include <algorithm>

namespace flood::view {

namespace {

int writeTo(GifFileType* gif, const GifByteType* data, int length) {
    auto* out = static_cast<std::ostream*>(gif->UserData);
    out->write(reinterpret_cast<const char*>(data), length);
    return *out ? length : 0;
}

}  // namespace

GifWriter::GifWriter(std::ostream& out, int width, int height, const std::vector<Rgb>& palette,
                     int delay)
    : width_(width), height_(height), delay_(delay) {
    int err = 0;
    gif_ = EGifOpen(&out, writeTo, &err);
    if (!gif_) {
        error_ = GifErrorString(err);
        return;
    }
    EGifSetGifVersion(gif_, true);  // GIF89a: frame delays and the loop extension
    // giflib wants a power-of-two colour count; the unused entries stay black.
    int bits = 1;
    while ((1 << bits) < int(palette.size())) ++bits;
    std::vector<GifColorType> colours(size_t(1) << bits, GifColorType{0, 0, 0});
    for (size_t i = 0; i < palette.size() && i < colours.size(); ++i)
        colours[i] = {palette[i][0], palette[i][1], palette[i][2]};
    ColorMapObject* map = GifMakeMapObject(int(colours.size()), colours.data());
    bool ok = map && check(EGifPutScreenDesc(gif_, width, height, bits, 0, map));
    GifFreeMapObject(map);
    // NETSCAPE2.0: loop forever (count 0), as a slide expects.
    const unsigned char loop[3] = {1, 0, 0};
    ok = ok && check(EGifPutExtensionLeader(gif_, APPLICATION_EXT_FUNC_CODE)) &&
         check(EGifPutExtensionBlock(gif_, 11, "NETSCAPE2.0")) &&
         check(EGifPutExtensionBlock(gif_, 3, loop)) && check(EGifPutExtensionTrailer(gif_));
    (void)ok;  // a failure is kept in error_ and refuses every later call
}

GifWriter::~GifWriter() {
    if (gif_) EGifCloseFile(gif_, nullptr);
}

bool GifWriter::check(int rc) {
    if (rc == GIF_OK) return true;
    if (error_.empty()) error_ = gif_ ? GifErrorString(gif_->Error) : "cannot start the GIF";
    return false;
}

bool GifWriter::addFrame(const std::vector<uint8_t>& indices) {
    if (!gif_ || !error_.empty() || indices.size() < size_t(width_) * height_) {
        if (error_.empty()) error_ = "a frame of the wrong size";
        return false;
    }
    GraphicsControlBlock gcb{DISPOSE_DO_NOT, false, delay_, NO_TRANSPARENT_COLOR};
    GifByteType ext[4];
    EGifGCBToExtension(&gcb, ext);
    if (!check(EGifPutExtension(gif_, GRAPHICS_EXT_FUNC_CODE, 4, ext)) ||
        !check(EGifPutImageDesc(gif_, 0, 0, width_, height_, false, nullptr)))
        return false;
    std::vector<GifPixelType> row(static_cast<size_t>(width_));
    for (int y = 0; y < height_; ++y) {
        std::copy_n(indices.begin() + long(y) * width_, width_, row.begin());
        if (!check(EGifPutLine(gif_, row.data(), width_))) return false;
    }
    return true;
}

bool GifWriter::finish() {
    if (!gif_) return false;
    int err = 0;
    int rc = EGifCloseFile(gif_, &err);
    gif_ = nullptr;
    if (rc != GIF_OK && error_.empty()) error_ = GifErrorString(err);
    return error_.empty();
}

}  // namespace flood::view
