#include "model/exchange/plcopen_import.h"
#include "model/tr.h"

#include "model/convert/convert.h"
#include "model/target/address.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include "model/ladder/ladder_text.h"
#include <cmath>

// The power flow of an LD body as chains (an element's input: the factors from the rail to it),
// and the outputs they feed as the target's instructions (docs/plcopen.md "Import").

namespace rung::model::plcopen {

Factor Importer::leaf(const Element &e, const Contact &c) const {
    return {QStringLiteral("e%1").arg(e.id), Expr::leafOf(c)};
}

std::optional<Contact> Importer::contactOfVariable(const QString &variable, int line) {
    QString name = variable.trimmed();
    Contact c;
    // A timer's or counter's output Q (QU, QD: a CTUD's) as a contact: its done bit.
    const qsizetype dot = name.lastIndexOf(QLatin1Char('.'));
    const auto instance = [this](const QString &n) {
        if (const auto v = m_vars.constFind(n);
            v != m_vars.constEnd() && (isTimerType(v->type) || isCounterType(v->type)))
            return true;
        return std::any_of(m_elements.begin(), m_elements.end(),
                           [&n](const Element &b) { return b.instanceName == n; });
    };
    if (dot > 0 && instance(name.left(dot))) {
        const QString member = name.mid(dot + 1).toUpper();
        name.truncate(dot);
        if (member != QLatin1String("Q") && member != QLatin1String("QU") &&
            member != QLatin1String("QD")) {
            issue(line, variable,
                  PlcopenTr::tr("%1 as a contact is not imported: only a timer's or counter's "
                                "bit (Q) is")
                      .arg(variable));
            return std::nullopt;
        }
        if (const ImportedCounter *counter = importedCounter(name);
            counter && member != QLatin1String("Q") && member != counter->choice.form.done) {
            issue(line, variable,
                  PlcopenTr::tr("%1 is not imported: the bit of %2 %3 is %4")
                      .arg(variable, counter->choice.spec->mnemonic,
                           formatAddress(m_t, counter->device), counter->choice.form.done));
            return std::nullopt;
        }
    }
    const auto a = resolve(name, line, QStringLiteral("BOOL"));
    if (!a)
        return std::nullopt;
    Operand o;
    o.address = *a;
    c.operands.push_back(o);
    return c;
}

std::optional<Chain> Importer::chainIn(const Pin *p, const Element &owner) {
    if (!p || p->connections.empty()) {
        issue(owner.line, describe(owner),
              PlcopenTr::tr("its input is connected to nothing: not imported"));
        return std::nullopt;
    }
    if (p->negated) {
        issue(owner.line, describe(owner),
              PlcopenTr::tr("its input %1 is negated: not imported").arg(p->formal));
        return std::nullopt;
    }
    // A counter counts rising edges of CU and CD anyway; any other input on an edge is an edge
    // detection the box does not have.
    const bool countInput = isCounterType(owner.typeName) &&
                            (p->formal.compare(QLatin1String("CU"), Qt::CaseInsensitive) == 0 ||
                             p->formal.compare(QLatin1String("CD"), Qt::CaseInsensitive) == 0);
    if (!p->edge.isEmpty() && !(countInput && p->edge == QLatin1String("rising"))) {
        issue(owner.line, describe(owner),
              PlcopenTr::tr("its input %1 on a %2 edge is not imported").arg(p->formal, p->edge));
        return std::nullopt;
    }
    std::vector<Chain> chains;
    // Branches that meet, from top to bottom as drawn (the file's order where level).
    std::vector<Connection> connections = p->connections;
    const auto height = [this](const Connection &c) {
        const Element *e = element(c.ref);
        return !e ? 1e300 : e->kind == QLatin1String("leftPowerRail") ? -1e300 : e->y;
    };
    std::stable_sort(
        connections.begin(), connections.end(),
        [&](const Connection &a, const Connection &b) { return height(a) < height(b); });
    for (const Connection &c : connections) {
        auto chain = chainOf(c.ref, c.formal, owner);
        if (!chain)
            return std::nullopt;
        chains.push_back(std::move(*chain));
    }
    if (chains.size() == 1)
        return chains.front();
    // Chains that meet: their common start, then the OR of the rest, grouped again by
    // what each group shares (a branch point inside the OR stays one).
    Chain prefix;
    for (std::size_t k = 0;; ++k) {
        bool same = true;
        for (const Chain &ch : chains)
            if (k >= ch.size() || ch[k].key != chains.front()[k].key)
                same = false;
        if (!same)
            break;
        prefix.push_back(chains.front()[k]);
    }
    std::vector<const Chain *> all;
    for (const Chain &ch : chains)
        all.push_back(&ch);
    const Grouped rest = groupChains(all, prefix.size());
    if (rest.always)
        return prefix; // one way through needs nothing more: the OR holds
    prefix.push_back({rest.key, rest.expr});
    return prefix;
}

// The OR of chains that share their first k factors: grouped by factor k in the order the
// groups first appear, each group its factor and the OR of what follows it.
Importer::Grouped Importer::groupChains(const std::vector<const Chain *> &chains, std::size_t k) {
    Grouped out;
    std::vector<std::pair<QString, std::vector<const Chain *>>> groups;
    for (const Chain *ch : chains) {
        if (ch->size() == k) {
            out.always = true;
            return out;
        }
        const QString &key = (*ch)[k].key;
        auto it = std::find_if(groups.begin(), groups.end(),
                               [&key](const auto &g) { return g.first == key; });
        if (it == groups.end()) {
            groups.push_back({key, {}});
            it = groups.end() - 1;
        }
        it->second.push_back(ch);
    }
    QStringList keys;
    for (const auto &[key, members] : groups) {
        const Factor &f = (*members.front())[k];
        const Grouped tail = groupChains(members, k + 1);
        Expr item = tail.always ? f.expr : detail::series(f.expr, tail.expr);
        if (item.empty()) {
            out.always = true; // a branch from a rail alone
            return out;
        }
        out.expr = detail::parallel(std::move(out.expr), std::move(item));
        keys << (tail.always ? key : key + QLatin1Char(',') + tail.key);
    }
    out.key =
        groups.size() == 1 ? keys.front() : QStringLiteral("(%1)").arg(keys.join(QLatin1Char('|')));
    return out;
}

std::optional<Chain> Importer::chainOf(int id, const QString &formal, const Element &from) {
    const Element *e = element(id);
    if (!e) {
        issue(from.line, describe(from),
              PlcopenTr::tr("it is connected to element %1, which the file does not have").arg(id));
        return std::nullopt;
    }
    const QString key = QStringLiteral("%1/%2").arg(id).arg(formal);
    if (const auto it = m_chains.find(key); it != m_chains.end())
        return it->second;
    if (!m_visiting.insert(key).second) {
        issue(e->line, describe(*e), PlcopenTr::tr("the power flow runs in a loop: not imported"));
        return std::nullopt;
    }
    auto chain = computeChain(*e, formal);
    m_visiting.erase(key);
    // A timer or counter whose Q is read is imported when its own output is, not here.
    if (chain && !consumesPower(*e))
        m_used.insert(e->id);
    m_chains[key] = chain;
    return chain;
}

std::optional<Chain> Importer::computeChain(const Element &e, const QString &formal) {
    if (e.kind == QLatin1String("leftPowerRail"))
        return Chain{{QStringLiteral("rail%1").arg(e.id), Expr()}};
    if (e.kind == QLatin1String("coil"))
        return chainIn(e.inputs.empty() ? nullptr : &e.inputs.front(), e);
    if (e.kind == QLatin1String("contact")) {
        auto in = chainIn(e.inputs.empty() ? nullptr : &e.inputs.front(), e);
        if (!in)
            return std::nullopt;
        auto c = contactOfVariable(e.variable, e.line);
        if (!c)
            return std::nullopt;
        if (e.negated && !e.edge.isEmpty() && e.edge != QLatin1String("none")) {
            issue(e.line, describe(e),
                  PlcopenTr::tr("a contact both negated and on an edge is not imported"));
            return std::nullopt;
        }
        c->mode = e.negated                            ? ContactMode::Negated
                  : e.edge == QLatin1String("rising")  ? ContactMode::Rising
                  : e.edge == QLatin1String("falling") ? ContactMode::Falling
                                                       : ContactMode::Normal;
        if (!m_t.findInstruction(Op::And, c->mode)) {
            issue(e.line, describe(e),
                  PlcopenTr::tr("%1 has no such contact").arg(m_t.displayName));
            return std::nullopt;
        }
        in->push_back(leaf(e, *c));
        return in;
    }
    if (e.kind == QLatin1String("inVariable")) // a BOOL variable as power
        if (auto c = contactOfVariable(e.variable, e.line))
            return Chain{leaf(e, *c)};
    if (e.kind == QLatin1String("continuation")) {
        for (const Element &c : m_elements)
            if (c.kind == QLatin1String("connector") && c.name == e.name) {
                m_used.insert(c.id);
                return chainIn(c.inputs.empty() ? nullptr : &c.inputs.front(), c);
            }
        issue(e.line, describe(e), PlcopenTr::tr("no connector is named %1").arg(e.name));
        return std::nullopt;
    }
    if (e.kind == QLatin1String("block"))
        return blockChain(e, formal);
    issue(e.line, describe(e),
          PlcopenTr::tr("a %1 carries no power flow %2 can take").arg(e.kind, m_t.displayName));
    return std::nullopt;
}

// A block's output as power: a comparison, NOT, an edge (R_TRIG / F_TRIG), a timer's or a
// counter's Q (its done bit), ENO (the power at EN).
std::optional<Chain> Importer::blockChain(const Element &e, const QString &formal) {
    const QString out = formal.isEmpty() ? QString() : formal.toUpper();
    if (out == QLatin1String("ENO"))
        return chainIn(pin(e, "EN"), e);
    if (!e.contact.isEmpty()) {
        QString why;
        const auto c = contactFromText(m_t, e.contact, &why, m_model);
        if (!c) {
            issue(e.line, describe(e), why);
            return std::nullopt;
        }
        const Pin *in = e.inputs.empty() ? nullptr : &e.inputs.front();
        auto chain = chainIn(in, e);
        if (!chain)
            return std::nullopt;
        for (const Pin &p : e.inputs)
            for (const Connection &conn : p.connections)
                if (const Element *src = element(conn.ref);
                    src && src->kind == QLatin1String("inVariable"))
                    m_used.insert(src->id);
        chain->push_back(leaf(e, *c));
        return chain;
    }
    if (const auto op = compareOf(e.typeName)) {
        const Pin *a = pin(e, "IN1");
        const Pin *b = pin(e, "IN2");
        if (!a || !b) {
            issue(e.line, describe(e), PlcopenTr::tr("a comparison needs IN1 and IN2"));
            return std::nullopt;
        }
        const auto x = pinExpression(*a, e.line);
        const auto y = pinExpression(*b, e.line);
        if (!x || !y)
            return std::nullopt;
        const auto ox = operandOf(*x, e.line);
        const auto oy = operandOf(*y, e.line);
        if (!ox || !oy)
            return std::nullopt;
        Contact c;
        c.compare = *op;
        c.operands = {*ox, *oy};
        if (!m_t.findInstruction(Op::And, ContactMode::Normal, *op)) {
            issue(e.line, describe(e),
                  PlcopenTr::tr("%1 has no compare contact %2")
                      .arg(m_t.displayName, QLatin1String(compareSymbol(*op))));
            return std::nullopt;
        }
        Chain chain;
        if (const Pin *en = pin(e, "EN"); en && !en->connections.empty()) {
            auto in = chainIn(en, e);
            if (!in)
                return std::nullopt;
            chain = *in;
        } else {
            chain = railChain();
        }
        chain.push_back(leaf(e, c));
        return chain;
    }
    if (e.typeName.compare(QLatin1String("NOT"), Qt::CaseInsensitive) == 0 ||
        e.typeName.compare(QLatin1String("R_TRIG"), Qt::CaseInsensitive) == 0 ||
        e.typeName.compare(QLatin1String("F_TRIG"), Qt::CaseInsensitive) == 0) {
        const bool edge = !e.typeName.startsWith(QLatin1String("N"), Qt::CaseInsensitive);
        Contact c;
        c.invert = true;
        c.mode = !edge ? ContactMode::Normal
                 : e.typeName.startsWith(QLatin1String("R"), Qt::CaseInsensitive)
                     ? ContactMode::Rising
                     : ContactMode::Falling;
        if (!m_t.findInstruction(Op::Invert, c.mode)) {
            issue(e.line, describe(e),
                  PlcopenTr::tr("%1 has no element for %2 in the power flow")
                      .arg(m_t.displayName, e.typeName));
            return std::nullopt;
        }
        auto chain = chainIn(e.inputs.empty() ? nullptr : &e.inputs.front(), e);
        if (!chain)
            return std::nullopt;
        chain->push_back(leaf(e, c));
        return chain;
    }
    if ((isTimerType(e.typeName) || isCounterType(e.typeName)) &&
        (out.isEmpty() || out == QLatin1String("Q") || out == QLatin1String("QU") ||
         out == QLatin1String("QD"))) {
        // Q: the element's done bit, a contact of its device; none when the block is not
        // imported (what reads it is listed with it).
        if (m_failedBlocks.contains(e.id))
            return std::nullopt;
        auto c =
            contactOfVariable(out.isEmpty() ? e.instanceName : e.instanceName + '.' + out, e.line);
        if (!c)
            return std::nullopt;
        return Chain{{QStringLiteral("q%1").arg(e.id), Expr::leafOf(*c)}};
    }
    issue(e.line, describe(e),
          PlcopenTr::tr("output %1 of %2 as power flow is not imported")
              .arg(formal.isEmpty() ? QStringLiteral("OUT") : formal, e.typeName));
    return std::nullopt;
}

// An output straight from the rail: the target's always-ON contact (W353's 253.13, Vigor's
// M8000...) stands in for the rail, as the PLC needs a condition.
Chain Importer::railChain() {
    Address on = systemAddress(m_t, SystemRole::AlwaysOn);
    if (!on.valid())
        on = systemAddress(m_t, SystemRole::Run); // PL110 SM0.0: ON while the program runs
    if (!on.valid())
        return {};
    Contact c;
    Operand o;
    o.address = on;
    c.operands.push_back(o);
    return {{QStringLiteral("always"), Expr::leafOf(c)}};
}

std::optional<Chain> Importer::neverChain(const Element &owner) {
    // The always-ON bit negated (railChain's).
    Address on = systemAddress(m_t, SystemRole::AlwaysOn);
    if (!on.valid())
        on = systemAddress(m_t, SystemRole::Run);
    if (!on.valid() || !m_t.findInstruction(Op::And, ContactMode::Negated)) {
        issue(owner.line, describe(owner),
              PlcopenTr::tr("%1 has no contact that is never ON for an input left FALSE")
                  .arg(m_t.displayName));
        return std::nullopt;
    }
    Contact c;
    c.mode = ContactMode::Negated;
    Operand o;
    o.address = on;
    c.operands.push_back(o);
    return Chain{{QStringLiteral("never"), Expr::leafOf(c)}};
}

bool Importer::enAlwaysOn(const Element &e) {
    const Pin *en = pin(e, "EN");
    if (!en || (en->connections.empty() && en->expression.isEmpty()))
        return true;
    if (boolLiteral(en->expression).value_or(false))
        return true;
    const auto chain = chainIn(en, e);
    if (!chain)
        return false;
    if (std::all_of(chain->begin(), chain->end(), [](const Factor &f) {
            return f.expr.empty() || f.key == QLatin1String("always");
        }))
        return true;
    issue(e.line, describe(e),
          PlcopenTr::tr("its EN has a condition: while EN is OFF an IEC block stops where it "
                        "stands, which %1's timers and counters do not; not imported")
              .arg(m_t.displayName));
    return false;
}

std::optional<Chain> Importer::powerPin(const Pin *p, const Element &owner, bool *never) {
    *never = false;
    std::optional<QString> literal;
    if (p && !p->expression.isEmpty())
        literal = p->expression;
    else if (p && p->connections.size() == 1)
        if (const Element *src = element(p->connections.front().ref);
            src && src->kind == QLatin1String("inVariable") && boolLiteral(src->variable)) {
            m_used.insert(src->id);
            literal = src->variable;
        }
    if (!p || (p->connections.empty() && !literal)) {
        *never = true; // an IEC input left open is FALSE
        return std::nullopt;
    }
    if (literal) {
        if (const auto b = boolLiteral(*literal)) {
            if (*b)
                return railChain();
            *never = true;
            return std::nullopt;
        }
        issue(owner.line, describe(owner),
              PlcopenTr::tr("input %1 is %2, not power: not imported").arg(p->formal, *literal));
        return std::nullopt;
    }
    return chainIn(p, owner);
}

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
            const QString text = m_t.constants.prefixed ? QStringLiteral("K%1").arg(units)
                                 : m_t.constants.bcdSetValues
                                     ? QStringLiteral("#%1").arg(units, 4, 10, QLatin1Char('0'))
                                     : QString::number(units);
            const auto c = parseConstant(m_t, text);
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
