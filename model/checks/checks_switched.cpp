#include "model/checks/checks_internal.h"
#include "model/tr.h"

#include <QCoreApplication>

// OP006: timers and counters that a system bit switches on or off (Area::enabledBy; PL110
// SM0.13, PL110 manual 2.1.2: "disabilita la gestione dei contatori C[1..16] ed abilita invece la
// gestione dei timer T[49..64], normalmente disabilitati") used where the program leaves them
// off: a timer T49.. that nothing switches on, a counter beside an instruction that writes
// the bit. A warning: the bit is retained and R/W over MODBUS, so it may be ON without the
// program.

namespace rung::model::detail {

namespace {

bool isDestination(OperandKind kind) {
    return kind == OperandKind::BitDest || kind == OperandKind::WordDest;
}

// The first instruction that writes the bit `gate` or the word that holds it; -1 when none.
int firstWriter(const InstructionList &list, const Address &gate) {
    for (std::size_t i = 0; i < list.instructions.size(); ++i) {
        const Instruction &ins = list.instructions[i];
        if (!ins.spec)
            continue;
        for (std::size_t k = 0; k < ins.operands.size() && k < ins.spec->operands.size(); ++k) {
            const Operand &o = ins.operands[k];
            if (o.kind != Operand::Kind::Device || !isDestination(ins.spec->operands[k].kind))
                continue;
            const bool bit = o.address == gate;
            const bool word =
                o.address.area == gate.area && o.address.index == gate.index && o.address.bit < 0;
            if (bit || word)
                return static_cast<int>(i);
        }
    }
    return -1;
}

} // namespace

void switchedElements(const InstructionList &list, std::vector<Finding> &found) {
    const Target &t = *list.target;
    for (std::size_t i = 0; i < list.instructions.size(); ++i) {
        const Instruction &ins = list.instructions[i];
        const Op op = ins.op();
        if ((op != Op::Timer && op != Op::Counter && op != Op::UpDownCounter) ||
            ins.operands.empty() || ins.operands[0].kind != Operand::Kind::Device ||
            !ins.operands[0].address.valid())
            continue;
        const Area &area = t.area(ins.operands[0].address.area);
        if (!area.enabledBy)
            continue;
        const auto parsed = parseAddress(t, QString::fromLatin1(area.enabledBy));
        const Address *gate = std::get_if<Address>(&parsed);
        if (!gate)
            continue;
        const int writer = firstWriter(list, *gate);
        const QString element = formatAddress(t, ins.operands[0].address);
        const QString bit = QString::fromLatin1(area.enabledBy);
        if (area.enabledWhenOn && writer < 0) {
            addFinding(found, list, "OP006", Severity::Warning, static_cast<int>(i),
                       ChecksTr::tr("%1 runs only while %2 is ON, and no instruction sets %2")
                           .arg(element, bit));
        } else if (!area.enabledWhenOn && writer >= 0) {
            const Instruction &w = list.instructions[static_cast<std::size_t>(writer)];
            Finding &f = addFinding(found, list, "OP006", Severity::Warning, static_cast<int>(i),
                                    ChecksTr::tr("%1 stops while %2 is ON, and line %3 writes %2")
                                        .arg(element, bit)
                                        .arg(w.line));
            f.related.push_back(writer);
            Location l;
            l.line = w.line;
            l.column = w.column;
            f.diagnostic.related.push_back(l);
        }
    }
}

} // namespace rung::model::detail
