#include "model/ladder/replace_device.h"

#include "model/listing/il.h"

#include <QCoreApplication>

namespace rung::model {

int replaceDevice(std::vector<Rung> &rungs, const Target &target, const Address &from,
                  const Address &to, QString *problem) {
    // First every place, then the change: a refused replacement leaves the program whole.
    for (std::size_t r = 0; r < rungs.size(); ++r) {
        const auto misfit = [&](const std::vector<Operand> &operands, auto kindOf) {
            for (std::size_t i = 0; i < operands.size(); ++i) {
                const Operand &o = operands[i];
                if (o.kind != Operand::Kind::Device || !(o.address == from))
                    continue;
                const QString expected = expectedDevice(target, to, kindOf(i));
                if (expected.isEmpty())
                    continue;
                if (problem)
                    *problem = QCoreApplication::translate(
                                   "rung::model::Ladder",
                                   "%1 cannot replace %2 in rung %3: %4 is expected there.")
                                   .arg(formatAddress(target, to), formatAddress(target, from))
                                   .arg(r + 1)
                                   .arg(expected);
                return true;
            }
            return false;
        };
        const Rung &rung = rungs[r];
        for (const Cell &c : rung.cells) {
            // A compare contact reads words; any other contact a bit.
            const OperandKind kind = c.contact.compare == CompareOp::None ? OperandKind::BitSource
                                                                          : OperandKind::WordSource;
            if (c.kind == CellKind::Contact &&
                misfit(c.contact.operands, [kind](std::size_t) { return kind; }))
                return -1;
        }
        for (const auto &out : rung.outputs)
            if (out && misfit(out->operands, [&out](std::size_t i) {
                    return out->spec && i < out->spec->operands.size() ? out->spec->operands[i].kind
                                                                       : OperandKind::WordSource;
                }))
                return -1;
    }
    int count = 0;
    auto replace = [&](std::vector<Operand> &operands) {
        for (Operand &o : operands)
            if (o.kind == Operand::Kind::Device && o.address == from) {
                o.address = to;
                ++count;
            }
    };
    for (Rung &r : rungs) {
        for (Cell &c : r.cells)
            replace(c.contact.operands);
        for (auto &out : r.outputs)
            if (out)
                replace(out->operands);
    }
    return count;
}

} // namespace rung::model
