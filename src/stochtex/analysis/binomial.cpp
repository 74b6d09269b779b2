#include "stochtex/analysis/binomial.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stochtex {

Proportion wilsonInterval(int k, int n, double z) {
    if (n < 1 || k < 0 || k > n) throw std::invalid_argument("wilsonInterval: need 0 <= k <= n and n >= 1");
    const double p = double(k) / n, z2 = z * z;
    const double denominator = 1.0 + z2 / n;
    const double centre = (p + z2 / (2.0 * n)) / denominator;
    const double half = z / denominator * std::sqrt(p * (1.0 - p) / n + z2 / (4.0 * n * double(n)));
    return {p, std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

}  // namespace stochtex
