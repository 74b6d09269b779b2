#pragma once
// A text file compiled into the binary (presets today, shaders later).
#include <cstddef>

namespace stochtex {

struct EmbeddedFile {
    const char* name;      // file stem, e.g. "camouflage"
    const char* contents;  // whole file
};

}  // namespace stochtex
