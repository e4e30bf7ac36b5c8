#include "engine.h"
#include "simulator/tr.h"

#include <QCoreApplication>

// Vigor CCD (compile_words.cpp): the check code of a frame held one character a word (8-bit
// mode, the programs of the Vigor M/VB/VH communication manual) or two (16-bit mode).

namespace rung::simulator {

void Engine::checkCode(const Step &s, std::size_t step) {
    const bool bytes = checkCodeBytes(s);
    const int words = bytes ? s.count : (s.count + 1) / 2;
    if (s.x.index < 0 || words > s.y.constant) {
        runtimeError(step, EngineTr::tr("operation error: %1 bytes need %2 words from the source, "
                                        "past the end of its area; the instruction is not executed")
                               .arg(s.count)
                               .arg(words));
        return;
    }
    std::int64_t sum = 0;
    std::uint32_t parity = 0; // bit k: an odd number of the bytes have bit k ON (FX, Delta)
    for (int k = 0; k < s.count; ++k) {
        const auto word = static_cast<std::uint32_t>(
            m_words[static_cast<std::size_t>(s.x.index) + (bytes ? k : k / 2)]);
        const std::uint32_t byte = (bytes || k % 2 == 0 ? word : word >> 8) & 0xFFu;
        sum += byte;
        parity ^= byte;
    }
    storeWord(static_cast<std::size_t>(s.dest), sum, s.width);
    if (s.slot >= 0)
        storeWord(static_cast<std::size_t>(s.slot), parity, 16);
}

} // namespace rung::simulator
