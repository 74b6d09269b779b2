#pragma once
// Confidence intervals for a proportion (the detection rate of a yes/no
// experiment): the Wilson score interval (Wilson 1927), which stays inside
// [0, 1] and keeps its coverage near the nominal level for small counts and
// rates near 0 or 1, where the normal-approximation (Wald) interval fails.
namespace stochtex {

// z of a two-sided 95 % interval: Φ⁻¹(0.975).
constexpr double kZ95 = 1.959963984540054;

struct Proportion {
    double rate = 0;           // k / n
    double low = 0, high = 1;  // the interval
};

// k successes out of n trials (0 ≤ k ≤ n, n ≥ 1; std::invalid_argument
// otherwise): with p = k / n,
//   centre = (p + z²/2n) / (1 + z²/n),
//   half   = z / (1 + z²/n) · √(p(1 − p)/n + z²/4n²).
Proportion wilsonInterval(int k, int n, double z = kZ95);

}  // namespace stochtex
