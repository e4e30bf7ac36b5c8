#include "engine.h"

#include "model/checks/operand_rules.h"
#include "simulator/tr.h"

#include <QCoreApplication>

// The Omron CPM1's application instructions (W353 section "Instruction Set", appendix B
// "Error and Arithmetic Flag Operation"): word moves, shifts, BCD and binary arithmetic and
// the flags ER 255.03, CY 255.04, GR 255.05, EQ 255.06, LE 255.07. An operand that is not BCD
// where BCD is read turns ER ON and the instruction does not run; an instruction that runs
// turns ER OFF and sets the other flags it has an arrow for. All five go OFF at END(01).

namespace rung::simulator {

namespace {

// The four BCD digits of a 16-bit word as a number, -1 when a digit is above 9.
int bcdValue(std::uint32_t word) {
    int value = 0;
    for (int shift = 12; shift >= 0; shift -= 4) {
        const int digit = static_cast<int>((word >> shift) & 0xF);
        if (digit > 9)
            return -1;
        value = value * 10 + digit;
    }
    return value;
}

QString hex(std::uint32_t word) {
    return QStringLiteral("#%1").arg(word & 0xFFFF, 4, 16, QLatin1Char('0')).toUpper();
}

} // namespace

// "... the instruction is skipped and ER 255.03 is ON": the flag as the target names it.
void Engine::operandError(std::size_t step, const QString &message) {
    setFlag(m_program->flags.error, true);
    const model::SystemDevice *er =
        layout().target().systemDevice(model::SystemRole::InstructionError);
    runtimeError(
        step,
        er ? EngineTr::tr("%1; the instruction is skipped and ER %2 is ON").arg(message, er->device)
           : EngineTr::tr("%1; the instruction is skipped").arg(message));
}

void Engine::clearArithmeticFlags() {
    const ArithmeticFlags &f = m_program->flags;
    for (const BitRef *b : {&f.error, &f.carry, &f.greater, &f.equal, &f.less})
        setFlag(*b, false);
}

void Engine::arithmetic(const Step &s, std::size_t step) {
    const ArithmeticFlags &f = m_program->flags;
    const auto read = [this](const WordOperand &o) {
        return static_cast<std::uint32_t>(o.index >= 0 ? m_words[static_cast<std::size_t>(o.index)]
                                                       : o.constant) &
               0xFFFFu;
    };
    const auto carry = [&] {
        return f.carry.valid() &&
               (static_cast<std::uint32_t>(m_words[static_cast<std::size_t>(f.carry.word)]) &
                f.carry.mask) != 0;
    };
    // Both BCD operands, or ER and nothing done.
    int a = 0;
    int b = 0;
    const auto bcdOperands = [&](int count) {
        const std::uint32_t wa = read(s.x);
        const std::uint32_t wb = count > 1 ? read(s.y) : 0;
        a = bcdValue(wa);
        b = count > 1 ? bcdValue(wb) : 0;
        if (a >= 0 && b >= 0)
            return true;
        operandError(step, EngineTr::tr("%1 is not a BCD number").arg(hex(a < 0 ? wa : wb)));
        return false;
    };
    const auto store = [&](std::int32_t index, std::int64_t value) {
        storeWord(static_cast<std::size_t>(index), value, 16);
    };
    switch (static_cast<ArithOp>(s.op)) {
    case ArithOp::Compare: {
        // CMP(20): the words as unsigned binary numbers.
        const std::uint32_t x = read(s.x);
        const std::uint32_t y = read(s.y);
        setFlag(f.error, false);
        setFlag(f.greater, x > y);
        setFlag(f.equal, x == y);
        setFlag(f.less, x < y);
        return;
    }
    case ArithOp::MoveNot: {
        const std::uint32_t r = ~read(s.x) & 0xFFFFu;
        store(s.dest, r);
        resultFlags(r);
        return;
    }
    case ArithOp::MoveBit: {
        // MOVB(82) S Bi D: Bi's rightmost two digits are S's bit, the leftmost two D's bit.
        const std::uint32_t control = read(s.y);
        if (!model::controlWordFits(model::ControlWord::BitPair, control)) {
            operandError(step, EngineTr::tr("bit designator %1 is not #DDSS with bits 00 to 15")
                                   .arg(hex(control)));
            return;
        }
        const int from = bcdValue(control) % 100;
        const int to = bcdValue(control) / 100;
        const std::uint32_t bit = (read(s.x) >> from) & 1u;
        const auto d = static_cast<std::uint32_t>(m_words[static_cast<std::size_t>(s.dest)]);
        store(s.dest, (d & ~(1u << to)) | (bit << to));
        setFlag(f.error, false);
        return;
    }
    case ArithOp::MoveDigit: {
        // MOVD(83) S Di D: digit 0 of Di the first source digit, digit 1 the count - 1, digit
        // 2 the first destination digit; digits past the leftmost wrap to the rightmost.
        const std::uint32_t control = read(s.y);
        if (!model::controlWordFits(model::ControlWord::Digits, control)) {
            operandError(step, EngineTr::tr("digit designator %1 is not #0DNS with digits 0 to 3")
                                   .arg(hex(control)));
            return;
        }
        const std::uint32_t source = read(s.x);
        auto d = static_cast<std::uint32_t>(m_words[static_cast<std::size_t>(s.dest)]) & 0xFFFFu;
        const int first = static_cast<int>(control & 0xF);
        const int count = static_cast<int>((control >> 4) & 0xF) + 1;
        const int to = static_cast<int>((control >> 8) & 0xF);
        for (int k = 0; k < count; ++k) {
            const int from = 4 * ((first + k) % 4);
            const int into = 4 * ((to + k) % 4);
            d = (d & ~(0xFu << into)) | (((source >> from) & 0xFu) << into);
        }
        store(s.dest, d);
        setFlag(f.error, false);
        return;
    }
    case ArithOp::WordShift:
        // WSFT(16) St E: E takes E-1 ... St+1 takes St, St takes 0000; E's word is lost.
        for (int k = s.count - 1; k > 0; --k)
            store(s.dest + k, m_words[static_cast<std::size_t>(s.dest + k - 1)]);
        if (s.count > 0)
            store(s.dest, 0);
        setFlag(f.error, false);
        return;
    case ArithOp::BcdIncrement:
    case ArithOp::BcdDecrement: {
        // INC(38) / DEC(39): BCD, 9999 + 1 = 0000 and 0000 - 1 = 9999; CY is not affected.
        if (!bcdOperands(1))
            return;
        const bool up = static_cast<ArithOp>(s.op) == ArithOp::BcdIncrement;
        const int r = (a + (up ? 1 : 9999)) % 10000;
        store(s.dest, toBcd(r));
        resultFlags(r);
        return;
    }
    case ArithOp::BcdAdd: {
        if (!bcdOperands(2))
            return;
        const int sum = a + b + (carry() ? 1 : 0);
        store(s.dest, toBcd(sum % 10000));
        setFlag(f.carry, sum > 9999);
        resultFlags(sum % 10000);
        return;
    }
    case ArithOp::BcdSubtract: {
        // Below zero: CY and the 10's complement (W353: "subtract the content of R from
        // zero" for the true result).
        if (!bcdOperands(2))
            return;
        int difference = a - b - (carry() ? 1 : 0);
        setFlag(f.carry, difference < 0);
        if (difference < 0)
            difference += 10000;
        store(s.dest, toBcd(difference));
        resultFlags(difference);
        return;
    }
    case ArithOp::BcdMultiply: {
        if (!bcdOperands(2))
            return;
        const std::int64_t product = std::int64_t{a} * b;
        store(s.dest, toBcd(product % 10000));
        if (s.count >= 0)
            store(s.count, toBcd(product / 10000));
        setFlag(f.error, false);
        setFlag(f.equal, product == 0);
        return;
    }
    case ArithOp::BcdDivide: {
        if (!bcdOperands(2))
            return;
        if (b == 0) {
            operandError(step, EngineTr::tr("division by zero"));
            return;
        }
        store(s.dest, toBcd(a / b));
        if (s.count >= 0)
            store(s.count, toBcd(a % b));
        resultFlags(a / b);
        return;
    }
    case ArithOp::BinaryAdd: {
        const std::uint32_t sum = read(s.x) + read(s.y) + (carry() ? 1u : 0u);
        store(s.dest, sum & 0xFFFFu);
        setFlag(f.carry, sum > 0xFFFFu);
        resultFlags(sum);
        return;
    }
    case ArithOp::BinarySubtract: {
        const std::int64_t difference =
            std::int64_t{read(s.x)} - read(s.y) - (carry() ? 1 : 0); // 2's complement below 0
        store(s.dest, difference & 0xFFFF);
        setFlag(f.carry, difference < 0);
        resultFlags(difference);
        return;
    }
    case ArithOp::SetCarry:
    case ArithOp::ClearCarry:
        setFlag(f.carry, static_cast<ArithOp>(s.op) == ArithOp::SetCarry);
        return;
    case ArithOp::FailureAlarm: {
        // FAL(06) N (W353): N 01..99 is a non-fatal error, its number as two BCD digits in the
        // low byte of the alarm word (SR 253.00..253.07; 253.08..253.15 are other flags and keep
        // theirs), and the program goes on; FAL 00 clears the number.
        if (s.dest < 0)
            return;
        const auto i = static_cast<std::size_t>(s.dest);
        const auto high = static_cast<std::uint32_t>(m_words[i]) & 0xFF00u;
        const std::int32_t n = s.x.constant;
        store(s.dest, high | (n > 0 && n <= 99 ? static_cast<std::uint32_t>(toBcd(n)) : 0u));
        return;
    }
    }
}

// SFT(10) St E (W353): on a rising edge of the shift pulse with reset OFF, every bit of St..E
// moves one place to the left (bit 15 of a word into bit 0 of the next, E's bit 15 is lost) and
// the data input goes into bit 0 of St; reset ON turns every bit OFF.
void Engine::shiftRegister(const Step &s, bool data, bool pulse, bool reset) {
    std::uint8_t &previous = m_edges[static_cast<std::size_t>(s.slot)];
    const bool rising = pulse && !previous;
    previous = pulse;
    if (reset) {
        for (int k = 0; k < s.count; ++k)
            storeWord(static_cast<std::size_t>(s.dest + k), 0, 16);
        return;
    }
    if (!rising)
        return;
    std::uint32_t in = data ? 1u : 0u;
    for (int k = 0; k < s.count; ++k) {
        const auto i = static_cast<std::size_t>(s.dest + k);
        const auto w = static_cast<std::uint32_t>(m_words[i]) & 0xFFFFu;
        storeWord(i, (w << 1) | in, 16);
        in = w >> 15;
    }
}

} // namespace rung::simulator
