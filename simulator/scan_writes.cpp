#include "simulator/scan_writes.h"

#include "simulator/program.h"

#include <algorithm>

namespace rung::simulator {

namespace {

// Collects [first, end) ranges; out of the image's words they are cut off.
class Collector {
public:
    explicit Collector(std::size_t words)
        : m_words(words) {}

    void word(std::int32_t index) { range(index, 1); }
    void range(std::int32_t first, std::int32_t count) {
        if (first < 0 || count <= 0)
            return;
        const auto b = static_cast<std::size_t>(first);
        const std::size_t e = std::min(m_words, b + static_cast<std::size_t>(count));
        if (b < e)
            m_ranges.emplace_back(b, e);
    }
    void bit(const BitRef &b) {
        if (b.valid())
            word(b.word);
    }
    void flags(const ArithmeticFlags &f) {
        for (const BitRef *b : {&f.error, &f.carry, &f.greater, &f.equal, &f.less, &f.stepStart})
            bit(*b);
    }
    WordRanges take(std::size_t gap) {
        std::sort(m_ranges.begin(), m_ranges.end());
        WordRanges out;
        for (const auto &r : m_ranges) {
            if (!out.empty() && r.first <= out.back().second + gap)
                out.back().second = std::max(out.back().second, r.second);
            else
                out.push_back(r);
        }
        return out;
    }

private:
    std::size_t m_words;
    WordRanges m_ranges;
};

} // namespace

std::optional<WordRanges> scanWrites(const Program &p, std::size_t gap) {
    // Replies and received bytes land where the image says at run time.
    if (!p.comms.empty() || !p.ports.empty())
        return std::nullopt;
    Collector c(static_cast<std::size_t>(p.layout->wordCount()));
    for (const Step &s : p.steps) {
        // An operand resolved at run time (engine_operands.cpp) may land anywhere in its areas.
        if (s.flags & kResolve)
            return std::nullopt;
        // Every code by name (no default): a new one does not compile until it says what it
        // writes (-Wswitch).
        switch (s.code) {
        case Code::Load:
        case Code::And:
        case Code::Or:
        case Code::LoadEdge:
        case Code::AndEdge:
        case Code::OrEdge:
        case Code::LoadCompare:
        case Code::AndCompare:
        case Code::OrCompare:
        case Code::AndBlock:
        case Code::OrBlock:
        case Code::Push:
        case Code::ReadStack:
        case Code::Pop:
        case Code::Invert:
        case Code::EdgeFlow: // edge memories are the engine's, not the image's
        case Code::SubroutineCall:
        case Code::SubroutineStart:
        case Code::SubroutineReturn:
        case Code::Interlock:
        case Code::InterlockClear:
        case Code::Jump:
        case Code::JumpEnd:
        case Code::StepLadder:
        case Code::Return:
        case Code::End:
        case Code::Nop:
            break;
        case Code::Out:
        case Code::Set:
        case Code::Pulse:
        case Code::Toggle:
        case Code::Keep:
            c.bit(s.bit);
            break;
        case Code::SetStep: // the current step's bit is reset
            c.bit(s.bit);
            if (s.slot >= 0 && static_cast<std::size_t>(s.slot) < p.bitLists.size())
                c.bit(p.bitLists[static_cast<std::size_t>(s.slot)]);
            break;
        case Code::StepNext:
            c.bit(s.bit);
            if (s.slot >= 0 && static_cast<std::size_t>(s.slot) < p.bitLists.size())
                c.bit(p.bitLists[static_cast<std::size_t>(s.slot)]);
            break;
        case Code::StepDefine: // 254.07, among the flags
            break;
        case Code::Reset:
            for (int k = 0; k < s.count; ++k) {
                const auto at = static_cast<std::size_t>(s.slot + k);
                if (s.slot < 0 || at >= p.resets.size())
                    break;
                c.bit(p.resets[at].bit);
                c.word(p.resets[at].word);
            }
            break;
        case Code::Timer:
        case Code::Counter:
        case Code::UpDownCounter:
        case Code::PlTimer:
        case Code::PlCounter:
            // The done bit, the current value, the set value in use (Step::y).
            c.bit(s.bit);
            c.word(s.dest);
            c.word(s.y.index);
            break;
        case Code::Transfer:
        case Code::Move:
        case Code::Add:
        case Code::Sub:
        case Code::Inc:
        case Code::Dec:
        case Code::WordLogic:
        case Code::Math:
        case Code::Swap:
        case Code::FromAscii:
        case Code::ShiftDigits:
            c.word(s.dest);
            break;
        case Code::Mul:
        case Code::Div:
        case Code::DoubleMove:
        case Code::CheckCode:
            c.word(s.dest);
            c.word(s.slot); // the high word, the remainder, the parity (-1: none)
            break;
        case Code::Compare: // three bits from bitLists[slot]
            for (std::size_t k = 0; k < 3; ++k) {
                const auto at = static_cast<std::size_t>(s.slot) + k;
                if (s.slot >= 0 && at < p.bitLists.size())
                    c.bit(p.bitLists[at]);
            }
            break;
        case Code::BlockMove:
        case Code::IndirectMove: // dest + an index below count
        case Code::MoveConstants:
        case Code::ShiftRegister:
        case Code::ToAscii: // at most count words (a byte a word)
            c.range(s.dest, std::max(1, s.count));
            break;
        case Code::DoubleDivide: // D .. D+3: wordLists[slot + 4 ..]
            for (std::size_t k = 4; k < 8; ++k) {
                const auto at = static_cast<std::size_t>(s.slot) + k;
                if (s.slot >= 0 && at < p.wordLists.size())
                    c.word(p.wordLists[at]);
            }
            break;
        case Code::Arithmetic:
            c.word(s.dest);
            if (static_cast<ArithOp>(s.op) == ArithOp::WordShift)
                c.range(s.dest, s.count);
            else if (static_cast<ArithOp>(s.op) == ArithOp::BcdMultiply ||
                     static_cast<ArithOp>(s.op) == ArithOp::BcdDivide)
                c.word(s.count); // the second word of the result (-1: none)
            break;
        case Code::Communicate:
            return std::nullopt; // (comms is not empty)
        }
    }
    // What the engine writes at the start of a scan: the inputs from the stimulus (and TEST
    // mode's), the system devices, the parallel port's word (engine.cpp, beginScan).
    for (const auto &[begin, end] : p.inputWordRanges)
        c.range(begin, end - begin);
    if (p.inputTest.valid())
        for (const BitRef &b : p.inputTestBits)
            c.bit(b);
    for (const SystemBinding &b : p.system) {
        c.word(b.word);
        c.bit(b.bit);
    }
    c.word(p.parallelInWord);
    // At END (endScan): the flags cleared, the parallel port's bits, the VPC's bits written
    // during the scan, the PL110's counters' bits, the terminal's pages.
    c.flags(p.flags);
    if (p.writesParallelOut)
        for (const BitRef &b : p.parallelOutBits)
            c.bit(b);
    if (p.deferredBitWrites)
        for (const auto &[begin, end] : p.bitWordRanges)
            c.range(begin, end - begin);
    for (const std::int32_t k : p.endOfScanCounters)
        if (k >= 0 && static_cast<std::size_t>(k) < p.steps.size())
            c.bit(p.steps[static_cast<std::size_t>(k)].bit);
    if (p.terminal.pageShown >= 0)
        for (const std::int32_t w : {p.terminal.pageShown, p.terminal.pageRequest,
                                     p.terminal.lastArea, p.terminal.lastNumber})
            c.word(w);
    return c.take(gap);
}

} // namespace rung::simulator
