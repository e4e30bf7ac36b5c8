#include "engine.h"
#include "simulator/tr.h"

#include <QCoreApplication>

// The Vigor instructions the Vigor M/VB/VH communication manual's communication programs build and
// read frames with (SWAP, ASCI, HEX, SMOV) and DDIV, which its MBUS example scales with. The manual
// defines them by those programs only; docs/simulator.md gives each reading and what it rests on.

namespace rung::simulator {

namespace {

constexpr char kHexDigits[] = "0123456789ABCDEF";

int hexValue(std::uint32_t c) {
    if (c >= '0' && c <= '9')
        return int(c - '0');
    if (c >= 'A' && c <= 'F')
        return int(c - 'A' + 10);
    return -1;
}

} // namespace

// SWAP D (FNC 147): "the high and low bytes of D" exchanged; Vigor M/VB/VH communication manual,
// B-3-9 swaps the value a Computer Link reply carries low byte first.
void Engine::swapBytes(const Step &s) {
    const auto v = static_cast<std::uint32_t>(m_words[static_cast<std::size_t>(s.dest)]);
    storeWord(static_cast<std::size_t>(s.dest), ((v & 0xFFu) << 8) | ((v >> 8) & 0xFFu), 16);
}

// ASCI S D n: the last n hexadecimal digits of S, the most significant first, as ASCII
// characters: one a word (low byte) with M9161 ON, two a word (low byte first) with it OFF.
// B-3-9: D100 = 1, ASCI D100 D2 K2 gives D2 = 30H, D3 = 31H ("01").
void Engine::toAscii(const Step &s, std::size_t step) {
    const bool bytes = readBit(s.bit);
    const int words = bytes ? s.count : (s.count + 1) / 2;
    if (words > s.y.constant) {
        runtimeError(step,
                     EngineTr::tr("operation error: %1 characters need %2 words from the "
                                  "destination, past the end of its area; the instruction is not "
                                  "executed")
                         .arg(s.count)
                         .arg(words));
        return;
    }
    const auto value =
        static_cast<std::uint32_t>(s.x.index >= 0 ? m_words[static_cast<std::size_t>(s.x.index)]
                                                  : s.x.constant) &
        0xFFFFu;
    for (int k = 0; k < s.count; ++k) {
        const auto c =
            static_cast<std::uint32_t>(kHexDigits[(value >> (4 * (s.count - 1 - k))) & 0xFu]);
        const auto w = static_cast<std::size_t>(s.dest + (bytes ? k : k / 2));
        if (bytes) {
            storeWord(w, c, 16);
        } else {
            const auto old = static_cast<std::uint32_t>(m_words[w]);
            storeWord(w, k % 2 == 0 ? (old & 0xFF00u) | c : (old & 0x00FFu) | (c << 8), 16);
        }
    }
}

// HEX S D n: n ASCII hexadecimal characters from S (as ASCI lays them out) as one number in D.
// A character that is no hexadecimal digit ('0'..'9', 'A'..'F') is the operation error: D is
// left as it was.
void Engine::fromAscii(const Step &s, std::size_t step) {
    const bool bytes = readBit(s.bit);
    const int words = bytes ? s.count : (s.count + 1) / 2;
    if (s.x.index < 0 || words > s.y.constant) {
        runtimeError(step, EngineTr::tr("operation error: %1 characters need %2 words from the "
                                        "source, past the end of its area; the instruction is not "
                                        "executed")
                               .arg(s.count)
                               .arg(words));
        return;
    }
    std::uint32_t value = 0;
    for (int k = 0; k < s.count; ++k) {
        const auto w = static_cast<std::uint32_t>(
            m_words[static_cast<std::size_t>(s.x.index + (bytes ? k : k / 2))]);
        const std::uint32_t c = (bytes || k % 2 == 0 ? w : w >> 8) & 0xFFu;
        const int digit = hexValue(c);
        if (digit < 0) {
            runtimeError(step, EngineTr::tr("operation error: character %1 (%2H) is no hexadecimal "
                                            "digit; the destination is unchanged")
                                   .arg(k + 1)
                                   .arg(QString::number(c, 16).toUpper().rightJustified(2, u'0')));
            return;
        }
        value = value << 4 | std::uint32_t(digit);
    }
    storeWord(static_cast<std::size_t>(s.dest), value, s.width);
}

// SMOV S m1 m2 D n: the m2 digits of S from digit m1 down go to D from digit n down; D's
// other digits stay. Digits are BCD (S and D 0..9999, the FX rule) unless M9168 is ON, when
// they are hexadecimal: Vigor M/VB/VH communication manual, B-4-5, SMOV D55 K2 K2 D110 K4 puts the
// low byte of D55 into the high byte of D110.
void Engine::shiftDigits(const Step &s, std::size_t step) {
    const bool hex = readBit(s.bit);
    const std::int32_t source =
        s.x.index >= 0 ? m_words[static_cast<std::size_t>(s.x.index)] : s.x.constant;
    const std::int32_t target = m_words[static_cast<std::size_t>(s.dest)];
    std::uint32_t from = static_cast<std::uint32_t>(source) & 0xFFFFu;
    std::uint32_t into = static_cast<std::uint32_t>(target) & 0xFFFFu;
    if (!hex) {
        for (const std::int32_t v : {source, target})
            if (v < 0 || v > 9999) {
                const model::SystemDevice *hexMode =
                    layout().target().systemDevice(model::SystemRole::HexDigits);
                //: %2 the relay that makes SMOV move hexadecimal digits (Vigor M9168)
                runtimeError(step, EngineTr::tr("operation error: %1 is no 4-digit BCD value "
                                                "(0..9999; %2 ON moves hexadecimal digits); the "
                                                "destination is unchanged")
                                       .arg(v)
                                       .arg(hexMode ? hexMode->device : QString()));
                return;
            }
        from = std::uint32_t(model::toBcd(source));
        into = std::uint32_t(model::toBcd(target));
    }
    for (int j = 0; j < s.count; ++j) {
        const int src = s.op - 1 - j;   // 0-based digit of S
        const int dst = s.slot - 1 - j; // 0-based digit of D
        if (src < 0 || dst < 0)
            break;
        const std::uint32_t digit = (from >> (4 * src)) & 0xFu;
        into = (into & ~(0xFu << (4 * dst))) | (digit << (4 * dst));
    }
    const std::int64_t result =
        hex ? std::int64_t(into) : model::fromBcd(std::int32_t(into)).value_or(0);
    storeWord(static_cast<std::size_t>(s.dest), result, s.width);
}

// DDIV S1 S2 D: the 32-bit quotient into D, D+1 (low word first), the remainder into D+2, D+3.
void Engine::doubleDivide(const Step &s, std::size_t step) {
    const std::int32_t *w = &m_program->wordLists[static_cast<std::size_t>(s.slot)];
    auto value = [&](std::int32_t low, std::int32_t high, std::int32_t constant) -> std::int64_t {
        if (low < 0)
            return constant;
        const auto lo = static_cast<std::uint32_t>(m_words[static_cast<std::size_t>(low)]);
        if (high < 0)
            return static_cast<std::int32_t>(lo);
        const auto hi = static_cast<std::uint32_t>(m_words[static_cast<std::size_t>(high)]);
        return static_cast<std::int32_t>((hi << 16) | (lo & 0xFFFFu));
    };
    const std::int64_t a = value(w[0], w[1], s.x.constant);
    const std::int64_t b = value(w[2], w[3], s.y.constant);
    if (b == 0) {
        runtimeError(step, EngineTr::tr("division by zero; the destination is unchanged"));
        return;
    }
    const std::int64_t q = a / b;
    const std::int64_t r = a % b;
    storeWord(static_cast<std::size_t>(w[4]), q, 16);
    storeWord(static_cast<std::size_t>(w[5]), q >> 16, 16);
    storeWord(static_cast<std::size_t>(w[6]), r, 16);
    storeWord(static_cast<std::size_t>(w[7]), r >> 16, 16);
}

} // namespace rung::simulator
