#include "model/exchange/plcopen_export.h"
#include "model/tr.h"

#include "model/exchange/plcopen_xml.h"
#include "model/ladder/ladder_text.h"
#include "model/target/address.h"

#include <QCoreApplication>
#include <QDateTime>

#include <cmath>

// The ladder as a PLCopen TC6 XML 2.01 LD body (docs/plcopen.md "Export"). Each rung's grid
// becomes a graph: the nodes of a row joined by wires and vertical links are one connection
// point; a contact connects the point on its left to the one on its right; an element's input
// lists every element whose output reaches its point (several: they are OR-ed, as the
// standard says). Blocks the IEC standard has (TON, TOF, MOVE, the comparisons, NOT, R_TRIG,
// F_TRIG) are written as such; any other instruction as a block of the PLC's own name. Every
// block and coil carries the instruction as the target writes it in addData, so that Rung
// Studio reads its own file back exactly.

namespace rung::model::plcopen {

PlcopenExport Exporter::run(const QString &name, const QDateTime &created) {
    // Timers and counters written as IEC timers and counters are declared as such; plan every
    // rung first.
    for (const Rung &r : m_p.program.rungs)
        for (const auto &out : r.outputs) {
            if (!out)
                continue;
            QString pv;
            if (standardTimer(*out)) {
                declare(out->operands.front().address, timerType(*out), true, QStringLiteral("Q"));
            } else if (const auto form = standardCounter(*out, &pv)) {
                const Address &counter = out->operands.front().address;
                declare(counter, form->type, true, form->done);
                m_vars.at(counter).counter = true;
                if (form->resetByRst)
                    m_resetByRst.insert(counter);
            }
        }
    int y = 20;
    const auto &rungs = m_p.program.rungs;
    for (std::size_t i = 0; i < rungs.size(); ++i) {
        // An IEC program ends where its body ends: the last END is not written (the
        // import adds it again, docs/plcopen.md).
        const Rung &rung = rungs[i];
        if (i + 1 == rungs.size() && isEnd(rung))
            continue;
        planRung(rung, &y);
    }
    wireResets();
    for (const Symbol &s : m_p.symbols)
        declare(s.address, {}, false);
    for (const auto &[address, value] : m_p.setValues)
        declare(address, {}, false);
    return write(name, created);
}

bool Exporter::isEnd(const Rung &rung) {
    int outputs = 0;
    bool end = false;
    for (const auto &o : rung.outputs)
        if (o) {
            ++outputs;
            end = o->op() == Op::End;
        }
    const bool noContacts = std::none_of(rung.cells.begin(), rung.cells.end(),
                                         [](const Cell &c) { return c.kind == CellKind::Contact; });
    return outputs == 1 && end && noContacts;
}

bool Exporter::bitDevice(const Address &a) const {
    const AreaKind k = m_t.area(a.area).kind;
    return k == AreaKind::Bit || a.bit >= 0;
}

// An on- or off-delay timer with a constant set value (or the VPC's, kept in setValues).
bool Exporter::standardTimer(const Instruction &ins) const {
    if (ins.op() != Op::Timer || ins.operands.empty() || ins.spec->doubleWord ||
        ins.operands.front().kind != Operand::Kind::Device || ins.operands.front().modified())
        return false;
    if (ins.spec->timerMode == TimerMode::Accumulating)
        return false;
    return presetMs(ins).has_value();
}

QString Exporter::timerType(const Instruction &ins) {
    return ins.spec->timerMode == TimerMode::OffDelay ? QStringLiteral("TOF")
                                                      : QStringLiteral("TON");
}

std::optional<qint64> Exporter::presetMs(const Instruction &ins) const {
    std::optional<qint64> units;
    for (std::size_t k = 0; k < ins.spec->operands.size() && k < ins.operands.size(); ++k)
        if (ins.spec->operands[k].kind == OperandKind::SetValue) {
            const Operand &o = ins.operands[k];
            if (o.kind != Operand::Kind::Constant || o.modified())
                return std::nullopt;
            units = o.constant.value;
        }
    if (!units) {
        // The set value kept in the PLC (VPC TIM00: the instruction has none).
        const auto it = m_p.setValues.find(ins.operands.front().address);
        if (it == m_p.setValues.end())
            return std::nullopt;
        units = it->second;
    }
    const double ms = static_cast<double>(*units) * timerBaseMs(m_t, ins);
    if (ms != std::floor(ms) || ms < 0)
        return std::nullopt;
    return static_cast<qint64>(ms);
}

std::optional<CounterForm> Exporter::standardCounter(const Instruction &ins, QString *pv,
                                                     QString *why) {
    const Op op = ins.op();
    if ((op != Op::Counter && op != Op::UpDownCounter) || ins.operands.empty() ||
        ins.spec->differentiated || ins.spec->doubleWord ||
        ins.operands.front().kind != Operand::Kind::Device || ins.operands.front().modified())
        return std::nullopt;
    const Address &counter = ins.operands.front().address;
    auto form = counterForm(m_t, *ins.spec, counter, why);
    if (!form)
        return std::nullopt;
    for (std::size_t k = 0; k < ins.spec->operands.size() && k < ins.operands.size(); ++k)
        if (ins.spec->operands[k].kind == OperandKind::SetValue) {
            const Operand &o = ins.operands[k];
            if (o.kind == Operand::Kind::Constant && !o.modified()) {
                *pv = QString::number(o.constant.value);
                return form;
            }
            // A set value in a word: PV the word's variable, where the word holds the number.
            if (o.kind == Operand::Kind::Device && !o.modified() && !m_t.constants.bcdSetValues) {
                *pv = expression(o, true);
                return form;
            }
            if (why && m_t.constants.bcdSetValues)
                *why = PlcopenTr::tr("%1 reads a set value in a word as BCD digits, where PV is "
                                     "a number")
                           .arg(m_t.displayName);
            return std::nullopt;
        }
    // The set value kept in the PLC (VPC CNT05: the instruction has none).
    const auto it = m_p.setValues.find(counter);
    if (it == m_p.setValues.end())
        return std::nullopt;
    *pv = QString::number(it->second);
    return form;
}

bool Exporter::standardMove(const Instruction &ins) const {
    if (ins.op() != Op::Apply || ins.spec->function != ApplyFunction::Mov ||
        ins.spec->differentiated || ins.spec->doubleWord || ins.operands.size() != 2)
        return false;
    const Operand &d = ins.operands[1];
    // A timer or counter written as an IEC instance is no variable to move a value into.
    const auto instance = m_vars.find(d.address);
    return !ins.operands[0].modified() && d.kind == Operand::Kind::Device && !d.modified() &&
           (instance == m_vars.end() || !instance->second.instance);
}

bool Exporter::counterReset(const Instruction &ins) const {
    return ins.op() == Op::Reset && ins.operands.size() == 1 &&
           ins.operands.front().kind == Operand::Kind::Device && !ins.operands.front().modified() &&
           m_resetByRst.contains(ins.operands.front().address);
}

void Exporter::declare(const Address &a, const QString &type, bool instance, const QString &done) {
    auto it = m_vars.find(a);
    if (it != m_vars.end()) {
        if (instance) {
            it->second.type = type;
            it->second.instance = true;
            it->second.done = done;
        }
        return;
    }
    Variable v;
    v.address = a;
    v.instance = instance;
    v.done = done;
    if (!type.isEmpty()) {
        v.type = type;
    } else {
        const Area &area = m_t.area(a.area);
        v.type = bitDevice(a) || area.kind == AreaKind::Timer || area.kind == AreaKind::Counter
                     ? QStringLiteral("BOOL")
                 : area.wordBits > 16 ? QStringLiteral("DINT")
                                      : QStringLiteral("INT");
    }
    m_vars.emplace(a, v);
}

// A device as a contact or coil names it: a timer declared as TON is its output Q.
QString Exporter::variableOf(const Address &a) {
    declare(a, {}, false);
    const Variable &v = m_vars.at(a);
    return v.instance ? iecName(m_t, a) + QLatin1Char('.') + v.done : iecName(m_t, a);
}

// An operand as an IEC expression: a device's name, a constant as a literal.
QString Exporter::expression(const Operand &o, bool value) {
    switch (o.kind) {
    case Operand::Kind::Device:
        if (o.modified())
            return formatOperand(m_t, o); // K4M0, D0E0: no IEC form (addData has it)
        declare(o.address, {}, false);
        if (value && m_vars.at(o.address).counter)
            return iecName(m_t, o.address) + QStringLiteral(".CV");
        return iecName(m_t, o.address);
    case Operand::Kind::Constant:
        switch (o.constant.style) {
        case Constant::Style::Hex:
            return QStringLiteral("16#") + QString::number(o.constant.value, 16).toUpper();
        case Constant::Style::Bcd:
            // The word the PLC holds: its digits read in hexadecimal (#0150 = 16#0150).
            return QStringLiteral("16#%1").arg(o.constant.value, 4, 10, QLatin1Char('0'));
        default:
            return QString::number(o.constant.value);
        }
    case Operand::Kind::Text:
        break;
    case Operand::Kind::String: {
        // An IEC 61131-3 STRING literal: in single quotes, $ escaping a quote and a dollar.
        QString text = o.text;
        text.replace(QLatin1Char('$'), QLatin1String("$$"));
        text.replace(QLatin1Char('\''), QLatin1String("$'"));
        return QLatin1Char('\'') + text + QLatin1Char('\'');
    }
    }
    return o.text;
}

Elem &Exporter::add(Elem::Kind kind, int x, int y) {
    Elem e;
    e.kind = kind;
    e.id = m_nextId++;
    e.x = x;
    e.y = y;
    m_elems.push_back(e);
    return m_elems.back();
}

int Exporter::inVariable(const QString &expression, int x, int y) {
    Elem &v = add(Elem::Kind::InVar, x, y);
    v.variable = expression;
    v.width = 40;
    v.height = 20;
    return v.id;
}

void Exporter::planRung(const Rung &rung, int *y0) {
    if (!rung.comment.isEmpty()) {
        Elem &c = add(Elem::Kind::Comment, 20, *y0);
        c.variable = rung.comment;
        c.width = 400;
        c.height = 20 * static_cast<int>(rung.comment.count(QLatin1Char('\n')) + 1);
        *y0 += c.height + 10;
    }
    const int top = *y0;
    Nodes nodes(rung);
    Elem &rail = add(Elem::Kind::LeftRail, 20, top);
    rail.width = 3;
    rail.height = rung.rows * kRow;
    const int railId = rail.id;
    std::map<int, std::vector<Conn>> sources;
    sources[nodes.find(nodes.rail())].push_back({railId, {}});
    auto cellX = [](int c) { return 40 + c * kCell; };
    auto rowY = [top](int r) { return top + r * kRow; };
    std::vector<std::size_t> powered; // elements whose first input comes from a node group
    for (int c = 0; c < rung.columns; ++c) {
        for (int r = 0; r < rung.rows; ++r) {
            const Cell &cell = rung.cell(r, c);
            if (cell.kind != CellKind::Contact)
                continue;
            const int in = nodes.find(nodes.node(r, c));
            const int out = nodes.find(nodes.node(r, c + 1));
            const Contact &k = cell.contact;
            QString outFormal;
            std::size_t index = 0;
            if (k.invert) {
                Elem &b = add(Elem::Kind::Block, cellX(c), rowY(r));
                const bool edge = k.mode == ContactMode::Rising || k.mode == ContactMode::Falling;
                if (edge) {
                    // PL110's P and N: the power flow's edge, an IEC R_TRIG / F_TRIG.
                    b.typeName = k.mode == ContactMode::Rising ? QStringLiteral("R_TRIG")
                                                               : QStringLiteral("F_TRIG");
                    b.instanceName = QStringLiteral("EDGE%1").arg(++m_edges);
                    m_edgeInstances.emplace_back(b.instanceName, b.typeName);
                    b.inputs.push_back({QStringLiteral("CLK"), {}});
                    b.outputs << QStringLiteral("Q");
                    outFormal = QStringLiteral("Q");
                } else {
                    b.typeName = QStringLiteral("NOT");
                    b.inputs.push_back({QStringLiteral("IN"), {}});
                    b.outputs << QStringLiteral("OUT");
                    outFormal = QStringLiteral("OUT");
                }
                b.contact = contactToText(m_t, k);
                b.width = 50;
                b.height = 30;
                b.inputGroup = in;
                index = m_elems.size() - 1;
            } else if (k.compare != CompareOp::None) {
                static const char *const names[] = {"", "EQ", "NE", "LT", "LE", "GT", "GE"};
                const QString contactText = contactToText(m_t, k);
                const int x = cellX(c);
                const int in1 =
                    inVariable(expression(k.operands.at(0), true), x - 30, rowY(r) + 20);
                const int in2 =
                    inVariable(expression(k.operands.at(1), true), x - 30, rowY(r) + 30);
                Elem &b = add(Elem::Kind::Block, x, rowY(r));
                b.typeName = QLatin1String(names[static_cast<int>(k.compare)]);
                b.inputs = {{QStringLiteral("EN"), {}},
                            {QStringLiteral("IN1"), {{in1, {}}}},
                            {QStringLiteral("IN2"), {{in2, {}}}}};
                b.outputs << QStringLiteral("ENO") << QStringLiteral("OUT");
                b.contact = contactText;
                b.width = 50;
                b.height = 50;
                b.inputGroup = in;
                outFormal = QStringLiteral("OUT");
                index = m_elems.size() - 1;
            } else {
                Elem &e = add(Elem::Kind::Contact, cellX(c), rowY(r));
                e.variable = variableOf(k.operands.at(0).address);
                e.negated = k.mode == ContactMode::Negated;
                e.edge = k.mode == ContactMode::Rising    ? QStringLiteral("rising")
                         : k.mode == ContactMode::Falling ? QStringLiteral("falling")
                                                          : QString();
                e.width = 21;
                e.height = 15;
                e.inputGroup = in;
                index = m_elems.size() - 1;
            }
            powered.push_back(index);
            sources[out].push_back({m_elems[index].id, outFormal, r, c});
        }
    }
    std::vector<int> coils;
    const int outX = cellX(rung.columns) + 40;
    for (int r = 0; r < rung.rows; ++r) {
        const auto &out = rung.outputs[static_cast<std::size_t>(r)];
        if (!out)
            continue;
        const std::vector<int> rows = rung.boxInputRows(r);
        const int group = nodes.find(nodes.node(r, rung.columns));
        const Instruction &ins = *out;
        const QString text = printInstruction(m_t, ins);
        const Op op = ins.op();
        const bool bitOperand =
            !ins.operands.empty() && ins.operands.front().kind == Operand::Kind::Device &&
            !ins.operands.front().modified() && bitDevice(ins.operands.front().address);
        const bool coil =
            bitOperand && rows.size() == 1 && ins.operands.size() == 1 &&
            (op == Op::Out || op == Op::Set || op == Op::Reset || op == Op::PulseRise ||
             op == Op::PulseFall) &&
            m_t.area(ins.operands.front().address.area).onlyWrittenBy == ApplyFunction::None;
        if (coil) {
            Elem &e = add(Elem::Kind::Coil, outX, rowY(r));
            e.variable = variableOf(ins.operands.front().address);
            e.negated = op == Op::Out && ins.spec->negated;
            e.storage = op == Op::Set     ? QStringLiteral("set")
                        : op == Op::Reset ? QStringLiteral("reset")
                                          : QString();
            e.edge = op == Op::PulseRise   ? QStringLiteral("rising")
                     : op == Op::PulseFall ? QStringLiteral("falling")
                                           : QString();
            e.instruction = text;
            e.width = 21;
            e.height = 15;
            e.inputGroup = group;
            powered.push_back(m_elems.size() - 1);
            coils.push_back(e.id);
            continue;
        }
        if (counterReset(ins)) {
            // The counter's R: its power goes there through a continuation (wireResets).
            const Address &counter = ins.operands.front().address;
            auto &resets = m_resets[counter];
            Elem &k = add(Elem::Kind::Connector, outX, rowY(r));
            k.variable = QStringLiteral("RESET_%1").arg(iecName(m_t, counter));
            if (!resets.empty())
                k.variable += QStringLiteral("_%1").arg(resets.size() + 1);
            k.instruction = text;
            k.width = 80;
            k.height = 20;
            k.inputGroup = group;
            resets.push_back(k.id);
            powered.push_back(m_elems.size() - 1);
            continue;
        }
        QString pv;
        QString why;
        if (const auto form = standardCounter(ins, &pv, &why)) {
            const int pvId = inVariable(pv, outX - 40, rowY(r) + 50);
            const int never = form->unused.isEmpty()
                                  ? 0
                                  : inVariable(QStringLiteral("FALSE"), outX - 40, rowY(r) + 40);
            Elem &b = add(Elem::Kind::Block, outX, rowY(r));
            b.typeName = form->type;
            b.instanceName = iecName(m_t, ins.operands.front().address);
            for (const QString &pin : form->pins)
                b.inputs.push_back({pin, {}});
            if (never)
                b.inputs.push_back({form->unused, {{never, {}}}});
            if (form->resetByRst)
                b.inputs.push_back({QStringLiteral("R"), {}}); // wireResets
            b.inputs.push_back({QStringLiteral("PV"), {{pvId, {}}}});
            if (form->kind == QLatin1String("CTUD"))
                b.outputs << QStringLiteral("QU") << QStringLiteral("QD");
            else
                b.outputs << QStringLiteral("Q");
            b.outputs << QStringLiteral("CV");
            b.instruction = text;
            b.width = 60;
            b.height = 30 + 10 * static_cast<int>(b.inputs.size());
            if (rows.size() == 1)
                b.inputGroup = group;
            else
                for (const int row : rows)
                    b.boxRows.push_back(nodes.find(nodes.node(row, rung.columns)));
            m_counterBlocks[ins.operands.front().address].push_back(m_elems.size() - 1);
            powered.push_back(m_elems.size() - 1);
            m_counterNotes.insert(PlcopenTr::tr("%1 is written as an IEC %2: %3")
                                      .arg(blockName(*ins.spec), form->kind, form->difference));
            continue;
        }
        if (standardTimer(ins)) {
            const int pt =
                inVariable(QStringLiteral("T#%1ms").arg(*presetMs(ins)), outX - 40, rowY(r) + 20);
            Elem &b = add(Elem::Kind::Block, outX, rowY(r));
            b.typeName = timerType(ins);
            b.instanceName = iecName(m_t, ins.operands.front().address);
            b.inputs = {{QStringLiteral("IN"), {}}, {QStringLiteral("PT"), {{pt, {}}}}};
            b.outputs << QStringLiteral("Q") << QStringLiteral("ET");
            b.instruction = text;
            b.width = 60;
            b.height = 50;
            b.inputGroup = group;
            powered.push_back(m_elems.size() - 1);
            continue;
        }
        if (standardMove(ins)) {
            const int source =
                inVariable(expression(ins.operands[0], true), outX - 40, rowY(r) + 20);
            Elem &b = add(Elem::Kind::Block, outX, rowY(r));
            b.typeName = QStringLiteral("MOVE");
            b.inputs = {{QStringLiteral("EN"), {}}, {QStringLiteral("IN"), {{source, {}}}}};
            b.outputs << QStringLiteral("ENO") << QStringLiteral("OUT");
            b.instruction = text;
            b.width = 60;
            b.height = 50;
            b.inputGroup = group;
            const int blockId = b.id;
            powered.push_back(m_elems.size() - 1);
            Elem &d = add(Elem::Kind::OutVar, outX + 80, rowY(r));
            d.variable = expression(ins.operands[1]);
            d.width = 40;
            d.height = 20;
            d.inputs.push_back({QString(), {{blockId, QStringLiteral("OUT")}}});
            continue;
        }
        // A block of the PLC's own: the instruction's name, its power inputs, its operands.
        std::vector<int> operandIds;
        for (std::size_t k = 0; k < ins.operands.size(); ++k)
            operandIds.push_back(inVariable(expression(ins.operands[k]), outX - 40,
                                            rowY(r) + 20 + static_cast<int>(k) * 10));
        Elem &b = add(Elem::Kind::Block, outX, rowY(r));
        b.typeName = blockName(*ins.spec);
        b.instruction = text;
        b.width = 60;
        b.height = 30 + 10 * static_cast<int>(ins.operands.size() + rows.size());
        if (!isUnconditional(op)) {
            if (rows.size() == 1) {
                b.inputs.push_back({QStringLiteral("EN"), {}});
                b.inputGroup = group;
            } else {
                for (std::size_t k = 0; k < rows.size(); ++k) {
                    b.inputs.push_back({QStringLiteral("IN%1").arg(k + 1), {}});
                    b.boxRows.push_back(nodes.find(nodes.node(rows[k], rung.columns)));
                }
            }
        }
        for (std::size_t k = 0; k < operandIds.size(); ++k)
            b.inputs.push_back({QStringLiteral("OP%1").arg(k + 1), {{operandIds[k], {}}}});
        b.outputs << QStringLiteral("ENO");
        powered.push_back(m_elems.size() - 1);
        m_vendor.insert(b.typeName);
        if (!why.isEmpty())
            m_vendorWhy[b.typeName] = why;
    }
    // Every element's power input: the outputs that reach its node group, the rail first,
    // then the branches from top to bottom as the grid draws them.
    for (auto &[group, list] : sources)
        std::stable_sort(list.begin(), list.end(), [](const Conn &a, const Conn &b) {
            return std::pair(a.row, a.column) < std::pair(b.row, b.column);
        });
    for (std::size_t index : powered) {
        Elem &e = m_elems[index];
        if (!e.boxRows.empty()) {
            for (std::size_t k = 0; k < e.boxRows.size(); ++k)
                e.inputs[k].second = sources[e.boxRows[k]];
            continue;
        }
        if (e.inputGroup < 0)
            continue;
        if (e.kind == Elem::Kind::Contact || e.kind == Elem::Kind::Coil ||
            e.kind == Elem::Kind::Connector)
            e.inputs.insert(e.inputs.begin(), {QString(), sources[e.inputGroup]});
        else
            e.inputs.front().second = sources[e.inputGroup];
    }
    if (!coils.empty()) {
        Elem &right = add(Elem::Kind::RightRail, outX + 60, top);
        right.width = 3;
        right.height = rung.rows * kRow;
        for (int id : coils)
            right.inputs.push_back({QString(), {{id, {}}}});
    }
    *y0 = top + rung.rows * kRow + 20;
}

void Exporter::wireResets() {
    for (const auto &[counter, blocks] : m_counterBlocks) {
        const auto resets = m_resets.find(counter);
        if (resets == m_resets.end() || blocks.empty())
            continue;
        // One continuation for each RST, left of the (first) block, feeding every block's R.
        const Elem first = m_elems[blocks.front()];
        std::vector<Conn> conns;
        int k = 0;
        for (const int connector : resets->second) {
            const QString name =
                std::find_if(m_elems.begin(), m_elems.end(), [connector](const Elem &e) {
                    return e.id == connector;
                })->variable;
            Elem &c = add(Elem::Kind::Continuation, first.x - 100, first.y + 30 + 20 * k++);
            c.variable = name;
            c.width = 80;
            c.height = 20;
            conns.push_back({c.id, {}});
        }
        for (const std::size_t index : blocks)
            for (auto &[formal, list] : m_elems[index].inputs)
                if (formal == QLatin1String("R"))
                    list = conns;
    }
}

QString Exporter::blockName(const InstructionSpec &spec) {
    // The mnemonic as an identifier: "KEEP(11)" -> KEEP, "@INC(38)" -> INC, "LD NOT" -> LD_NOT.
    QString name = spec.mnemonic;
    name.remove(QLatin1Char('@'));
    if (const qsizetype p = name.indexOf(QLatin1Char('(')); p > 0)
        name = name.left(p);
    QString out;
    for (const QChar c : name)
        out += c.isLetterOrNumber() && c.unicode() < 128 ? c : QLatin1Char('_');
    return out;
}

} // namespace rung::model::plcopen

namespace rung::model {

PlcopenExport exportPlcopen(const Project &project, const QString &name, const QDateTime &created) {
    return plcopen::Exporter(project).run(name, created);
}

} // namespace rung::model
