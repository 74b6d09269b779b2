// Two renderers timed alternately in one run: each benchmark iteration times
// the first, then the second, so that machine drift (clock changes, other
// load) falls on both alike and cancels in their ratio. One loop and one set
// of counters for every "A beside B" benchmark (CPU and GPU).
#pragma once

#include <benchmark/benchmark.h>

#include <chrono>
#include <string>
#include <type_traits>

namespace stochtex::bench {

// Wall-clock seconds of one call of `f`.
template <class F>
double seconds(F&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Seconds spent by each of the two (or three), summed over the benchmark's iterations.
struct AlternateTimes {
    double first = 0;
    double second = 0;
    double third = 0;
};

// The seconds of one measurement: a callable returning nothing is timed on
// the wall clock; one returning a number returns its own seconds (a GPU
// timer query, `GpuView::secondsPerFrame`).
template <class F>
double measure(F& f) {
    if constexpr (std::is_void_v<std::invoke_result_t<F&>>) {
        return seconds(f);
    } else {
        return double(f());
    }
}

// Runs the benchmark loop, measuring `first` then `second` once per
// iteration, and then `third` if given (a limit measured under the same
// conditions: the gather floor).
template <class First, class Second, class... Third>
AlternateTimes timeAlternately(benchmark::State& state, First&& first, Second&& second, Third&&... third) {
    static_assert(sizeof...(Third) <= 1, "two or three callables");
    AlternateTimes t;
    for (auto _ : state) {
        t.first += measure(first);
        t.second += measure(second);
        ((t.third += measure(third)), ...);
    }
    return t;
}

// One of the pair as reported: its counter prefix and its summed seconds.
struct Timed {
    const char* name;  // "filtered" gives the counter "filtered_Mtexel/s"
    double seconds;
};

enum class TexelRate { Mega, Giga };  // counters in Mtexel/s or Gtexel/s

// The pair's counters: `<a>_Mtexel/s`, `<b>_Mtexel/s` (or Gtexel/s) over
// `texelsPerIteration` texels per iteration, and `ratioName` = b's seconds /
// a's seconds (how many times a's rate is b's).
inline void reportAlternateRates(benchmark::State& state, double texelsPerIteration, TexelRate rate, Timed a, Timed b,
                                 const char* ratioName = "ratio") {
    const double texels = texelsPerIteration * double(state.iterations());
    const double scale = rate == TexelRate::Mega ? 1e-6 : 1e-9;
    const std::string unit = rate == TexelRate::Mega ? "_Mtexel/s" : "_Gtexel/s";
    state.counters[a.name + unit] = texels / a.seconds * scale;
    state.counters[b.name + unit] = texels / b.seconds * scale;
    state.counters[ratioName] = b.seconds / a.seconds;
}

}  // namespace stochtex::bench
