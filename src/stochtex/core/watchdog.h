#pragma once
// A watchdog for work that cannot be interrupted once it has started: a GL
// driver compiling a shader (a macro that expands exponentially, an array of
// 10⁸ elements: minutes and gigabytes inside one call), a GPU running a frame
// (a loop that never ends). One thread of the process checks every watched
// work's wall time and the growth of the process's resident memory every few
// milliseconds; past either budget the work cannot be stopped or unwound
// from, so the process ends: the live temporary files removed, what ran over
// said, exit status 2 (bad input).
#include <chrono>
#include <string>

namespace stochtex {

// Ends the process because `message` ran over its budget: removes the live
// temporary files (core/atomic_file.h), writes "stochtex: error: MESSAGE" and
// the advice to stderr and _exit(2).
[[noreturn]] void overrun(const std::string& message);
// What a program adds to that message, asked for when it is written (so it
// can say how the budgets it was started with are raised); null adds nothing.
using OverrunAdvice = std::string (*)();
void setOverrunAdvice(OverrunAdvice advice);

// The process's resident memory in bytes (/proc/self/statm); 0 if unknown.
long long residentBytes();

class Watchdog {
public:
    // Watches from now until destruction: past `seconds` of wall time, or
    // once resident memory has grown by more than `bytes` since the watch's
    // first check (within a poll of now), overrun("WHAT ran past ...").
    // Cheap (a lock and a list entry: a ShaderToy frame arms one a pass);
    // the one watching thread starts with the first watchdog and sleeps
    // while none is armed.
    Watchdog(std::string what, double seconds, long long bytes);
    ~Watchdog();
    Watchdog(const Watchdog&) = delete;
    Watchdog& operator=(const Watchdog&) = delete;

private:
    struct Monitor;
    Monitor* monitor_;  // the one it is armed with (a forked child starts its own)
    unsigned long long id_;
};

}  // namespace stochtex
