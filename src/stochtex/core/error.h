#pragma once
// User-facing errors. An InputError means the user gave something we cannot
// use (a malformed file, an absurd size, ...): the CLI prints its message and
// exits with code 2. Anything else that escapes is a bug (exit code 1).
//
// The library speaks in its own parameters, never in CLI flags: a parameter
// outside its domain is InputError::parameter("aniso", "must be in [1, 16],
// got 0"), whose message reads "aniso must be in [1, 16], got 0". Whoever
// set the parameter (the CLI from a flag, a JSON reader from a member) finds
// the name in parameter() and adds the flag or the JSON pointer. Errors about
// inputs that are not parameters (a file, a JSON value) use the plain
// constructor and name the input themselves.
#include <sstream>
#include <stdexcept>
#include <string>

namespace stochtex {

class InputError : public std::runtime_error {
public:
    explicit InputError(const std::string& message) : std::runtime_error(message) {}

    // `problem` continues the sentence after the name: "must be in [1, 16], got 0".
    static InputError parameter(const std::string& name, const std::string& problem) {
        return InputError(name, name + " " + problem);
    }

    // A request beyond a work or memory budget (core/budget.h): the input
    // is valid, but asks for more than the budget allows; whoever runs the
    // library may say how to raise it. `name`: the parameter, or empty;
    // `message` is the whole message (it need not start with the name).
    static InputError overBudget(const std::string& name, const std::string& message) {
        InputError e(name, message);
        e.overBudget_ = true;
        return e;
    }

    // The library's name of the offending parameter; empty for a plain error.
    const std::string& parameter() const { return parameter_; }
    bool isOverBudget() const { return overBudget_; }

private:
    InputError(std::string name, const std::string& message)
        : std::runtime_error(message), parameter_(std::move(name)) {}

    std::string parameter_;
    bool overBudget_ = false;
};

// A number as a message shows it: shortest of 6 significant digits, "nan",
// "inf" (std::to_string would print 0.000000 for 1e-9).
inline std::string formatValue(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

}  // namespace stochtex
