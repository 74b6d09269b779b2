// A target with a planted bug, so ctest shows the replay fails on a finding:
// input "input-error" is refused cleanly, "logic-error" escapes as another
// exception type (what every real target must never let happen).
#include <stdexcept>

#include "fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace stochtex;
    return fuzz::run([&] {
        const std::string s = fuzz::text(data, size);
        if (s.starts_with("input-error")) throw InputError("refused cleanly");
        if (s.starts_with("logic-error")) throw std::logic_error("a planted bug");
    });
}
