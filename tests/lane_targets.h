#pragma once
// Runs a test body once per vector target the SIMD lanes were compiled for
// and this CPU supports (Highway's dynamic dispatch, forced target by
// target), so the SSSE3, SSE4, AVX2 and AVX-512 lanes and Highway's
// one-lane SCALAR fallback are all held to the scalar kernel where the
// machine can run them — the fallback reading through plain loads that the
// sanitizers check, which they cannot do for hardware gathers.
#include <gtest/gtest.h>

#include <hwy/targets.h>

namespace stochtex::test {

template <class F>
void forEachLaneTarget(F&& body) {
    const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
    EXPECT_GE(targets.size(), 2u);  // at least the best target and the emulated fallback
    for (const int64_t target : targets) {
        hwy::SetSupportedTargetsForTest(target);
        SCOPED_TRACE(hwy::TargetName(target));
        body(hwy::TargetName(target));
    }
    hwy::SetSupportedTargetsForTest(0);
}

}  // namespace stochtex::test
