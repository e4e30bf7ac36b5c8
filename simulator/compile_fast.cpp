#include "compiler_detail.h"

#include <algorithm>
#include <optional>
#include <utility>

// Program::fast: which steps the plain scan's loop (Engine::runFast, engine_fast.cpp) runs
// itself. A step keeps the full interpreter (Slow) when it has an operand resolved at run
// time or runs differentiated, or when its code moves the loop or the interlock state.

namespace rung::simulator::detail {

namespace {

FastOp fastOf(const Step &s) {
    if (s.flags & (kResolve | kDifferentiated))
        return FastOp::Slow;
    const bool negated = (s.flags & kNegated) != 0;
    const bool bit = s.bit.valid();
    switch (s.code) {
    case Code::Load:
        if (!bit)
            return FastOp::Slow;
        if (s.flags & kRungStart)
            return negated ? FastOp::LoadStartNot : FastOp::LoadStart;
        return negated ? FastOp::LoadNot : FastOp::Load;
    case Code::And:
        return !bit ? FastOp::Slow : negated ? FastOp::AndNot : FastOp::And;
    case Code::Or:
        return !bit ? FastOp::Slow : negated ? FastOp::OrNot : FastOp::Or;
    case Code::LoadEdge:
        return bit ? FastOp::LoadEdge : FastOp::Slow;
    case Code::AndEdge:
        return bit ? FastOp::AndEdge : FastOp::Slow;
    case Code::OrEdge:
        return bit ? FastOp::OrEdge : FastOp::Slow;
    case Code::AndBlock:
        return FastOp::AndBlock;
    case Code::OrBlock:
        return FastOp::OrBlock;
    case Code::Push:
        return FastOp::Push;
    case Code::ReadStack:
        return FastOp::ReadStack;
    case Code::Pop:
        return FastOp::Pop;
    case Code::Invert:
        return FastOp::Invert;
    case Code::Out:
        return !bit ? FastOp::Slow : negated ? FastOp::OutNot : FastOp::Out;
    case Code::Set:
        return bit ? FastOp::Set : FastOp::Slow;
    case Code::Reset:
        return FastOp::Reset;
    case Code::Timer:
        return FastOp::Timer;
    case Code::Counter:
        return FastOp::Counter;
    case Code::Move:
        return FastOp::Move;
    case Code::Add:
        return FastOp::Add;
    case Code::Sub:
        return FastOp::Sub;
    case Code::Inc:
        return FastOp::Inc;
    case Code::Dec:
        return FastOp::Dec;
    case Code::Nop:
    case Code::JumpEnd:
        return FastOp::Nop;
    case Code::End:
        return FastOp::End;
    case Code::StepLadder:
        return bit ? FastOp::StepLadder : FastOp::Slow;
    case Code::Return:
        return FastOp::Return;
    case Code::Interlock:
        return FastOp::Interlock;
    case Code::InterlockClear:
        return FastOp::InterlockClear;
    case Code::SetStep:
        return bit ? FastOp::SetStep : FastOp::Slow;
    case Code::Jump:
        return FastOp::Jump;
    default:
        return FastOp::Slow;
    }
}

// A timer counting up (not retentive) or a one-input counter counting up with a K set value
// (FastOp::TimerK / CounterK): its operands and what follows from the set value; none for the
// others, which keep FastOp::Timer / Counter.
std::optional<FastElement> constantElement(const Program &program, const Step &s) {
    if (s.x.index >= 0 || (s.flags & kDown) || s.slot < 0 || s.dest < 0 || !s.bit.valid())
        return std::nullopt;
    FastElement e;
    e.state = static_cast<std::int32_t>(static_cast<std::size_t>(s.slot) * kElementStateBytes);
    e.dest = s.dest;
    // Without a word to show the set value in, the current value's word takes it first: the
    // op writes its value after, and tests nothing.
    e.setWord = s.y.index >= 0 ? s.y.index : s.dest;
    e.bitWord = s.bit.word;
    e.bitMask = s.bit.mask;
    e.bitKeep = ~s.bit.mask;
    e.set = std::max<std::int32_t>(0, s.x.constant);
    if (s.code == Code::Counter)
        return (s.flags & kOneInput) && s.width == 16 ? std::optional(e) : std::nullopt;
    if (s.op == kTimerAccumulates || s.count <= 0 || e.set > program.timerMax)
        return std::nullopt;
    e.base = s.count;
    e.limitMs = std::int64_t{e.set} * s.count;
    // The multiply-shift equals the division for every ms up to the limit (< 2^25) and a base
    // up to 2^13: the error ms * (magic - 2^38 / base) stays below 2^38 / base >= 2^25, and
    // ms * magic below 2^63.
    if (e.limitMs >= (std::int64_t{1} << 25) || s.count > (1 << 13))
        return std::nullopt;
    e.magic = ((std::uint64_t{1} << kFastDivShift) / static_cast<std::uint64_t>(s.count)) + 1;
    return e;
}

// The op a rung's first contact becomes when this op follows it (FastOp::LoadStartTimerK ...);
// Slow: none.
FastOp afterLoadStart(FastOp next) {
    constexpr std::pair<FastOp, FastOp> kFused[] = {
        {FastOp::TimerK, FastOp::LoadStartTimerK},
        {FastOp::CounterK, FastOp::LoadStartCounterK},
        {FastOp::MoveWord16, FastOp::LoadStartMoveWord16},
        {FastOp::MoveConst16, FastOp::LoadStartMoveConst16},
        {FastOp::Out, FastOp::LoadStartOut}};
    for (const auto &[op, fused] : kFused)
        if (op == next)
            return fused;
    return FastOp::Slow;
}

// Runs of fast steps that run as one (FastOp::SeriesStart2 ...): the first step's op
// becomes the run's, the others keep theirs.
void fuse(std::vector<FastStep> &fast) {
    auto is = [&](std::size_t i, std::initializer_list<FastOp> ops) {
        return i < fast.size() && std::find(ops.begin(), ops.end(), fast[i].op) != ops.end();
    };
    const auto contactAnd = {FastOp::And, FastOp::AndNot};
    const auto load = {FastOp::Load, FastOp::LoadNot};
    for (std::size_t i = 0; i < fast.size();) {
        if (is(i, {FastOp::LoadStart, FastOp::LoadStartNot}) && is(i + 1, contactAnd) &&
            is(i + 2, {FastOp::Or, FastOp::OrNot})) {
            fast[i].op = FastOp::SeriesStartOr;
            i += 3;
        } else if (is(i, {FastOp::LoadStart, FastOp::LoadStartNot}) && is(i + 1, contactAnd)) {
            fast[i].op = FastOp::SeriesStart2;
            i += 2;
        } else if (is(i, load) && is(i + 1, {FastOp::Or, FastOp::OrNot}) &&
                   is(i + 2, {FastOp::AndBlock})) {
            fast[i].op = FastOp::ParallelAnd;
            i += 3;
        } else if (is(i, load) && is(i + 1, contactAnd) && is(i + 2, {FastOp::OrBlock})) {
            fast[i].op = FastOp::SeriesOr;
            i += 3;
        } else if (const FastOp fused =
                       is(i, {FastOp::LoadStart, FastOp::LoadStartNot}) && i + 1 < fast.size()
                           ? afterLoadStart(fast[i + 1].op)
                           : FastOp::Slow;
                   fused != FastOp::Slow) {
            fast[i].op = fused;
            i += 2;
        } else if (is(i, contactAnd) && is(i + 1, contactAnd)) {
            fast[i].op = FastOp::SeriesAnd2;
            i += 2;
        } else if (is(i, {FastOp::Push}) && is(i + 1, contactAnd) &&
                   is(i + 2, {FastOp::Out, FastOp::OutNot}) && is(i + 3, {FastOp::Pop})) {
            fast[i].op = fast[i + 2].op == FastOp::Out ? FastOp::BranchOut : FastOp::BranchOutNot;
            i += 4;
        } else {
            ++i;
        }
    }
}

// Program::guarded: whether the fast loop reads the gate at every contact and tests the
// stacks' bounds. Without a jump or a subroutine, each rung starts with both stacks empty
// (its LD empties them) and runs in order, so at most its own LDs and MPSs are on them.
bool guardedSteps(const std::vector<Step> &steps) {
    int loads = 0;
    int pushes = 0;
    for (const Step &s : steps) {
        switch (s.code) {
        case Code::StepLadder: // the gate
        case Code::Return:
        case Code::StepDefine:
        case Code::Interlock:
        case Code::InterlockClear:
        case Code::Jump: // the order of the steps
        case Code::SubroutineCall:
        case Code::SubroutineStart:
        case Code::SubroutineReturn:
            return true;
        case Code::Load:
        case Code::LoadEdge:
        case Code::LoadCompare:
            if (s.flags & kRungStart) {
                loads = 0;
                pushes = 0;
            } else if (++loads >= model::kMaxOpenBlocks) {
                return true;
            }
            break;
        case Code::Push:
            if (++pushes >= model::kMaxStackDepthOfAnyTarget)
                return true;
            break;
        default:
            break;
        }
    }
    return false;
}

// A run of contacts none of which is negated takes the op's P form (FastOp::SeriesStart2P ...).
void positiveForms(std::vector<FastStep> &fast) {
    struct Form {
        FastOp op, positive;
        std::size_t first, count; // the contacts of the run
    };
    constexpr Form kForms[] = {{FastOp::SeriesStart2, FastOp::SeriesStart2P, 0, 2},
                               {FastOp::SeriesAnd2, FastOp::SeriesAnd2P, 0, 2},
                               {FastOp::ParallelAnd, FastOp::ParallelAndP, 0, 2},
                               {FastOp::SeriesOr, FastOp::SeriesOrP, 0, 2},
                               {FastOp::BranchOut, FastOp::BranchOutP, 1, 1},
                               {FastOp::BranchOutNot, FastOp::BranchOutNotP, 1, 1},
                               {FastOp::SeriesStartOr, FastOp::SeriesStartOrP, 0, 3}};
    for (std::size_t i = 0; i < fast.size(); ++i)
        for (const Form &form : kForms) {
            if (fast[i].op != form.op)
                continue;
            bool positive = i + form.first + form.count <= fast.size();
            for (std::size_t k = form.first; positive && k < form.first + form.count; ++k)
                positive = fast[i + k].flip == 0;
            if (positive)
                fast[i].op = form.positive;
        }
}

} // namespace

void buildFastSteps(Program &program) {
    program.fast.clear();
    program.fast.reserve(program.steps.size() + 1);
    program.fastElements.clear();
    const bool lean = program.gates.empty(); // no timer or counter is gated
    const bool flags = program.flags.any();
    program.guarded = guardedSteps(program.steps);
    for (std::size_t i = 0; i < program.steps.size(); ++i) {
        const Step &s = program.steps[i];
        FastStep f;
        f.op = fastOf(s);
        f.word = s.bit.word;
        f.mask = s.bit.mask;
        f.flip = (s.flags & kNegated) ? s.bit.mask : 0;
        if (f.op == FastOp::Out || f.op == FastOp::OutNot || f.op == FastOp::Set)
            f.flip = ~s.bit.mask;
        const bool word16 = s.width == 16 && !flags && s.dest >= 0 && s.x.index >= 0;
        auto operands = [&](FastOp wordConst, FastOp wordWord) {
            f.op = s.y.index >= 0 ? wordWord : wordConst;
            f.word = s.dest;
            f.mask = static_cast<std::uint32_t>(s.x.index);
            f.flip = static_cast<std::uint32_t>(s.y.index >= 0 ? s.y.index : s.y.constant);
        };
        switch (f.op) {
        case FastOp::Timer:
        case FastOp::Counter:
            if (!lean || (s.flags & kBcd)) {
                f.op = f.op == FastOp::Timer ? FastOp::TimerFull : FastOp::CounterFull;
            } else if (const std::optional<FastElement> e = constantElement(program, s)) {
                f.op = f.op == FastOp::Timer ? FastOp::TimerK : FastOp::CounterK;
                f.word = static_cast<std::int32_t>(program.fastElements.size());
                program.fastElements.push_back(*e);
                program.fast.push_back(f);
                continue;
            }
            break;
        case FastOp::Move:
            if (s.width == 16 && !flags && s.dest >= 0) {
                f.op = s.x.index >= 0 ? FastOp::MoveWord16 : FastOp::MoveConst16;
                f.word = s.dest;
                f.mask = static_cast<std::uint32_t>(s.x.index >= 0 ? s.x.index
                                                                   : wrapToWidth(s.x.constant, 16));
            }
            break;
        case FastOp::Add:
            if (word16)
                operands(FastOp::AddWordConst16, FastOp::AddWordWord16);
            break;
        case FastOp::Sub:
            if (word16)
                operands(FastOp::SubWordConst16, FastOp::SubWordWord16);
            break;
        default:
            break;
        }
        switch (f.op) { // the ops that read their Step find it by its byte offset
        case FastOp::LoadEdge:
        case FastOp::AndEdge:
        case FastOp::OrEdge:
        case FastOp::Reset:
        case FastOp::Timer:
        case FastOp::Counter:
        case FastOp::TimerFull:
        case FastOp::CounterFull:
        case FastOp::Move:
        case FastOp::Add:
        case FastOp::Sub:
        case FastOp::Inc:
        case FastOp::Dec:
        case FastOp::SetStep:
            f.word = static_cast<std::int32_t>(i * sizeof(Step));
            break;
        case FastOp::Jump:
            f.word = s.slot;
            break;
        default:
            break;
        }
        program.fast.push_back(f);
    }
    fuse(program.fast);
    positiveForms(program.fast);
    // fastElements is complete: its elements stay where they are for the program's life.
    for (FastStep &f : program.fast)
        if (f.op == FastOp::TimerK || f.op == FastOp::CounterK)
            f.setElement(&program.fastElements[static_cast<std::size_t>(f.word)]);
    FastStep stop;
    stop.op = FastOp::Stop;
    program.fast.push_back(stop);
}

} // namespace rung::simulator::detail
