#pragma once
// Owning handles for OpenGL objects: each deletes its object when it goes
// out of scope (with the context that made it current), moves but never
// copies. Zero is "no object", as in GL.
#include <epoxy/gl.h>

#include <utility>

namespace stochtex::gl {

template <void (*Delete)(GLuint)>
class Handle {
public:
    Handle() = default;
    explicit Handle(GLuint id) : id_(id) {}
    ~Handle() { reset(); }
    Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
    Handle& operator=(Handle&& o) noexcept {
        if (this != &o) {
            reset();
            id_ = std::exchange(o.id_, 0);
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_) Delete(id_);
        id_ = 0;
    }

private:
    GLuint id_ = 0;
};

namespace detail {
// glDelete* take arrays; these adapters take one name.
inline void deleteTexture(GLuint id) { glDeleteTextures(1, &id); }
inline void deleteBuffer(GLuint id) { glDeleteBuffers(1, &id); }
inline void deleteFramebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
inline void deleteRenderbuffer(GLuint id) { glDeleteRenderbuffers(1, &id); }
inline void deleteVertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }
inline void deleteProgram(GLuint id) { glDeleteProgram(id); }
}  // namespace detail

using Texture = Handle<detail::deleteTexture>;
using Buffer = Handle<detail::deleteBuffer>;
using Framebuffer = Handle<detail::deleteFramebuffer>;
using Renderbuffer = Handle<detail::deleteRenderbuffer>;
using VertexArray = Handle<detail::deleteVertexArray>;
using Program = Handle<detail::deleteProgram>;

// New objects from a glGen* function (nothing is bound).
template <class H>
H generate(void (*gen)(GLsizei, GLuint*)) {
    GLuint id = 0;
    gen(1, &id);
    return H(id);
}
inline Texture newTexture() { return generate<Texture>(glGenTextures); }
inline Buffer newBuffer() { return generate<Buffer>(glGenBuffers); }
inline Framebuffer newFramebuffer() { return generate<Framebuffer>(glGenFramebuffers); }
inline Renderbuffer newRenderbuffer() { return generate<Renderbuffer>(glGenRenderbuffers); }
inline VertexArray newVertexArray() { return generate<VertexArray>(glGenVertexArrays); }

}  // namespace stochtex::gl
