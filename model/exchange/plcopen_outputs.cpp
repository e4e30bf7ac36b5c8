#include "model/exchange/plcopen_import.h"
#include "model/tr.h"

#include "model/convert/convert.h"
#include "model/target/address.h"

#include <QCoreApplication>

#include <cmath>

// The outputs of an LD body as the target's instructions (docs/plcopen.md "Import"): coils,
// TON / TOF as the target's timers, MOVE, Rung Studio's own blocks; which elements are outputs.
// Counters are in plcopen_import_counters.cpp, the power that feeds them in plcopen_power.cpp.

namespace rung::model::plcopen {

std::optional<Instruction> Importer::parseInstruction(const QString &text, const Element &e) {
    const ParseResult parsed = parseInstructionList(m_t, text, m_model);
    if (!parsed.ok() || parsed.list.instructions.size() != 1) {
        issue(e.line, describe(e),
              QStringLiteral("\"%1\": %2")
                  .arg(text, parsed.errors.empty() ? PlcopenTr::tr("one instruction is expected")
                                                   : parsed.errors.front().message));
        return std::nullopt;
    }
    Instruction ins = parsed.list.instructions.front();
    ins.line = ins.column = ins.step = 0;
    return ins;
}

// The instruction with these operands, checked as the target's listing reads it.
std::optional<Instruction> Importer::build(const InstructionSpec *spec,
                                           std::vector<Operand> operands, const Element &e) {
    Instruction ins;
    ins.spec = spec;
    ins.operands = std::move(operands);
    return parseInstruction(printInstruction(m_t, ins), e);
}

std::optional<Output> Importer::coilOutput(const Element &e) {
    Output out;
    out.element = &e;
    if (!e.instruction.isEmpty()) {
        auto ins = parseInstruction(e.instruction, e);
        if (!ins)
            return std::nullopt;
        out.instruction = *ins;
    } else {
        auto c = contactOfVariable(e.variable, e.line);
        if (!c)
            return std::nullopt;
        const Op op = e.storage == QLatin1String("set")     ? Op::Set
                      : e.storage == QLatin1String("reset") ? Op::Reset
                      : e.edge == QLatin1String("rising")   ? Op::PulseRise
                      : e.edge == QLatin1String("falling")  ? Op::PulseFall
                                                            : Op::Out;
        if (e.negated && op != Op::Out) {
            issue(e.line, describe(e),
                  PlcopenTr::tr("a negated coil that also sets, resets or pulses is not imported"));
            return std::nullopt;
        }
        const InstructionSpec *spec =
            m_t.findInstruction(op, ContactMode::Normal, CompareOp::None, e.negated);
        if (!spec) {
            issue(e.line, describe(e), PlcopenTr::tr("%1 has no such coil").arg(m_t.displayName));
            return std::nullopt;
        }
        auto ins = build(spec, c->operands, e);
        if (!ins)
            return std::nullopt;
        out.instruction = *ins;
    }
    auto chain = chainIn(e.inputs.empty() ? nullptr : &e.inputs.front(), e);
    if (!chain)
        return std::nullopt;
    out.chain = *chain;
    return out;
}

// An IEC timer (TON, TOF) as the target's timer of that kind: its instance a timer device,
// PT in the timer's units.
std::optional<Output> Importer::timerOutput(const Element &e) {
    if (!enAlwaysOn(e))
        return std::nullopt;
    const Pin *pt = pin(e, "PT");
    const auto ptText = pt ? pinExpression(*pt, e.line) : std::nullopt;
    const auto ms = ptText ? timeLiteral(*ptText) : std::nullopt;
    if (!ms) {
        issue(e.line, describe(e),
              PlcopenTr::tr("PT must be a time literal (T#1s) to be a set value: not imported"));
        return std::nullopt;
    }
    const auto device = resolve(e.instanceName, e.line, e.typeName);
    if (!device)
        return std::nullopt;
    const TimerMode mode = e.typeName.compare(QLatin1String("TOF"), Qt::CaseInsensitive) == 0
                               ? TimerMode::OffDelay
                               : TimerMode::OnDelay;
    if (e.typeName.compare(QLatin1String("TP"), Qt::CaseInsensitive) == 0) {
        issue(e.line, describe(e),
              PlcopenTr::tr("%1 has no pulse timer (TP)").arg(m_t.displayName));
        return std::nullopt;
    }
    for (const InstructionSpec &spec : m_t.instructions) {
        if (spec.op != Op::Timer || spec.timerMode != mode || spec.differentiated ||
            spec.doubleWord)
            continue;
        Output out;
        out.element = &e;
        if (auto ins = timerInstruction(spec, *device, *ms, &out.setValue)) {
            out.instruction = *ins;
            auto chain = chainIn(pin(e, "IN"), e);
            if (!chain)
                return std::nullopt;
            out.chain = *chain;
            return out;
        }
    }
    issue(e.line, describe(e),
          PlcopenTr::tr("%1 has no %2 timer that times %3 ms on %4")
              .arg(m_t.displayName, e.typeName)
              .arg(*ms)
              .arg(formatAddress(m_t, *device)));
    return std::nullopt;
}

std::variant<Constant, AddressError> Importer::setValueConstant(qint64 value) const {
    const QString text = m_t.constants.prefixed ? QStringLiteral("K%1").arg(value)
                         : m_t.constants.bcdSetValues
                             ? QStringLiteral("#%1").arg(value, 4, 10, QLatin1Char('0'))
                             : QString::number(value);
    auto c = parseConstant(m_t, text);
    if (auto *k = std::get_if<Constant>(&c);
        k && k->style == Constant::Style::Plain && m_t.constants.prefixed)
        k->style = Constant::Style::Decimal;
    return c;
}

std::optional<Instruction> Importer::timerInstruction(const InstructionSpec &spec,
                                                      const Address &timer, qint64 ms,
                                                      std::optional<qint64> *kept) {
    // The slots: the timer, a set value, a time base chosen among its allowed values.
    std::vector<std::vector<int>> bases{{}};
    for (std::size_t k = 0; k < spec.operands.size(); ++k)
        if (spec.operands[k].kind == OperandKind::Constant &&
            !spec.operands[k].allowedValues.empty()) {
            std::vector<int> values = spec.operands[k].allowedValues;
            std::sort(values.rbegin(), values.rend());
            bases = {values};
        }
    for (const int base : bases.front().empty() ? std::vector<int>{0} : bases.front()) {
        Instruction ins;
        ins.spec = &spec;
        bool ok = true;
        int setSlot = -1;
        for (std::size_t k = 0; k < spec.operands.size() && ok; ++k) {
            const OperandSpec &s = spec.operands[k];
            Operand o;
            if (s.kind == OperandKind::TimerNumber) {
                o.address = timer;
            } else if (s.kind == OperandKind::SetValue) {
                setSlot = static_cast<int>(k);
                o.kind = Operand::Kind::Constant;
            } else if (s.kind == OperandKind::Constant && !s.allowedValues.empty()) {
                o.kind = Operand::Kind::Constant;
                o.constant.value = base;
            } else if (!s.optional) {
                ok = false;
            } else {
                continue;
            }
            ins.operands.push_back(o);
        }
        if (!ok || ins.operands.empty())
            continue;
        const double step = timerBaseMs(m_t, ins);
        if (step <= 0 || std::fmod(static_cast<double>(ms), step) != 0)
            continue;
        const auto units = static_cast<qint64>(static_cast<double>(ms) / step);
        if (setSlot >= 0) {
            Operand &o = ins.operands[static_cast<std::size_t>(setSlot)];
            const auto c = setValueConstant(units);
            if (!std::holds_alternative<Constant>(c))
                continue;
            o.constant = std::get<Constant>(c);
        } else {
            *kept = units; // kept in the PLC (VPC TIM00): a set value of the project
        }
        for (Operand &o : ins.operands)
            if (o.kind == Operand::Kind::Constant && o.constant.style == Constant::Style::Plain &&
                m_t.constants.prefixed)
                o.constant.style = Constant::Style::Decimal;
        const ParseResult parsed = parseInstructionList(m_t, printInstruction(m_t, ins), m_model);
        if (!parsed.ok() || parsed.list.instructions.size() != 1)
            continue;
        Instruction done = parsed.list.instructions.front();
        done.line = done.column = done.step = 0;
        return done;
    }
    return std::nullopt;
}

std::optional<Instruction> Importer::copyInstruction(const Operand &source, const Operand &dest,
                                                     bool fromBcd, const Element &e) {
    // The target's move (MOV, MOV(21)), its BCD-to-binary one (BIN(23)), or the VPC's transfer
    // OUT d,s (VPC user's manual, III), which writes while its condition is ON.
    const ApplyFunction function = fromBcd ? ApplyFunction::FromBcd : ApplyFunction::Mov;
    for (const InstructionSpec &x : m_t.instructions) {
        if (x.differentiated || x.doubleWord || x.operands.size() != 2)
            continue;
        if (x.op == Op::Apply && x.function == function)
            return build(&x, {source, dest}, e);
        if (!fromBcd && x.op == Op::Transfer && x.transfer == TransferOp::Assign && !x.negated)
            return build(&x, {dest, source}, e);
    }
    issue(
        e.line, describe(e),
        fromBcd
            ? PlcopenTr::tr("%1 has no instruction to make a BCD value binary").arg(m_t.displayName)
            : PlcopenTr::tr("%1 has no move instruction").arg(m_t.displayName));
    return std::nullopt;
}

std::optional<Output> Importer::moveOutput(const Element &e) {
    const Pin *in = pin(e, "IN");
    const auto source = in ? pinExpression(*in, e.line) : std::nullopt;
    if (!source)
        return std::nullopt;
    // OUT goes to an output variable: the destination.
    const Element *dest = nullptr;
    for (const Element &o : m_elements)
        if (o.kind == QLatin1String("outVariable") && !o.inputs.empty())
            for (const Connection &c : o.inputs.front().connections)
                if (c.ref == e.id)
                    dest = &o;
    if (!dest) {
        issue(e.line, describe(e), PlcopenTr::tr("MOVE's OUT goes to no variable: not imported"));
        return std::nullopt;
    }
    m_used.insert(dest->id);
    const auto s = operandOf(*source, e.line);
    const auto d = operandOf(dest->variable, dest->line);
    if (!s || !d)
        return std::nullopt;
    Output out;
    out.element = &e;
    auto ins = copyInstruction(*s, *d, false, e);
    if (!ins)
        return std::nullopt;
    out.instruction = *ins;
    const Pin *en = pin(e, "EN");
    if (en && !en->connections.empty()) {
        auto chain = chainIn(en, e);
        if (!chain)
            return std::nullopt;
        out.chain = *chain;
    } else {
        out.chain = railChain();
    }
    return out;
}

// A block of Rung Studio's own file: its instruction; its power inputs EN (IN for a timer, a
// counter's CU, CD, R, LD as plcopen_counters.h writes them) or IN1..INk; its operands are the
// instruction's. A connector of the file is an RST of a counter: its power the connector's.
std::optional<Output> Importer::ownBlockOutput(const Element &e) {
    auto ins = parseInstruction(e.instruction, e);
    if (!ins)
        return std::nullopt;
    std::vector<const Pin *> power;
    if (e.kind == QLatin1String("connector")) {
        if (!e.inputs.empty())
            power.push_back(&e.inputs.front());
    } else if (const auto form = isCounterType(e.typeName) && !ins->operands.empty()
                                     ? counterForm(m_t, *ins->spec, ins->operands.front().address)
                                     : std::nullopt) {
        for (const QString &formal : form->pins)
            power.push_back(pin(e, formal.toLatin1().constData()));
    } else if (const Pin *en = pin(e, "EN")) {
        power.push_back(en);
    } else if (pin(e, "IN") && !pin(e, "IN1")) {
        power.push_back(pin(e, "IN"));
    } else {
        for (int i = 1; i <= std::max(1, ins->spec->inputs); ++i)
            if (const Pin *p = pin(e, QStringLiteral("IN%1").arg(i).toLatin1().constData()))
                power.push_back(p);
    }
    // The operands' variables, a counter's PV, FALSE and R's continuations go with the block.
    for (const Pin &p : e.inputs)
        if (std::find(power.begin(), power.end(), &p) == power.end())
            for (const Connection &c : p.connections)
                m_used.insert(c.ref);
    for (const Element &o : m_elements)
        if (o.kind == QLatin1String("outVariable") && !o.inputs.empty())
            for (const Connection &c : o.inputs.front().connections)
                if (c.ref == e.id)
                    m_used.insert(o.id);
    Output out;
    out.element = &e;
    out.instruction = *ins;
    if (isUnconditional(ins->op()))
        return out;
    if (power.size() <= 1) {
        auto chain = chainIn(power.empty() ? nullptr : power.front(), e);
        if (!chain)
            return std::nullopt;
        out.chain = *chain;
        return out;
    }
    out.multi = true;
    for (const Pin *p : power) {
        if (!p)
            break;
        auto chain = chainIn(p, e);
        if (!chain)
            return std::nullopt;
        out.inputs.push_back(*chain);
    }
    return out;
}

std::optional<Output> Importer::outputOf(const Element &e) {
    if (e.kind == QLatin1String("coil"))
        return coilOutput(e);
    if (e.kind == QLatin1String("outVariable"))
        return valueOutput(e);
    if (!e.instruction.isEmpty())
        return ownBlockOutput(e);
    if (e.kind != QLatin1String("block"))
        return std::nullopt;
    if (isTimerType(e.typeName))
        return timerOutput(e);
    if (e.typeName.compare(QLatin1String("MOVE"), Qt::CaseInsensitive) == 0)
        return moveOutput(e);
    return std::nullopt;
}

bool Importer::consumesPower(const Element &e) const {
    if (e.kind == QLatin1String("coil"))
        return true;
    if (e.kind == QLatin1String("connector"))
        return !e.instruction.isEmpty(); // Rung Studio's RST of a counter
    if (e.kind == QLatin1String("outVariable")) {
        // A timer's or counter's value to a variable (a MOVE's OUT goes with the MOVE).
        QString formal;
        const Element *source = valueSource(e, &formal);
        return source && e.instruction.isEmpty() && source->instruction.isEmpty() &&
               isInstanceBlock(*source);
    }
    if (e.kind != QLatin1String("block") || !e.contact.isEmpty() || compareOf(e.typeName))
        return false;
    if (!e.instruction.isEmpty())
        return true;
    return isInstanceBlock(e) ||
           e.typeName.compare(QLatin1String("MOVE"), Qt::CaseInsensitive) == 0;
}

bool Importer::isInstanceBlock(const Element &e) {
    return e.kind == QLatin1String("block") &&
           (isTimerType(e.typeName) || isCounterType(e.typeName));
}

const Element *Importer::valueSource(const Element &e, QString *formal) const {
    if (e.inputs.empty() || e.inputs.front().connections.size() != 1)
        return nullptr;
    const Connection &c = e.inputs.front().connections.front();
    const Element *source = element(c.ref);
    if (!source || source->kind != QLatin1String("block"))
        return nullptr;
    *formal = c.formal;
    return source;
}

} // namespace rung::model::plcopen
