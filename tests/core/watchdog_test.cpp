#include "stochtex/core/watchdog.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

#include "stochtex/core/budget.h"
#include "stochtex/core/error.h"

namespace stochtex {
namespace {

TEST(Budget, TheFactorScalesEveryBudgetWithinItsRange) {
    EXPECT_EQ(budgetFactor(), 1.0);
    EXPECT_EQ(budgeted(1000), 1000);
    setBudgetFactor(4);
    EXPECT_EQ(budgeted(1000), 4000);
    EXPECT_DOUBLE_EQ(budgetedSeconds(30), 120);
    setBudgetFactor(1.0 / 64);
    EXPECT_EQ(budgeted(1000), 15);  // rounded down
    EXPECT_EQ(budgeted(10), 1);     // never below 1
    for (double bad : {0.0, -1.0, 65.0, 1.0 / 65, std::nan("")}) {
        try {
            setBudgetFactor(bad);
            ADD_FAILURE() << bad << " accepted";
        } catch (const InputError& e) {
            EXPECT_EQ(e.parameter(), "budget");
        }
    }
    EXPECT_EQ(budgetFactor(), 1.0 / 64);  // a refused factor changes nothing
    setBudgetFactor(1);
}

TEST(WatchdogDeathTest, WorkWithinItsBudgetEndsQuietly) {
    // A watch that outlived its work would end the process 0.5 s in, with
    // status 2; the process lives on to 1.5 s and exits 0 instead. The
    // parent's watching thread, started here, is not in the child: under the
    // sanitizers, its exit must find nothing of it leaked.
    { const Watchdog parent("the parent's work", 10, 1LL << 30); }
    // Let the parent's new thread finish starting before the fork: GCC 12's
    // ASan takes its allocator's lock in a starting thread (its stack
    // bounds: calloc) and does not hold it across fork, so a fork in that
    // moment left the child's allocator locked, and the child hung at its
    // exit's leak check (seen once in a CI run; gdb of the child: its monitor
    // thread in ThreadStart -> calloc, its main thread in LockAllocator).
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    EXPECT_EXIT(
        {
            {
                const Watchdog watchdog("quick work", 0.5, 1LL << 30);
                std::this_thread::sleep_for(std::chrono::milliseconds(20));
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(1500));
            std::exit(0);
        },
        testing::ExitedWithCode(0), "");
}

std::string adviceForTest() { return " (more with --budget)"; }

TEST(WatchdogDeathTest, TheProgramsAdviceEndsTheMessage) {
    EXPECT_EXIT(
        {
            setOverrunAdvice(adviceForTest);
            const Watchdog watchdog("a sleeping pass", 0.05, 1LL << 30);
            std::this_thread::sleep_for(std::chrono::seconds(20));
        },
        testing::ExitedWithCode(2), "a sleeping pass ran past its time budget of 0.05 s \\(more with --budget\\)\n");
}

TEST(WatchdogDeathTest, WorkPastItsTimeEndsTheProcessWithStatus2) {
    // The parent's watching thread started here is not in the forked child
    // the death test runs in: the child's watch must start its own.
    { const Watchdog parent("the parent's work", 10, 1LL << 30); }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // its start-up done (above)
    EXPECT_EXIT(
        {
            const Watchdog watchdog("a sleeping pass", 0.05, 1LL << 30);
            std::this_thread::sleep_for(std::chrono::seconds(20));
        },
        testing::ExitedWithCode(2), "stochtex: error: a sleeping pass ran past its time budget of 0.05 s");
}

TEST(WatchdogDeathTest, MemoryGrowingPastItsBudgetEndsTheProcess) {
    EXPECT_EXIT(
        {
            const Watchdog watchdog("a greedy compile", 60, 16LL << 20);
            std::vector<std::vector<char>> blocks;
            for (int i = 0; i < 64; ++i) {  // 256 MiB, touched, over a few seconds at most
                blocks.emplace_back(4 << 20);
                std::memset(blocks.back().data(), 1, blocks.back().size());
                std::this_thread::sleep_for(std::chrono::milliseconds(20));
            }
            std::exit(0);  // the watchdog missed it
        },
        testing::ExitedWithCode(2), "a greedy compile grew the process's memory by more than its budget of 16 MiB");
}

}  // namespace
}  // namespace stochtex
