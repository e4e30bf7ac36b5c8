#include "compiler_detail.h"
#include "simulator/tr.h"

// Operands that are no single word of the image: digit-designated bits (K4Y0), operands
// modified by an index register (D0E0, K4M0E1, K10F0) and double words (PL110 VD0). The
// compiler describes each as an OperandRef; the engine resolves it each time the step runs
// (engine_operands.cpp), since an index register changes while the program runs.

namespace rung::simulator::detail {

bool Compiler::resolvedAtRunTime(const model::Operand &o) const {
    if (o.modified())
        return true;
    return isDevice(o) && m_layout->area(o.address.area).doubleWords;
}

std::int32_t Compiler::refFor(const model::Instruction &ins, const model::Operand &o, std::size_t i,
                              bool dest, int offset) {
    OperandRef r;
    r.operand = static_cast<std::int32_t>(i);
    if (o.index.valid()) {
        r.index = m_layout->word(o.index);
        r.indexArea = o.index.area;
        r.indexElement = o.index.index;
        if (r.index < 0)
            error(ins, CompilerTr::tr("%1 is not an index register").arg(describe(o)));
    }
    if (o.kind == model::Operand::Kind::Constant) {
        r.kind = OperandRef::Kind::Constant;
        r.element = static_cast<std::int32_t>(o.constant.value);
        if (dest)
            error(ins,
                  CompilerTr::tr("%1 is a constant; a device is expected here").arg(describe(o)));
    } else if (!isDevice(o)) {
        error(ins, CompilerTr::tr("%1 is not a word device or a constant").arg(describe(o)));
        return -1;
    } else {
        const model::Area &area = m_target.area(o.address.area);
        const AreaLayout &l = m_layout->area(o.address.area);
        r.area = o.address.area;
        r.element = o.address.index + offset;
        if (o.digits > 0) {
            r.kind = OperandRef::Kind::Bits;
            r.bits = o.digits * 4;
        } else if (l.doubleWords) {
            r.kind = OperandRef::Kind::DoubleWord;
            r.word = m_layout->word(o.address);
        }
        if (dest && !area.writable) {
            error(ins,
                  trCompiler(QT_TRANSLATE_NOOP("rung::simulator::Compiler", "%1 cannot be written"))
                      .arg(describe(o)));
            return -1;
        }
        // Every area of the prefix: an index may carry D199 into D200 (another area).
        r.firstSegment = static_cast<std::int32_t>(m_program->segments.size());
        for (int k = 0; k < m_layout->areaCount(); ++k) {
            const model::Area &a = m_target.area(k);
            const AreaLayout &al = m_layout->area(k);
            if (a.prefix != area.prefix || al.kind != l.kind || al.count <= 0)
                continue;
            Segment seg;
            seg.first = al.first;
            seg.last = al.first + al.count - 1;
            seg.bits = r.kind == OperandRef::Kind::Bits;
            seg.base = seg.bits ? al.bitBase : al.wordBase;
            seg.wordBits = static_cast<std::uint8_t>(al.wordBits);
            if (seg.base >= 0)
                m_program->segments.push_back(seg);
        }
        r.segmentCount = static_cast<std::int32_t>(m_program->segments.size()) - r.firstSegment;
    }
    m_program->refs.push_back(r);
    m_resolve = true;
    return refCode(m_program->refs.size() - 1);
}

// MUL's high word and DIV's remainder go to the word after D. A digit-designated D has none
// (the FX family keeps the low bits of the product and no remainder).
std::int32_t Compiler::nextRef(const model::Instruction &ins, const model::Operand &o,
                               std::size_t i) {
    if (o.digits > 0 || m_layout->area(o.address.area).doubleWords)
        return -1;
    return refFor(ins, o, i, true, 1);
}

} // namespace rung::simulator::detail
