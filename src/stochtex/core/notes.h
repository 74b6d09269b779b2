#pragma once
// Notes to the user on stderr ("note: …"): something the run did that they
// did not ask for (an exemplar resampled, a fallback codec). Each distinct
// note is printed once per process, however often the code that finds it
// runs (a pattern is built for the CPU, the GPU and the export alike).
#include <string>

namespace stochtex {

void note(const std::string& message);

}  // namespace stochtex
