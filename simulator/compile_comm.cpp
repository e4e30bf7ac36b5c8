#include "compiler_detail.h"

#include "model/comm/port_config.h"

#include <variant>

// The instructions of the Vigor M/VB/VH communication manual's communication programs: the ones
// that build and read frames (SWAP, ASCI, HEX, SMOV, VRRD, DDIV) and the ones that drive a port
// (LINK, MBUS, RS, FROM / TO; PL110 SEND, COM / EXP). docs/simulator.md and docs/network.md say
// what each does.

namespace rung::simulator::detail {

BitRef Compiler::systemBit(model::SystemRole role) {
    const model::SystemDevice *d = m_target.systemDevice(role);
    if (!d)
        return {};
    const auto parsed = model::parseAddress(m_target, d->device);
    const auto *a = std::get_if<model::Address>(&parsed);
    return a ? m_layout->bit(*a) : BitRef{};
}

std::int32_t Compiler::systemWord(model::SystemRole role) {
    const model::SystemDevice *d = m_target.systemDevice(role);
    if (!d)
        return -1;
    const auto parsed = model::parseAddress(m_target, d->device);
    const auto *a = std::get_if<model::Address>(&parsed);
    return a ? m_layout->word(*a) : -1;
}

std::int32_t Compiler::wordsToAreaEnd(const model::Operand &o) const {
    if (!isDevice(o))
        return 0;
    return m_target.area(o.address.area).last - o.address.index + 1;
}

void Compiler::compileCommDevices() {
    using R = model::SystemRole;
    CommDevices &d = m_program->commDevices;
    d.cycleDone = systemBit(R::LinkCycleDone);
    d.sendRequest = systemBit(R::RsSendRequest);
    d.receiveDone = systemBit(R::RsReceiveDone);
    d.timeout = systemBit(R::RsTimeout);
    d.error = systemBit(R::CommError);
    d.byteMode = systemBit(R::ByteMode);
    d.errorCode = systemWord(R::CommErrorCode);
    d.sendLeft = systemWord(R::RsSendLeft);
    d.received = systemWord(R::RsReceived);
    d.timeoutWord = systemWord(R::CommTimeout);
}

void Compiler::compileText(const model::Instruction &ins, Step &s) {
    using model::ApplyFunction;
    const ApplyFunction f = ins.spec->function;
    auto constantOf = [&](std::size_t i) -> int {
        const model::Operand *o = operand(ins, i);
        if (!o)
            return 0;
        if (o->kind != model::Operand::Kind::Constant || o->modified()) {
            error(ins, CompilerTr::tr("%1 needs a constant as operand %2")
                           .arg(ins.spec->mnemonic)
                           .arg(i + 1));
            return 0;
        }
        return static_cast<int>(o->constant.value);
    };
    switch (f) {
    case ApplyFunction::Swap:
        s.code = Code::Swap;
        s.dest = destOf(ins, 0, false, &s.width);
        break;
    case ApplyFunction::ToAscii:
    case ApplyFunction::FromAscii: {
        const bool toAscii = f == ApplyFunction::ToAscii;
        s.code = toAscii ? Code::ToAscii : Code::FromAscii;
        s.x = sourceOf(ins, 0);
        s.dest = destOf(ins, 1, false, &s.width);
        s.count = constantOf(2);
        s.bit = systemBit(model::SystemRole::ByteMode);
        // The characters' block stays in its area: D's for ASCI, S's for HEX.
        const model::Operand *block = operand(ins, toAscii ? 1 : 0);
        s.y.constant = block && !resolvedAtRunTime(*block) ? wordsToAreaEnd(*block) : 1 << 20;
        break;
    }
    case ApplyFunction::ShiftDigits: {
        s.code = Code::ShiftDigits;
        s.x = sourceOf(ins, 0);
        const int m1 = constantOf(1);
        s.count = constantOf(2);
        s.dest = destOf(ins, 3, false, &s.width);
        s.slot = constantOf(4);
        s.op = static_cast<std::uint8_t>(std::clamp(m1, 0, 4));
        s.bit = systemBit(model::SystemRole::HexDigits);
        // The digits moved are m1 down to m1 - m2 + 1 of S and n down to n - m2 + 1 of D.
        if (!m_muted && (s.count > m1 || s.count > s.slot))
            error(ins, CompilerTr::tr(
                           "%1 moves %2 digits from digit %3 to digit %4: the digits would run "
                           "below digit 1")
                           .arg(ins.spec->mnemonic)
                           .arg(s.count)
                           .arg(m1)
                           .arg(s.slot));
        break;
    }
    case ApplyFunction::ReadVolume: {
        // VRRD K D: a move from the element K of the panel's area (OperandSpec::elementOf).
        s.code = Code::Move;
        const int k = constantOf(0);
        s.dest = destOf(ins, 1, false, &s.width);
        const char *areaKey =
            ins.spec->operands.empty() ? nullptr : ins.spec->operands[0].elementOf;
        for (int a = 0; areaKey && a < m_layout->areaCount(); ++a)
            if (m_target.area(a).key == QLatin1String(areaKey))
                s.x.index = m_layout->word(model::Address{a, k, -1});
        if (s.x.index < 0 && !m_muted)
            error(
                ins,
                CompilerTr::tr("%1 has no variable resistor %2").arg(m_target.displayName).arg(k));
        break;
    }
    default:
        break;
    }
}

// DDIV S1 S2 D: (S1+1, S1) / (S2+1, S2) into (D+1, D), the remainder into (D+3, D+2); a
// 32-bit constant or counter is one value.
void Compiler::compileDoubleDivide(const model::Instruction &ins, Step &s) {
    s.code = Code::DoubleDivide;
    s.slot = static_cast<int>(m_program->wordLists.size());
    auto pair = [&](std::size_t i, WordOperand *constant) {
        const model::Operand *o = operand(ins, i);
        std::int32_t low = -1;
        std::int32_t high = -1;
        if (o && o->kind == model::Operand::Kind::Constant && !o->modified()) {
            constant->constant =
                static_cast<std::int32_t>(model::wrapToWidth(o->constant.value, 32));
        } else if (o && (!isDevice(*o) || resolvedAtRunTime(*o))) {
            error(ins, CompilerTr::tr("%1 takes a register, a 32-bit counter or a constant, not %2")
                           .arg(ins.spec->mnemonic, describe(*o)));
        } else if (o) {
            low = m_layout->word(o->address);
            if (m_layout->wordBits(o->address) < 32)
                high = nextWord(ins, i);
        }
        m_program->wordLists.push_back(low);
        m_program->wordLists.push_back(high);
    };
    pair(0, &s.x);
    pair(1, &s.y);
    const model::Operand *d = operand(ins, 2);
    if (!d)
        return;
    if (!isDevice(*d) || resolvedAtRunTime(*d) || m_layout->wordBits(d->address) >= 32 ||
        !m_target.area(d->address.area).writable) {
        error(ins, CompilerTr::tr("%1 writes four registers from %2: give a data register")
                       .arg(ins.spec->mnemonic, describe(*d)));
        return;
    }
    for (int k = 0; k < 4; ++k) {
        const int w = m_layout->word(model::offsetAddress(m_target, d->address, k));
        if (w < 0)
            error(ins,
                  trCompiler(QT_TRANSLATE_NOOP("rung::simulator::Compiler",
                                               "%1 needs the next word too, which does not exist"))
                      .arg(describe(*d)));
        m_program->wordLists.push_back(w);
    }
    s.width = 16;
}

void Compiler::compileComm(const model::Instruction &ins, Step &s) {
    using model::ApplyFunction;
    CommStep c;
    c.port = model::instructionPort(ins);
    c.spec = ins.spec;
    // LINK and MBUS "can be used once only in the program" (B-3-3, B-3-6; check's DC002).
    if (ins.spec->oncePerProgram)
        for (const CommStep &other : m_program->comms)
            if (other.spec == ins.spec) {
                error(ins, CompilerTr::tr("%1 is programmed twice; the PLC allows it once only in "
                                          "a program")
                               .arg(ins.spec->mnemonic));
                return;
            }
    c.step = static_cast<std::int32_t>(&s - m_program->steps.data());
    const bool module = ins.spec->function == ApplyFunction::ModuleRead ||
                        ins.spec->function == ApplyFunction::ModuleWrite;
    // The tables, buffers and counts are plain registers: an index register would move a
    // table the PLC reads in the background, which no example does. FROM / TO alone take a
    // digit group, and TO a constant, for one word (TO K1 K1 K1M20 K1, TOP K1 K0 H7096 K1:
    // the VB-1COM programs of B-4-5).
    for (std::size_t i = 0; i < ins.operands.size(); ++i)
        if (resolvedAtRunTime(ins.operands[i]) && !(module && i == 2)) {
            error(ins, CompilerTr::tr("%1 takes plain registers, not %2")
                           .arg(ins.spec->mnemonic, describe(ins.operands[i])));
            return;
        }
    auto word = [&](std::size_t i, std::int32_t *index, std::int32_t *words) {
        const model::Operand *o = operand(ins, i);
        if (!o)
            return;
        *index = isDevice(*o) ? m_layout->word(o->address) : -1;
        *words = wordsToAreaEnd(*o);
        if (*index < 0)
            error(ins, CompilerTr::tr("%1 is not a word device").arg(describe(*o)));
    };
    switch (ins.spec->function) {
    case ApplyFunction::EasyLink:
    case ApplyFunction::ModbusMaster:
        c.kind = ins.spec->function == ApplyFunction::EasyLink ? CommKind::EasyLink
                                                               : CommKind::ModbusMaster;
        word(0, &c.first, &c.firstWords);
        word(1, &c.second, &c.secondWords);
        break;
    case ApplyFunction::SerialData:
        c.kind = CommKind::SerialData;
        word(0, &c.first, &c.firstWords);
        c.m = sourceOf(ins, 1);
        word(2, &c.second, &c.secondWords);
        c.n = sourceOf(ins, 3);
        break;
    case ApplyFunction::ModuleRead:
    case ApplyFunction::ModuleWrite: {
        c.kind = ins.spec->function == ApplyFunction::ModuleRead ? CommKind::ModuleRead
                                                                 : CommKind::ModuleWrite;
        const model::Operand *m1 = operand(ins, 0);
        c.module = m1 && m1->kind == model::Operand::Kind::Constant
                       ? static_cast<std::int32_t>(m1->constant.value)
                       : 0;
        c.m = sourceOf(ins, 1);
        c.n = sourceOf(ins, 3);
        const model::Operand *data = operand(ins, 2);
        const bool constant =
            data && data->kind == model::Operand::Kind::Constant && c.kind == CommKind::ModuleWrite;
        if (data && (resolvedAtRunTime(*data) || constant)) {
            // One word through the step: a constant (TOP K1 K0 H7096 K1), or a group the
            // engine resolves each time (K2M30).
            const model::Operand *n = operand(ins, 3);
            if (!n || n->kind != model::Operand::Kind::Constant || n->constant.value != 1) {
                error(ins, CompilerTr::tr("%1 moves one word with %2: n must be K1")
                               .arg(ins.spec->mnemonic, describe(*data)));
                return;
            }
            if (c.kind == CommKind::ModuleRead)
                s.dest = destOf(ins, 2, false, &s.width);
            else
                s.x = sourceOf(ins, 2);
            c.firstWords = 1;
        } else {
            word(2, &c.first, &c.firstWords);
        }
        break;
    }
    case ApplyFunction::FreePortSend:
        c.kind = CommKind::FreePortSend;
        c.n = sourceOf(ins, 1);
        c.portIndex = portIndex(c.port);
        break;
    case ApplyFunction::MasterQuery:
        c.kind = CommKind::MasterQuery;
        c.portIndex = portIndex(c.port);
        if (!compileQuery(ins, &c))
            return;
        break;
    default:
        return;
    }
    s.code = Code::Communicate;
    s.op = static_cast<std::uint8_t>(c.kind);
    // Not `slot`: TOP is differentiated, and its edge memory is the step's slot.
    s.count = static_cast<std::int32_t>(m_program->comms.size());
    m_program->comms.push_back(std::move(c));
}

// The markers and buffers of the target's ports (model::PortMarkers) and their power-on
// values: SM73 20 ms, SM74 5 ms, SM75 10 (PL110 manual 2.1.2); the counters, free-port and
// the receive count 0.
void Compiler::compilePorts() {
    auto word = [&](const char *device) -> std::int32_t {
        if (!device)
            return -1;
        const auto parsed = model::parseAddress(m_target, QString::fromLatin1(device));
        const auto *a = std::get_if<model::Address>(&parsed);
        return a ? m_layout->word(*a) : -1;
    };
    auto area = [&](const char *device, std::int32_t *first, std::int32_t *size) {
        *first = word(device);
        if (!device || *first < 0)
            return;
        const auto parsed = model::parseAddress(m_target, QString::fromLatin1(device));
        const model::Address &a = std::get<model::Address>(parsed);
        *size = m_target.area(a.area).last - a.index + 1;
    };
    for (const model::PortSpec &spec : m_target.ports) {
        const model::PortMarkers &m = spec.markers;
        if (!m.freePort && !m.status)
            continue;
        PortDevices d;
        d.port = spec.name;
        d.markers = &m;
        d.status = word(m.status);
        d.replyTimeout = word(m.replyTimeout);
        d.requestGap = word(m.requestGap);
        d.errorLimit = word(m.errorLimit);
        d.timeouts = word(m.timeouts);
        d.errors = word(m.errors);
        d.freePort = word(m.freePort);
        d.received = word(m.received);
        if (m.sending) {
            const auto parsed = model::parseAddress(m_target, QString::fromLatin1(m.sending));
            if (const auto *a = std::get_if<model::Address>(&parsed))
                d.sending = m_layout->bit(*a);
        }
        area(m.transmit, &d.transmit, &d.transmitSize);
        area(m.receive, &d.receive, &d.receiveSize);
        const std::pair<std::int32_t, std::int32_t> loads[] = {{d.replyTimeout, m.replyTimeoutMs},
                                                               {d.requestGap, m.requestGapMs},
                                                               {d.errorLimit, m.errorLimitCount},
                                                               {d.timeouts, 0},
                                                               {d.errors, 0},
                                                               {d.freePort, 0},
                                                               {d.received, 0}};
        for (const auto &[w, v] : loads)
            if (w >= 0)
                m_program->presetLoads.emplace_back(w, v);
        m_program->ports.push_back(std::move(d));
    }
}

std::int32_t Compiler::portIndex(const QString &port) const {
    for (std::size_t k = 0; k < m_program->ports.size(); ++k)
        if (m_program->ports[k].port.compare(port, Qt::CaseInsensitive) == 0)
            return static_cast<std::int32_t>(k);
    return -1;
}

// COM / EXP index operation slave type number area count (PL110 manual 4.2.21). The table's
// rules (ranges, the words READ / WRITE / READWRITE and WORD / BIT) are check's OP005; here the
// area: every word or bit of it there, and writable when the query reads into it.
bool Compiler::compileQuery(const model::Instruction &ins, CommStep *c) {
    auto constant = [&](std::size_t i) -> std::int32_t {
        const model::Operand *o = operand(ins, i);
        return o && o->kind == model::Operand::Kind::Constant
                   ? static_cast<std::int32_t>(o->constant.value)
                   : 0;
    };
    auto text = [&](std::size_t i) {
        const model::Operand *o = operand(ins, i);
        return o ? o->text.trimmed().toUpper() : QString();
    };
    c->index = constant(0);
    const QString operation = text(1);
    c->operation = operation == QLatin1String("WRITE")       ? 1
                   : operation == QLatin1String("READWRITE") ? 2
                                                             : 0;
    c->slave = constant(2);
    c->bitData = text(3) == QLatin1String("BIT");
    c->number = constant(4);
    c->count = constant(6);
    if (m_failed || m_muted)
        return false;
    // "si possono impostare al massimo 16 interrogazioni seriali diverse": COM_1..COM_16, one
    // query each; the index names the query's status bit.
    for (const CommStep &other : m_program->comms)
        if (other.kind == CommKind::MasterQuery && other.portIndex == c->portIndex &&
            other.index == c->index) {
            error(ins, CompilerTr::tr("%1_%2 is programmed twice; each index is one query of "
                                      "the port")
                           .arg(ins.spec->mnemonic)
                           .arg(c->index));
            return false;
        }
    const model::Operand *o = operand(ins, 5);
    if (!o || !isDevice(*o))
        return false;
    const model::Area &area = m_target.area(o->address.area);
    if (c->operation != 1 && !area.writable) {
        error(ins, CompilerTr::tr("%1 reads into %2, which the program cannot write")
                       .arg(ins.spec->mnemonic, describe(*o)));
        return false;
    }
    for (std::int32_t k = 0; k < c->count; ++k) {
        if (c->bitData) {
            // Bits from the word's bit 0 on, 16 to a word: V10 holds the bits V10.0..V10.15,
            // M1 (16 markers read as a word) M1..M16.
            model::Address a = o->address;
            if (area.kind == model::AreaKind::Bit) {
                a.index += k;
            } else {
                a.index += k / 16;
                a.bit = k % 16;
            }
            const BitRef b = m_layout->bit(a);
            if (!b.valid()) {
                error(ins, CompilerTr::tr("%1 needs %2 bits from %3, past the end of its area")
                               .arg(ins.spec->mnemonic)
                               .arg(c->count)
                               .arg(describe(*o)));
                return false;
            }
            c->bits.push_back(b);
        } else {
            // A bit area read as words (Area::bitsAsWords): M1, M17, ...
            model::Address a = o->address;
            if (area.kind == model::AreaKind::Bit)
                a.index += 16 * k;
            else
                a = model::offsetAddress(m_target, a, k);
            const std::int32_t w = m_layout->word(a);
            if (w < 0) {
                error(ins, CompilerTr::tr("%1 needs %2 words from %3, past the end of its area")
                               .arg(ins.spec->mnemonic)
                               .arg(c->count)
                               .arg(describe(*o)));
                return false;
            }
            c->words.push_back(w);
        }
    }
    return true;
}

} // namespace rung::simulator::detail
