// Peak resident memory of one step of a benchmark, from Linux's /proc: the
// peak (VmHWM) is reset to the current resident size by writing 5 to
// /proc/self/clear_refs, so the peak read after the step minus the size
// before it is what the step itself held at most.
#pragma once

#include <cstddef>
#include <fstream>
#include <string>

namespace stochtex::bench {

inline size_t statusBytes(const std::string& key) {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind(key + ":", 0) == 0) return size_t(std::stoull(line.substr(key.size() + 1))) * 1024;  // kB
    return 0;
}

// Resets the peak to the current resident size and returns that size.
inline size_t resetPeakResidentBytes() {
    std::ofstream("/proc/self/clear_refs") << "5";
    return statusBytes("VmRSS");
}

inline size_t peakResidentBytes() { return statusBytes("VmHWM"); }

}  // namespace stochtex::bench
