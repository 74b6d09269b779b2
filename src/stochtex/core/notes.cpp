#include "stochtex/core/notes.h"

#include <cstdio>
#include <mutex>
#include <set>

namespace stochtex {

void note(const std::string& message) {
    static std::mutex mutex;
    static std::set<std::string> printed;
    const std::lock_guard<std::mutex> lock(mutex);
    if (!printed.insert(message).second) return;
    std::fprintf(stderr, "note: %s\n", message.c_str());
}

}  // namespace stochtex
