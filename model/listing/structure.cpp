#include "model/listing/structure.h"

#include <QCoreApplication>

#include <algorithm>
#include <map>

namespace rung::model {

namespace {

// The messages are the checks' (NE*, SL001): one text whichever room reports it.
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(rung::model::Checks)
};

// After an output the accumulator still holds the branch point's condition: a block loaded
// there that a later ANB / ORB joins to it continues the rung.
bool joinsTheAccumulator(const std::vector<Instruction> &ins, std::size_t index) {
    int depth = 0;
    for (std::size_t j = index; j < ins.size(); ++j) {
        const Op op = ins[j].op();
        if (op == Op::Load)
            ++depth;
        else if (joinsBlocks(op))
            --depth;
        else if (op != Op::And && op != Op::Or && op != Op::Invert)
            return false;
        if (depth == 0)
            return true;
    }
    return false;
}

} // namespace

bool loadsAfterOutput(const std::vector<Instruction> &ins, int index) {
    const auto i = static_cast<std::size_t>(index);
    return index > 0 && i < ins.size() && ins[i].op() == Op::Load && isOutput(ins[i - 1].op()) &&
           !joinsTheAccumulator(ins, i);
}

std::vector<RungSpan> rungSpans(const std::vector<Instruction> &ins) {
    std::vector<RungSpan> spans;
    const int count = static_cast<int>(ins.size());
    int start = 0;
    int pending = 0; // MPS without their MPP
    for (int i = 0; i < count; ++i) {
        const Op op = ins[static_cast<std::size_t>(i)].op();
        if (isUnconditional(op)) {
            if (start < i)
                spans.push_back({start, i});
            spans.push_back({i, i + 1});
            start = i + 1;
            pending = 0;
            continue;
        }
        if (pending == 0 && start < i && loadsAfterOutput(ins, i)) {
            spans.push_back({start, i});
            start = i;
        }
        if (op == Op::Push)
            ++pending;
        else if (op == Op::Pop && pending > 0)
            --pending;
    }
    if (start < count)
        spans.push_back({start, count});
    return spans;
}

RungSpan spanOf(const std::vector<RungSpan> &spans, int index) {
    auto it = std::upper_bound(spans.begin(), spans.end(), index,
                               [](int i, const RungSpan &s) { return i < s.first; });
    if (it != spans.begin() && index < std::prev(it)->last)
        return *std::prev(it);
    return {index, index + 1};
}

BlockPairs pairBlocks(const InstructionList &list) {
    BlockPairs pairs;
    const auto &ins = list.instructions;
    const int count = static_cast<int>(ins.size());
    pairs.partner.assign(ins.size(), -1);
    if (!list.target)
        return pairs;
    const Target &t = *list.target;
    const auto at = [&](int i) -> const Instruction & { return ins[static_cast<std::size_t>(i)]; };
    const auto name = [&](int i) { return at(i).spec ? at(i).spec->mnemonic : QString(); };
    const auto add = [&](const char *code, int index, const QString &message, bool jump,
                         int related = -1) {
        pairs.problems.push_back({code, index, related, message, jump});
    };
    const auto pair = [&](int a, int b) {
        pairs.partner[static_cast<std::size_t>(a)] = b;
        pairs.partner[static_cast<std::size_t>(b)] = a;
    };
    const auto number = [&](int i) -> qint64 {
        return at(i).operands.empty() ? -1 : at(i).operands[0].constant.value;
    };
    for (int i = 0; i < count && pairs.end < 0; ++i)
        if (at(i).op() == Op::End)
            pairs.end = i;
    const int last = pairs.end >= 0 ? pairs.end : count;

    const bool labels = t.limits.jumpLabels > 0;
    int il = -1;
    std::vector<int> jumps; // open JMP (nesting targets), innermost last
    int stl = -1;
    std::vector<int> numbered;         // JMP with a number, in order
    std::map<qint64, int> ends;        // a number's JME
    std::map<qint64, int> firstJumpOf; // a number's first JMP
    for (int i = 0; i < last; ++i) {
        switch (at(i).op()) {
        case Op::Interlock:
            if (il >= 0)
                add("NE001", i, Tr::tr("IL inside IL: close the first with ILC"), false);
            il = i;
            break;
        case Op::InterlockClear:
            if (il < 0) {
                add("NE002", i, Tr::tr("ILC without IL (\"IL (JMP) missing\")"), false);
            } else {
                if (!jumps.empty() && jumps.back() > il)
                    add("NE005", i,
                        Tr::tr("IL-JMP interlace: the jump opened inside the interlock is still "
                               "open"),
                        false);
                pair(il, i);
            }
            il = -1;
            break;
        case Op::Jump:
            if (labels) {
                const qint64 n = number(i);
                if (n >= t.limits.jumpLabels)
                    add("NE006", i,
                        Tr::tr("Jump number %1 is beyond 00..%2")
                            .arg(n)
                            .arg(t.limits.jumpLabels - 1),
                        true);
                numbered.push_back(i);
                firstJumpOf.emplace(n, i);
                break;
            }
            if (!jumps.empty())
                add("NE003", i, Tr::tr("JMP inside JMP: close the first jump"), true);
            jumps.push_back(i);
            break;
        case Op::JumpEnd:
            if (labels) {
                const qint64 n = number(i);
                if (const auto seen = ends.find(n); seen != ends.end())
                    add("NE007", i,
                        Tr::tr("A second %1 %2: several JMP may share a number, only one JME")
                            .arg(name(i))
                            .arg(n),
                        true, seen->second);
                else
                    ends.emplace(n, i);
                if (const auto first = firstJumpOf.find(n); first == firstJumpOf.end())
                    add("NE004", i, Tr::tr("%1 %2 without a JMP before it").arg(name(i)).arg(n),
                        true);
                else if (pairs.partner[static_cast<std::size_t>(i)] < 0)
                    pairs.partner[static_cast<std::size_t>(i)] = first->second;
                break;
            }
            if (jumps.empty()) {
                add("NE004", i, Tr::tr("%1 without JMP (\"IL (JMP) missing\")").arg(name(i)), true);
                break;
            }
            if (il > jumps.back())
                add("NE005", i,
                    Tr::tr("IL-JMP interlace: the interlock opened inside the jump is still "
                           "open"),
                    true);
            pair(jumps.back(), i);
            jumps.pop_back();
            break;
        case Op::StepLadder:
            stl = i;
            break;
        case Op::Return:
            stl = -1;
            break;
        default:
            break;
        }
    }
    if (il >= 0)
        add("NE002", il, Tr::tr("IL without ILC"), false);
    for (int j : jumps)
        add("NE004", j,
            Tr::tr("JMP without its end (%1)")
                .arg(t.findInstruction(Op::JumpEnd) ? t.findInstruction(Op::JumpEnd)->mnemonic
                                                    : QString()),
            true);
    // A numbered JMP goes forward to its JME: one before it is no end for it.
    for (int j : numbered) {
        const qint64 n = number(j);
        const auto e = ends.find(n);
        if (e == ends.end())
            add("NE004", j, Tr::tr("JMP %1 has no JME %1").arg(n), true);
        else if (e->second < j)
            add("NE004", j, Tr::tr("JMP %1 has no JME %1 after it").arg(n), true, e->second);
        else
            pairs.partner[static_cast<std::size_t>(j)] = e->second;
    }
    if (stl >= 0)
        add("SL001", stl, Tr::tr("The step ladder is not closed with RET"), false);
    return pairs;
}

} // namespace rung::model
