#pragma once

// The word instructions longer than a line, as execute() runs them with their input ON:
// transfers and moves, the three-way compare, multiplication, division, the PL110 FM
// functions. (Word logic and BCD are Engine::wordLogic, the CPM1's own Engine::arithmetic.)
// Included by engine_execute.cpp and engine_fast.cpp alone: the bodies are inlined into the
// scans' loops (engine.h, Engine::Pass). Not part of the simulator's interface: include engine.h
// instead.

#include "engine.h"

#include "simulator/tr.h"

#include <QCoreApplication>

namespace rung::simulator {

[[gnu::always_inline]] inline void Engine::transfer(const Step &s, std::size_t step,
                                                    const Pass &pass) {
    const std::int64_t v = readWord(pass.R, s.x);
    const std::int64_t d = pass.R[s.dest];
    const auto kind = static_cast<TransferKind>(s.op);
    std::int64_t r = kind == TransferKind::Assign ? v : kind == TransferKind::Add ? d + v : d - v;
    if ((s.flags & kDecimal4) && (r < 0 || r > 9999)) [[unlikely]]
        r = outOfDecimalRange(step, r);
    store(s.dest, r, s.width);
}

[[gnu::always_inline]] inline void Engine::compare(const Step &s, const Pass &pass) {
    const std::int32_t a = readWord(pass.R, s.x);
    const std::int32_t b = readWord(pass.R, s.y);
    const BitRef *bits = &pass.program.bitLists[static_cast<std::size_t>(s.slot)];
    put(pass.W, bits[0], a > b);
    put(pass.W, bits[1], a == b);
    put(pass.W, bits[2], a < b);
}

[[gnu::always_inline]] inline void Engine::multiply(const Step &s, const Pass &pass) {
    const std::int64_t product = std::int64_t{readWord(pass.R, s.x)} * readWord(pass.R, s.y);
    if (s.slot >= 0 && s.width < 32) {
        store(s.dest, product & 0xFFFF, 16);
        store(s.slot, product >> 16, 16);
    } else {
        store(s.dest, product, 32);
        if (s.slot >= 0)
            store(s.slot, product >> 32, 32);
    }
}

[[gnu::always_inline]] inline void Engine::divide(const Step &s, std::size_t step,
                                                  const Pass &pass) {
    const std::int64_t a = readWord(pass.R, s.x);
    const std::int64_t b = readWord(pass.R, s.y);
    if (b == 0) {
        runtimeError(step, EngineTr::tr("division by zero; the destination is unchanged"));
        return;
    }
    store(s.dest, a / b, s.width);
    if (s.slot >= 0)
        store(s.slot, a % b, s.width);
}

[[gnu::always_inline]] inline void Engine::math(const Step &s, std::size_t step, const Pass &pass) {
    const std::int64_t a = readWord(pass.R, s.x);
    const std::int64_t b = readWord(pass.R, s.y);
    std::int64_t r = 0;
    switch (static_cast<MathOp>(s.op)) {
    case MathOp::Add:
        r = a + b;
        break;
    case MathOp::Sub:
        r = a - b;
        break;
    case MathOp::Mul:
        r = a * b;
        break;
    case MathOp::Div:
        r = b == 0 ? 0 : a / b;
        break;
    case MathOp::Or:
        r = a | b;
        break;
    case MathOp::And:
        r = a & b;
        break;
    case MathOp::Xor:
        r = a ^ b;
        break;
    case MathOp::Shl:
        r = b < 0 || b > 31 ? 0 : static_cast<std::int64_t>(static_cast<std::uint64_t>(a) << b);
        break;
    case MathOp::Shr:
        r = b < 0 || b > 31 ? 0 : static_cast<std::int64_t>(static_cast<std::uint32_t>(a) >> b);
        break;
    }
    if (static_cast<MathOp>(s.op) == MathOp::Div && b == 0)
        runtimeError(step, EngineTr::tr("division by zero; the destination is unchanged"));
    else
        store(s.dest, r, s.width);
}

[[gnu::always_inline]] inline void Engine::blockMove(const Step &s, const Pass &pass) {
    const std::int32_t *R = pass.R;
    // memmove order: an overlapping block copies as if through a buffer
    if (s.x.index >= 0 && s.x.index < s.dest) {
        for (int k = s.count - 1; k >= 0; --k)
            store(s.dest + k, R[s.x.index + k], s.width);
    } else {
        for (int k = 0; k < s.count; ++k)
            store(s.dest + k, s.x.index >= 0 ? R[s.x.index + k] : s.x.constant, s.width);
    }
}

[[gnu::always_inline]] inline void Engine::doubleMove(const Step &s, const Pass &pass) {
    const std::int32_t *R = pass.R;
    // FX order: the low word first (DMOV H00310035 D4: D4 = 0035h, D5 = 0031h).
    const std::int32_t v =
        s.y.index >= 0
            ? static_cast<std::int32_t>((static_cast<std::uint32_t>(R[s.y.index]) << 16) |
                                        (static_cast<std::uint32_t>(readWord(R, s.x)) & 0xFFFFu))
            : readWord(R, s.x);
    if (s.slot >= 0) {
        store(s.dest, v, 16);
        store(s.slot, v >> 16, 16);
    } else {
        store(s.dest, v, s.width);
    }
}

[[gnu::always_inline]] inline void Engine::indirectMove(const Step &s, std::size_t step,
                                                        const Pass &pass) {
    const std::int32_t index = readWord(pass.R, s.y);
    if (index < 0 || index >= s.count) {
        runtimeError(step, EngineTr::tr("MOVIND index %1 is outside 0..%2; nothing is written")
                               .arg(index)
                               .arg(s.count - 1));
        return;
    }
    store(s.dest + index, readWord(pass.R, s.x), s.width);
}

} // namespace rung::simulator
