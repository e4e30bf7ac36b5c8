#include "model/listing/structure.h"
#include "model/tr.h"

#include <QCoreApplication>

#include <algorithm>
#include <map>

namespace rung::model {

namespace {

// The messages are the checks' (NE*, SL001): one text whichever room reports it.

// The message, and the PLC console's own text for it where the target's manual gives one
// (VPC "IL (JMP) missing"): a CPM1 user reads no VPC console text.
QString withConsole(const QString &message, const char *console) {
    return console
               ? ChecksTr::tr("%1 (the PLC says \"%2\")").arg(message, QString::fromLatin1(console))
               : message;
}

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

// W353 "Subroutines": SBN(92) N .. RET(93) after the main program and before END(01), one
// SBN per number, each SBS(91) N with its SBN; "Step Instructions": STEP(08) B opens the step
// of control bit B up to the next STEP(08), STEP(08) without a bit ends the steps, and IL,
// JMP and SBN cannot stand inside a step.
void pairSubroutinesAndSteps(const InstructionList &list, int last, BlockPairs &pairs) {
    const auto &ins = list.instructions;
    const auto at = [&](int i) -> const Instruction & { return ins[static_cast<std::size_t>(i)]; };
    const auto name = [&](int i) { return at(i).spec ? at(i).spec->mnemonic : QString(); };
    const auto number = [&](int i) -> qint64 {
        return at(i).operands.empty() ? -1 : at(i).operands[0].constant.value;
    };
    const auto add = [&](const char *code, int index, const QString &message, int related = -1,
                         bool warning = false) {
        pairs.problems.push_back({code, index, related, message, !warning, warning});
    };
    const auto specOf = [&](Op op) {
        const InstructionSpec *spec = list.target->findInstruction(op);
        return spec ? spec->mnemonic : QString();
    };
    std::map<qint64, int> defined; // a number's SBN
    std::vector<int> calls;
    int open = -1;         // the SBN whose RET is still to come
    bool mainDone = false; // the first SBN ends the main program
    bool outside = false;  // an instruction between subroutines was reported
    int steps = -1;        // the first STEP(08) B of the open step area
    for (int i = 0; i < last; ++i) {
        const Op op = at(i).op();
        if (steps >= 0 && (op == Op::Interlock || op == Op::Jump || op == Op::SubroutineStart))
            add("SP003", i,
                ChecksTr::tr("%1 cannot stand inside a step (STEP(08) .. STEP(08))").arg(name(i)));
        switch (op) {
        case Op::SubroutineStart: {
            mainDone = true;
            outside = false;
            if (open >= 0)
                add("SB003", i,
                    ChecksTr::tr("%1 %2 inside subroutine %3: close that one with %4 first")
                        .arg(name(i))
                        .arg(number(i))
                        .arg(number(open))
                        .arg(specOf(Op::SubroutineReturn)),
                    open);
            const auto [first, fresh] = defined.emplace(number(i), i);
            if (!fresh)
                add("SB002", i,
                    ChecksTr::tr("A second %1 %2: each subroutine number is defined once")
                        .arg(name(i))
                        .arg(number(i)),
                    first->second);
            open = i;
            break;
        }
        case Op::SubroutineReturn:
            if (open < 0) {
                add("SB003", i,
                    ChecksTr::tr("%1 without %2 before it")
                        .arg(name(i), specOf(Op::SubroutineStart)));
            } else {
                pairs.partner[static_cast<std::size_t>(open)] = i;
                pairs.partner[static_cast<std::size_t>(i)] = open;
            }
            open = -1;
            break;
        case Op::StepDefine:
            if (!at(i).operands.empty()) {
                if (steps < 0)
                    steps = i;
            } else if (steps < 0) {
                add("SP002", i,
                    ChecksTr::tr("%1 without a control bit ends the steps, but no step is open")
                        .arg(name(i)));
            } else {
                steps = -1;
            }
            break;
        default:
            if (op == Op::Apply && at(i).spec->function == ApplyFunction::SubroutineCall)
                calls.push_back(i);
            break;
        }
        // After the main program only subroutines run (W353): the rest never does.
        if (mainDone && open < 0 && op != Op::SubroutineReturn && op != Op::SubroutineStart &&
            !outside) {
            outside = true;
            add("SB004", i,
                ChecksTr::tr(
                    "%1 is after the main program and outside the subroutines: it never runs")
                    .arg(name(i)),
                -1, true);
        }
    }
    if (open >= 0)
        add("SB003", open,
            ChecksTr::tr("%1 %2 is not closed with %3")
                .arg(name(open))
                .arg(number(open))
                .arg(specOf(Op::SubroutineReturn)));
    if (steps >= 0)
        add("SP001", steps,
            ChecksTr::tr("The steps are not closed with %1 without a control bit")
                .arg(name(steps)));
    for (int c : calls) {
        const auto it = defined.find(number(c));
        if (it == defined.end())
            add("SB001", c,
                ChecksTr::tr("%1 %2: there is no %3 %2 before END")
                    .arg(name(c))
                    .arg(number(c))
                    .arg(specOf(Op::SubroutineStart)));
        else
            pairs.partner[static_cast<std::size_t>(c)] = it->second;
    }
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
    const auto opName = [&](Op op) {
        const InstructionSpec *spec = t.findInstruction(op);
        return spec ? spec->mnemonic : QString();
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
                add("NE001", i, ChecksTr::tr("IL inside IL: close the first with ILC"), false);
            il = i;
            break;
        case Op::InterlockClear:
            if (il < 0) {
                add("NE002", i,
                    withConsole(ChecksTr::tr("%1 without %2").arg(name(i), opName(Op::Interlock)),
                                t.console.blockMissing),
                    false);
            } else {
                if (!jumps.empty() && jumps.back() > il)
                    add("NE005", i,
                        withConsole(ChecksTr::tr("IL and JMP overlap: the jump opened inside the "
                                                 "interlock is still open"),
                                    t.console.interlace),
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
                        ChecksTr::tr("Jump number %1 is beyond 00..%2")
                            .arg(n)
                            .arg(t.limits.jumpLabels - 1),
                        true);
                numbered.push_back(i);
                firstJumpOf.emplace(n, i);
                break;
            }
            if (!jumps.empty())
                add("NE003", i, ChecksTr::tr("JMP inside JMP: close the first jump"), true);
            jumps.push_back(i);
            break;
        case Op::JumpEnd:
            if (labels) {
                const qint64 n = number(i);
                if (const auto seen = ends.find(n); seen != ends.end())
                    add("NE007", i,
                        ChecksTr::tr("A second %1 %2: several JMP may share a number, only one JME")
                            .arg(name(i))
                            .arg(n),
                        true, seen->second);
                else
                    ends.emplace(n, i);
                if (const auto first = firstJumpOf.find(n); first == firstJumpOf.end())
                    add("NE004", i,
                        ChecksTr::tr("%1 %2 without a JMP before it").arg(name(i)).arg(n), true);
                else if (pairs.partner[static_cast<std::size_t>(i)] < 0)
                    pairs.partner[static_cast<std::size_t>(i)] = first->second;
                break;
            }
            if (jumps.empty()) {
                add("NE004", i,
                    withConsole(ChecksTr::tr("%1 without %2").arg(name(i), opName(Op::Jump)),
                                t.console.blockMissing),
                    true);
                break;
            }
            if (il > jumps.back())
                add("NE005", i,
                    withConsole(ChecksTr::tr("IL and JMP overlap: the interlock opened inside the "
                                             "jump is still open"),
                                t.console.interlace),
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
        add("NE002", il, ChecksTr::tr("IL without ILC"), false);
    for (int j : jumps)
        add("NE004", j,
            ChecksTr::tr("JMP without its end (%1)")
                .arg(t.findInstruction(Op::JumpEnd) ? t.findInstruction(Op::JumpEnd)->mnemonic
                                                    : QString()),
            true);
    // A numbered JMP goes forward to its JME: one before it is no end for it.
    for (int j : numbered) {
        const qint64 n = number(j);
        const auto e = ends.find(n);
        if (e == ends.end())
            add("NE004", j, ChecksTr::tr("JMP %1 has no JME %1").arg(n), true);
        else if (e->second < j)
            add("NE004", j, ChecksTr::tr("JMP %1 has no JME %1 after it").arg(n), true, e->second);
        else
            pairs.partner[static_cast<std::size_t>(j)] = e->second;
    }
    if (stl >= 0)
        add("SL001", stl, ChecksTr::tr("The step ladder is not closed with RET"), false);
    pairSubroutinesAndSteps(list, last, pairs);
    return pairs;
}

} // namespace rung::model
