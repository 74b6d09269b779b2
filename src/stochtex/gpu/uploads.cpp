#include "stochtex/gpu/uploads.h"

#include <epoxy/gl.h>

#include <cmath>
#include <numbers>

namespace stochtex {

// A float texture read with texelFetch only (no filtering, no mipmaps).
gl::Texture floatTexture(int width, int height, int channels, const float* data) {
    static const GLenum internal[] = {GL_R32F, GL_RG32F, GL_RGB32F, GL_RGBA32F};
    static const GLenum format[] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
    gl::Texture t = gl::newTexture();
    glBindTexture(GL_TEXTURE_2D, t.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal[channels - 1]), width, height, 0, format[channels - 1], GL_FLOAT, data);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    return t;
}

// A pyramid's levels as the mip chain of one RG32F texture (mean, moment).
gl::Texture pyramidTexture(const StatsPyramid& p) {
    gl::Texture t = gl::newTexture();
    glBindTexture(GL_TEXTURE_2D, t.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int l = 0; l < p.levels(); ++l) {
        const Image rg = p.interleavedLevel(l, 2);
        glTexImage2D(GL_TEXTURE_2D, l, GL_RG32F, rg.width(), rg.height(), 0, GL_RG, GL_FLOAT, rg.data().data());
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, p.levels() - 1);
    return t;
}

// RGB tables (rx × ry entries, `layers` of them stacked in `rgb`) as one
// texture array read with texelFetch: the colormap H (one layer) and the
// prefiltered table's layers (see atlas()).
gl::Texture tableTexture(int rx, int ry, int layers, const float* rgb) {
    gl::Texture t = gl::newTexture();
    glBindTexture(GL_TEXTURE_2D_ARRAY, t.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGB32F, rx, ry, layers, 0, GL_RGB, GL_FLOAT, rgb);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
    return t;
}

void setCameraUniforms(unsigned program, const Camera& camera, bool rasterizerDerivatives) {
    const View& view = camera.view;
    auto uniform = [&](const char* name) { return glGetUniformLocation(program, name); };
    const double pi = std::numbers::pi;
    glUniform1i(uniform("uPlane"), camera.kind == Camera::Kind::Plane);
    glUniform1f(uniform("uTanHalfFov"), float(std::tan(0.5 * camera.fovDeg * pi / 180.0)));
    glUniform1f(uniform("uSinTilt"), float(std::sin(camera.tiltDeg * pi / 180.0)));
    glUniform1f(uniform("uCosTilt"), float(std::cos(camera.tiltDeg * pi / 180.0)));
    glUniform2f(uniform("uViewSize"), float(view.width), float(view.height));
    glUniform2f(uniform("uOffset"), float(view.offsetU), float(view.offsetV));
    glUniform1f(uniform("uScale"), float(view.scale));
    glUniform1i(uniform("uRasterizerDerivatives"), rasterizerDerivatives);
}

}  // namespace stochtex
