#include "stochtex/core/names.h"

#include <algorithm>

namespace stochtex {

size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (size_t i = 1; i <= a.size(); ++i)
        for (size_t j = 1; j <= b.size(); ++j) {
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

namespace {

// Whether `given` keeps `name`'s first letter and the rest of its letters in order.
bool abbreviates(const std::string& given, const std::string& name) {
    if (given.empty() || name.empty() || given.size() >= name.size() || given[0] != name[0]) return false;
    size_t j = 0;
    for (const char c : name)
        if (j < given.size() && c == given[j]) ++j;
    return j == given.size();
}

}  // namespace

std::vector<std::string> closestNames(const std::string& given, const std::vector<std::string>& candidates) {
    std::string best;
    size_t bestDistance = std::max<size_t>(1, std::min<size_t>(3, given.size() / 3)) + 1;
    for (const std::string& c : candidates)
        if (const size_t d = editDistance(given, c); d < bestDistance) {
            best = c;
            bestDistance = d;
        }
    if (!best.empty()) return {best};
    std::vector<std::string> out;
    for (const std::string& c : candidates)
        if (abbreviates(given, c)) out.push_back(c);
    if (out.size() > 3) out.clear();
    return out;
}

std::string didYouMean(const std::string& given, const std::vector<std::string>& candidates) {
    const std::vector<std::string> names = closestNames(given, candidates);
    if (names.empty()) return "";
    std::string s = " (did you mean ";
    for (size_t k = 0; k < names.size(); ++k) s += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + names[k];
    return s + "?)";
}

}  // namespace stochtex
