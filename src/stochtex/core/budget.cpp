#include "stochtex/core/budget.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "stochtex/core/error.h"

namespace stochtex {
namespace {
// Set once by a command before any work; read from any thread.
std::atomic<double> gFactor{1.0};
}  // namespace

double budgetFactor() { return gFactor.load(std::memory_order_relaxed); }

void setBudgetFactor(double factor) {
    if (!(factor >= kMinBudgetFactor && factor <= kMaxBudgetFactor))
        throw InputError::parameter("budget", "must be in [1/64, 64], got " + formatValue(factor));
    gFactor.store(factor, std::memory_order_relaxed);
}

long long budgeted(long long base) {
    // The bases are at most a few 2³⁰, so base × 64 stays far inside a long long.
    return std::max(1LL, static_cast<long long>(std::floor(double(base) * budgetFactor())));
}

double budgetedSeconds(double base) { return base * budgetFactor(); }

}  // namespace stochtex
