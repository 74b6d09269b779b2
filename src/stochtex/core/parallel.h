#pragma once
// Thin layer over oneTBB: row-parallel loops and a scoped thread limit.
// Every loop body writes only its own rows, so results never depend on the
// number of threads.
#include <functional>
#include <memory>

#include "stochtex/core/progress.h"

namespace stochtex {

// Calls body(y0, y1) over disjoint row ranges covering [0, rows).
void parallelRows(int rows, const std::function<void(int, int)>& body);
// The same, reporting the fraction of rows done after each range (one call
// at a time, from the worker threads; the step is left unnamed).
void parallelRows(int rows, const std::function<void(int, int)>& body, const Progress& progress);

// Limits the worker threads of every parallel loop while alive (0 = all cores).
class ThreadLimit {
public:
    explicit ThreadLimit(int threads);
    ~ThreadLimit();
    ThreadLimit(const ThreadLimit&) = delete;
    ThreadLimit& operator=(const ThreadLimit&) = delete;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace stochtex
