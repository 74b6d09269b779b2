#pragma once
// A watchdog for work that cannot be interrupted once it has started: a GL
// driver compiling a shader (a macro that expands exponentially, an array of
// 10⁸ elements: minutes and gigabytes inside one call), a GPU running a frame
// (a loop that never ends). A thread beside the work checks its wall time and
// the growth of the process's resident memory every few milliseconds; past
// either budget the work cannot be stopped or unwound from, so the process
// ends: the overrun handler removes the live temporary files, says what ran
// over and exits with status 2 (bad input), never returning.
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace stochtex {

// Ends the process because `message` ran over its budget. Must not return.
using OverrunHandler = void (*)(const std::string& message);
// The default: removes the live temporary files (core/atomic_file.h), writes
// "stochtex: error: MESSAGE" to stderr and _exit(2). A program may install
// its own (to word the message its way); null restores the default.
void setOverrunHandler(OverrunHandler handler);
[[noreturn]] void overrun(const std::string& message);

// The process's resident memory in bytes (/proc/self/statm); 0 if unknown.
long long residentBytes();

class Watchdog {
public:
    // Watches from now until destruction: past `seconds` of wall time, or
    // once resident memory has grown by more than `bytes` since now,
    // overrun("WHAT ran past ... (its budget ...)").
    Watchdog(std::string what, double seconds, long long bytes);
    ~Watchdog();
    Watchdog(const Watchdog&) = delete;
    Watchdog& operator=(const Watchdog&) = delete;

private:
    void watch(double seconds, long long bytes);

    std::string what_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool done_ = false;
    std::thread thread_;
};

}  // namespace stochtex
