#include "model/exchange/plcopen_import.h"
#include "model/tr.h"

#include "model/listing/il.h"
#include "model/target/address.h"

#include <QCoreApplication>

// IEC counters read into a target's counters (docs/plcopen.md "Counters"): a CTU, CTD or CTUD
// block becomes the target's counter that counts alike (plcopen_counters.h), its inputs the
// box's power inputs, R on a one-input counter an RST after it; a counter's CV to a variable a
// move of its present value. What the target's counter does otherwise is a note; what it
// cannot do is listed.

namespace rung::model::plcopen {

namespace {

const QString kCU = QStringLiteral("CU");
const QString kCD = QStringLiteral("CD");
const QString kR = QStringLiteral("R");
const QString kLD = QStringLiteral("LD");

// The input of the target's counter that an input of the file's block is: the same name, or
// across directions (a CTU as a down counter: CU counts, R is its reset, LD).
QString crossed(const QString &formal, bool sameKind) {
    if (sameKind)
        return formal;
    if (formal == kCU)
        return kCD;
    if (formal == kCD)
        return kCU;
    if (formal == kR)
        return kLD;
    return kR;
}

} // namespace

void Importer::note(const QString &text) {
    if (!m_result.notes.contains(text))
        m_result.notes << text;
}

const Importer::ImportedCounter *Importer::importedCounter(const QString &instance) const {
    const auto it = m_counters.find(instance);
    return it == m_counters.end() ? nullptr : &it->second;
}

bool Importer::counterOutputs(const Element &e, std::vector<Output> *outs) {
    const QString kind = counterKind(e.typeName);
    if (!enAlwaysOn(e))
        return false;
    const auto device = resolve(e.instanceName, e.line, e.typeName);
    if (!device)
        return false;
    if (m_t.area(device->area).kind != AreaKind::Counter) {
        issue(e.line, describe(e),
              PlcopenTr::tr("%1 is no counter of %2: give %3 a counter in the mapping file")
                  .arg(formatAddress(m_t, *device), m_t.displayName, e.instanceName));
        return false;
    }
    // The file's inputs that carry power (TRUE: the rail); FALSE or open ones are never ON.
    const QStringList inputs = kind == QLatin1String("CTU")   ? QStringList{kCU, kR}
                               : kind == QLatin1String("CTD") ? QStringList{kCD, kLD}
                                                              : QStringList{kCU, kCD, kR, kLD};
    std::map<QString, Chain> chains;
    for (const QString &formal : inputs) {
        bool never = false;
        auto chain = powerPin(pin(e, formal.toLatin1().constData()), e, &never);
        if (!never && !chain)
            return false; // said why
        if (!never)
            chains[formal] = *chain;
    }
    const std::vector<CounterChoice> choices = counterChoices(m_t, kind, *device);
    const CounterChoice *chosen = nullptr;
    for (const CounterChoice &c : choices) {
        const bool fits = std::all_of(chains.begin(), chains.end(), [&c](const auto &in) {
            const QString mine = crossed(in.first, c.sameKind);
            return c.form.pins.contains(mine) || (c.form.resetByRst && mine == kR);
        });
        if (fits) {
            chosen = &c;
            break;
        }
    }
    if (!chosen) {
        QStringList used;
        for (const auto &[formal, chain] : chains)
            used << formal;
        issue(e.line, describe(e),
              choices.empty() ? PlcopenTr::tr("%1 has no counter that counts as %2 does on %3")
                                    .arg(m_t.displayName, kind, formatAddress(m_t, *device))
                              : PlcopenTr::tr("it uses %1 together, which no counter of %2 has")
                                    .arg(used.join(QStringLiteral(", ")), m_t.displayName));
        return false;
    }
    const CounterForm &form = chosen->form;
    // PV: a literal, the counter's set value; a variable, a word the target reads as one.
    const Pin *pvPin = pin(e, "PV");
    if (!pvPin) {
        issue(e.line, describe(e), PlcopenTr::tr("PV is not given: not imported"));
        return false;
    }
    const auto pvText = pinExpression(*pvPin, e.line);
    if (!pvText)
        return false;
    const auto pv = integerLiteral(*pvText);
    std::vector<Operand> operands;
    std::optional<qint64> kept;
    bool hasSetValue = false;
    for (const OperandSpec &s : chosen->spec->operands) {
        Operand o;
        if (s.kind == OperandKind::CounterNumber) {
            o.address = *device;
        } else if (s.kind == OperandKind::SetValue) {
            hasSetValue = true;
            if (pv) {
                const auto c = setValueConstant(*pv);
                if (const auto *error = std::get_if<AddressError>(&c)) {
                    issue(e.line, describe(e),
                          QStringLiteral("PV %1: %2").arg(*pvText, error->message));
                    return false;
                }
                o.kind = Operand::Kind::Constant;
                o.constant = std::get<Constant>(c);
            } else if (m_t.constants.bcdSetValues) {
                issue(e.line, describe(e),
                      PlcopenTr::tr("PV %1 is a variable: %2 reads a set value in a word as BCD "
                                    "digits; not imported")
                          .arg(*pvText, m_t.displayName));
                return false;
            } else {
                const auto word = operandOf(*pvText, e.line);
                if (!word)
                    return false;
                o = *word;
            }
        } else if (s.optional) {
            continue;
        } else {
            return false;
        }
        operands.push_back(o);
    }
    if (!hasSetValue) {
        // Kept in the PLC (VPC CNT05): a set value of the project.
        if (!pv) {
            issue(e.line, describe(e),
                  PlcopenTr::tr("PV %1 is a variable: %2 keeps a counter's set value in the PLC, "
                                "a number; not imported")
                      .arg(*pvText, m_t.displayName));
            return false;
        }
        kept = *pv;
    }
    const auto ins = build(chosen->spec, operands, e);
    if (!ins)
        return false;
    // The box's power inputs in its order; an input the file leaves FALSE is never ON.
    Output out;
    out.element = &e;
    out.instruction = *ins;
    out.setValue = kept;
    std::vector<Chain> boxInputs;
    for (const QString &mine : form.pins) {
        const auto it = chains.find(crossed(mine, chosen->sameKind));
        if (it != chains.end()) {
            boxInputs.push_back(it->second);
            continue;
        }
        auto never = neverChain(e);
        if (!never)
            return false;
        boxInputs.push_back(*never);
    }
    if (boxInputs.size() == 1) {
        out.chain = boxInputs.front();
    } else {
        out.multi = true;
        out.inputs = boxInputs;
    }
    outs->push_back(out);
    // A one-input counter: R is an RST after it, so that a reset wins over a count in the same
    // scan as IEC's R does.
    if (form.resetByRst)
        if (const auto r = chains.find(crossed(kR, chosen->sameKind)); r != chains.end()) {
            Operand o;
            o.address = *device;
            const auto reset = build(m_t.findInstruction(Op::Reset), {o}, e);
            if (!reset)
                return false;
            Output rst;
            rst.element = &e;
            rst.instruction = *reset;
            rst.chain = r->second;
            outs->push_back(rst);
        }
    m_counters[e.instanceName] = {*device, *chosen};
    CounterNote &n = m_counterNotes[{kind, chosen->spec->mnemonic, chosen->sameKind}];
    n.instances << e.instanceName;
    n.difference = form.difference;
    return true;
}

void Importer::noteCounters() {
    // One note a kind: the instances, the target's counter, what it does otherwise.
    for (const auto &[key, n] : m_counterNotes) {
        const auto &[kind, mnemonic, sameKind] = key;
        const QString instances = n.instances.join(QStringLiteral(", "));
        if (sameKind)
            note(PlcopenTr::tr("%1 (%2) is imported as %3's %4: %5")
                     .arg(kind, instances, m_t.displayName, mnemonic, n.difference));
        else
            note(PlcopenTr::tr("%1 (%2) is imported as %3's %4, which counts the other way: its "
                               "bit is %1's Q once %5 has been ON, and its present value is not CV")
                     .arg(kind, instances, m_t.displayName, mnemonic,
                          kind == QLatin1String("CTU") ? kR : kLD));
    }
}

std::optional<Operand> Importer::counterValue(const QString &instance, int line,
                                              const QString &element) {
    std::optional<Address> device;
    if (const ImportedCounter *c = importedCounter(instance)) {
        if (!c->choice.sameKind) {
            issue(line, element.isEmpty() ? instance + QStringLiteral(".CV") : element,
                  PlcopenTr::tr("%1.CV is not imported: %2 counts the other way, its present "
                                "value is not CV")
                      .arg(instance, formatAddress(m_t, c->device)));
            return std::nullopt;
        }
        device = c->device;
    } else {
        device = resolve(instance, line, QStringLiteral("CTU"));
    }
    if (!device)
        return std::nullopt;
    Operand o;
    o.address = *device;
    return o;
}

std::optional<Output> Importer::valueOutput(const Element &e) {
    QString formal;
    const Element *source = valueSource(e, &formal);
    if (!source || m_failedBlocks.contains(source->id))
        return std::nullopt; // listed with the block
    if (!isCounterType(source->typeName) ||
        formal.compare(QLatin1String("CV"), Qt::CaseInsensitive) != 0) {
        issue(e.line, describe(e),
              PlcopenTr::tr("%1 of %2 to a variable is not imported: only a counter's CV is")
                  .arg(formal, describe(*source)));
        return std::nullopt;
    }
    const auto value = counterValue(source->instanceName, e.line, describe(e));
    const auto dest = value ? operandOf(e.variable, e.line) : std::nullopt;
    if (!dest)
        return std::nullopt;
    // The present value copied every scan, as the block writes CV; where the target keeps it as
    // BCD digits (CPM1), converted to binary.
    const auto ins = copyInstruction(*value, *dest, m_t.constants.bcdSetValues, e);
    if (!ins)
        return std::nullopt;
    Output out;
    out.element = &e;
    out.instruction = *ins;
    out.chain = railChain();
    return out;
}

} // namespace rung::model::plcopen
