#pragma once

// How the rungs of two programs are paired (docs/version-control.md "How rungs are matched").
// Internal to model/compare.

#include "model/compare/compare.h"

#include <QString>

#include <vector>

namespace rung::model {

// What a rung is made of, for telling how alike two rungs are: each instruction as written,
// each operand, the devices the outputs drive (weighted twice: a rung is mostly what it
// drives) and the comment. Sorted.
struct RungTokens {
    std::vector<QString> tokens;
};
RungTokens rungTokens(const Target &target, const ComparedRung &rung);

// How alike: 2 x shared / (both sizes), 0..1.
double similarity(const RungTokens &a, const RungTokens &b);

struct RungMatching {
    std::vector<int> bOf;    // per A rung: its B rung, -1 when deleted
    std::vector<int> aOf;    // per B rung: its A rung, -1 when inserted
    std::vector<bool> moved; // per B rung: matched out of the order of the others
};

// keysA / keysB: equal keys are the same rung (logic and comment). Pairs equal rungs in order
// first (the longest common order, found from the rungs unique in both, as patience diff
// does), then equal rungs out of order (moved), then alike rungs (changed: similarity at
// least kAlike, or kAlikeInPlace between the same two rungs in order).
inline constexpr double kAlike = 0.5;
inline constexpr double kAlikeInPlace = 0.3;
RungMatching matchRungs(const std::vector<QString> &keysA, const std::vector<QString> &keysB,
                        const std::vector<RungTokens> &tokensA,
                        const std::vector<RungTokens> &tokensB);

// The rung pairing of compareProjects (compare_rungs.cpp).
std::vector<RungDifference> compareRungs(const Target &target, const std::vector<ComparedRung> &a,
                                         const std::vector<ComparedRung> &b);

} // namespace rung::model
