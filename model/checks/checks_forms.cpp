#include "model/checks/checks_internal.h"
#include "model/convert/convert.h"

#include <algorithm>

// The rewrites behind the fuzzy-form findings (PLC concepts (WPLSoft family) 1.7 and 1.8).

namespace rung::model::detail {

namespace {

const Instruction &at(const InstructionList &list, int i) {
    return list.instructions[static_cast<std::size_t>(i)];
}

} // namespace

std::optional<const InstructionSpec *> inSeries(const InstructionList &list, int single, int join) {
    const Instruction &load = at(list, single + 1);
    if (load.op() != Op::Load || !load.spec)
        return std::nullopt;
    for (int k = single + 2; k < join; ++k)
        if (at(list, k).op() != Op::And)
            return std::nullopt;
    const InstructionSpec *spec = load.spec;
    const InstructionSpec *asAnd =
        list.target->findInstruction(Op::And, spec->mode, spec->compare, spec->negated);
    if (!asAnd)
        return std::nullopt;
    return asAnd;
}

RungForm canonicalForm(const InstructionList &list, int first, int last) {
    RungForm form;
    InstructionList part;
    part.target = list.target;
    part.instructions.assign(list.instructions.begin() + first, list.instructions.begin() + last);
    const ToLadderResult drawn = listToLadder(part);
    if (!drawn.ok())
        return form;
    ToListingResult back = ladderToList(drawn.ladder);
    if (!back.ok())
        return form;
    form.known = true;
    form.rewrite = std::move(back.list.instructions);
    form.canonical =
        std::equal(form.rewrite.begin(), form.rewrite.end(), part.instructions.begin(),
                   part.instructions.end(),
                   [](const Instruction &a, const Instruction &b) { return a.sameAs(b); });
    return form;
}

bool stackBetween(const InstructionList &list, int first, int last) {
    for (int k = first; k <= last; ++k) {
        const Op op = at(list, k).op();
        if (op == Op::Push || op == Op::ReadStack || op == Op::Pop)
            return true;
    }
    return false;
}

// FZ004/FZ005: the single contact `single` (a load) joined at `join` with the block that
// follows it moves behind that block as an AND/OR, and the ANB/ORB goes.
std::optional<std::vector<Instruction>>
moveBehind(const InstructionList &list, std::pair<int, int> span, int single, int join, Op as) {
    const InstructionSpec *spec = at(list, single).spec;
    const InstructionSpec *to =
        spec ? list.target->findInstruction(as, spec->mode, spec->compare, spec->negated) : nullptr;
    if (!to)
        return std::nullopt;
    const auto [first, last] = span;
    std::vector<Instruction> out;
    if (const auto series = inSeries(list, single, join); series && as == Op::And) {
        // The block is contacts in series: it joins the single one where it stands, its load
        // an AND, so that the contacts keep the order they were written in.
        for (int k = first; k < last; ++k) {
            if (k == join)
                continue;
            out.push_back(at(list, k));
            if (k == single + 1)
                out.back().spec = *series;
        }
        return out;
    }
    for (int k = first; k < last; ++k) {
        if (k == single)
            continue;
        if (k == join) {
            Instruction moved = at(list, single);
            moved.spec = to;
            out.push_back(moved);
            continue;
        }
        out.push_back(at(list, k));
    }
    return out;
}

// FZ006: the output right after MRD/MPP at `read` goes before the MPS it reads, and the stack
// instructions it needed go. Only where that output is the branch's whole content.
std::optional<std::vector<Instruction>> liftOutput(const InstructionList &list,
                                                   std::pair<int, int> span, int read) {
    const auto [first, last] = span;
    const int output = read + 1;
    const bool lastBranch = at(list, read).op() == Op::Pop;
    const int next = output + 1;
    const bool alone =
        next >= last || at(list, next).op() == Op::ReadStack || at(list, next).op() == Op::Pop;
    if (!alone || (!lastBranch && next >= last))
        return std::nullopt;
    int push = -1;
    int sibling = -1; // the last MRD of the same MPS before `read`
    int depth = 0;
    for (int k = read - 1; k >= first && push < 0; --k) {
        const Op op = at(list, k).op();
        if (op == Op::Pop)
            ++depth;
        else if (op == Op::Push && depth-- == 0)
            push = k;
        else if (op == Op::ReadStack && depth == 0 && sibling < 0)
            sibling = k;
    }
    const InstructionSpec *pop = list.target->findInstruction(Op::Pop);
    if (push < 0 || !pop)
        return std::nullopt;
    std::vector<Instruction> out;
    for (int k = first; k < last; ++k) {
        if (k == push) {
            out.push_back(at(list, output));
            if (lastBranch && sibling < 0)
                continue; // the MPS guarded only this output
        }
        if (k == read || k == output)
            continue;
        Instruction ins = at(list, k);
        if (lastBranch && k == sibling)
            ins.spec = pop; // the branch before is now the last one
        out.push_back(ins);
    }
    return out;
}

} // namespace rung::model::detail
