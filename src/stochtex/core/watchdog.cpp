#include "stochtex/core/watchdog.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>

#include "stochtex/core/atomic_file.h"
#include "stochtex/core/error.h"

namespace stochtex {
namespace {

[[noreturn]] void endProcess(const std::string& message) {
    removeLiveTempFiles();
    std::fprintf(stderr, "stochtex: error: %s\n", message.c_str());
    std::fflush(stderr);
    _exit(2);
}

std::atomic<OverrunHandler> gHandler{nullptr};

// Often enough that memory growing at GB/s overshoots by a few tens of MB.
constexpr auto kPollInterval = std::chrono::milliseconds(10);

}  // namespace

void setOverrunHandler(OverrunHandler handler) { gHandler.store(handler); }

void overrun(const std::string& message) {
    if (const OverrunHandler handler = gHandler.load()) handler(message);
    endProcess(message);  // the default, and a handler that returned
}

long long residentBytes() {
    std::FILE* f = std::fopen("/proc/self/statm", "r");
    if (!f) return 0;
    long long size = 0, resident = 0;
    const int read = std::fscanf(f, "%lld %lld", &size, &resident);
    std::fclose(f);
    return read == 2 ? resident * static_cast<long long>(sysconf(_SC_PAGESIZE)) : 0;
}

Watchdog::Watchdog(std::string what, double seconds, long long bytes) : what_(std::move(what)) {
    thread_ = std::thread([this, seconds, bytes] { watch(seconds, bytes); });
}

Watchdog::~Watchdog() {
    {
        std::lock_guard lock(mutex_);
        done_ = true;
    }
    wake_.notify_one();
    thread_.join();
}

void Watchdog::watch(double seconds, long long bytes) {
    const auto start = std::chrono::steady_clock::now();
    const long long startBytes = residentBytes();
    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, kPollInterval, [this] { return done_; })) {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (elapsed > seconds) overrun(what_ + " ran past its time budget of " + formatValue(seconds) + " s");
        const long long grown = residentBytes() - startBytes;
        if (startBytes > 0 && grown > bytes)
            overrun(what_ + " grew the process's memory by more than its budget of " +
                    formatValue(double(bytes) / (1 << 20)) + " MiB");
    }
}

}  // namespace stochtex
