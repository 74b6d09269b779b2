#include "stochtex/core/watchdog.h"

#include <pthread.h>
#include <unistd.h>

#include <atomic>
#include <condition_variable>
#include <cstdio>
#include <list>
#include <mutex>
#include <stdexcept>

#include "stochtex/core/atomic_file.h"
#include "stochtex/core/error.h"

namespace stochtex {
namespace {

std::atomic<OverrunAdvice> gAdvice{nullptr};

// Often enough that memory growing at GB/s overshoots by a few tens of MB.
constexpr auto kPollInterval = std::chrono::milliseconds(10);

}  // namespace

void setOverrunAdvice(OverrunAdvice advice) { gAdvice.store(advice); }

void overrun(const std::string& message) {
    removeLiveTempFiles();
    const OverrunAdvice advice = gAdvice.load();
    std::fprintf(stderr, "stochtex: error: %s%s\n", message.c_str(), advice ? advice().c_str() : "");
    std::fflush(stderr);
    _exit(2);
}

long long residentBytes() {
    std::FILE* f = std::fopen("/proc/self/statm", "r");
    if (!f) return 0;
    long long size = 0, resident = 0;
    const int read = std::fscanf(f, "%lld %lld", &size, &resident);
    std::fclose(f);
    return read == 2 ? resident * static_cast<long long>(sysconf(_SC_PAGESIZE)) : 0;
}

// One thread for every watchdog of the process: a thread started and joined
// around each pass cost a ShaderToy frame 0.35 ms (bench
// BM_ShadertoyWatchdogShare, 64 × 36), more than its passes took.
struct Watchdog::Monitor {
    struct Watch {
        unsigned long long id;
        std::string what;
        std::chrono::steady_clock::time_point start;
        double seconds;
        long long bytes;
        long long startBytes = -1;  // read at the first poll after arming
    };
    std::mutex mutex;
    std::condition_variable armed;
    std::list<Watch> watches;
    unsigned long long nextId = 0;

    // Never destroyed (nor is its thread joined): a watch may be armed until
    // the process ends. A forked child has no thread, so it starts anew.
    static Monitor& instance() {
        static std::once_flag once;
        std::call_once(once, [] {
            pthread_atfork(nullptr, nullptr, [] {
                if (Monitor* parents = current.exchange(nullptr)) abandoned = parents;
            });
        });
        Monitor* m = current.load();
        if (!m) {
            static std::mutex starting;
            const std::lock_guard lock(starting);
            m = current.load();
            if (!m) {
                m = new Monitor;
                m->abandoned_ = abandoned.exchange(nullptr);
                // A plain pthread: std::thread's start-up state would live on
                // the heap, reachable only from this thread's stack, which a
                // forked child does not have (a leak report at its exit).
                pthread_t thread;
                if (pthread_create(
                        &thread, nullptr,
                        [](void* monitor) -> void* {
                            static_cast<Monitor*>(monitor)->watch();
                            return nullptr;
                        },
                        m) != 0)
                    throw std::runtime_error("Watchdog: cannot start its thread");
                pthread_detach(thread);
                current.store(m);
            }
        }
        return *m;
    }
    static inline std::atomic<Monitor*> current{nullptr};
    // A parent's, in a forked child: kept reachable (a leak checker would
    // report it), never used.
    static inline std::atomic<Monitor*> abandoned{nullptr};
    Monitor* abandoned_ = nullptr;

    // Polls while a watch is armed and for a second after the last one (a
    // ShaderToy frame arms one a pass, the next frame's soon after), then
    // sleeps until one is armed: waking a sleeping thread costs the arming
    // call several microseconds.
    static constexpr int kIdlePolls = 100;
    bool sleeping = false;

    void watch() {
        std::unique_lock lock(mutex);
        int idlePolls = 0;
        unsigned long long seen = nextId;  // watches armed up to here
        for (;;) {
            if (watches.empty() && idlePolls >= kIdlePolls) {
                sleeping = true;
                armed.wait(lock, [this] { return !watches.empty(); });
                sleeping = false;
            }
            armed.wait_for(lock, kPollInterval);
            // Idle: nothing armed since the last poll (a pass's watch may come
            // and go between two polls).
            idlePolls = watches.empty() && nextId == seen ? idlePolls + 1 : 0;
            seen = nextId;
            if (watches.empty()) continue;
            lock.unlock();
            const long long resident = residentBytes();
            const auto now = std::chrono::steady_clock::now();
            lock.lock();
            for (Watch& w : watches) {
                if (std::chrono::duration<double>(now - w.start).count() > w.seconds)
                    overrun(w.what + " ran past its time budget of " + formatValue(w.seconds) + " s");
                if (w.startBytes < 0) {
                    w.startBytes = resident;
                } else if (w.startBytes > 0 && resident - w.startBytes > w.bytes) {
                    overrun(w.what + " grew the process's memory by more than its budget of " +
                            formatValue(double(w.bytes) / (1 << 20)) + " MiB");
                }
            }
        }
    }
};

Watchdog::Watchdog(std::string what, double seconds, long long bytes) : monitor_(&Monitor::instance()) {
    const auto start = std::chrono::steady_clock::now();
    bool wake = false;
    {
        const std::lock_guard lock(monitor_->mutex);
        id_ = monitor_->nextId++;
        wake = monitor_->sleeping;
        monitor_->watches.push_back({id_, std::move(what), start, seconds, bytes});
    }
    if (wake) monitor_->armed.notify_one();
}

Watchdog::~Watchdog() {
    // Armed before a fork, destroyed in the child: the parent's monitor is
    // abandoned there (its mutex may have been held at the fork).
    if (monitor_ != Monitor::current.load()) return;
    const std::lock_guard lock(monitor_->mutex);
    monitor_->watches.remove_if([this](const Monitor::Watch& w) { return w.id == id_; });
}

}  // namespace stochtex
