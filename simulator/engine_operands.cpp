#include "engine.h"

#include "model/target/address.h"
#include "simulator/tr.h"

#include <QCoreApplication>

#include <optional>

// Operands resolved each time their step runs (OperandRef, compile_operands.cpp): a digit
// group of bits (K4Y0) is read into a value or written through the scratch word; an index
// register moves a word, a group or a constant (D0E0, K4M0E1, K10F0); a PL110 double word
// joins two words. An indexed operand that lands outside every area of its prefix is the
// PLC's operation error: the instruction is not executed (PLC concepts (WPLSoft family): the
// PLC flags it and goes on with the scan), and the simulator names the operand and the index.

namespace rung::simulator {

namespace {

const Segment *segmentOf(const Program &p, const OperandRef &ref, std::int64_t element) {
    for (std::int32_t k = 0; k < ref.segmentCount; ++k) {
        const Segment &s = p.segments[static_cast<std::size_t>(ref.firstSegment + k)];
        if (element >= s.first && element <= s.last)
            return &s;
    }
    return nullptr;
}

BitRef bitAt(const Segment &s, std::int64_t element) {
    const auto i = static_cast<std::int32_t>(element - s.first);
    return {s.base + i / 16, 1u << (i % 16)};
}

bool isCompareContact(Code code) {
    return code == Code::LoadCompare || code == Code::AndCompare || code == Code::OrCompare;
}

} // namespace

QString Engine::refText(const OperandRef &ref) const {
    const model::Target &t = layout().target();
    QString text = ref.kind == OperandRef::Kind::Constant
                       ? model::formatConstant(
                             t, model::Constant{ref.element, model::Constant::Style::Decimal})
                       : model::formatAddress(t, model::Address{ref.area, ref.element, -1});
    if (ref.kind == OperandRef::Kind::Bits)
        text.prepend(QStringLiteral("K%1").arg(ref.bits / 4));
    if (ref.indexArea >= 0)
        text += model::formatAddress(t, model::Address{ref.indexArea, ref.indexElement, -1});
    return text;
}

// The first element the operand names now, and that all `extent` elements from it exist
// (a word block: in consecutive words of the image).
std::int64_t Engine::resolveElement(const OperandRef &ref, std::size_t step, int extent, bool *ok) {
    const Program &p = *m_program;
    const std::int64_t offset = ref.index >= 0 ? m_words[static_cast<std::size_t>(ref.index)] : 0;
    const std::int64_t element = std::int64_t{ref.element} + offset;
    // The first element that does not exist (an index may be negative: no sentinel value).
    std::optional<std::int64_t> missing;
    if (ref.kind == OperandRef::Kind::Bits) {
        for (int k = 0; k < extent && !missing; ++k)
            if (!segmentOf(p, ref, element + k))
                missing = element + k;
    } else {
        const Segment *first = segmentOf(p, ref, element);
        const Segment *last = segmentOf(p, ref, element + extent - 1);
        if (!first)
            missing = element;
        else if (!last || last->base + (element + extent - 1 - last->first) !=
                              first->base + (element - first->first) + extent - 1)
            missing = element + extent - 1;
    }
    if (!missing)
        return element;
    *ok = false;
    const model::Target &t = layout().target();
    const QString where =
        model::formatAddress(t, model::Address{ref.area, static_cast<int>(*missing), -1});
    if (ref.indexArea >= 0)
        runtimeError(
            step,
            EngineTr::tr("operation error: %1 with %2 = %3 reaches %4, which does not exist; "
                         "the instruction is not executed")
                .arg(refText(ref),
                     model::formatAddress(t, model::Address{ref.indexArea, ref.indexElement, -1}))
                .arg(offset)
                .arg(where));
    else
        runtimeError(step, EngineTr::tr("operation error: %1 reaches %2, which does not exist; the "
                                        "instruction is not executed")
                               .arg(refText(ref), where));
    return element;
}

std::int32_t Engine::readBits(const OperandRef &ref, std::int64_t element) const {
    const Program &p = *m_program;
    std::uint32_t v = 0;
    for (int k = 0; k < ref.bits; ++k) {
        const Segment *s = segmentOf(p, ref, element + k);
        const BitRef b = bitAt(*s, element + k);
        if (static_cast<std::uint32_t>(m_words[static_cast<std::size_t>(b.word)]) & b.mask)
            v |= 1u << k;
    }
    return static_cast<std::int32_t>(v);
}

bool Engine::resolveStep(const Step &s, std::size_t step, Step &r) {
    const Program &p = *m_program;
    r = s;
    bool ok = true;
    // CCD reads n words from its source in 8-bit mode, n / 2 rounded up in 16-bit mode, and
    // writes one word (its parity word is resolved as the slot).
    const bool checkCode = s.code == Code::CheckCode;
    int extent = 1;
    if (s.code == Code::BlockMove)
        extent = std::max(1, s.count);
    else if (checkCode)
        extent = checkCodeBytes(s) ? std::max(1, s.count) : (s.count + 1) / 2;
    auto word = [&](const OperandRef &ref, std::int64_t element) {
        const Segment *seg = segmentOf(p, ref, element);
        return static_cast<std::int32_t>(seg->base + (element - seg->first));
    };
    auto source = [&](WordOperand &o) {
        if (o.index > kRefBase)
            return;
        const OperandRef &ref = p.refs[refOf(o.index)];
        o.index = -1;
        switch (ref.kind) {
        case OperandRef::Kind::Constant:
            o.constant = model::wrapToWidth(
                std::int64_t{ref.element} +
                    (ref.index >= 0 ? m_words[static_cast<std::size_t>(ref.index)] : 0),
                32);
            break;
        case OperandRef::Kind::Word: {
            const std::int64_t e = resolveElement(ref, step, extent, &ok);
            if (ok)
                o.index = word(ref, e);
            break;
        }
        case OperandRef::Kind::Bits: {
            const std::int64_t e = resolveElement(ref, step, ref.bits, &ok);
            if (ok)
                o.constant = readBits(ref, e);
            break;
        }
        case OperandRef::Kind::DoubleWord:
            o.constant = model::wrapToWidth(
                (std::int64_t{m_words[static_cast<std::size_t>(ref.word)]} << 16) |
                    (m_words[static_cast<std::size_t>(ref.word) + 1] & 0xFFFF),
                32);
            break;
        }
    };
    source(r.x);
    source(r.y);
    if (checkCode) {
        if (s.x.index <= kRefBase)
            r.y.constant = extent; // the block was found whole where the index put it
        extent = 1;
    }
    if (ok && s.dest <= kRefBase) {
        const OperandRef &ref = p.refs[refOf(s.dest)];
        switch (ref.kind) {
        case OperandRef::Kind::Word: {
            const std::int64_t e = resolveElement(ref, step, extent, &ok);
            if (ok) {
                r.dest = word(ref, e);
                r.width = segmentOf(p, ref, e)->wordBits;
            }
            break;
        }
        case OperandRef::Kind::Bits: {
            m_destElement = resolveElement(ref, step, ref.bits, &ok);
            if (ok)
                m_words[m_scratch] = readBits(ref, m_destElement);
            r.dest = static_cast<std::int32_t>(m_scratch);
            r.width = 32;
            break;
        }
        case OperandRef::Kind::DoubleWord: {
            const auto w = static_cast<std::size_t>(ref.word);
            m_words[m_scratch] =
                static_cast<std::int32_t>((static_cast<std::uint32_t>(m_words[w]) << 16) |
                                          (static_cast<std::uint32_t>(m_words[w + 1]) & 0xFFFFu));
            r.dest = static_cast<std::int32_t>(m_scratch);
            r.width = 32;
            break;
        }
        case OperandRef::Kind::Constant:
            ok = false; // the compiler refuses a constant destination
            break;
        }
    }
    if (ok && s.slot <= kRefBase &&
        (s.code == Code::Mul || s.code == Code::Div || s.code == Code::DoubleMove || checkCode)) {
        const OperandRef &ref = p.refs[refOf(s.slot)];
        const std::int64_t e = resolveElement(ref, step, 1, &ok);
        if (ok)
            r.slot = word(ref, e);
    }
    if (ok)
        return true;
    if (isCompareContact(s.code)) {
        // A contact still takes its place in the rung: it is open.
        r.x = WordOperand{};
        r.y = WordOperand{};
        r.op = static_cast<std::uint8_t>(model::CompareOp::Ne);
        r.flags = static_cast<std::uint8_t>(r.flags & ~kNegated);
        return true;
    }
    return false;
}

void Engine::writeBack(const Step &s, const Step &r, std::int32_t *bits) {
    if (s.dest > kRefBase || r.dest != static_cast<std::int32_t>(m_scratch))
        return;
    const Program &p = *m_program;
    const OperandRef &ref = p.refs[refOf(s.dest)];
    const auto v = static_cast<std::uint32_t>(m_words[m_scratch]);
    if (ref.kind == OperandRef::Kind::Bits) {
        for (int k = 0; k < ref.bits; ++k)
            put(bits, bitAt(*segmentOf(p, ref, m_destElement + k), m_destElement + k),
                ((v >> k) & 1u) != 0);
    } else if (ref.kind == OperandRef::Kind::DoubleWord) {
        storeWord(static_cast<std::size_t>(ref.word), v >> 16, 16);
        storeWord(static_cast<std::size_t>(ref.word) + 1, v, 16);
    }
}

} // namespace rung::simulator
