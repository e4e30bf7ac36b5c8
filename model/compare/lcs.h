#pragma once

// The longest common subsequence of two runs, by the classic table: the one implementation the
// comparison of two rungs' instructions and the matching of two programs' rungs share.

#include <algorithm>
#include <cstddef>
#include <vector>

namespace rung::model {

// A table larger than this (16 MB of int) is not built: the caller falls back to what it can
// match without it.
inline constexpr std::size_t kLcsMaxCells = 4'000'000;

// Pairs items 0..n-1 of one run with items 0..m-1 of the other, the most that `same(i, j)`
// allows in order, calling `pair(i, j)` for each pair in increasing order. False, with nothing
// paired, when the table would be larger than kLcsMaxCells.
template <class Same, class Pair>
bool longestCommonSubsequence(std::size_t n, std::size_t m, Same same, Pair pair) {
    if ((n + 1) * (m + 1) > kLcsMaxCells)
        return false;
    std::vector<int> len((n + 1) * (m + 1), 0);
    auto at = [&](std::size_t i, std::size_t j) -> int & { return len[i * (m + 1) + j]; };
    for (std::size_t i = n; i-- > 0;)
        for (std::size_t j = m; j-- > 0;)
            at(i, j) = same(i, j) ? at(i + 1, j + 1) + 1 : std::max(at(i + 1, j), at(i, j + 1));
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < n && j < m) {
        if (same(i, j)) {
            pair(i, j);
            ++i;
            ++j;
        } else if (at(i + 1, j) >= at(i, j + 1)) {
            ++i;
        } else {
            ++j;
        }
    }
    return true;
}

} // namespace rung::model
