#include "offscreen.h"

#include "gl_api.h"

#include "renderer.h"  // readFramebuffer

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
                         " offscreen: this OpenGL allows at most " + std::to_string(maxSize) +
                         " pixels a side";
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
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                  depthStencil_);
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
    return fbo_ && readFramebuffer(GL_COLOR_ATTACHMENT0, width_, height_, rgba);
}

void Offscreen::unbind() const { glBindFramebuffer(GL_FRAMEBUFFER, 0); }

}  // namespace flood::view
