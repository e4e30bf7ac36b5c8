#include "lcs.h"
#include "model/compare/compare.h"

#include "model/compare/rung_matching.h"
#include "model/ladder/ladder_text.h"
#include "model/listing/structure.h"

#include <algorithm>

// The rungs of two programs matched by their logic (docs/version-control.md "How rungs are
// matched"), and the elements of a matched pair that differ.

namespace rung::model {

namespace {

enum class Category : std::uint8_t { Contact, Output, Branches };

Category category(const Instruction &ins) {
    switch (ins.op()) {
    case Op::Load:
    case Op::And:
    case Op::Or:
    case Op::Invert:
        return Category::Contact;
    case Op::AndBlock:
    case Op::OrBlock:
    case Op::Push:
    case Op::ReadStack:
    case Op::Pop:
        return Category::Branches;
    default:
        return Category::Output;
    }
}

ElementChange::Element elementOf(Category c) {
    switch (c) {
    case Category::Contact:
        return ElementChange::Element::Contact;
    case Category::Output:
        return ElementChange::Element::Output;
    case Category::Branches:
        break;
    }
    return ElementChange::Element::Branches;
}

// Whether two instructions of one category are one element changed rather than one removed
// and another added: the same device with another spelling or mode (AND X1 -> ANI X1, OUT Y0
// -> SET Y0), or the same instruction on the same first device (TMR T0 K10 -> TMR T0 K20).
bool sameElement(const Instruction &x, const Instruction &y) {
    if (x.operands == y.operands)
        return true;
    return x.spec == y.spec && !x.operands.empty() && !y.operands.empty() &&
           x.operands.front() == y.operands.front();
}

// The longest common subsequence of two short instruction lists (a rung's), as index pairs.
std::vector<std::pair<int, int>> commonInstructions(const std::vector<Instruction> &a,
                                                    const std::vector<Instruction> &b) {
    const std::size_t n = a.size();
    const std::size_t m = b.size();
    // A rung longer than kLcsMaxCells allows is compared by its common start and end only.
    std::vector<std::pair<int, int>> pairs;
    std::size_t head = 0;
    while (head < n && head < m && a[head].sameAs(b[head]))
        ++head;
    std::size_t tail = 0;
    while (tail < n - head && tail < m - head && a[n - 1 - tail].sameAs(b[m - 1 - tail]))
        ++tail;
    for (std::size_t k = 0; k < head; ++k)
        pairs.emplace_back(static_cast<int>(k), static_cast<int>(k));
    const std::size_t rn = n - head - tail;
    const std::size_t rm = m - head - tail;
    if (rn > 0 && rm > 0)
        longestCommonSubsequence(
            rn, rm, [&](std::size_t i, std::size_t j) { return a[head + i].sameAs(b[head + j]); },
            [&](std::size_t i, std::size_t j) {
                pairs.emplace_back(static_cast<int>(head + i), static_cast<int>(head + j));
            });
    for (std::size_t k = tail; k > 0; --k)
        pairs.emplace_back(static_cast<int>(n - k), static_cast<int>(m - k));
    return pairs;
}

CellOrigin originAt(const ComparedRung &rung, int k) {
    if (k < 0 || static_cast<std::size_t>(k) >= rung.origin.size())
        return {};
    CellOrigin o = rung.origin[static_cast<std::size_t>(k)];
    o.rung = -1; // the caller knows the rung
    return o;
}

// What differs between the instructions of a matched pair.
std::vector<ElementChange> elementChanges(const Target &t, const ComparedRung &x,
                                          const ComparedRung &y) {
    std::vector<ElementChange> changes;
    if (x.instructions.empty() || y.instructions.empty()) {
        // A rung that does not list (it is compared by its drawing): no element detail.
        if (x.signature != y.signature) {
            ElementChange c;
            c.element = ElementChange::Element::Branches;
            changes.push_back(c);
        }
        return changes;
    }
    const auto common = commonInstructions(x.instructions, y.instructions);
    bool branches = false;
    auto hunk = [&](int a0, int a1, int b0, int b1) {
        std::vector<int> removed;
        std::vector<int> added;
        for (int i = a0; i < a1; ++i) {
            if (category(x.instructions[static_cast<std::size_t>(i)]) == Category::Branches)
                branches = true;
            else
                removed.push_back(i);
        }
        for (int j = b0; j < b1; ++j) {
            if (category(y.instructions[static_cast<std::size_t>(j)]) == Category::Branches)
                branches = true;
            else
                added.push_back(j);
        }
        // The same instruction on both sides stands elsewhere in the rung: the branches
        // changed around it, the element did not.
        for (auto r = removed.begin(); r != removed.end();) {
            const Instruction &ri = x.instructions[static_cast<std::size_t>(*r)];
            const auto same = std::find_if(added.begin(), added.end(), [&](int j) {
                return y.instructions[static_cast<std::size_t>(j)].sameAs(ri);
            });
            if (same == added.end()) {
                ++r;
                continue;
            }
            branches = true;
            added.erase(same);
            r = removed.erase(r);
        }
        std::vector<int> partner(removed.size(), -1);
        std::vector<bool> taken(added.size(), false);
        // First the same element changed, then any two of one category in their order.
        for (int pass = 0; pass < 2; ++pass) {
            for (std::size_t r = 0; r < removed.size(); ++r) {
                if (partner[r] >= 0)
                    continue;
                const Instruction &ri = x.instructions[static_cast<std::size_t>(removed[r])];
                for (std::size_t k = 0; k < added.size(); ++k) {
                    if (taken[k])
                        continue;
                    const Instruction &ai = y.instructions[static_cast<std::size_t>(added[k])];
                    if (category(ri) != category(ai))
                        continue;
                    if (pass == 0 && !sameElement(ri, ai))
                        continue;
                    partner[r] = static_cast<int>(k);
                    taken[k] = true;
                    break;
                }
            }
        }
        // In the order of B's rung, removed elements where they stood.
        std::size_t nextRemoved = 0;
        auto flushRemoved = [&](std::size_t upTo) {
            for (; nextRemoved < upTo; ++nextRemoved) {
                if (partner[nextRemoved] >= 0)
                    continue;
                const Instruction &ri =
                    x.instructions[static_cast<std::size_t>(removed[nextRemoved])];
                ElementChange c;
                c.element = elementOf(category(ri));
                c.kind = ElementChange::Kind::Removed;
                c.before = printInstruction(t, ri);
                c.cellA = originAt(x, removed[nextRemoved]);
                changes.push_back(c);
            }
        };
        for (std::size_t k = 0; k < added.size(); ++k) {
            const Instruction &ai = y.instructions[static_cast<std::size_t>(added[k])];
            const auto r = std::find(partner.begin(), partner.end(), static_cast<int>(k));
            ElementChange c;
            c.element = elementOf(category(ai));
            c.after = printInstruction(t, ai);
            c.cellB = originAt(y, added[k]);
            if (r == partner.end()) {
                c.kind = ElementChange::Kind::Added;
            } else {
                const auto ri = static_cast<std::size_t>(r - partner.begin());
                flushRemoved(ri);
                const Instruction &before = x.instructions[static_cast<std::size_t>(removed[ri])];
                c.kind = ElementChange::Kind::Changed;
                c.before = printInstruction(t, before);
                c.cellA = originAt(x, removed[ri]);
                if (before.spec == ai.spec && before.operands.size() == ai.operands.size())
                    for (std::size_t o = 0; o < ai.operands.size(); ++o)
                        if (!(before.operands[o] == ai.operands[o]))
                            c.operands.push_back({static_cast<int>(o),
                                                  formatOperand(t, before.operands[o]),
                                                  formatOperand(t, ai.operands[o])});
            }
            changes.push_back(c);
        }
        flushRemoved(removed.size());
    };
    int pa = 0;
    int pb = 0;
    for (const auto &[i, j] : common) {
        if (i > pa || j > pb)
            hunk(pa, i, pb, j);
        pa = i + 1;
        pb = j + 1;
    }
    hunk(pa, static_cast<int>(x.instructions.size()), pb, static_cast<int>(y.instructions.size()));
    if (branches) {
        ElementChange c;
        c.element = ElementChange::Element::Branches;
        changes.push_back(c);
    }
    return changes;
}

QStringList instructionLines(const Target &t, const ComparedRung &rung) {
    QStringList lines;
    for (const Instruction &ins : rung.instructions)
        lines << printInstruction(t, ins);
    if (lines.isEmpty())
        lines = rung.signature.split(QLatin1Char('\n'));
    return lines;
}

} // namespace

std::vector<ComparedRung> comparedRungs(const LadderProgram &program) {
    const Target &t = *program.target;
    const ToListingResult listed = ladderToList(program);
    std::vector<bool> failed(program.rungs.size(), false);
    for (const Diagnostic &d : listed.problems)
        if (d.location.onLadder() && static_cast<std::size_t>(d.location.rung) < failed.size())
            failed[static_cast<std::size_t>(d.location.rung)] = true;
    std::vector<ComparedRung> rungs(program.rungs.size());
    for (std::size_t r = 0; r < program.rungs.size(); ++r) {
        ComparedRung &out = rungs[r];
        out.comment = program.rungs[r].comment.simplified();
        const bool listedWhole = !failed[r] && r + 1 < listed.rungFirst.size();
        if (listedWhole) {
            const auto first = static_cast<std::size_t>(listed.rungFirst[r]);
            const auto last = static_cast<std::size_t>(listed.rungFirst[r + 1]);
            QStringList lines;
            for (std::size_t k = first; k < last; ++k) {
                out.instructions.push_back(listed.list.instructions[k]);
                out.origin.push_back(listed.origin[k]);
                lines << printInstruction(t, listed.list.instructions[k]);
            }
            out.signature = lines.join(QLatin1Char('\n'));
        }
        if (out.instructions.empty()) {
            // No listing for it (reverse current, an open branch): known by its drawing.
            LadderProgram one;
            one.target = program.target;
            one.rungs.push_back(program.rungs[r]);
            one.rungs.back().comment.clear();
            QStringList lines = printLadderText(one).split(QLatin1Char('\n'));
            lines.removeFirst(); // the LADDER header
            out.signature = lines.join(QLatin1Char('\n'));
        }
    }
    return rungs;
}

void addInstructionComments(const InstructionList &list, LadderProgram *ladder) {
    const std::vector<RungSpan> spans = rungSpans(list.instructions);
    if (spans.size() != ladder->rungs.size())
        return; // a rung did not convert: which comment belongs where is not known
    for (std::size_t r = 0; r < spans.size(); ++r) {
        QStringList notes;
        for (int k = spans[r].first; k < spans[r].last; ++k)
            if (const QString &c = list.instructions[static_cast<std::size_t>(k)].comment;
                !c.isEmpty())
                notes << c;
        if (notes.isEmpty())
            continue;
        QString &comment = ladder->rungs[r].comment;
        if (!comment.isEmpty())
            comment += QLatin1Char('\n');
        comment += notes.join(QLatin1Char('\n'));
    }
}

std::vector<ListingRow> comparisonListing(const Comparison &comparison, const LadderProgram &a,
                                          const LadderProgram &b) {
    const Target &t = *comparison.target;
    const std::vector<ComparedRung> ra = comparedRungs(a);
    const std::vector<ComparedRung> rb = comparedRungs(b);
    std::vector<ListingRow> rows;
    auto row = [&rows](ListingRow::Kind kind, int d, const QString &x, const QString &y) {
        rows.push_back({kind, d, x, y});
    };
    for (std::size_t d = 0; d < comparison.rungs.size(); ++d) {
        const RungDifference &r = comparison.rungs[d];
        const int di = static_cast<int>(d);
        row(ListingRow::Kind::Rung, di, {}, {});
        const ComparedRung *x = r.a >= 0 && static_cast<std::size_t>(r.a) < ra.size()
                                    ? &ra[static_cast<std::size_t>(r.a)]
                                    : nullptr;
        const ComparedRung *y = r.b >= 0 && static_cast<std::size_t>(r.b) < rb.size()
                                    ? &rb[static_cast<std::size_t>(r.b)]
                                    : nullptr;
        if (!x || !y || x->instructions.empty() || y->instructions.empty()) {
            const QStringList lx = x ? instructionLines(t, *x) : QStringList();
            const QStringList ly = y ? instructionLines(t, *y) : QStringList();
            const bool same = x && y && x->signature == y->signature;
            for (qsizetype k = 0; k < std::max(lx.size(), ly.size()); ++k)
                row(same             ? ListingRow::Kind::Same
                    : k >= ly.size() ? ListingRow::Kind::Removed
                    : k >= lx.size() ? ListingRow::Kind::Added
                                     : ListingRow::Kind::Changed,
                    di, lx.value(k), ly.value(k));
            continue;
        }
        const auto common = commonInstructions(x->instructions, y->instructions);
        int pa = 0;
        int pb = 0;
        auto hunk = [&](int a1, int b1) {
            while (pa < a1 || pb < b1) {
                const bool both = pa < a1 && pb < b1;
                row(both      ? ListingRow::Kind::Changed
                    : pa < a1 ? ListingRow::Kind::Removed
                              : ListingRow::Kind::Added,
                    di,
                    pa < a1 ? printInstruction(t, x->instructions[static_cast<std::size_t>(pa)])
                            : QString(),
                    pb < b1 ? printInstruction(t, y->instructions[static_cast<std::size_t>(pb)])
                            : QString());
                if (pa < a1)
                    ++pa;
                if (pb < b1)
                    ++pb;
            }
        };
        for (const auto &[i, j] : common) {
            hunk(i, j);
            const QString text = printInstruction(t, x->instructions[static_cast<std::size_t>(i)]);
            row(ListingRow::Kind::Same, di, text, text);
            pa = i + 1;
            pb = j + 1;
        }
        hunk(static_cast<int>(x->instructions.size()), static_cast<int>(y->instructions.size()));
    }
    return rows;
}

std::vector<RungDifference> compareRungs(const Target &t, const std::vector<ComparedRung> &a,
                                         const std::vector<ComparedRung> &b) {
    std::vector<QString> keysA;
    std::vector<QString> keysB;
    // A rung is the same when its logic and its comment are: the key holds both.
    for (const ComparedRung &r : a)
        keysA.push_back(r.signature + QLatin1Char('\x1f') + r.comment);
    for (const ComparedRung &r : b)
        keysB.push_back(r.signature + QLatin1Char('\x1f') + r.comment);
    std::vector<RungTokens> tokensA;
    std::vector<RungTokens> tokensB;
    for (const ComparedRung &r : a)
        tokensA.push_back(rungTokens(t, r));
    for (const ComparedRung &r : b)
        tokensB.push_back(rungTokens(t, r));
    const RungMatching matching = matchRungs(keysA, keysB, tokensA, tokensB);

    std::vector<RungDifference> out;
    // Deleted rungs stand after the B rung matched to the A rung before them.
    std::vector<std::vector<int>> deletedAfter(b.size() + 1);
    int anchor = -1;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const int j = matching.bOf[i];
        if (j >= 0)
            anchor = j;
        else
            deletedAfter[static_cast<std::size_t>(anchor + 1)].push_back(static_cast<int>(i));
    }
    auto emitDeleted = [&](std::size_t slot) {
        for (int i : deletedAfter[slot]) {
            RungDifference d;
            d.status = RungStatus::Deleted;
            d.a = i;
            d.instructions = instructionLines(t, a[static_cast<std::size_t>(i)]);
            d.commentA = a[static_cast<std::size_t>(i)].comment;
            out.push_back(d);
        }
    };
    emitDeleted(0);
    for (std::size_t j = 0; j < b.size(); ++j) {
        RungDifference d;
        d.b = static_cast<int>(j);
        d.a = matching.aOf[j];
        d.instructions = instructionLines(t, b[j]);
        if (d.a < 0) {
            d.status = RungStatus::Inserted;
            d.commentB = b[j].comment;
        } else {
            const ComparedRung &x = a[static_cast<std::size_t>(d.a)];
            const ComparedRung &y = b[j];
            d.elements = elementChanges(t, x, y);
            d.commentChanged = x.comment != y.comment;
            if (d.commentChanged) {
                d.commentA = x.comment;
                d.commentB = y.comment;
            }
            const bool changed = x.signature != y.signature || d.commentChanged;
            const bool moved = matching.moved[j];
            d.status = changed ? (moved ? RungStatus::MovedChanged : RungStatus::Changed)
                               : (moved ? RungStatus::Moved : RungStatus::Same);
        }
        out.push_back(d);
        emitDeleted(j + 1);
    }
    return out;
}

} // namespace rung::model
