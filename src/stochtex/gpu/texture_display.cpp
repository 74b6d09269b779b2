#include "stochtex/gpu/texture_display.h"

#include <epoxy/gl.h>

#include "stochtex/gpu/programs.h"
#include "stochtex/gpu/uploads.h"

namespace stochtex {

TextureDisplay::TextureDisplay() : program_(buildProgram("display")), vao_(gl::newVertexArray()) {}

void TextureDisplay::show(GLuint texture, const DisplayRect& rect, const Look& look) const {
    glViewport(rect.x, rect.y, rect.width, rect.height);
    glUseProgram(program_.id());
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture);
    auto uniform = [&](const char* name) { return glGetUniformLocation(program_.id(), name); };
    glUniform1i(uniform("uImage"), 0);
    glUniform4i(uniform("uRect"), rect.x, rect.y, rect.width, rect.height);
    glUniform1i(uniform("uTurnOver"), look.turnOver);
    glUniform1i(uniform("uEncode"), look.encode);
    glUniform1f(uniform("uOpacity"), look.opacity);
    glUniform1i(uniform("uAlpha"), look.alpha);
    const bool blend = look.opacity < 1 || look.alpha;
    if (blend) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }
    glBindVertexArray(vao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    if (blend) glDisable(GL_BLEND);
}

void DisplayImage::upload(const Image& image) {
    const Image rgb = image.channels() == 3 || image.channels() == 4 ? image : toRgb(image);
    texture_ = floatTexture(rgb.width(), rgb.height(), rgb.channels(), rgb.data().data());
    width_ = rgb.width();
    height_ = rgb.height();
}

}  // namespace stochtex
