#pragma once
// User-facing errors. An InputError means the user gave something we cannot
// use (a malformed file, an absurd size, ...): the CLI prints its message and
// exits with code 2. Anything else that escapes is a bug (exit code 1).
#include <stdexcept>
#include <string>

namespace stochtex {

class InputError : public std::runtime_error {
public:
    explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace stochtex
