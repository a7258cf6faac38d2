#include "offscreen.h"

#include <glad/gl.h>

#include <algorithm>

namespace flood::view {

Offscreen::~Offscreen() { release(); }

void Offscreen::release() {
    if (fbo_) glDeleteFramebuffers(1, &fbo_);
    if (colour_) glDeleteRenderbuffers(1, &colour_);
    if (depthStencil_) glDeleteRenderbuffers(1, &depthStencil_);
    fbo_ = colour_ = depthStencil_ = 0;
    width_ = height_ = 0;
}

bool Offscreen::bind(int width, int height, std::string* error) {
    if (width != width_ || height != height_ || !fbo_) {
        release();
        GLint maxSize = 0;
        glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
        if (width <= 0 || height <= 0 || width > maxSize || height > maxSize) {
            if (error)
                *error = "cannot render " + std::to_string(width) + "x" + std::to_string(height) +
                         " offscreen: this OpenGL allows at most " + std::to_string(maxSize) + " pixels a side";
            return false;
        }
        glGenFramebuffers(1, &fbo_);
        glGenRenderbuffers(1, &colour_);
        glGenRenderbuffers(1, &depthStencil_);
        glBindRenderbuffer(GL_RENDERBUFFER, colour_);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
        glBindRenderbuffer(GL_RENDERBUFFER, depthStencil_);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depthStencil_);
        GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (status != GL_FRAMEBUFFER_COMPLETE || glGetError() != GL_NO_ERROR) {
            release();
            if (error)
                *error = "cannot render " + std::to_string(width) + "x" + std::to_string(height) +
                         " offscreen: the framebuffer is incomplete (out of memory?)";
            return false;
        }
        width_ = width, height_ = height;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    return true;
}

bool Offscreen::read(std::vector<uint8_t>& rgba) const {
    if (!fbo_) return false;
    std::vector<uint8_t> raw(size_t(width_) * height_ * 4);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, raw.data());
    if (glGetError() != GL_NO_ERROR) return false;
    // GL's rows start at the bottom, PNG's and GIF's at the top.
    rgba.resize(raw.size());
    size_t row = size_t(width_) * 4;
    for (int y = 0; y < height_; ++y)
        std::copy_n(raw.data() + (height_ - 1 - y) * row, row, rgba.data() + y * row);
    for (size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
    return true;
}

void Offscreen::unbind() const { glBindFramebuffer(GL_FRAMEBUFFER, 0); }

}  // namespace flood::view
