#pragma once
// An offscreen float render target: an RGBA32F texture (complete without
// mipmaps, so also usable as a compute image) attached to a framebuffer,
// with an optional depth buffer, and its read-back.
#include "stochtex/gpu/gl_objects.h"
#include "stochtex/image/image.h"

namespace stochtex {

class RenderTarget {
public:
    // Needs a current context. width, height ≥ 1.
    RenderTarget(int width, int height, bool depth);

    // Binds the framebuffer and sets the viewport to the whole target.
    void bind() const;
    GLuint texture() const { return colour_.id(); }
    GLuint framebuffer() const { return framebuffer_.id(); }
    int width() const { return width_; }
    int height() const { return height_; }

    // Which framebuffer row becomes image row 0: GL's row 0 is the bottom.
    enum class Rows { AsDrawn, TopDown };
    // The RGB channels (binds the target first).
    Image readRgb(Rows rows) const;

private:
    int width_, height_;
    gl::Texture colour_;
    gl::Renderbuffer depth_;
    gl::Framebuffer framebuffer_;
};

// The RGB channels of the framebuffer bound for reading (a target after
// bind(), or a window's back buffer), width × height from GL's (0, 0).
Image readBoundFramebufferRgb(int width, int height, RenderTarget::Rows rows);

}  // namespace stochtex
