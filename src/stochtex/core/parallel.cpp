#include "stochtex/core/parallel.h"

#include <mutex>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

namespace stochtex {

void parallelRows(int rows, const std::function<void(int, int)>& body) {
    tbb::parallel_for(tbb::blocked_range<int>(0, rows, 4),
                      [&](const tbb::blocked_range<int>& r) { body(r.begin(), r.end()); });
}

void parallelRows(int rows, const std::function<void(int, int)>& body, const Progress& progress) {
    if (!progress) return parallelRows(rows, body);
    std::mutex mutex;
    int done = 0;
    parallelRows(rows, [&](int y0, int y1) {
        body(y0, y1);
        const std::lock_guard<std::mutex> lock(mutex);
        done += y1 - y0;
        progress(double(done) / rows, "");
    });
}

struct ThreadLimit::Impl {
    std::unique_ptr<tbb::global_control> control;
};

ThreadLimit::ThreadLimit(int threads) : impl_(std::make_unique<Impl>()) {
    if (threads > 0)
        impl_->control = std::make_unique<tbb::global_control>(
            tbb::global_control::max_allowed_parallelism, static_cast<size_t>(threads));
}

ThreadLimit::~ThreadLimit() = default;

}  // namespace stochtex
