// An offscreen framebuffer (GL 3.3 FBO: RGBA8 colour, depth 24 + stencil 8 for the even-odd
// polygon fill) that exports render the canvas into at any size, independent of the window.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace flood::view {

class Offscreen {
public:
    Offscreen() = default;
    ~Offscreen();  // needs the GL context it was made in
    Offscreen(const Offscreen&) = delete;
    Offscreen& operator=(const Offscreen&) = delete;

    // (Re)creates the buffers at width x height if needed and binds the framebuffer for
    // drawing. False with a reason (too large for the GL implementation, incomplete).
    bool bind(int width, int height, std::string* error);
    // Reads the bound framebuffer: RGBA, top row first, alpha 255.
    bool read(std::vector<uint8_t>& rgba) const;
    void unbind() const;  // back to the window's framebuffer

private:
    void release();
    uint32_t fbo_ = 0, colour_ = 0, depthStencil_ = 0;
    int width_ = 0, height_ = 0;
};

}  // namespace flood::view
