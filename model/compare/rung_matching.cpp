#include "model/compare/rung_matching.h"
#include "lcs.h"

#include <QHash>
#include <QRegularExpression>

#include <algorithm>
#include <tuple>

namespace rung::model {

namespace {

// The longest increasing subsequence of `values` (indices into it).
std::vector<std::size_t> longestIncreasing(const std::vector<int> &values) {
    std::vector<std::size_t> tails; // index of the smallest tail of each length
    std::vector<std::ptrdiff_t> previous(values.size(), -1);
    for (std::size_t k = 0; k < values.size(); ++k) {
        const auto pos = std::lower_bound(tails.begin(), tails.end(), values[k],
                                          [&](std::size_t t, int v) { return values[t] < v; });
        if (pos != tails.begin())
            previous[k] = static_cast<std::ptrdiff_t>(*(pos - 1));
        if (pos == tails.end())
            tails.push_back(k);
        else
            *pos = k;
    }
    std::vector<std::size_t> out;
    for (std::ptrdiff_t k = tails.empty() ? -1 : static_cast<std::ptrdiff_t>(tails.back()); k >= 0;
         k = previous[static_cast<std::size_t>(k)])
        out.push_back(static_cast<std::size_t>(k));
    std::reverse(out.begin(), out.end());
    return out;
}

// Equal keys in the longest common order: common start and end, then the keys unique in both
// ranges as anchors (their longest order), then the same between the anchors; a range without
// unique keys is small enough for the table of the longest common subsequence, or left
// unmatched (the later passes pair its rungs).
void alignEqual(const std::vector<QString> &a, const std::vector<QString> &b, RungMatching *m) {
    struct Range {
        int a0, a1, b0, b1;
    };
    std::vector<Range> work{{0, static_cast<int>(a.size()), 0, static_cast<int>(b.size())}};
    auto pair = [m](int i, int j) {
        m->bOf[static_cast<std::size_t>(i)] = j;
        m->aOf[static_cast<std::size_t>(j)] = i;
    };
    while (!work.empty()) {
        Range r = work.back();
        work.pop_back();
        while (r.a0 < r.a1 && r.b0 < r.b1 &&
               a[static_cast<std::size_t>(r.a0)] == b[static_cast<std::size_t>(r.b0)])
            pair(r.a0++, r.b0++);
        while (r.a0 < r.a1 && r.b0 < r.b1 &&
               a[static_cast<std::size_t>(r.a1 - 1)] == b[static_cast<std::size_t>(r.b1 - 1)])
            pair(--r.a1, --r.b1);
        if (r.a0 >= r.a1 || r.b0 >= r.b1)
            continue;
        QHash<QString, std::pair<int, int>> countA; // key -> (count, index)
        QHash<QString, std::pair<int, int>> countB;
        for (int i = r.a0; i < r.a1; ++i) {
            auto &c = countA[a[static_cast<std::size_t>(i)]];
            ++c.first;
            c.second = i;
        }
        for (int j = r.b0; j < r.b1; ++j) {
            auto &c = countB[b[static_cast<std::size_t>(j)]];
            ++c.first;
            c.second = j;
        }
        std::vector<std::pair<int, int>> unique; // (i, j), by i
        for (int i = r.a0; i < r.a1; ++i) {
            const QString &key = a[static_cast<std::size_t>(i)];
            if (countA.value(key).first != 1)
                continue;
            const auto inB = countB.constFind(key);
            if (inB != countB.cend() && inB->first == 1)
                unique.emplace_back(i, inB->second);
        }
        if (!unique.empty()) {
            std::vector<int> js;
            for (const auto &u : unique)
                js.push_back(u.second);
            int pa = r.a0;
            int pb = r.b0;
            for (std::size_t k : longestIncreasing(js)) {
                const auto [i, j] = unique[k];
                work.push_back({pa, i, pb, j});
                pair(i, j);
                pa = i + 1;
                pb = j + 1;
            }
            work.push_back({pa, r.a1, pb, r.b1});
            continue;
        }
        // No anchor: the longest common subsequence when the table is small enough.
        const auto n = static_cast<std::size_t>(r.a1 - r.a0);
        const auto k = static_cast<std::size_t>(r.b1 - r.b0);
        longestCommonSubsequence(
            n, k, [&](std::size_t i, std::size_t j) { return a[r.a0 + i] == b[r.b0 + j]; },
            [&](std::size_t i, std::size_t j) {
                pair(r.a0 + static_cast<int>(i), r.b0 + static_cast<int>(j));
            });
    }
}

} // namespace

RungTokens rungTokens(const Target &t, const ComparedRung &rung) {
    RungTokens out;
    for (const Instruction &ins : rung.instructions) {
        out.tokens.push_back(printInstruction(t, ins));
        for (const Operand &o : ins.operands)
            out.tokens.push_back(formatOperand(t, o));
        if (!isLogic(ins.op()) && !ins.operands.empty()) {
            const QString driven = QStringLiteral("=>") + formatOperand(t, ins.operands.front());
            out.tokens.push_back(driven);
            out.tokens.push_back(driven);
        }
    }
    if (rung.instructions.empty()) {
        static const QRegularExpression words(QStringLiteral("[\\s|+()\\[\\]-]+"));
        for (const QString &w : rung.signature.split(words, Qt::SkipEmptyParts))
            out.tokens.push_back(w);
    }
    if (!rung.comment.isEmpty()) {
        out.tokens.push_back(QLatin1Char('#') + rung.comment);
        out.tokens.push_back(QLatin1Char('#') + rung.comment);
    }
    std::sort(out.tokens.begin(), out.tokens.end());
    return out;
}

double similarity(const RungTokens &a, const RungTokens &b) {
    const std::size_t total = a.tokens.size() + b.tokens.size();
    if (total == 0)
        return 1.0;
    std::size_t shared = 0;
    auto x = a.tokens.begin();
    auto y = b.tokens.begin();
    while (x != a.tokens.end() && y != b.tokens.end()) {
        if (*x < *y) {
            ++x;
        } else if (*y < *x) {
            ++y;
        } else {
            ++shared;
            ++x;
            ++y;
        }
    }
    return 2.0 * static_cast<double>(shared) / static_cast<double>(total);
}

RungMatching matchRungs(const std::vector<QString> &keysA, const std::vector<QString> &keysB,
                        const std::vector<RungTokens> &tokensA,
                        const std::vector<RungTokens> &tokensB) {
    RungMatching m;
    m.bOf.assign(keysA.size(), -1);
    m.aOf.assign(keysB.size(), -1);
    m.moved.assign(keysB.size(), false);
    alignEqual(keysA, keysB, &m);
    // The anchors: equal rungs in their common order. A rung's gap is how many anchors
    // stand before it; a pair in one gap stands between the same two anchors.
    std::vector<bool> anchor(keysB.size(), false);
    for (std::size_t j = 0; j < keysB.size(); ++j)
        anchor[j] = m.aOf[j] >= 0;
    std::vector<int> gapA(keysA.size());
    std::vector<int> gapB(keysB.size());
    for (std::size_t i = 0, g = 0; i < keysA.size(); ++i) {
        gapA[i] = static_cast<int>(g);
        g += m.bOf[i] >= 0 ? 1 : 0;
    }
    for (std::size_t j = 0, g = 0; j < keysB.size(); ++j) {
        gapB[j] = static_cast<int>(g);
        g += anchor[j] ? 1 : 0;
    }

    // Equal rungs out of the common order: in their order of appearance.
    QHash<QString, std::vector<int>> freeB;
    for (std::size_t j = keysB.size(); j-- > 0;)
        if (m.aOf[j] < 0)
            freeB[keysB[j]].push_back(static_cast<int>(j));
    for (std::size_t i = 0; i < keysA.size(); ++i) {
        if (m.bOf[i] >= 0)
            continue;
        auto it = freeB.find(keysA[i]);
        if (it == freeB.end() || it->empty())
            continue;
        const int j = it->back();
        it->pop_back();
        m.bOf[i] = j;
        m.aOf[static_cast<std::size_t>(j)] = static_cast<int>(i);
    }

    // Alike rungs: candidates share a token; a token in very many rungs (END, the always-ON
    // contact) finds no candidates on its own.
    constexpr std::size_t kCommonToken = 200;
    QHash<QString, std::vector<int>> rungsOfToken;
    for (std::size_t j = 0; j < keysB.size(); ++j) {
        if (m.aOf[j] >= 0)
            continue;
        const auto &tokens = tokensB[j].tokens;
        for (std::size_t k = 0; k < tokens.size(); ++k)
            if (k == 0 || tokens[k] != tokens[k - 1])
                rungsOfToken[tokens[k]].push_back(static_cast<int>(j));
    }
    struct Candidate {
        double score;
        bool sameGap;
        int distance;
        int i, j;
    };
    std::vector<Candidate> candidates;
    for (std::size_t i = 0; i < keysA.size(); ++i) {
        if (m.bOf[i] >= 0)
            continue;
        std::vector<int> seen;
        const auto &tokens = tokensA[i].tokens;
        for (std::size_t k = 0; k < tokens.size(); ++k) {
            if (k > 0 && tokens[k] == tokens[k - 1])
                continue;
            const auto it = rungsOfToken.constFind(tokens[k]);
            if (it == rungsOfToken.cend() || it->size() > kCommonToken)
                continue;
            seen.insert(seen.end(), it->begin(), it->end());
        }
        std::sort(seen.begin(), seen.end());
        seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
        for (int j : seen) {
            const double score = similarity(tokensA[i], tokensB[static_cast<std::size_t>(j)]);
            const bool sameGap = gapA[i] == gapB[static_cast<std::size_t>(j)];
            if (score >= kAlike || (sameGap && score >= kAlikeInPlace))
                candidates.push_back(
                    {score, sameGap, std::abs(static_cast<int>(i) - j), static_cast<int>(i), j});
        }
    }
    std::sort(candidates.begin(), candidates.end(), [](const Candidate &x, const Candidate &y) {
        return std::tie(y.score, y.sameGap, x.distance, x.i, x.j) <
               std::tie(x.score, x.sameGap, y.distance, y.i, y.j);
    });
    for (const Candidate &c : candidates) {
        if (m.bOf[static_cast<std::size_t>(c.i)] >= 0 || m.aOf[static_cast<std::size_t>(c.j)] >= 0)
            continue;
        m.bOf[static_cast<std::size_t>(c.i)] = c.j;
        m.aOf[static_cast<std::size_t>(c.j)] = c.i;
    }

    // Moved: a pair that is no anchor, in another gap, or out of the longest order of the
    // pairs of its gap.
    std::vector<std::vector<int>> pairsOfGap; // B rungs by gap, in A's order
    pairsOfGap.resize(static_cast<std::size_t>(gapA.empty() ? 1 : gapA.back() + 2));
    for (std::size_t i = 0; i < keysA.size(); ++i) {
        const int j = m.bOf[i];
        if (j < 0 || anchor[static_cast<std::size_t>(j)])
            continue;
        if (gapA[i] != gapB[static_cast<std::size_t>(j)])
            m.moved[static_cast<std::size_t>(j)] = true;
        else
            pairsOfGap[static_cast<std::size_t>(gapA[i])].push_back(j);
    }
    for (const std::vector<int> &js : pairsOfGap) {
        std::vector<bool> inOrder(js.size(), false);
        for (std::size_t k : longestIncreasing(js))
            inOrder[k] = true;
        for (std::size_t k = 0; k < js.size(); ++k)
            if (!inOrder[k])
                m.moved[static_cast<std::size_t>(js[k])] = true;
    }
    return m;
}

} // namespace rung::model
