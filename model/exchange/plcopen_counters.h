#pragma once

// A target's counters as the IEC 61131-3 counters CTU, CTD and CTUD (docs/plcopen.md
// "Counters"): which IEC block a counter instruction is, which IEC inputs its box's power inputs
// are, and what it does otherwise than the standard's block, said in the note the tools print.
// The export and the import read the same rule. Internal to model/exchange.

#include "model/target/address.h"
#include "model/target/target.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace rung::model::plcopen {

struct CounterForm {
    QString kind;     // CTU, CTD or CTUD
    QString type;     // the IEC type written: the kind, or CTU_DINT... for a 32-bit counter
    QStringList pins; // the IEC inputs the box's power inputs are, in the box's order
    QString unused;   // an IEC input the target's counter has not, written FALSE (CTUD's LD or R)
    QString done;     // the IEC output that is the counter's bit: Q, QU or QD
    // The counter has one input: R is every RST of the counter, wherever it stands (Vigor CNT).
    bool resetByRst = false;
    // Its present value counts down from the set value (CPM1 CNT, VPC CNT00..15).
    bool countsDown = false;
    // Translated: what the target's counter does otherwise than the IEC block.
    QString difference;
};

// The IEC counter a counter instruction of the target is, for the counter `counter` (VPC: the
// element number decides the direction); nullopt when no IEC counter behaves alike (CPM1
// CNTR(12) wraps around at its limits), with *why saying so when given.
std::optional<CounterForm> counterForm(const Target &target, const InstructionSpec &spec,
                                       const Address &counter, QString *why = nullptr);

// CTU, CTD or CTUD for an IEC counter type (CTU_DINT is a CTU), empty for any other type.
QString counterKind(const QString &type);

// The target's counter instructions that may stand for an IEC counter of `kind` on the
// counter `counter`, the best first: the same kind; else the other direction (a CTU as a down
// counter, a CTD as an up counter), whose bit is the same once counting has begun.
struct CounterChoice {
    const InstructionSpec *spec = nullptr;
    CounterForm form;
    bool sameKind = true;
};
std::vector<CounterChoice> counterChoices(const Target &target, const QString &kind,
                                          const Address &counter);

} // namespace rung::model::plcopen
