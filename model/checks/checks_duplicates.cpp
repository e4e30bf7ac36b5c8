#include "model/checks/checks_list_detail.h"
#include "model/tr.h"

// A coil driven twice (DC001) and an instruction the manual allows once only, programmed twice
// (DC002; docs/diagnostics.md).

namespace rung::model::detail {

void ListChecker::duplicates() {
    std::map<Address, int> driven;
    std::map<const InstructionSpec *, int> once;
    for (int i = 0; i < size(); ++i) {
        const Instruction &ins = at(i);
        // Vigor LINK and MBUS "can be used once only in the program" (Vigor M/VB/VH
        // communication manual, B-3-3, B-3-6): a second one is refused, as the simulator does.
        if (ins.spec && ins.spec->oncePerProgram) {
            const auto [first, inserted] = once.emplace(ins.spec, i);
            if (!inserted) {
                Finding &f = add("DC002", Severity::Error, i,
                                 ChecksTr::tr("%1 is programmed twice; the PLC allows it once "
                                              "only in a program (the first is on line %2)")
                                     .arg(ins.spec->mnemonic)
                                     .arg(at(first->second).line));
                f.diagnostic.related.push_back(location(first->second));
                f.related.push_back(first->second);
                f.ladderMessage = ChecksTr::tr("%1 is programmed twice; the PLC allows it once "
                                               "only in a program (the first is in rung %2)")
                                      .arg(ins.spec->mnemonic, QStringLiteral("%1"));
            }
        }
        if (!drivesCoil(ins.op()) || ins.operands.empty() ||
            ins.operands[0].kind != Operand::Kind::Device)
            continue;
        const Address a = ins.operands[0].address;
        if (a.valid() && m_t.area(a.area).branchMemory)
            continue; // OUT TR 0 in every rung that branches (W353)
        const auto it = driven.find(a);
        if (it == driven.end()) {
            driven.emplace(a, i);
            continue;
        }
        const bool error = m_t.limits.duplicateCoilIsError;
        Finding &f = add(
            "DC001", error ? Severity::Error : Severity::Warning, i,
            error ? ChecksTr::tr("%1 is driven twice; a coil may be driven only once (the first "
                                 "is on line "
                                 "%2)")
                        .arg(formatAddress(m_t, a))
                        .arg(at(it->second).line)
                  : ChecksTr::tr("%1 is driven twice; the later one wins (first on line %2)")
                        .arg(formatAddress(m_t, a))
                        .arg(at(it->second).line));
        if (m_t.console.duplicate) // the VPC console's "Oper duplication"
            f.diagnostic.message =
                ChecksTr::tr("%1 (the PLC says \"%2\")")
                    .arg(f.diagnostic.message, QString::fromLatin1(m_t.console.duplicate));
        f.diagnostic.related.push_back(location(it->second));
        f.related.push_back(it->second);
        const QString device = formatAddress(m_t, a);
        f.ladderMessage =
            error ? ChecksTr::tr("%1 is driven twice; a coil may be driven only once (the first is "
                                 "in rung "
                                 "%2)")
                        .arg(device, QStringLiteral("%1"))
                  : ChecksTr::tr("%1 is driven twice; the later one wins (first in rung %2)")
                        .arg(device, QStringLiteral("%1"));
    }
}

} // namespace rung::model::detail
