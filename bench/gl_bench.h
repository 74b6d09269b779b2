// What the benchmarks that need OpenGL share.
#pragma once

#include <benchmark/benchmark.h>

#include <memory>

#include "stochtex/gpu/gl_context.h"

namespace stochtex::bench {

// A headless context, or the benchmark skipped with the reason.
inline std::unique_ptr<GlContext> contextOrSkip(benchmark::State& state) {
    try {
        return GlContext::headless();
    } catch (const GpuUnavailable& e) {
        state.SkipWithError(e.what());
        return nullptr;
    }
}

}  // namespace stochtex::bench
