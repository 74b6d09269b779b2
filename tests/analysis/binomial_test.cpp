// The Wilson score interval against hand-computed values.
#include <gtest/gtest.h>

#include <stdexcept>

#include "stochtex/analysis/binomial.h"

namespace stochtex {
namespace {

TEST(WilsonInterval, MatchesHandComputedBounds) {
    const double z2 = kZ95 * kZ95;
    // k = 0: [0, z²/(n + z²)]; k = n: [n/(n + z²), 1] (the closed forms at the ends).
    Proportion p = wilsonInterval(0, 4);
    EXPECT_EQ(p.rate, 0.0);
    EXPECT_NEAR(p.low, 0.0, 1e-15);
    EXPECT_NEAR(p.high, z2 / (4 + z2), 1e-12);
    p = wilsonInterval(5, 5);
    EXPECT_NEAR(p.low, 5 / (5 + z2), 1e-12);
    EXPECT_NEAR(p.high, 1.0, 1e-15);
    // 3 of 4 and 7 of 20, worked by hand to 6 digits (1e-6).
    p = wilsonInterval(3, 4);
    EXPECT_NEAR(p.low, 0.300642, 1e-6);
    EXPECT_NEAR(p.high, 0.954413, 1e-6);
    p = wilsonInterval(7, 20);
    EXPECT_EQ(p.rate, 0.35);
    EXPECT_NEAR(p.low, 0.181192, 1e-6);
    EXPECT_NEAR(p.high, 0.567146, 1e-6);
    EXPECT_THROW(wilsonInterval(1, 0), std::invalid_argument);
    EXPECT_THROW(wilsonInterval(3, 2), std::invalid_argument);
}

}  // namespace
}  // namespace stochtex
