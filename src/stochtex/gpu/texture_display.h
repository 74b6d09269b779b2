#pragma once
// Textures shown in a window: a render target drawn as `render` draws it
// (linear light, image row 0 in GL row 0), a ShaderToy frame (display codes,
// GL rows) or an analysis figure (codes, uploaded top row first), each in a
// rectangle of the window's framebuffer.
#include "stochtex/gpu/gl_objects.h"
#include "stochtex/image/image.h"

namespace stochtex {

// A rectangle of the window's framebuffer in GL coordinates (origin at the
// bottom left).
struct DisplayRect {
    int x = 0, y = 0, width = 1, height = 1;
};

class TextureDisplay {
public:
    // What a texture's texels are and how its rows run.
    struct Look {
        bool turnOver = false;  // image row 0 is in GL row 0 (render targets, uploaded images)
        bool encode = false;    // linear light to sRGB codes (render targets)
        float opacity = 1;      // < 1: blended over what the rectangle holds
        bool alpha = false;     // the texture's alpha (an RGBA upload) scales the opacity, blended
    };
    static constexpr Look kRenderTarget{true, true, 1, false};  // a pattern drawn as `render` draws it
    static constexpr Look kImageCodes{true, false, 1, false}; // an uploaded Image of display codes
    static constexpr Look kGlCodes{false, false, 1, false}; // a ShaderToy pass's output
    static constexpr Look kGlLinear{false, true, 1, false}; // linear light drawn the GL way up (a mesh)

    // Needs a current context.
    TextureDisplay();
    // Draws `texture` over `rect` of the framebuffer bound now (0: the window's).
    void show(GLuint texture, const DisplayRect& rect, const Look& look) const;

private:
    gl::Program program_;
    gl::VertexArray vao_;
};

// An image uploaded for display (RGB or gray shown as RGB), kept until replaced.
class DisplayImage {
public:
    void upload(const Image& image);
    GLuint texture() const { return texture_.id(); }
    bool empty() const { return width_ == 0; }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    gl::Texture texture_;
    int width_ = 0, height_ = 0;
};

}  // namespace stochtex
