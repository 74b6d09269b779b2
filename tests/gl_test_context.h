#pragma once
// The headless OpenGL context the GL tests of a test binary share (EGL on
// llvmpipe where there is no GPU), made on first use.
#include <memory>

#include "stochtex/gpu/gl_context.h"

namespace stochtex::test {

inline GlContext& glContext() {
    static const std::unique_ptr<GlContext> context = GlContext::headless();
    return *context;
}

}  // namespace stochtex::test
