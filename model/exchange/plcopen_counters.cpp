#include "model/exchange/plcopen_counters.h"
#include "model/tr.h"

#include <QCoreApplication>

// IEC 61131-3 (2.5.2.3.3) defines the counters as function blocks: CTU counts rising edges of
// CU up from 0, R sets CV to 0, Q = CV >= PV; CTD counts rising edges of CD down, LD loads PV,
// Q = CV <= 0; CTUD has both, QU and QD. They count on to the limits of their type. A target's
// counter is written as the block that behaves alike, its inputs in the box's order (the
// target tables' `inputs`: Vigor CNT one, reset by RST (PLC concepts (WPLSoft family)); VPC CNT
// and CPM1 CNT count and reset (VPC user's manual, III; Omron CPM1 guide, CNT); PL110 MUP and
// MDOWN UP, DOWN and RESET (PL110 manual 4.2.5)), and what still differs is said.

namespace rung::model::plcopen {

std::optional<CounterForm> counterForm(const Target &t, const InstructionSpec &spec,
                                       const Address &counter, QString *why) {
    CounterForm f;
    f.done = QStringLiteral("Q");
    const QString name = spec.mnemonic;
    const QString plc = t.displayName;
    if (spec.op == Op::Counter && spec.inputs <= 1) {
        f.kind = QStringLiteral("CTU");
        f.pins = {QStringLiteral("CU")};
        f.resetByRst = true;
        f.difference = PlcopenTr::tr("%1's %2 stops counting at its set value, where CV counts on "
                                     "past PV (Q is the same); its reset is an RST, which acts "
                                     "where it stands in the program, not when the counter runs "
                                     "as R does")
                           .arg(plc, name);
    } else if (spec.op == Op::Counter) {
        const bool down = counter.valid() && counter.index < t.semantics.downCountersBelow;
        if (down) {
            f.kind = QStringLiteral("CTD");
            f.pins = {QStringLiteral("CD"), QStringLiteral("LD")};
            f.difference =
                PlcopenTr::tr("%1's %2 stops counting at 0, where CV counts on below 0 (Q is the "
                              "same), and it is OFF until it has counted down, where a CTD is ON "
                              "until LD first loads PV")
                    .arg(plc, name);
        } else {
            f.kind = QStringLiteral("CTU");
            f.pins = {QStringLiteral("CU"), QStringLiteral("R")};
            f.difference = PlcopenTr::tr("%1's %2 stops counting at its set value, where CV "
                                         "counts on past PV (Q is the same)")
                               .arg(plc, name);
        }
    } else if (spec.op == Op::UpDownCounter && t.semantics.upDownCountersSaturate) {
        f.kind = QStringLiteral("CTUD");
        if (spec.counterMode == CounterMode::Down) {
            f.pins = {QStringLiteral("CU"), QStringLiteral("CD"), QStringLiteral("LD")};
            f.unused = QStringLiteral("R");
            f.done = QStringLiteral("QD");
            f.difference = PlcopenTr::tr("%1's %2 stops counting at 0, where CV counts on below "
                                         "0, and %1 compares the count at the end of the scan, "
                                         "where a CTUD sets QD when it runs")
                               .arg(plc, name);
        } else {
            f.pins = {QStringLiteral("CU"), QStringLiteral("CD"), QStringLiteral("R")};
            f.unused = QStringLiteral("LD");
            f.done = QStringLiteral("QU");
            f.difference = PlcopenTr::tr("%1 compares the count of %2 with PV at the end of the "
                                         "scan, where a CTUD sets QU when it runs")
                               .arg(plc, name);
        }
    } else {
        if (why && spec.op == Op::UpDownCounter)
            *why = PlcopenTr::tr("%1's %2 wraps around at its limits, where IEC's CTUD stops")
                       .arg(plc, name);
        return std::nullopt;
    }
    f.type = f.kind;
    if (counter.valid() && t.area(counter.area).wordBits > 16)
        f.type += QStringLiteral("_DINT");
    return f;
}

QString counterKind(const QString &type) {
    const QString t = type.toUpper();
    for (const char *kind : {"CTUD", "CTU", "CTD"}) {
        const QLatin1String k(kind);
        if (t == k)
            return k;
        // The typed forms of IEC 61131-3 edition 3: CTU_INT, CTU_DINT, CTU_LINT, CTU_UDINT...
        if (t.startsWith(k + QLatin1Char('_')) && !t.startsWith(QLatin1String("CTUD_")))
            return k;
        if (k == QLatin1String("CTUD") && t.startsWith(QLatin1String("CTUD_")))
            return k;
    }
    return {};
}

std::vector<CounterChoice> counterChoices(const Target &t, const QString &kind,
                                          const Address &counter) {
    std::vector<CounterChoice> same, other;
    for (const InstructionSpec &spec : t.instructions) {
        if ((spec.op != Op::Counter && spec.op != Op::UpDownCounter) || spec.differentiated)
            continue;
        const auto form = counterForm(t, spec, counter);
        if (!form)
            continue;
        // A CTU is PL110's MUP with DOWN never ON, a CTD its MDOWN with UP never ON: the same
        // count and bit.
        const bool alike = form->kind == kind ||
                           (form->kind == QLatin1String("CTUD") &&
                            ((kind == QLatin1String("CTU") && form->done == QLatin1String("QU")) ||
                             (kind == QLatin1String("CTD") && form->done == QLatin1String("QD"))));
        const bool crossed = (kind == QLatin1String("CTU") && form->kind == QLatin1String("CTD")) ||
                             (kind == QLatin1String("CTD") && form->kind == QLatin1String("CTU"));
        if (alike)
            same.push_back({&spec, *form, true});
        else if (crossed)
            other.push_back({&spec, *form, false});
    }
    same.insert(same.end(), other.begin(), other.end());
    return same;
}

} // namespace rung::model::plcopen
