#include "stochtex/gpu/render_target.h"

#include <vector>

namespace stochtex {

RenderTarget::RenderTarget(int width, int height, bool depth)
    : width_(width), height_(height), colour_(gl::newTexture()), framebuffer_(gl::newFramebuffer()) {
    glBindTexture(GL_TEXTURE_2D, colour_.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
    // Complete without mipmaps: an incomplete texture bound as a compute
    // image takes no stores (NVIDIA enforces this; llvmpipe does not).
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_.id(), 0);
    if (depth) {
        depth_ = gl::newRenderbuffer();
        glBindRenderbuffer(GL_RENDERBUFFER, depth_.id());
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
    }
    glViewport(0, 0, width, height);
}

void RenderTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, width_, height_);
}

Image RenderTarget::readRgb(Rows rows) const {
    bind();
    return readBoundFramebufferRgb(width_, height_, rows);
}

Image readBoundFramebufferRgb(int width, int height, RenderTarget::Rows rows) {
    std::vector<float> rgba(size_t(width) * size_t(height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, rgba.data());
    Image out(width, height, 3, Image::Uninitialized{});
    for (int y = 0; y < height; ++y) {
        const int row = rows == RenderTarget::Rows::TopDown ? height - 1 - y : y;
        const float* src = rgba.data() + size_t(row) * size_t(width) * 4;
        float* dst = out.row(y);
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) dst[3 * x + c] = src[4 * x + c];
    }
    return out;
}

}  // namespace stochtex
