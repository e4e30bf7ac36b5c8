#include "compiler_detail.h"
#include "simulator/tr.h"

// Vigor instructions on more than one word: DMOV (the 32-bit MOV) and CCD (the check code of
// a block of bytes), which the communication programs of the Vigor M/VB/VH communication
// manual use to build and check frames.

namespace rung::simulator::detail {

// DMOV S D: S is a 32-bit constant, a 32-bit device (C200..C255) or the pair S (low word),
// S+1 (high word); D likewise. A 16-bit timer or counter gives its value sign-extended.
void Compiler::compileDoubleMove(const model::Instruction &ins, Step &s) {
    s.code = Code::DoubleMove;
    const model::Operand *src = operand(ins, 0);
    const model::Operand *dst = operand(ins, 1);
    if (!src || !dst)
        return;
    if (src->kind == model::Operand::Kind::Constant && !src->modified()) {
        // H00310035 and K-2147483648..K2147483647; HFFFFFFFF is -1 in 32 bits.
        s.x.constant = static_cast<std::int32_t>(model::wrapToWidth(src->constant.value, 32));
    } else {
        s.x = sourceOf(ins, 0);
        const bool pair =
            isDevice(*src) && m_layout->wordBits(src->address) < 32 && !isTimerOrCounter(*src);
        if (pair && resolvedAtRunTime(*src)) {
            s.y.index = refFor(ins, *src, 0, false, 1);
        } else if (pair) {
            model::Address high = src->address;
            ++high.index;
            s.y.index = m_layout->word(high);
            if (s.y.index < 0)
                error(ins, trCompiler(QT_TRANSLATE_NOOP(
                                          "rung::simulator::Compiler",
                                          "%1 needs the next word too, which does not exist"))
                               .arg(describe(*src)));
        }
    }
    s.dest = destOf(ins, 1, false, &s.width);
    if (isDevice(*dst) && m_layout->wordBits(dst->address) < 32)
        s.slot = nextWord(ins, 1);
}

// CCD S D n (FX / Delta FNC 84; Vigor M/VB/VH communication manual, B-3-9: "Accumulate then
// take the last two digits"): the sum of n bytes from S into D and their parity into D+1.
// While the 8-bit mode flag is ON each word gives its low byte; OFF, its low byte then its high
// byte.
void Compiler::compileCheckCode(const model::Instruction &ins, Step &s) {
    s.code = Code::CheckCode;
    const model::Operand *src = operand(ins, 0);
    const model::Operand *n = operand(ins, 2);
    if (!src || !n)
        return;
    if (!isDevice(*src)) {
        error(ins, CompilerTr::tr("%1 reads a block of words: %2 is not a word device")
                       .arg(ins.spec->mnemonic, describe(*src)));
        return;
    }
    s.x = sourceOf(ins, 0);
    s.dest = destOf(ins, 1, false, &s.width);
    s.slot = nextWord(ins, 1);
    if (n->kind != model::Operand::Kind::Constant || n->modified() || n->constant.value < 1 ||
        n->constant.value > 256) {
        error(ins,
              CompilerTr::tr("%1 needs a count from 1 to %2").arg(ins.spec->mnemonic).arg(256));
        return;
    }
    s.count = static_cast<int>(n->constant.value);
    if (const model::SystemDevice *mode = m_target.systemDevice(model::SystemRole::ByteMode)) {
        const auto parsed = model::parseAddress(m_target, mode->device);
        if (const auto *a = std::get_if<model::Address>(&parsed))
            s.bit = m_layout->bit(*a);
    }
    // The words from S to the end of its area; an indexed S is measured where it lands.
    if (s.x.index >= 0)
        s.y.constant = m_target.area(src->address.area).last - src->address.index + 1;
}

} // namespace rung::simulator::detail
