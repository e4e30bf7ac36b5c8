#include "model/checks/unmodelled.h"

#include "model/target/address.h"
#include "model/tr.h"

#include <QCoreApplication>

namespace rung::model {

namespace {

std::optional<Address> addressOf(const Target &target, const QString &text) {
    const auto parsed = parseAddress(target, text);
    if (const auto *a = std::get_if<Address>(&parsed))
        return *a;
    return std::nullopt;
}

// The words of `area` an operand reaches: a double word (PL110 SMD20) is two words of the
// area it is made of.
bool reaches(const Target &target, const Operand &o, int area, int first, int last) {
    const Area &own = target.area(o.address.area);
    int from = o.address.index;
    int to = from;
    if (own.doubleWordsOf) {
        if (target.area(area).key != QLatin1String(own.doubleWordsOf))
            return false;
        to = from + 1;
    } else if (o.address.area != area) {
        return false;
    }
    return from <= last && to >= first;
}

} // namespace

std::vector<UnmodelledUse> unmodelledUses(const Target &target, const Instruction &ins) {
    std::vector<UnmodelledUse> found;
    if (target.unmodelled.empty())
        return found;
    for (std::size_t k = 0; k < ins.operands.size(); ++k) {
        const Operand &o = ins.operands[k];
        if (o.kind != Operand::Kind::Device || !o.address.valid() ||
            o.address.area >= static_cast<int>(target.areas.size()))
            continue;
        for (const UnmodelledDevices &range : target.unmodelled) {
            const auto first = addressOf(target, range.first);
            const auto last = addressOf(target, range.last);
            if (!first || !last || !reaches(target, o, first->area, first->index, last->index))
                continue;
            found.push_back(
                {static_cast<int>(k),
                 ChecksTr::tr("%1 is not simulated: %2")
                     .arg(formatOperand(target, o),
                          QCoreApplication::translate("rung::model::Target", range.what))});
            break;
        }
    }
    return found;
}

} // namespace rung::model
